#include <errno.h>
#include <string.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>
#include "ind_files.h"

PetscErrorCode IndMakeDirectory(MPI_Comm comm, const char dir[], const char option[])
{
  PetscMPIInt rank;
  int         err = 0;
  char        path[PETSC_MAX_PATH_LEN];

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0) {
    PetscCall(PetscStrncpy(path, dir, sizeof(path)));
    for (char *p = path + 1; *p && !err; ++p)
      if (*p == '/') {
        *p = 0;
        if (mkdir(path, 0777) && errno != EEXIST) err = errno;
        *p = '/';
      }
    if (!err && mkdir(path, 0777) && errno != EEXIST) err = errno;
    if (!err && access(path, W_OK)) err = errno;
  }
  PetscCallMPI(MPI_Bcast(&err, 1, MPI_INT, 0, comm));
  PetscCheck(!err, comm, PETSC_ERR_FILE_OPEN, "Cannot create or write to the output directory '%s' (%s): %s", dir, option, strerror(err));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Paths and values go to a shell: single quotes keep spaces and specials literal, so a quote itself
   is refused rather than escaped. */
static PetscBool Quotable(const char s[])
{
  return strchr(s, '\'') ? PETSC_FALSE : PETSC_TRUE;
}

PetscErrorCode IndGmshMesh(MPI_Comm comm, const char gmsh[], const char geo[], char *params[], PetscInt nparams, const char msh[])
{
  PetscMPIInt rank;
  int         status = 0;
  char        cmd[4 * PETSC_MAX_PATH_LEN], log[PETSC_MAX_PATH_LEN + 8];

  PetscFunctionBeginUser;
  PetscCheck(Quotable(gmsh) && Quotable(geo) && Quotable(msh), comm, PETSC_ERR_ARG_WRONG, "-mesh_file, -mesh_gmsh and the mesh's output path must not contain a single quote");
  PetscCall(PetscSNPrintf(log, sizeof(log), "%s.log", msh));
  PetscCall(PetscSNPrintf(cmd, sizeof(cmd), "'%s' -3 '%s' -format msh41", gmsh, geo));
  for (PetscInt i = 0; i < nparams; ++i) {
    char  *eq = strchr(params[i], '='), tail[PETSC_MAX_PATH_LEN];
    size_t len;
    PetscCheck(eq && eq != params[i] && eq[1] && Quotable(params[i]), comm, PETSC_ERR_ARG_WRONG, "-mesh_geo_parameters: '%s' is not name=value", params[i]);
    PetscCall(PetscStrlen(cmd, &len));
    PetscCall(PetscSNPrintf(tail, sizeof(tail), " -setnumber '%.*s' '%s'", (int)(eq - params[i]), params[i], eq + 1));
    PetscCall(PetscStrlcat(cmd, tail, sizeof(cmd)));
  }
  {
    char tail[3 * PETSC_MAX_PATH_LEN];
    PetscCall(PetscSNPrintf(tail, sizeof(tail), " -o '%s' > '%s' 2>&1", msh, log));
    PetscCall(PetscStrlcat(cmd, tail, sizeof(cmd)));
  }
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (!rank) {
    status = system(cmd);
    if (status == 0) {
      PetscBool ok;
      PetscCall(PetscTestFile(msh, 'r', &ok));
      if (!ok) status = -1;
    }
  }
  PetscCallMPI(MPI_Bcast(&status, 1, MPI_INT, 0, comm));
  PetscCheck(status == 0, comm, PETSC_ERR_LIB, "gmsh could not mesh '%s' (-mesh_file): see '%s'; the command was: %s", geo, log, cmd);
  PetscFunctionReturn(PETSC_SUCCESS);
}
