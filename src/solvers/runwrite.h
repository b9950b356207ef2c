#pragma once
/* The run's writes (runwrite.c), private to src/solvers: each is a phase whose failed write ends the run as
   an ordinary event (status 74, one line naming the file, the step and the cause, and a checkpoint of the
   last accepted step when there is room for it; ind_iofault.h). */
#include "ind_app.h"
#include "ind_summary.h"

/* The wall time of this part of the run so far, into app->elapsed_now. */
PetscErrorCode IndAppElapsed(IndApp app);
/* The accepted step's fields, its line of the curve (p; NULL without an indenter) and scratch.csv. */
PetscErrorCode IndAppWriteStep(IndApp app, const IndStepResult *r, const IndCurvePoint *p);
/* The checkpoint of the last accepted step, unless this run wrote it already; stopping: a stop signal
   came (a second one waits for the write to end). */
PetscErrorCode IndAppWriteCheckpoint(IndApp app, PetscBool stopping);
PetscErrorCode IndAppWriteSummary(IndApp app, const IndRunInfo *info);
/* The marker IND_STOPPED_FILE after a stop's checkpoint; a failed write of it is not an error. */
PetscErrorCode IndAppWriteStopMarker(IndApp app, const char signal[]);
/* The marker of an earlier part, by the restart that continues it. */
PetscErrorCode IndAppRemoveStopMarker(IndApp app);
/* A stop signal came (signum): the checkpoint of the last accepted step, the stop marker, and the line saying
   how to continue; the run loop then ends. */
PetscErrorCode IndAppStop(IndApp app, int signum);
/* A finished run's checkpoints (this one and the previous), which could only restart a finished run. */
PetscErrorCode IndAppRemoveCheckpoint(IndApp app);
