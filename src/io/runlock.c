#define _XOPEN_SOURCE 700 /* gethostname, kill */
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>
#include "ind_runlock.h"

/* The lock this process holds, released at exit (normal, after an error, or after a signal that ends
   the run): a SIGKILLed run leaves it, and the next run on the same host finds its process gone. */
static struct {
  char  path[PETSC_MAX_PATH_LEN];
  pid_t pid;
} Held;

static void Release(void)
{
  if (Held.path[0] && Held.pid == getpid()) (void)unlink(Held.path);
  Held.path[0] = 0;
}

void IndRunLockRelease(void)
{
  Release();
}

/* The scheduler's id of this job (a requeued job's earlier part is over once this part runs). */
static const char *JobId(void)
{
  const char *names[] = {"SLURM_JOB_ID", "PBS_JOBID", "LSB_JOBID"};
  for (size_t k = 0; k < sizeof(names) / sizeof(names[0]); ++k) {
    const char *v = getenv(names[k]);
    if (v && v[0]) return v;
  }
  return "-";
}

void IndRunLockParse(const char text[], IndRunLockOwner *o)
{
  memset(o, 0, sizeof(*o));
  if (sscanf(text, "pid %ld host %255s job %127s started %63s", &o->pid, o->host, o->job, o->started) < 2) o->pid = 0;
}

IndRunLockVerdict IndRunLockJudge(const IndRunLockOwner *o, const char host[], const char job[], PetscBool alive)
{
  if (o->pid <= 0) return IND_RUNLOCK_UNREADABLE;
  if (strcmp(job, "-") && !strcmp(o->job, job)) return IND_RUNLOCK_STALE; /* an earlier part of this job */
  if (strcmp(o->host, host)) return IND_RUNLOCK_ELSEWHERE;
  return alive ? IND_RUNLOCK_LIVE : IND_RUNLOCK_STALE;
}

/* Whether process pid runs here: a zombie (killed, not yet reaped by a parent that died with it) does not. */
static PetscBool Alive(long pid)
{
  char  path[64], stat[256];
  FILE *fp;

  if (pid <= 0 || (kill((pid_t)pid, 0) && errno != EPERM)) return PETSC_FALSE;
  snprintf(path, sizeof(path), "/proc/%ld/stat", pid);
  fp = fopen(path, "r");
  if (fp) {
    size_t      n = fread(stat, 1, sizeof(stat) - 1, fp);
    const char *close;
    fclose(fp);
    stat[n] = 0;
    close   = strrchr(stat, ')'); /* "pid (name) S ...": the state follows the name */
    if (close && close[1] == ' ' && close[2] == 'Z') return PETSC_FALSE;
  }
  return PETSC_TRUE;
}

/* Creates the lock at path holding text, whole at once: the text goes to a file of this process's own, linked to the
   lock's name (link fails when the lock exists), so that no other run reads a lock before its owner is in it (it took
   an empty lock for one that names no run). Where the file system has no hard links: created exclusively, then
   written. 0 or an errno (EEXIST: the lock is there). */
static int CreateLock(const char dir[], const char path[], const char host[], const char text[])
{
  const size_t n = strlen(text);
  char         own[PETSC_MAX_PATH_LEN];
  int          fd, err = 0;

  snprintf(own, sizeof(own), "%s/.%s.%s.%ld", dir, IND_RUNLOCK_FILE, host, (long)getpid());
  fd = open(own, O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (fd < 0) return errno;
  if (write(fd, text, n) != (ssize_t)n) err = errno ? errno : EIO;
  if (close(fd) && !err) err = errno;
  if (!err && link(own, path)) err = errno;
  (void)unlink(own);
  if (err != EPERM && err != ENOTSUP && err != EOPNOTSUPP && err != EMLINK && err != ENOSYS) return err;
  fd = open(path, O_WRONLY | O_CREAT | O_EXCL, 0644);
  if (fd < 0) return errno;
  err = 0;
  if (write(fd, text, n) != (ssize_t)n) err = errno ? errno : EIO;
  if (close(fd) && !err) err = errno;
  if (err) (void)unlink(path);
  return err;
}

/* On rank 0: takes the lock, or says in why (a sentence) whose it is; warning: a stale lock taken over. */
static void Take(const char dir[], char why[], size_t wlen, char warning[], size_t len)
{
  char            path[PETSC_MAX_PATH_LEN], host[256] = "", text[512], started[64];
  const time_t    now = time(NULL);
  struct tm       utc;
  IndRunLockOwner o;

  why[0] = warning[0] = 0;
  snprintf(path, sizeof(path), "%s/%s", dir, IND_RUNLOCK_FILE);
  (void)gethostname(host, sizeof(host) - 1);
  gmtime_r(&now, &utc);
  strftime(started, sizeof(started), "%Y-%m-%dT%H:%M:%SZ", &utc);
  for (int attempt = 0; attempt < 2; ++attempt) {
    int err;
    snprintf(text, sizeof(text), "pid %ld host %s job %s started %s\n", (long)getpid(), host, JobId(), started);
    err = CreateLock(dir, path, host, text);
    if (!err) {
      snprintf(Held.path, sizeof(Held.path), "%s", path);
      Held.pid = getpid();
      atexit(Release);
      return;
    }
    if (err != EEXIST) {
      snprintf(why, wlen, "cannot create the lock '%s': %s", path, strerror(err));
      return;
    }
    {
      FILE  *fp = fopen(path, "r");
      size_t n  = fp ? fread(text, 1, sizeof(text) - 1, fp) : 0;
      if (fp) fclose(fp);
      text[n] = 0;
    }
    IndRunLockParse(text, &o);
    switch (IndRunLockJudge(&o, host, JobId(), Alive(o.pid))) {
    case IND_RUNLOCK_LIVE:
      snprintf(why, wlen, "'%s' is in use by a run started %s on %s (pid %ld)", dir, o.started, o.host, o.pid);
      return;
    case IND_RUNLOCK_ELSEWHERE:
      snprintf(why, wlen,
               "'%s' is in use by a run started %s on %s (pid %ld), another host: if that run is over, remove '%s'",
               dir, o.started, o.host, o.pid, path);
      return;
    case IND_RUNLOCK_UNREADABLE:
      snprintf(why, wlen, "'%s' holds a lock that names no run ('%s'): remove it if no run uses the directory", dir,
               path);
      return;
    case IND_RUNLOCK_STALE:
      snprintf(warning, len,
               "took over the lock of a run that is no longer running (started %s on %s, pid %ld) in '%s'",
               o.started, o.host, o.pid, dir);
      (void)unlink(path);
      break;
    }
  }
  snprintf(why, wlen, "another run took the lock of '%s' at the same moment", dir);
}

PetscErrorCode IndRunLockTake(MPI_Comm comm, const char dir[], const char option[], char warning[], size_t len)
{
  PetscMPIInt rank;
  char        why[2 * PETSC_MAX_PATH_LEN + 256] = "";

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  warning[0] = 0;
  if (!rank) Take(dir, why, sizeof(why), warning, len);
  PetscCallMPI(MPI_Bcast(why, sizeof(why), MPI_CHAR, 0, comm));
  PetscCallMPI(MPI_Bcast(warning, (PetscMPIInt)len, MPI_CHAR, 0, comm));
  PetscCheck(!why[0], comm, PETSC_ERR_FILE_OPEN, "%s: %s", option, why);
  PetscFunctionReturn(PETSC_SUCCESS);
}
