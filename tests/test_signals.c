static const char help[] =
  "Unit test: a repeated stop signal during a checkpoint's write waits for its end (signals.c).\n";

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>
#include "ind_signals.h"

static int failures = 0;

static void Expect(PetscBool ok, const char what[])
{
  if (!ok) failures++;
  (void)PetscPrintf(PETSC_COMM_SELF, "%s %s\n", ok ? "ok  " : "FAIL", what);
}

/* In a child: the first SIGUSR1 is recorded, the second arrives "during the write"; the child reports
   through its exit status how far it came (3: past the write, alive) or dies by the signal. */
static int Child(PetscBool stopping)
{
  if (IndSignalsInstall()) _exit(10);
  raise(SIGUSR1);
  IndSignalsDeferBegin();
  raise(SIGUSR1); /* the repeat, mid-write */
  IndSignalsDeferEnd(stopping);
  _exit(3);
}

static int Run(PetscBool stopping, int *signaled)
{
  int   status = 0;
  pid_t pid    = fork();

  if (pid == 0) Child(stopping);
  waitpid(pid, &status, 0);
  *signaled = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

int main(int argc, char **argv)
{
  int code, sig;

  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  code = Run(PETSC_TRUE, &sig);
  Expect(code == 3 && !sig, "stopping: the repeat during the write is absorbed, the run goes on to exit 75");
  code = Run(PETSC_FALSE, &sig);
  Expect(code == -1 && sig == SIGUSR1, "a periodic checkpoint: the repeat ends the process once the write is over");
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "%d failure(s)\n", failures));
  PetscCall(PetscFinalize());
  return failures ? 1 : 0;
}
