#define _XOPEN_SOURCE 700
#include <pthread.h>
#include <signal.h>
#include <stdlib.h>
#include <time.h>
#include <unistd.h>
#include "ind_parentwatch.h"

static pid_t parent;
static int (*stopping)(void); /* nonzero once a stop signal came: the rank is finishing its checkpoint */

/* Every half second: a launcher that is gone (SIGKILL to mpiexec, a lost node daemon) leaves this rank
   orphaned, and its parent changes; the rank then ends as the job did, at once and without a word
   (a killed job writes nothing more). A launcher that forwarded a stop signal before it went (SIGTERM
   to mpiexec) leaves the rank to finish its checkpoint and exit. */
static void *Watch(void *unused)
{
  const struct timespec half = {0, 500000000L};

  (void)unused;
  for (;;) {
    nanosleep(&half, NULL);
    if (getppid() != parent && !(stopping && stopping())) kill(getpid(), SIGKILL);
  }
  return NULL;
}

/* Launched by an MPI launcher: its rank variables are set. A program started by hand (no launcher) may
   outlive its shell on purpose (nohup), and is not watched. */
static int Launched(void)
{
  const char *names[] = {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK", "MV2_COMM_WORLD_SIZE"};
  for (size_t k = 0; k < sizeof(names) / sizeof(names[0]); ++k)
    if (getenv(names[k])) return 1;
  return 0;
}

int IndParentWatchStart(int (*stop_requested)(void))
{
  pthread_t      thread;
  pthread_attr_t attr;
  int            err;

  if (!Launched()) return 0;
  stopping = stop_requested;
  parent   = getppid();
  if (parent <= 1) return 0; /* already orphaned, or a launcher that is init itself: nothing to watch */
  pthread_attr_init(&attr);
  pthread_attr_setdetachstate(&attr, PTHREAD_CREATE_DETACHED);
  err = pthread_create(&thread, &attr, Watch, NULL);
  pthread_attr_destroy(&attr);
  return err;
}
