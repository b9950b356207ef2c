#include "ind_keyedio.h"

PetscErrorCode IndPointCentroid(DM dm, PetscInt p, PetscReal c[3])
{
  DM           cdm;
  PetscSection cs;
  Vec          X;
  PetscScalar *vals = NULL;
  PetscInt     n;

  PetscFunctionBeginUser;
  PetscCall(DMGetCoordinateDM(dm, &cdm));
  PetscCall(DMGetLocalSection(cdm, &cs));
  PetscCall(DMGetCoordinatesLocal(dm, &X));
  PetscCall(DMPlexVecGetClosure(cdm, cs, X, p, &n, &vals));
  c[0] = c[1] = c[2] = 0;
  for (PetscInt k = 0; k < n; ++k) c[k % 3] += PetscRealPart(vals[k]);
  for (int d = 0; d < 3; ++d) c[d] /= (PetscReal)(n / 3);
  PetscCall(DMPlexVecRestoreClosure(cdm, cs, X, p, &n, &vals));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndRowsWrite(PetscViewer v, const char name[], PetscInt n, PetscInt bs, const PetscReal *rows)
{
  Vec          x;
  PetscScalar *a;

  PetscFunctionBeginUser;
  PetscCall(VecCreateMPI(PetscObjectComm((PetscObject)v), n * bs, PETSC_DETERMINE, &x));
  PetscCall(VecSetBlockSize(x, bs));
  PetscCall(PetscObjectSetName((PetscObject)x, name));
  PetscCall(VecGetArray(x, &a));
  for (PetscInt k = 0; k < n * bs; ++k) a[k] = rows[k];
  PetscCall(VecRestoreArray(x, &a));
  PetscCall(VecView(x, v));
  PetscCall(VecDestroy(&x));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndRowsRead(PetscViewer v, const char name[], PetscInt bs, Vec *x)
{
  PetscFunctionBeginUser;
  PetscCall(VecCreate(PetscObjectComm((PetscObject)v), x));
  PetscCall(VecSetBlockSize(*x, bs));
  PetscCall(PetscObjectSetName((PetscObject)*x, name));
  PetscCall(VecLoad(*x, v));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndRowsLocate(PetscViewer v, const char keys[], const char what[], const char file[], PetscInt n,
                             const PetscReal *mine, PetscInt **index)
{
  MPI_Comm           comm = PetscObjectComm((PetscObject)v);
  Vec                fk;
  const PetscScalar *k;
  PetscReal         *rowid, *found;
  PetscInt           nk, rstart, missing, duplicate, total = n, nfile;

  PetscFunctionBeginUser;
  PetscCall(IndRowsRead(v, keys, 3, &fk));
  PetscCall(VecGetLocalSize(fk, &nk));
  PetscCall(VecGetOwnershipRange(fk, &rstart, NULL));
  PetscCall(VecGetSize(fk, &nfile));
  nk /= 3;
  PetscCall(PetscMalloc2(nk + 1, &rowid, n + 1, &found));
  for (PetscInt i = 0; i < nk; ++i) rowid[i] = (PetscReal)(rstart / 3 + i);
  PetscCall(VecGetArrayRead(fk, &k));
  PetscCall(IndKeyJoin(comm, 1, nk, (const PetscReal *)k, rowid, n, mine, found, &missing, &duplicate));
  PetscCall(VecRestoreArrayRead(fk, &k));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &total, 1, MPIU_INT, MPI_SUM, comm));
  PetscCheck(!missing && !duplicate && nfile / 3 == total, comm, PETSC_ERR_ARG_INCOMP,
             "'%s' was made on another mesh (%" PetscInt_FMT " %s there, %" PetscInt_FMT " here, %" PetscInt_FMT " of "
               "these not found)", file,
             nfile / 3, what, total, missing);
  PetscCall(PetscMalloc1(n + 1, index));
  for (PetscInt i = 0; i < n; ++i) (*index)[i] = (PetscInt)found[i];
  PetscCall(PetscFree2(rowid, found));
  PetscCall(VecDestroy(&fk));
  PetscFunctionReturn(PETSC_SUCCESS);
}
