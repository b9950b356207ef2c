#define _POSIX_C_SOURCE 200809L /* strtok_r */
#include <string.h>
#include <petscviewerhdf5.h>
#include "ind_checkpoint.h"
#include "ind_keyedio.h"

/* Every dataset a checkpoint holds is listed in its attribute "datasets" (group/name per line, written by
   IndStateFileClose), and carries the checksum IndRowsWrite wrote with it. */

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
static PetscErrorCode Dataset(PetscViewer v, const char group[], const char name[], char why[], size_t len)
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
  PetscCall(VecDestroy(&x));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Verify(MPI_Comm comm, const char path[], PetscInt *step, char why[], size_t len)
{
  PetscViewer v;
  PetscBool   exists;
  char       *list = NULL, *line, *save = NULL;

  PetscFunctionBeginUser;
  PetscCall(PetscViewerHDF5Open(comm, path, FILE_MODE_READ, &v));
  PetscCall(PetscViewerHDF5HasAttribute(v, "/", "datasets", &exists));
  if (!exists) PetscCall(PetscSNPrintf(why, len, "it lists no datasets (not a whole checkpoint of this version)"));
  else PetscCall(PetscViewerHDF5ReadAttribute(v, "/", "datasets", PETSC_STRING, NULL, &list));
  if (step) {
    PetscCall(PetscViewerHDF5HasAttribute(v, "/", "accepted_steps", &exists));
    if (exists) PetscCall(PetscViewerHDF5ReadAttribute(v, "/", "accepted_steps", PETSC_INT, NULL, step));
  }
  for (line = list ? strtok_r(list, "\n", &save) : NULL; line && !why[0]; line = strtok_r(NULL, "\n", &save)) {
    char *name = strrchr(line, '/');
    if (!name || name == line) continue;
    *name++ = 0;
    PetscCall(PetscViewerHDF5PushGroup(v, line));
    PetscCall(PetscViewerHDF5HasDataset(v, name, &exists));
    if (exists) PetscCall(Dataset(v, line, name, why, len));
    else PetscCall(PetscSNPrintf(why, len, "dataset %s/%s is missing", line, name));
    PetscCall(PetscViewerHDF5PopGroup(v));
  }
  PetscCall(PetscFree(list));
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
