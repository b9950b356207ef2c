#pragma once
/* The per-step CSV files beside the curve (csm.csv, scratch.csv): rank 0 appends one line per accepted
   step, the first column being the step's number, and a restarted run drops the lines of the steps after
   its checkpoint. */
#include <petscsys.h>
#include "ind_common.h"

/* Appends `line` (without its newline) to <dir>/<name>, the header first when the file is new. */
PetscErrorCode IndStepCSVAppend(MPI_Comm comm, const char dir[], const char name[], const char header[],
                                const char line[]);
/* Drops the lines of steps after `step` (the file is rewritten under a temporary name and renamed). */
PetscErrorCode IndStepCSVTruncate(MPI_Comm comm, const char dir[], const char name[], PetscInt step);
