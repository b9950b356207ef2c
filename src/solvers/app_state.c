#include "app_impl.h"
#include "ind_checkpoint.h"

/* The run's own part of the state: the displacement, when the run began and its wall time so far. */
static PetscErrorCode RunState(void *obj, IndStateFile f)
{
  IndApp    app     = (IndApp)obj;
  PetscReal elapsed = app->elapsed_before + app->elapsed_now;

  PetscFunctionBeginUser;
  PetscCall(IndStateNodes(f, "U", app->U));
  PetscCall(IndStateReals(f, "elapsed", 1, &elapsed));
  PetscCall(IndStateString(f, "start_time", app->start_time, sizeof(app->start_time)));
  if (IndStateReading(f)) {
    PetscCall(VecCopy(app->U, app->Uprev));
    app->elapsed_before = elapsed;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndAppGetStateParts(IndApp app, PetscInt *n, IndStatePart parts[IND_APP_MAX_STATE_PARTS])
{
  PetscFunctionBeginUser;
  *n            = 0;
  parts[(*n)++] = (IndStatePart){"run", RunState, app};
  parts[(*n)++] = (IndStatePart){"load_path", IndLoadPathState, &app->path};
  parts[(*n)++] = (IndStatePart){"predictor", IndPredictorState, app->predictor};
  parts[(*n)++] = (IndStatePart){"history", IndHistoryState, app->history};
  parts[(*n)++] = (IndStatePart){"solver", IndSolverState, app->solver};
  if (app->contact) parts[(*n)++] = (IndStatePart){"contact", IndContactState, app->contact};
  if (app->control) parts[(*n)++] = (IndStatePart){"load_control", IndLoadControlState, app->control};
  if (app->summary) parts[(*n)++] = (IndStatePart){"curve", IndSummaryState, app->summary};
  parts[(*n)++] = (IndStatePart){"output", IndOutputState, app->output};
  parts[(*n)++] = (IndStatePart){"warnings", IndWarningsState, &app->warnings};
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndAppCheckpoint(IndApp app, const char path[], PetscFileMode mode)
{
  IndStatePart parts[IND_APP_MAX_STATE_PARTS];
  PetscInt     n;

  PetscFunctionBeginUser;
  PetscCall(IndAppGetStateParts(app, &n, parts));
  if (mode == FILE_MODE_WRITE) PetscCall(IndCheckpointWrite(app->comm, app->disc, path, app->path.accepted, n, parts));
  else PetscCall(IndCheckpointRead(app->comm, app->disc, path, n, parts));
  PetscFunctionReturn(PETSC_SUCCESS);
}
