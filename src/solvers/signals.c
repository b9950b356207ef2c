#define _POSIX_C_SOURCE 200809L /* sigaction, gmtime_r, strtok_r */
#include <signal.h>
#include "ind_signals.h"

static volatile sig_atomic_t received = 0, deferring = 0, deferred = 0;
static const int             watched[] = {SIGTERM, SIGINT, SIGUSR1};
#define NWATCHED ((int)(sizeof(watched) / sizeof(watched[0])))
static struct sigaction previous[NWATCHED];
static PetscBool        installed = PETSC_FALSE;

/* Async-signal-safe: records the first signal; a repeated one restores the default action and
   re-raises, so a user pressing Ctrl-C twice is not kept waiting for the step to end, except while a
   checkpoint is written: then it waits for the checkpoint to be whole. */
static void OnSignal(int signum)
{
  if (received == signum) {
    if (deferring) {
      deferred = signum;
      return;
    }
    signal(signum, SIG_DFL);
    raise(signum);
    return;
  }
  if (!received) received = signum;
}

PetscErrorCode IndSignalsInstall(void)
{
  PetscFunctionBeginUser;
  if (installed) PetscFunctionReturn(PETSC_SUCCESS);
  for (int k = 0; k < NWATCHED; ++k) {
    struct sigaction sa;
    sa.sa_handler = OnSignal;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = SA_RESTART;
    PetscCheck(sigaction(watched[k], &sa, &previous[k]) == 0, PETSC_COMM_SELF, PETSC_ERR_SYS,
      "Cannot install the handler of %s",
               IndSignalName(watched[k]));
  }
  installed = PETSC_TRUE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndSignalsRestore(void)
{
  PetscFunctionBeginUser;
  if (!installed) PetscFunctionReturn(PETSC_SUCCESS);
  for (int k = 0; k < NWATCHED; ++k) sigaction(watched[k], &previous[k], NULL);
  installed = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndSignalsPending(MPI_Comm comm, int *signum)
{
  int mine = (int)received;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Allreduce(&mine, signum, 1, MPI_INT, MPI_MAX, comm));
  PetscFunctionReturn(PETSC_SUCCESS);
}

const char *IndSignalName(int signum)
{
  switch (signum) {
  case SIGTERM:
    return "SIGTERM";
  case SIGINT:
    return "SIGINT";
  case SIGUSR1:
    return "SIGUSR1";
  default:
    return "a signal";
  }
}

void IndSignalsRaise(int signum)
{
  if (!received) received = signum;
}

void IndSignalsDeferBegin(void)
{
  deferring = 1;
}

void IndSignalsDeferEnd(PetscBool stopping)
{
  const int signum = (int)deferred;

  deferring = 0;
  deferred  = 0;
  if (signum && !stopping) {
    signal(signum, SIG_DFL);
    raise(signum);
  }
}

int IndSignalsReceived(void)
{
  return (int)received;
}
