#include <petscviewerhdf5.h>
#include "ind_checkpoint.h"
#include "ind_keyedio.h"

/* Every dataset a checkpoint holds; the first ones always, the rest when the run had curve points or
   output steps. Each carries the checksum IndRowsWrite wrote with it. */
static const char *const Datasets[][2] = {
  {"/run", "scalars"}, {"/nodes", "keys"}, {"/nodes", "values"}, {"/cells", "keys"},
  {"/cells", "history"}, {"/run", "curve"}, {"/run", "output_times"}, {"/run", "output_info"}};
#define NREQUIRED 5

/* Whether HDF5 opens the file at all (a truncated file fails here), asked on rank 0 with HDF5's own
   error report silenced: the caller says it in one line. */
static PetscErrorCode Opens(MPI_Comm comm, const char path[], PetscBool *ok)
{
  PetscMPIInt rank;
  int         good = 0;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (!rank) {
    H5E_auto2_t report;
    void       *data;
    hid_t       f;
    H5Eget_auto2(H5E_DEFAULT, &report, &data);
    H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
    f = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
    if (f >= 0) {
      good = 1;
      H5Fclose(f);
    }
    H5Eset_auto2(H5E_DEFAULT, report, data);
  }
  PetscCallMPI(MPI_Bcast(&good, 1, MPI_INT, 0, comm));
  *ok = good ? PETSC_TRUE : PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Reads dataset name of the current group and compares it with its checksum; why says what is wrong. Errors
   of HDF5 or PETSc while reading (damaged metadata) are returned, not reported: the caller words them. */
static PetscErrorCode Dataset(PetscViewer v, const char group[], const char name[], PetscInt *step, char why[],
                              size_t len)
{
  Vec       x;
  PetscBool has, same;

  PetscFunctionBeginUser;
  PetscCall(PetscViewerHDF5HasAttribute(v, name, "checksum", &has));
  if (!has) {
    PetscCall(PetscSNPrintf(why, len, "dataset %s/%s has no checksum", group, name));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(VecCreate(PetscObjectComm((PetscObject)v), &x));
  PetscCall(PetscObjectSetName((PetscObject)x, name));
  PetscCall(VecLoad(x, v));
  PetscCall(IndRowsChecksumMatches(v, name, x, &has, &same));
  if (!same)
    PetscCall(PetscSNPrintf(why, len, "dataset %s/%s does not match the checksum written with it", group, name));
  else if (step && !strcmp(name, "scalars")) {
    const PetscScalar *s;
    PetscInt           n;
    PetscCall(VecGetSize(x, &n));
    PetscCall(VecGetArrayRead(x, &s));
    /* the accepted steps are the third scalar, on the rank that holds it */
    {
      PetscInt  rstart, rend;
      PetscReal mine = -1;
      PetscCall(VecGetOwnershipRange(x, &rstart, &rend));
      if (n > 2 && rstart <= 2 && 2 < rend) mine = PetscRealPart(s[2 - rstart]);
      PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &mine, 1, MPIU_REAL, MPIU_MAX, PetscObjectComm((PetscObject)v)));
      *step = (PetscInt)mine;
    }
    PetscCall(VecRestoreArrayRead(x, &s));
  }
  PetscCall(VecDestroy(&x));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Verify(MPI_Comm comm, const char path[], PetscInt *step, char why[], size_t len)
{
  PetscViewer v;
  PetscBool   exists;

  PetscFunctionBeginUser;
  PetscCall(PetscViewerHDF5Open(comm, path, FILE_MODE_READ, &v));
  for (int k = 0; k < (int)(sizeof(Datasets) / sizeof(Datasets[0])) && !why[0]; ++k) {
    PetscCall(PetscViewerHDF5PushGroup(v, Datasets[k][0]));
    PetscCall(PetscViewerHDF5HasDataset(v, Datasets[k][1], &exists));
    if (exists) PetscCall(Dataset(v, Datasets[k][0], Datasets[k][1], step, why, len));
    else if (k < NREQUIRED)
      PetscCall(PetscSNPrintf(why, len, "dataset %s/%s is missing", Datasets[k][0], Datasets[k][1]));
    PetscCall(PetscViewerHDF5PopGroup(v));
  }
  PetscCall(PetscViewerDestroy(&v));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndCheckpointVerify(MPI_Comm comm, const char path[], PetscInt *step, char why[], size_t len)
{
  PetscBool      opens = PETSC_FALSE;
  PetscErrorCode ierr;
  H5E_auto2_t    report;
  void          *data;

  PetscFunctionBeginUser;
  why[0] = 0;
  if (step) *step = -1;
  PetscCall(Opens(comm, path, &opens));
  if (!opens) {
    PetscCall(PetscSNPrintf(why, len, "HDF5 cannot open it (truncated, or not an HDF5 file)"));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  /* Damaged metadata fails inside HDF5 or PETSc: returned quietly here, and said in one line. */
  H5Eget_auto2(H5E_DEFAULT, &report, &data);
  H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
  PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
  ierr = Verify(comm, path, step, why, len);
  PetscCall(PetscPopErrorHandler());
  H5Eset_auto2(H5E_DEFAULT, report, data);
  if (ierr && !why[0]) PetscCall(PetscSNPrintf(why, len, "HDF5 cannot read its datasets"));
  /* every rank says the same */
  {
    PetscMPIInt bad = why[0] ? 1 : 0, any;
    PetscCallMPI(MPI_Allreduce(&bad, &any, 1, MPI_INT, MPI_MAX, comm));
    if (any && !bad) PetscCall(PetscSNPrintf(why, len, "HDF5 cannot read its datasets on every rank"));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}
