#include <stdio.h>
#include "ind_stepcsv.h"

PetscErrorCode IndStepCSVAppend(MPI_Comm comm, const char dir[], const char name[], const char header[],
                                const char line[])
{
  PetscMPIInt rank;
  char        path[PETSC_MAX_PATH_LEN];
  PetscBool   exists;
  FILE       *fp;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscSNPrintf(path, sizeof(path), "%s/%s", dir, name));
  PetscCall(PetscTestFile(path, 'r', &exists));
  fp = fopen(path, "a");
  PetscCheck(fp, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "Cannot write '%s' (-output_dir)", path);
  if (!exists) fprintf(fp, "%s\n", header);
  fprintf(fp, "%s\n", line);
  PetscCheck(fclose(fp) == 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "Error writing '%s'", path);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndStepCSVTruncate(MPI_Comm comm, const char dir[], const char name[], PetscInt step)
{
  PetscMPIInt rank;
  char        path[PETSC_MAX_PATH_LEN], tmp[PETSC_MAX_PATH_LEN], line[1024];
  FILE       *in, *out;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscSNPrintf(path, sizeof(path), "%s/%s", dir, name));
  in = fopen(path, "r");
  if (!in) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscSNPrintf(tmp, sizeof(tmp), "%s.tmp", path));
  out = fopen(tmp, "w");
  PetscCheck(out, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "Cannot write '%s' (-output_dir)", tmp);
  while (fgets(line, sizeof(line), in)) {
    long k;
    if (sscanf(line, "%ld,", &k) == 1 && k > step) continue;
    fputs(line, out);
  }
  fclose(in);
  PetscCheck(fclose(out) == 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "Error writing '%s'", tmp);
  PetscCheck(rename(tmp, path) == 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "Cannot rename '%s'", tmp);
  PetscFunctionReturn(PETSC_SUCCESS);
}
