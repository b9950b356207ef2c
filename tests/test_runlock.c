static const char help[] = "Unit test: the run-directory lock's decisions (src/io/runlock.c) on small cases.\n";

#define _XOPEN_SOURCE 700 /* mkdtemp */
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
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

  /* a lock taken in a scratch directory: whole (this process's line) and alone there (the file it was written to,
     before it took the lock's name at once, is gone); released, the directory is empty */
  {
    char           dir[] = "/tmp/indent-runlock-XXXXXX", path[PETSC_MAX_PATH_LEN], text[512] = "", want[64];
    char           warning[256];
    int            entries = 0;
    FILE          *fp;
    DIR           *d;
    struct dirent *e;
    Expect(mkdtemp(dir) != NULL, "a scratch directory");
    PetscCall(IndRunLockTake(PETSC_COMM_SELF, dir, "-output_dir", warning, sizeof(warning)));
    snprintf(path, sizeof(path), "%s/%s", dir, IND_RUNLOCK_FILE);
    snprintf(want, sizeof(want), "pid %ld host ", (long)getpid());
    fp = fopen(path, "r");
    if (fp) {
      size_t n = fread(text, 1, sizeof(text) - 1, fp);
      text[n] = 0;
      fclose(fp);
    }
    Expect(!strncmp(text, want, strlen(want)) && strchr(text, '\n'), "the lock names this process, whole");
    d = opendir(dir);
    while (d && (e = readdir(d)))
      if (strcmp(e->d_name, ".") && strcmp(e->d_name, "..")) entries++;
    if (d) closedir(d);
    Expect(entries == 1 && !warning[0], "the lock is the directory's only file, taken without a warning");
    IndRunLockRelease();
    Expect(access(path, F_OK) != 0, "released: the lock is gone");
    Expect(rmdir(dir) == 0, "released: the directory is empty");
  }
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "%d failure(s)\n", failures));
  PetscCall(PetscFinalize());
  return failures ? 1 : 0;
}
