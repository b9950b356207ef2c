#include <inttypes.h>
#include <string.h>
#include "ind_keyedio.h"
#include "ind_h5rows.h"

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

/* splitmix64's finaliser: every input bit moves about half the output bits. */
static uint64_t Mix(uint64_t z)
{
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

/* n values at global positions rstart.. of a vector spread over comm */
static PetscErrorCode ChecksumValues(MPI_Comm comm, PetscInt n, PetscInt rstart, const PetscScalar *a,
                                     char sum[IND_ROWS_CHECKSUM_LEN])
{
  uint64_t h = 0;

  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < n; ++k) {
    const PetscReal r = PetscRealPart(a[k]);
    uint64_t        bits;
    memcpy(&bits, &r, sizeof(bits));
    h += Mix(bits ^ Mix((uint64_t)(rstart + k) + 0x9e3779b97f4a7c15ULL)); /* wraps: a sum modulo 2^64 */
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &h, 1, MPI_UINT64_T, MPI_SUM, comm));
  PetscCall(PetscSNPrintf(sum, IND_ROWS_CHECKSUM_LEN, "%016" PRIx64, h));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndRowsChecksum(Vec x, char sum[IND_ROWS_CHECKSUM_LEN])
{
  const PetscScalar *a;
  PetscInt           n, rstart;

  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(x, &n));
  PetscCall(VecGetOwnershipRange(x, &rstart, NULL));
  PetscCall(VecGetArrayRead(x, &a));
  PetscCall(ChecksumValues(PetscObjectComm((PetscObject)x), n, rstart, a, sum));
  PetscCall(VecRestoreArrayRead(x, &a));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Straight from the rows: a copy in a vector for VecView would double them for the time of the write. */
PetscErrorCode IndRowsWrite(PetscViewer v, const char name[], PetscInt n, PetscInt bs, const PetscReal *rows)
{
  MPI_Comm comm = PetscObjectComm((PetscObject)v);
  PetscInt values = n * bs, below = 0;
  char     sum[IND_ROWS_CHECKSUM_LEN];

  PetscFunctionBeginUser;
  PetscCall(IndH5WriteRows(v, name, n, bs, rows));
  PetscCallMPI(MPI_Scan(&values, &below, 1, MPIU_INT, MPI_SUM, comm));
  below -= values;
  PetscCall(ChecksumValues(comm, values, below, (const PetscScalar *)rows, sum));
  PetscCall(PetscViewerHDF5WriteAttribute(v, name, "checksum", PETSC_STRING, sum));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndRowsRead(PetscViewer v, const char name[], PetscInt bs, Vec *x)
{
  PetscBool has, same;

  PetscFunctionBeginUser;
  PetscCall(VecCreate(PetscObjectComm((PetscObject)v), x));
  PetscCall(VecSetBlockSize(*x, bs));
  PetscCall(PetscObjectSetName((PetscObject)*x, name));
  PetscCall(VecLoad(*x, v));
  PetscCall(IndRowsChecksumMatches(v, name, *x, &has, &same));
  if (has && !same) {
    const char *file = NULL;
    char        path[PETSC_MAX_PATH_LEN], *group = NULL;
    PetscCall(PetscViewerFileGetName(v, &file));
    PetscCall(PetscViewerHDF5GetGroup(v, name, &group));
    PetscCall(PetscStrncpy(path, group, sizeof(path)));
    PetscCall(PetscFree(group));
    SETERRQ(PetscObjectComm((PetscObject)v), PETSC_ERR_FILE_UNEXPECTED,
            "'%s' is damaged: dataset %s does not match the checksum written with it", file, path);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndRowsChecksumMatches(PetscViewer v, const char name[], Vec x, PetscBool *has, PetscBool *same)
{
  char sum[IND_ROWS_CHECKSUM_LEN], *saved = NULL;

  PetscFunctionBeginUser;
  *same = PETSC_FALSE;
  PetscCall(PetscViewerHDF5HasAttribute(v, name, "checksum", has));
  if (!*has) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(IndRowsChecksum(x, sum));
  PetscCall(PetscViewerHDF5ReadAttribute(v, name, "checksum", PETSC_STRING, NULL, &saved));
  PetscCall(PetscStrcmp(sum, saved, same));
  PetscCall(PetscFree(saved));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndCellCentroids(IndDisc disc, PetscReal **keys)
{
  const IndDiscLayout *L;
  DM                   dm;

  PetscFunctionBeginUser;
  PetscCall(IndDiscGetLayout(disc, &L));
  PetscCall(IndDiscGetDM(disc, &dm));
  PetscCall(PetscMalloc1(3 * L->ncell + 1, keys));
  for (PetscInt i = 0; i < L->ncell; ++i) PetscCall(IndPointCentroid(dm, L->cStart + i, *keys + 3 * i));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndRowsJoin(PetscViewer v, const char keys[], const char values[], PetscInt bs, const char what[],
                           const char file[], PetscInt n, const PetscReal *mine, PetscReal *out)
{
  MPI_Comm           comm = PetscObjectComm((PetscObject)v);
  Vec                fk, fv = NULL;
  const PetscScalar *k, *x = NULL;
  PetscReal         *rowid = NULL;
  PetscInt           nk, rstart, missing, duplicate, total = n, nfile;

  PetscFunctionBeginUser;
  PetscCall(IndRowsRead(v, keys, 3, &fk));
  PetscCall(VecGetLocalSize(fk, &nk));
  PetscCall(VecGetOwnershipRange(fk, &rstart, NULL));
  PetscCall(VecGetSize(fk, &nfile));
  nk /= 3;
  if (values) {
    PetscInt nx;
    PetscCall(IndRowsRead(v, values, bs, &fv));
    PetscCall(VecGetLocalSize(fv, &nx));
    PetscCheck(nx == nk * bs, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s: the %s' keys and values disagree", file,
               what);
    PetscCall(VecGetArrayRead(fv, &x));
  } else { /* the row of each key */
    PetscCall(PetscMalloc1(nk + 1, &rowid));
    for (PetscInt i = 0; i < nk; ++i) rowid[i] = (PetscReal)(rstart / 3 + i);
  }
  PetscCall(VecGetArrayRead(fk, &k));
  PetscCall(IndKeyJoin(comm, bs, nk, (const PetscReal *)k, values ? (const PetscReal *)x : rowid, n, mine, out,
                       &missing, &duplicate));
  PetscCall(VecRestoreArrayRead(fk, &k));
  if (fv) PetscCall(VecRestoreArrayRead(fv, &x));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &total, 1, MPIU_INT, MPI_SUM, comm));
  PetscCheck(!missing && !duplicate && nfile / 3 == total, comm, PETSC_ERR_ARG_INCOMP,
             "%s was made on another mesh (%" PetscInt_FMT " %s there, %" PetscInt_FMT " here, %" PetscInt_FMT
             " of these not found)", file, nfile / 3, what, total, missing);
  PetscCall(PetscFree(rowid));
  PetscCall(VecDestroy(&fv));
  PetscCall(VecDestroy(&fk));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndRowsLocate(PetscViewer v, const char keys[], const char what[], const char file[], PetscInt n,
                             const PetscReal *mine, PetscInt **index)
{
  PetscReal *found;

  PetscFunctionBeginUser;
  PetscCall(PetscMalloc1(n + 1, &found));
  PetscCall(IndRowsJoin(v, keys, NULL, 1, what, file, n, mine, found));
  PetscCall(PetscMalloc1(n + 1, index));
  for (PetscInt i = 0; i < n; ++i) (*index)[i] = (PetscInt)found[i];
  PetscCall(PetscFree(found));
  PetscFunctionReturn(PETSC_SUCCESS);
}
