#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include "app_impl.h"
#include "runwrite.h"
#include "ind_checkpoint.h"
#include "ind_iofault.h"
#include "ind_signals.h"

PetscErrorCode IndAppElapsed(IndApp app)
{
  PetscLogDouble now;

  PetscFunctionBeginUser;
  PetscCall(PetscTime(&now));
  app->elapsed_now = now - app->t_start;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Checkpoint(IndApp app, PetscBool stopping)
{
  PetscLogDouble t0, t1;

  PetscFunctionBeginUser;
  if (!app->rundir.ready || app->checkpointed == app->path.accepted) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(IndAppElapsed(app));
  PetscCall(PetscTime(&t0));
  IndSignalsDeferBegin(); /* a second Ctrl-C must not leave half a checkpoint */
  PetscCall(IndAppCheckpoint(app, app->rundir.checkpoint, FILE_MODE_WRITE));
  app->checkpointed = app->path.accepted;
  IndSignalsDeferEnd(stopping);
  PetscCall(PetscTime(&t1));
  if (!app->quiet) {
    struct stat st;
    double      mb = stat(app->rundir.checkpoint, &st) ? 0.0 : (double)st.st_size / (1 << 20);
    PetscCall(PetscPrintf(app->comm, "  checkpoint after step %" PetscInt_FMT ": %.1f MB in %.2f s\n",
      app->path.accepted, mb,
                          (double)(t1 - t0)));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndAppRemoveCheckpoint(IndApp app)
{
  PetscMPIInt rank;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(app->comm, &rank));
  if (!rank && app->rundir.ready) {
    char previous[PETSC_MAX_PATH_LEN];
    IndRunDirPreviousCheckpoint(app->rundir.checkpoint, previous, sizeof(previous));
    (void)remove(app->rundir.checkpoint);
    (void)remove(previous);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The writes of the run's files, each a phase that GuardedWrite runs; *file names the file being written. */
typedef PetscErrorCode (*WritePhase)(IndApp app, const void *a, const void *b, char file[], size_t len);

static PetscErrorCode WriteStepFiles(IndApp app, const void *a, const void *b, char file[], size_t len)
{
  const IndStepResult *r = (const IndStepResult *)a;
  const IndCurvePoint *p = (const IndCurvePoint *)b;
  IndLoadPath         *lp = &app->path;

  PetscFunctionBeginUser;
  PetscCall(PetscSNPrintf(file, len, "%s", IndOutputGetFieldFile(app->output)));
  if (IndOutputFieldsEnabled(app->output) && r->fields) {
    PetscReal bytes;
    PetscCall(IndOutputBytesPerStep(app->output, &bytes));
    PetscCall(IndIOFaultCheckRoom(app->comm, file, 1.05 * bytes + (1 << 16)));
  }
  if (r->fields) PetscCall(IndOutputWriteStep(app->output, app->contact ? r->depth : r->lambda, app->U, app->assembly));
  if (p) {
    PetscCall(PetscSNPrintf(file, len, "%s/load_displacement.csv", IndOutputGetDir(app->output)));
    PetscCall(IndOutputCurvePoint(app->output, p));
  }
  if (app->scratch.length > 0 && app->rundir.ready) {
    PetscCall(PetscSNPrintf(file, len, "%s/scratch.csv", app->rundir.dir));
    PetscCall(IndScratchWrite(app->comm, app->rundir.dir, &app->scratch, lp->accepted, r->t,
                              IndLoadPathScratchFraction(lp, r->t), r->depth, &r->contact));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Room a checkpoint needs (bytes): the last one's size and a quarter, else a bound from the state's size. The
   new one is written beside the old, so its whole size counts. */
static double CheckpointBytes(IndApp app)
{
  struct stat st;
  PetscInt    ndof = 0, nhist = 0, stride = 1;
  Vec         H;

  if (!stat(app->rundir.checkpoint, &st)) return 1.1 * (double)st.st_size + (1 << 16);
  /* per node its 3 keys and 12 values (U, dU, the contact's reactions and displacements), per cell its 3 keys
     and its history */
  (void)VecGetSize(app->U, &ndof);
  (void)IndHistoryGetCommitted(app->history, &H, &stride);
  (void)VecGetSize(H, &nhist);
  return 1.25 * 8.0 * (5.0 * (double)ndof + (double)nhist * (1.0 + 3.0 / (double)stride)) + (1 << 16);
}

static PetscErrorCode WriteCheckpointPhase(IndApp app, PetscBool stopping, char file[], size_t len)
{
  PetscFunctionBeginUser;
  PetscCall(PetscSNPrintf(file, len, "%s", app->rundir.checkpoint));
  if (app->rundir.ready) { /* written under a temporary name: a file of its own */
    char tmp[PETSC_MAX_PATH_LEN + 8];
    PetscCall(PetscSNPrintf(tmp, sizeof(tmp), "%s.tmp", file));
    PetscCall(IndIOFaultCheckRoom(app->comm, tmp, CheckpointBytes(app)));
  }
  PetscCall(Checkpoint(app, stopping));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode WriteCheckpoint(IndApp app, const void *a, const void *b, char file[], size_t len)
{
  PetscFunctionBeginUser;
  (void)a, (void)b;
  PetscCall(WriteCheckpointPhase(app, PETSC_FALSE, file, len));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode WriteStopCheckpoint(IndApp app, const void *a, const void *b, char file[], size_t len)
{
  PetscFunctionBeginUser;
  (void)a, (void)b;
  PetscCall(WriteCheckpointPhase(app, PETSC_TRUE, file, len));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode WriteSummary(IndApp app, const void *a, const void *b, char file[], size_t len)
{
  PetscFunctionBeginUser;
  (void)b;
  PetscCall(PetscSNPrintf(file, len, "%s/summary.txt and summary.json", IndOutputGetDir(app->output)));
  PetscCall(IndSummaryFinish(app->summary, IndContactGetIndenter(app->contact), (const IndRunInfo *)a,
                             IndOutputGetDir(app->output),
                             IndOutputCurveEnabled(app->output), app->quiet ? PETSC_FALSE : PETSC_TRUE));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* What a run ended by a failed write continues from, as the end of its error line: the checkpoint just
   written (written), or the last complete one of this run, or none. */
static PetscErrorCode ContinueFrom(IndApp app, PetscBool written, char text[], size_t len)
{
  PetscFunctionBeginUser;
  if (!app->rundir.ready) PetscCall(PetscSNPrintf(text, len, "no checkpoint to continue from"));
  else if (written)
    PetscCall(PetscSNPrintf(text, len, "the checkpoint of step %" PetscInt_FMT " is written: make room and continue "
                            "with the same options and -restart %s", app->path.accepted, app->rundir.dir));
  else if (app->checkpointed >= 0)
    PetscCall(PetscSNPrintf(text, len, "the last checkpoint, of step %" PetscInt_FMT ", is %s: make room and continue "
                            "with the same options and -restart %s", app->checkpointed, app->rundir.checkpoint,
                            app->rundir.dir));
  else PetscCall(PetscSNPrintf(text, len, "no checkpoint to continue from: make room and run again"));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Runs one write phase; when a write fails on any rank, the run ends: one line naming the file, the step
   and the cause, exit status IND_EXIT_IO, after a checkpoint of the last accepted step when the failed
   file was not the checkpoint and there is room for it. No temporary checkpoint is left behind. */
static PetscErrorCode GuardedWrite(IndApp app, WritePhase phase, const void *a, const void *b)
{
  char           file[PETSC_MAX_PATH_LEN] = "", text[2 * PETSC_MAX_PATH_LEN], alone[4 * PETSC_MAX_PATH_LEN];
  char           tmp[PETSC_MAX_PATH_LEN + 8];
  IndIOFault     fault, again = {PETSC_TRUE, 0};
  PetscErrorCode ierr;
  PetscMPIInt    rank;

  PetscFunctionBeginUser;
  PetscCall(IndIOFaultBegin());
  ierr = phase(app, a, b, file, sizeof(file));
  PetscCall(ContinueFrom(app, PETSC_FALSE, text, sizeof(text)));
  PetscCall(PetscSNPrintf(alone, sizeof(alone), "writing '%s' after step %" PetscInt_FMT " failed (%s); a rank is left "
                          "inside the write", file, app->path.accepted, text));
  PetscCall(IndIOFaultEnd(app->comm, ierr, alone, &fault));
  if (!fault.failed) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCallMPI(MPI_Comm_rank(app->comm, &rank));
  PetscCall(PetscSNPrintf(tmp, sizeof(tmp), "%s.tmp", app->rundir.checkpoint));
  if (app->rundir.ready && strcmp(file, app->rundir.checkpoint)) {
    char other[PETSC_MAX_PATH_LEN];
    PetscCall(IndIOFaultBegin());
    ierr = WriteCheckpointPhase(app, PETSC_TRUE, other, sizeof(other));
    PetscCall(PetscSNPrintf(alone, sizeof(alone), "writing '%s' after step %" PetscInt_FMT " failed (%s), and then "
                            "the checkpoint", file, app->path.accepted, text));
    PetscCall(IndIOFaultEnd(app->comm, ierr, alone, &again));
  }
  if (!rank && again.failed && app->rundir.ready) (void)remove(tmp);
  PetscCallMPI(MPI_Barrier(app->comm));
  PetscCall(ContinueFrom(app, again.failed ? PETSC_FALSE : PETSC_TRUE, text, sizeof(text)));
  SETERRQ(app->comm, PETSC_ERR_FILE_WRITE, "writing '%s' after step %" PetscInt_FMT " failed: %s; %s", file,
          app->path.accepted, IndIOFaultCause(&fault), text);
}

/* The marker beside the checkpoint (IND_STOPPED_FILE) for job scripts; a failed write of it only costs the
   script's knowing, so it is not an error. */
PetscErrorCode IndAppWriteStopMarker(IndApp app, const char signal[])
{
  PetscMPIInt rank;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(app->comm, &rank));
  if (!rank) {
    char  path[PETSC_MAX_PATH_LEN];
    FILE *fp;
    PetscCall(PetscSNPrintf(path, sizeof(path), "%s/%s", app->rundir.dir, IND_STOPPED_FILE));
    fp = fopen(path, "w");
    if (fp) {
      fprintf(fp, "stopped by %s after step %" PetscInt_FMT "\n", signal, app->path.accepted);
      (void)fclose(fp);
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndAppRemoveStopMarker(IndApp app)
{
  PetscMPIInt rank;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(app->comm, &rank));
  if (!rank && app->rundir.ready) {
    char path[PETSC_MAX_PATH_LEN];
    PetscCall(PetscSNPrintf(path, sizeof(path), "%s/%s", app->rundir.dir, IND_STOPPED_FILE));
    (void)remove(path);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndAppWriteStep(IndApp app, const IndStepResult *r, const IndCurvePoint *p)
{
  PetscFunctionBeginUser;
  PetscCall(GuardedWrite(app, WriteStepFiles, r, p));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndAppWriteCheckpoint(IndApp app, PetscBool stopping)
{
  PetscFunctionBeginUser;
  PetscCall(GuardedWrite(app, stopping ? WriteStopCheckpoint : WriteCheckpoint, NULL, NULL));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndAppWriteSummary(IndApp app, const IndRunInfo *info)
{
  PetscFunctionBeginUser;
  PetscCall(GuardedWrite(app, WriteSummary, info, NULL));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A signal came: the state of the last accepted step goes to the checkpoint, and the run ends. */
PetscErrorCode IndAppStop(IndApp app, int signum)
{
  const char *name = IndSignalName(signum);

  PetscFunctionBeginUser;
  PetscCall(IndAppWriteCheckpoint(app, PETSC_TRUE));
  app->stopped = signum;
  if (app->rundir.ready) PetscCall(IndAppWriteStopMarker(app, name));
  if (app->rundir.ready)
    PetscCall(PetscPrintf(app->comm,
                          "indent: stopped by %s after step %" PetscInt_FMT "; checkpoint %s written: "
                          "continue with the same options and -restart %s\n",
                          name, app->path.accepted, app->rundir.checkpoint, app->rundir.dir));
  else
    PetscCall(PetscPrintf(app->comm,
      "indent: stopped by %s after step %" PetscInt_FMT " (no files, so no checkpoint)\n",
                          name, app->path.accepted));
  PetscFunctionReturn(PETSC_SUCCESS);
}
