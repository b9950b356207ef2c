#pragma once
/* A run directory has one owner. A run that writes into -output_dir holds <dir>/indent.lock for its
   life: the file names its process, host, scheduler job and start time, is created exclusively, and is
   removed when the run exits. A second run into the directory (fresh, -output_overwrite or -restart)
   is refused with one line naming the owner. A lock whose process is gone (same host), or that an
   earlier part of the same scheduler job left, is taken over with a warning; a lock of another host
   cannot be checked and is left to the user. */
#include "ind_common.h"

#define IND_RUNLOCK_FILE "indent.lock"

typedef struct {
  long pid;
  char host[256], job[128], started[64];
} IndRunLockOwner;

typedef enum {
  IND_RUNLOCK_LIVE,       /* its process runs on this host: refuse */
  IND_RUNLOCK_STALE,      /* its process is gone, or it is an earlier part of this job: take it over */
  IND_RUNLOCK_ELSEWHERE,  /* another host's: cannot be checked, refuse */
  IND_RUNLOCK_UNREADABLE  /* names no run: refuse */
} IndRunLockVerdict;

/* The owner written in a lock file's text (pid 0 when it cannot be read). */
void              IndRunLockParse(const char text[], IndRunLockOwner *owner);
/* What to do with a lock of owner, found by this process on host in scheduler job (job "-": none);
   alive: whether the owner's pid is a running process here. */
IndRunLockVerdict IndRunLockJudge(const IndRunLockOwner *owner, const char host[], const char job[], PetscBool alive);
/* Collective: takes the lock of dir (which exists) for this process until it exits, or errors with one
   line starting with option and naming the owner; warning: non-empty when a stale lock was taken over. */
PetscErrorCode    IndRunLockTake(MPI_Comm comm, const char dir[], const char option[], char warning[], size_t len);
/* Removes the lock this process holds (also done at exit): before the ranks end with a non-zero status,
   since mpiexec kills the ranks still running when one of them ends so, before their exit handlers run. */
void              IndRunLockRelease(void);
