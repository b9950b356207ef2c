#pragma once
/* Warnings of a run (run_checks.c): printed once ("indent: warning: ..." on rank 0, stderr) and kept,
   once per kind, for the summary (summary.json "warnings"). Plain data: no dependency on the app. */
#include "ind_common.h"
#include "ind_state.h"

#define IND_MAX_WARNINGS 16
#define IND_WARNING_LEN  512

typedef struct {
  PetscInt n;
  char     key[IND_MAX_WARNINGS][32];
  char     text[IND_MAX_WARNINGS][IND_WARNING_LEN];
} IndWarnings;

/* Adds text under key unless a warning of that key is there already (a condition met at every step
   from some depth on is reported at its first). Prints it when print is true. Collective (the text must
   be the same on every rank). */
PetscErrorCode IndWarningsAdd(MPI_Comm comm, IndWarnings *warnings, const char key[], PetscBool print,
  const char text[]);
/* The warnings' part of a checkpoint (an IndStatePart's transfer, obj an IndWarnings): a restarted run's summary
   keeps those of the steps before the restart. Read back, they join the list (without being printed again); a
   checkpoint written before warnings were kept has none to add. */
PetscErrorCode IndWarningsState(void *obj, IndStateFile file);
