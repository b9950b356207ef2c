static const char help[] = "Unit test: the run-directory lock's decisions (src/io/runlock.c) on small cases.\n";

#include <string.h>
#include "ind_runlock.h"

static int failures = 0;

static void Expect(PetscBool ok, const char what[])
{
  if (!ok) failures++;
  (void)PetscPrintf(PETSC_COMM_SELF, "%s %s\n", ok ? "ok  " : "FAIL", what);
}

int main(int argc, char **argv)
{
  IndRunLockOwner o;

  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  IndRunLockParse("pid 4242 host nodeA job 77 started 2026-11-26T04:00:00Z\n", &o);
  Expect(o.pid == 4242 && !strcmp(o.host, "nodeA") && !strcmp(o.job, "77") &&
           !strcmp(o.started, "2026-11-26T04:00:00Z"),
         "a lock's text parsed into pid, host, job and start");
  Expect(IndRunLockJudge(&o, "nodeA", "-", PETSC_TRUE) == IND_RUNLOCK_LIVE, "same host, process running: live");
  Expect(IndRunLockJudge(&o, "nodeA", "-", PETSC_FALSE) == IND_RUNLOCK_STALE, "same host, process gone: stale");
  Expect(IndRunLockJudge(&o, "nodeB", "-", PETSC_FALSE) == IND_RUNLOCK_ELSEWHERE,
         "another host: cannot be checked, whatever a local pid says");
  Expect(IndRunLockJudge(&o, "nodeB", "77", PETSC_FALSE) == IND_RUNLOCK_STALE,
         "another host, same scheduler job (requeued): an earlier part of this job, stale");
  Expect(IndRunLockJudge(&o, "nodeA", "78", PETSC_TRUE) == IND_RUNLOCK_LIVE, "same host, another job, running: live");
  IndRunLockParse("pid 9 host nodeA job - started x\n", &o);
  Expect(IndRunLockJudge(&o, "nodeA", "-", PETSC_TRUE) == IND_RUNLOCK_LIVE,
         "no scheduler on either side: decided by the process alone");
  IndRunLockParse("garbage\n", &o);
  Expect(IndRunLockJudge(&o, "nodeA", "-", PETSC_FALSE) == IND_RUNLOCK_UNREADABLE, "a text naming no run: unreadable");
  IndRunLockParse("", &o);
  Expect(IndRunLockJudge(&o, "nodeA", "-", PETSC_FALSE) == IND_RUNLOCK_UNREADABLE, "an empty lock: unreadable");
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "%d failure(s)\n", failures));
  PetscCall(PetscFinalize());
  return failures ? 1 : 0;
}
