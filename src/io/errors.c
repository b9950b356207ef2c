#define _POSIX_C_SOURCE 200809L /* strtok_r */
#include <stdio.h>
#include <string.h>
#include <time.h>
#include "ind_common.h"
#include "ind_iofault.h"

/* The error being propagated: recorded where it was raised (PETSC_ERROR_INITIAL), read at the end. */
static struct {
  PetscBool      raised;
  PetscBool      user;       /* user-facing: one line, no traceback */
  PetscBool      collective; /* raised on a communicator that holds every rank */
  PetscErrorCode code;
  char           message[2048];
  MPI_Comm       agree; /* a duplicate of MPI_COMM_WORLD, for the ranks to find each other at the end */
  char           program[64];
} E;

/* indent's sources are the files under the directory holding this one's src/: compilers name them by
   the path CMake gives, which is absolute. */
static PetscBool OwnSource(const char file[])
{
  const char *self = __FILE__, *tail = strstr(self, "src/io/errors.c");
  size_t      root = tail ? (size_t)(tail - self) : 0;

  if (!file) return PETSC_FALSE;
  if (root == 0) return file[0] == '.' ? PETSC_FALSE : PETSC_TRUE; /* relative names: PETSc's start with ./ */
  return strncmp(file, self, root) ? PETSC_FALSE : PETSC_TRUE;
}

static PetscBool UserFacing(PetscErrorCode n, const char file[])
{
  if (n == PETSC_ERR_ARG_UNKNOWN_TYPE) return PETSC_TRUE;
  if (OwnSource(file)) {
    switch (n) {
    case PETSC_ERR_ARG_WRONG:
    case PETSC_ERR_ARG_OUTOFRANGE:
    case PETSC_ERR_ARG_INCOMP:
    case PETSC_ERR_ARG_SIZ:
    case PETSC_ERR_FILE_OPEN:
    case PETSC_ERR_FILE_READ:
    case PETSC_ERR_FILE_WRITE:
    case PETSC_ERR_FILE_UNEXPECTED:
    case PETSC_ERR_USER_INPUT:
    case PETSC_ERR_SUP:
    case PETSC_ERR_NOT_CONVERGED:
    case PETSC_ERR_WRONG_MPI_SIZE:
    case PETSC_ERR_SIG:
      return PETSC_TRUE;
    default:
      return PETSC_FALSE;
    }
  }
  if (file && (strstr(file, "sys/objects/options.c") || strstr(file, "sys/objects/aoptions.c")))
    return n == PETSC_ERR_ARG_WRONG || n == PETSC_ERR_ARG_OUTOFRANGE || n == PETSC_ERR_USER || n == PETSC_ERR_USER_INPUT
             ? PETSC_TRUE
             : PETSC_FALSE;
  return PETSC_FALSE;
}

/* The option whose value is value, for PETSc's conversion messages, which name only the value. */
static void OptionWithValue(const char value[], char name[], size_t len)
{
  char *all = NULL, *save = NULL, *prev = NULL;

  name[0] = 0;
  if (PetscOptionsGetAll(NULL, &all) || !all) return;
  for (char *tok = strtok_r(all, " ", &save); tok; tok = strtok_r(NULL, " ", &save)) {
    if (prev && !strcmp(tok, value)) {
      snprintf(name, len, "%s", prev);
      break;
    }
    prev = tok[0] == '-' ? tok : NULL;
  }
  (void)PetscFree(all);
}

/* PETSc's messages for an option value it cannot convert, rewritten to name the option. */
static void NameTheOption(char msg[], size_t len)
{
  const char *forms[][2] = {
    {"Input string ", " has no numeric value"},
    {"Input string ", " has no integer value"},
    {"Unknown logical value: ", ""},
  };
  const char *what[] = {"a number", "an integer", "a boolean (true or false)"};

  for (int k = 0; k < 3; ++k) {
    size_t pre = strlen(forms[k][0]);
    char   value[256], name[256];
    if (strncmp(msg, forms[k][0], pre)) continue;
    snprintf(value, sizeof(value), "%.255s", msg + pre); /* the bound said, for the compiler */
    if (forms[k][1][0]) {
      char *end = strstr(value, forms[k][1]);
      if (!end) continue;
      *end = 0;
    }
    OptionWithValue(value, name, sizeof(name));
    if (name[0]) snprintf(msg, len, "%s: '%s' is not %s", name, value, what[k]);
    return;
  }
}

static PetscErrorCode Handler(MPI_Comm comm, int line, const char *fun, const char *file, PetscErrorCode n,
  PetscErrorType p, const char *mess, void *ctx)
{
  if (p == PETSC_ERROR_INITIAL) {
    PetscMPIInt size = 0, world = 1;
    E.raised = PETSC_TRUE;
    E.code   = n;
    E.user   = UserFacing(n, file);
    snprintf(E.message, sizeof(E.message), "%s", mess && mess[0] ? mess : "(no message)");
    /* PETSc's messages may span lines; one line is promised */
    for (char *c = E.message; *c; ++c)
      if (*c == '\n') *c = ' ';
    for (size_t l = strlen(E.message); l > 0 && E.message[l - 1] == ' '; --l) E.message[l - 1] = 0;
    if (E.user) NameTheOption(E.message, sizeof(E.message));
    MPI_Comm_size(MPI_COMM_WORLD, &world);
    if (comm != MPI_COMM_NULL) MPI_Comm_size(comm, &size);
    E.collective = size == world ? PETSC_TRUE : PETSC_FALSE;
  }
  if (E.raised && E.user) return n;
  return PetscTraceBackErrorHandler(comm, line, fun, file, n, p, mess, ctx);
}

PetscErrorCode IndErrorSetUp(const char program[])
{
  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(&E, sizeof(E)));
  PetscCall(PetscStrncpy(E.program, program, sizeof(E.program)));
  PetscCallMPI(MPI_Comm_dup(MPI_COMM_WORLD, &E.agree));
  PetscCall(PetscPushErrorHandler(Handler, NULL));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Whether every rank reaches the end with an error within the time limit. */
static PetscBool EveryRankFailed(double seconds)
{
  PetscMPIInt size;
  MPI_Request req;
  int         done = 0;
  double      t0   = MPI_Wtime();

  MPI_Comm_size(MPI_COMM_WORLD, &size);
  if (size == 1) return PETSC_TRUE;
  if (MPI_Ibarrier(E.agree, &req) != MPI_SUCCESS) return PETSC_FALSE;
  while (!done && MPI_Wtime() - t0 < seconds) {
    if (MPI_Test(&req, &done, MPI_STATUS_IGNORE) != MPI_SUCCESS) return PETSC_FALSE;
    if (!done) {
      const struct timespec pause = {0, 2000000};
      nanosleep(&pause, NULL);
    }
  }
  return done ? PETSC_TRUE : PETSC_FALSE;
}

/* A failed write (IND_EXIT_IO) or a stop signal before anything could be saved (EX_TEMPFAIL, as a stopped
   run's, so that a job script sees the stop; it finds no checkpoint of this part) end with their own status. */
static int ExitStatus(void)
{
  if (E.code == PETSC_ERR_FILE_WRITE) return IND_EXIT_IO;
  if (E.code == PETSC_ERR_SIG) return 75;
  return 1;
}

int IndErrorFinish(PetscErrorCode ierr)
{
  PetscMPIInt rank = 0;

  if (!ierr) {
    ierr = PetscPopErrorHandler();
    if (!ierr) ierr = MPI_Comm_free(&E.agree) ? PETSC_ERR_MPI : PETSC_SUCCESS;
    if (!ierr) ierr = PetscFinalize();
    return ierr ? 1 : 0;
  }
  if (!E.raised || !E.user) {
    /* A bug: the last frame of PETSc's report, its option table and MPI_Abort, as PetscCall(...) in
       main() gives. */
    (void)PetscError(PETSC_COMM_SELF, __LINE__, "main", __FILE__, ierr, PETSC_ERROR_REPEAT, " ");
    return (int)ierr;
  }
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  /* Ranks that raised it together meet at once; one that raised it alone finds no partner. */
  if (EveryRankFailed(E.collective ? 30.0 : 3.0)) {
    if (rank == 0) {
      fprintf(stderr, "%s: error: %s\n", E.program, E.message);
      fflush(stderr);
    }
    /* The run stops half-built: neither the options nobody read by then nor the memory held by the
       objects it abandons are worth a report. */
    (void)PetscOptionsSetValue(NULL, "-options_left", "0");
    (void)PetscOptionsClearValue(NULL, "-malloc_dump");
    (void)PetscOptionsClearValue(NULL, "-malloc_view");
    (void)PetscOptionsClearValue(NULL, "-log_view");
    MPI_Comm_free(&E.agree);
    (void)PetscFinalize();
    return ExitStatus();
  }
  fprintf(stderr, "%s: error: %s\n", E.program, E.message);
  fflush(stderr);
  MPI_Abort(MPI_COMM_WORLD, ExitStatus());
  return 1;
}

PetscBool IndErrorIsUserFacing(void)
{
  return E.raised && E.user ? PETSC_TRUE : PETSC_FALSE;
}

const char *IndErrorMessage(void)
{
  return E.message;
}
