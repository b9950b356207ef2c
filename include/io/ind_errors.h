#pragma once
/* How indent ends on an error (errors.c).

   A user-facing error is one the person running indent can fix: a bad option value, a missing or
   unreadable file, an unsupported combination, a physically meaningless run, a load step that fails
   too often. Rule: the error code is one of
     PETSC_ERR_ARG_WRONG, _ARG_OUTOFRANGE, _ARG_INCOMP, _ARG_SIZ, _ARG_UNKNOWN_TYPE, PETSC_ERR_FILE_OPEN,
     _FILE_READ, _FILE_WRITE, _FILE_UNEXPECTED, PETSC_ERR_USER_INPUT, PETSC_ERR_SUP, PETSC_ERR_NOT_CONVERGED,
     PETSC_ERR_WRONG_MPI_SIZE, PETSC_ERR_SIG
   and it was raised by indent's own code (a source file under the project's directory); or it was raised
   by PETSc's options database while converting an option's value (PETSC_ERR_ARG_WRONG, _ARG_OUTOFRANGE,
   PETSC_ERR_USER, PETSC_ERR_USER_INPUT in PETSc's options.c or aoptions.c); or it is PETSc's unknown-type
   error (a misspelt -ksp_type and the like). Such an error prints one line on rank 0,
     <program>: error: <message>
   and the program exits with status 1 (IND_EXIT_IO, 74, for PETSC_ERR_FILE_WRITE: a failed write; 75 for
   PETSC_ERR_SIG: a stop signal before anything could be saved) after a clean PetscFinalize, without
   PETSc's traceback, its configure line, its option table or its list of unused options. Every other
   error (PETSC_ERR_PLIB, memory, MPI, library failures, ...) is a bug to report: it keeps PETSc's full
   report and MPI_Abort.

   Raised on one rank only (a check on PETSC_COMM_SELF, or a collective check some ranks never reached),
   the other ranks may be waiting in a collective call: if they have not all reached the end with an error
   of their own within a few seconds, the rank that has the error prints its line and calls
   MPI_Abort(MPI_COMM_WORLD, 1). Open MPI's mpiexec then prints a banner of its own unless
   OMPI_MCA_orte_execute_quiet=1 (or mpiexec -q); it exits with 1 in both cases. */
#include <petscsys.h>

/* Installs the handler; program names the program in the error line ("indent", "indent-op"). Call right
   after PetscInitialize(); collective on PETSC_COMM_WORLD. */
PetscErrorCode IndErrorSetUp(const char program[]);
/* Ends the program: with ierr 0, PetscFinalize(); otherwise as described above. Returns main()'s exit
   status (it does not return after MPI_Abort). Collective unless the error was on some ranks only. */
int IndErrorFinish(PetscErrorCode ierr);
/* Whether the last error raised is user-facing, and its message (for tests). */
PetscBool IndErrorIsUserFacing(void);
const char *IndErrorMessage(void);
