#pragma once
/* The -options_file arguments, checked before PETSc reads them (PetscInitialize would stop with its
   error block): a missing, unreadable or directory path ends the program with one line
   "<program>: error: -options_file '<path>': <why>" (from the first rank only) and status 1. A file
   saved with a UTF-8 byte-order mark (as some editors on Windows do) is read from a copy without it,
   made in the system's temporary directory and removed once PETSc has read it. */
#include <petscsys.h>

#define IND_MAX_OPTIONS_FILES 8

typedef struct {
  int  n;
  char path[IND_MAX_OPTIONS_FILES][PETSC_MAX_PATH_LEN];
} IndOptionsFileCopies;

/* Before PetscInitialize: 0 when the program may go on (argv may now name copies), 1 after the error
   line was printed. */
int  IndOptionsFilesPrepare(const char program[], int argc, char **argv, IndOptionsFileCopies *copies);
/* After PetscInitialize (or on the way out): removes the copies. */
void IndOptionsFilesRemoveCopies(IndOptionsFileCopies *copies);
/* Before PetscInitialize: a word of the command line that is neither an option nor the value of the one before it,
   which PETSc would skip without a word (the second half of an unquoted value with a space), ends the program with
   one line naming it (from the first rank only): 1; 0 when there is none. */
int  IndArgsCheckStray(const char program[], int argc, char **argv);
