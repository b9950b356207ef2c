#define _POSIX_C_SOURCE 200809L /* sigaction, nanosleep */
#include <errno.h>
#include <libgen.h>
#include <signal.h>
#include <stdio.h>
#include <string.h>
#include <time.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <hdf5.h>
#include "ind_iofault.h"

static int first_errno; /* errno where the first error of the phase was raised */
static int recorded;

/* An error handler that returns quietly: the write phase's caller decides what the run does. errno is
   read where the failure is detected, before clean-up calls overwrite it. */
static PetscErrorCode Recording(MPI_Comm comm, int line, const char *fun, const char *file, PetscErrorCode n,
                                PetscErrorType p, const char *mess, void *ctx)
{
  (void)comm, (void)line, (void)fun, (void)file, (void)mess, (void)ctx;
  if (p == PETSC_ERROR_INITIAL && !recorded) {
    first_errno = errno;
    recorded    = 1;
  }
  return n;
}

PetscErrorCode IndIOFaultSetUp(void)
{
  struct sigaction sa;

  PetscFunctionBeginUser;
  PetscCheck(H5Eset_auto2(H5E_DEFAULT, NULL, NULL) >= 0, PETSC_COMM_SELF, PETSC_ERR_LIB, "H5Eset_auto2 failed");
  memset(&sa, 0, sizeof(sa));
  sa.sa_handler = SIG_IGN;
  sigemptyset(&sa.sa_mask);
  PetscCheck(sigaction(SIGXFSZ, &sa, NULL) == 0, PETSC_COMM_SELF, PETSC_ERR_SYS, "sigaction(SIGXFSZ) failed");
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* 0 when bytes more fit in the file at path, else ENOSPC or EFBIG. */
static int Room(const char path[], double bytes)
{
  char           dir[PETSC_MAX_PATH_LEN];
  struct statvfs fs;
  struct stat    st;
  struct rlimit  lim;
  const double   size = stat(path, &st) ? 0.0 : (double)st.st_size;

  snprintf(dir, sizeof(dir), "%s", path);
  if (statvfs(dirname(dir), &fs) == 0 && (double)fs.f_bavail * (double)fs.f_frsize < bytes) return ENOSPC;
  if (getrlimit(RLIMIT_FSIZE, &lim) == 0 && lim.rlim_cur != RLIM_INFINITY && size + bytes > (double)lim.rlim_cur)
    return EFBIG;
  return 0;
}

int IndIOFaultFileCause(const char path[])
{
  struct stat   st;
  struct rlimit lim;

  if (Room(path, 1 << 20) == ENOSPC) return ENOSPC;
  if (!stat(path, &st) && !getrlimit(RLIMIT_FSIZE, &lim) && lim.rlim_cur != RLIM_INFINITY &&
      (double)st.st_size >= (double)lim.rlim_cur)
    return EFBIG;
  return 0;
}

PetscErrorCode IndIOFaultCheckRoom(MPI_Comm comm, const char path[], double bytes)
{
  PetscMPIInt rank;
  int         cause = 0;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (!rank) cause = Room(path, bytes);
  PetscCallMPI(MPI_Bcast(&cause, 1, MPI_INT, 0, comm));
  errno = cause; /* for the recording handler */
  PetscCheck(!cause, comm, PETSC_ERR_FILE_WRITE, "no room for %.3g MB more in '%s'", bytes / (1 << 20), path);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndIOFaultBegin(void)
{
  PetscFunctionBeginUser;
  errno       = 0;
  first_errno = 0;
  recorded    = 0;
  PetscCall(PetscPushErrorHandler(Recording, NULL));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndIOFaultEnd(MPI_Comm comm, PetscErrorCode ierr, const char alone[], IndIOFault *f)
{
  int         mine[2], all[2], done = 0;
  MPI_Request req;
  double      t0;

  PetscFunctionBeginUser;
  PetscCall(PetscPopErrorHandler());
  mine[0] = ierr ? 1 : 0;
  mine[1] = ierr ? first_errno : 0;
  PetscCallMPI(MPI_Iallreduce(mine, all, 2, MPI_INT, MPI_MAX, comm, &req));
  t0 = MPI_Wtime();
  while (!done) {
    PetscCallMPI(MPI_Test(&req, &done, MPI_STATUS_IGNORE));
    if (!done && ierr && MPI_Wtime() - t0 > 10.0) {
      IndIOFault self = {PETSC_TRUE, first_errno};
      fprintf(stderr, "indent: error: %s: %s\n", alone, IndIOFaultCause(&self));
      fflush(stderr);
      MPI_Abort(MPI_COMM_WORLD, IND_EXIT_IO);
    }
    if (!done) {
      const struct timespec pause = {0, 1000000};
      nanosleep(&pause, NULL);
    }
  }
  f->failed = all[0] ? PETSC_TRUE : PETSC_FALSE;
  f->cause  = all[1];
  PetscFunctionReturn(PETSC_SUCCESS);
}

const char *IndIOFaultCause(const IndIOFault *f)
{
  return f->cause ? strerror(f->cause) : "write failed";
}
