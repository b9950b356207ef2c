#pragma once
/* The application: owns every object and the order in which they are made and destroyed. */
#include "ind_mesh.h"
#include "ind_disc.h"
#include "ind_material.h"
#include "ind_assembly.h"
#include "ind_bc.h"
#include "ind_solver.h"
#include "ind_output.h"
#include "ind_history.h"
#include "ind_loadpath.h"
#include "ind_contact.h"
#include "ind_summary.h"
#include "ind_rundir.h"
#include "ind_warnings.h"
#include "ind_scratch.h"
#include "ind_state.h"

/* What one attempt at a load step did. */
typedef struct {
  PetscReal           t;         /* pseudo-time of the load program aimed at */
  PetscReal           lambda;    /* its load factor */
  PetscReal           depth;     /* indenter depth, nm (0 without an indenter) */
  PetscReal           slide;     /* distance the indenter has slid in a scratch test, nm */
  PetscBool           converged; /* accepted: history and contact committed; otherwise nothing changed */
  SNESConvergedReason reason;
  PetscInt            newton, linear, outer;
  PetscInt            plastic; /* yielding quadrature points at the converged state, all ranks */
  PetscInt            failed;  /* quadrature points whose return map failed, last residual */
  IndContactSummary   contact;
  char                why[256];
  PetscLogDouble      seconds;
  PetscBool           fields; /* accepted, and its fields are written (-output_fields_every) */
} IndStepResult;

typedef struct _p_IndApp *IndApp;
typedef PetscErrorCode (*IndStepMonitor)(IndApp app, const IndStepResult *step, void *ctx);


PetscErrorCode IndAppCreate(MPI_Comm comm, IndApp *app);
PetscErrorCode IndAppDestroy(IndApp *app);
/* The objects it owns (borrowed; contact and summary are NULL without an indenter), for drivers and tests. */
MPI_Comm       IndAppGetComm(IndApp app);
DM             IndAppGetDM(IndApp app);
IndMesh        IndAppGetMesh(IndApp app);
IndDisc        IndAppGetDisc(IndApp app);
IndMaterials   IndAppGetMaterials(IndApp app);
IndBC          IndAppGetBC(IndApp app);
IndContact     IndAppGetContact(IndApp app);
IndAssembly    IndAppGetAssembly(IndApp app);
IndSolver      IndAppGetSolver(IndApp app);
const IndLoadPath *IndAppGetLoadPath(IndApp app);
/* The displacement of the last accepted step (or of the step under way, in a step monitor), global. */
Vec            IndAppGetSolution(IndApp app);
/* Every object's part of the evolving state, in a fixed order (app_state.c): what a checkpoint holds. */
#define IND_APP_MAX_STATE_PARTS 16
PetscErrorCode IndAppGetStateParts(IndApp app, PetscInt *n, IndStatePart parts[IND_APP_MAX_STATE_PARTS]);
/* Writes the checkpoint of the last accepted step at path (FILE_MODE_WRITE), or reads the state back from one. */
PetscErrorCode IndAppCheckpoint(IndApp app, const char path[], PetscFileMode mode);
/* Hooks for verification problems (manufactured solutions, patch tests), set before IndAppRun. */
PetscErrorCode IndAppSetBodyForce(IndApp app, IndVectorFn fn, void *ctx);
PetscErrorCode IndAppAddBoundaryFunction(IndApp app, const char surface[], PetscInt mask, IndVectorFn fn, void *ctx);
/* Called after every accepted step of IndAppRun, after its output. */
PetscErrorCode IndAppSetStepMonitor(IndApp app, IndStepMonitor fn, void *ctx);
/* One attempt from the current state to pseudo-time t of the load program: on convergence the trial
   history and the contact state are committed; otherwise U is restored and nothing changes. */
PetscErrorCode IndAppSolveStep(IndApp app, PetscReal t, IndStepResult *step);
/* The next step of the load program (under load control, to its load): accepted, the program moves on; failed,
   its increment is cut (an error once it cannot be). Writes nothing. */
PetscErrorCode IndAppStep(IndApp app, IndStepResult *step);
/* Applies the load from 0 to 1 in adaptive steps (-load_steps and friends), writing output after each,
   and a checkpoint every -checkpoint_every steps; a SIGTERM, SIGINT or SIGUSR1 ends it after the step
   under way with a checkpoint (see IndAppStoppedBy). */
PetscErrorCode IndAppRun(IndApp app);
/* The signal that stopped IndAppRun after writing a checkpoint, 0 when the run finished. */
int            IndAppStoppedBy(IndApp app);
/* The exit status of a run stopped by a signal with its checkpoint written (EX_TEMPFAIL): a job script
   resubmits on it. */
#define IND_EXIT_CHECKPOINTED 75
