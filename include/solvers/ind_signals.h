#pragma once
/* Stop requests from the batch system or the user: SIGTERM, SIGINT and SIGUSR1 set a flag that the run
   polls between load steps, collectively, so that every rank stops after the same step and the
   checkpoint holds a consistent state. A second signal of the same kind ends the process at once, or,
   while a checkpoint is written, once it is whole. */
#include "ind_common.h"

/* Installs the handlers (idempotent); on the first signal the previous handler is kept aside. */
PetscErrorCode IndSignalsInstall(void);
/* Restores the handlers that were there before IndSignalsInstall. */
PetscErrorCode IndSignalsRestore(void);
/* Collective: the signal number any rank has received since installation (0: none). */
PetscErrorCode IndSignalsPending(MPI_Comm comm, int *signum);
/* The signal's name ("SIGTERM"), for messages. */
const char    *IndSignalName(int signum);
/* Pretends signum arrived (tests and the -checkpoint_stop_after_step option). */
void           IndSignalsRaise(int signum);
/* Around a checkpoint's write: a repeated signal waits for its end, and then ends the process, unless
   the run is stopping anyway (it then exits as after the first signal). */
void           IndSignalsDeferBegin(void);
void           IndSignalsDeferEnd(PetscBool stopping);
/* Async-signal-safe, any thread: the stop signal received so far (0: none). */
int            IndSignalsReceived(void);
