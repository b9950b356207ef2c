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

/* How each step's Newton iteration starts: from the last increment extrapolated when there is one
   (else the tangent response), always from the tangent response, or from the prescribed values alone. */
typedef enum { IND_PREDICTOR_EXTRAPOLATE, IND_PREDICTOR_TANGENT, IND_PREDICTOR_NONE } IndPredictor;
extern const char *const IndPredictorTypes[];

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
} IndStepResult;

typedef struct _p_IndApp *IndApp;
typedef PetscErrorCode (*IndStepMonitor)(IndApp app, const IndStepResult *step, void *ctx);

struct _p_IndApp {
  MPI_Comm     comm;
  IndMesh      mesh;
  IndDisc      disc;
  IndMaterials mats;
  IndHistory   history;
  IndBC        bc;
  IndContact   contact; /* NULL without an indenter */
  IndAssembly  assembly;
  IndSolver    solver;
  IndOutput    output;
  IndSummary   summary; /* NULL without an indenter */
  Vec          U;     /* displacement (nm), global */
  Vec          Uprev; /* U of the last accepted step, to retry from */
  Vec          dU;    /* increment of the last accepted step, for the predictor */
  PetscReal    dlambda_last; /* its load-factor increment; 0 before the first step */
  PetscReal    ddepth_last;  /* its indenter-depth increment, nm */
  PetscReal    dslide_last;  /* its slide (scratch) increment, nm */
  PetscReal    load_last;    /* load control: the load of the last accepted step, uN */
  PetscReal    slope_last;   /* load control: its dP/dh, uN/nm (0: unknown) */
  PetscReal    depth_trial;  /* load control: the depth the step's Newton iteration starts from (-1: none) */
  IndPredictor predictor;
  IndLoadPath  path;
  IndScratch   scratch;
  PetscBool    quiet;
  IndStepMonitor monitor;
  void          *monitor_ctx;
  IndRunDir      rundir;
  PetscInt       checkpoint_every; /* accepted steps between checkpoints (0: only on a signal) */
  PetscInt       csm_every;        /* -csm_every: the unloading stiffness every N accepted loading steps (0: never) */
  PetscInt       stop_after;       /* -checkpoint_stop_after_step: act as if SIGTERM came after it (tests) */
  PetscInt       checkpointed;     /* the accepted step of the last checkpoint written (-1: none) */
  int            stopped;          /* the signal that stopped the run after its checkpoint (0: none) */
  char           start_time[64];   /* when the run (its first part, for a restarted one) started */
  PetscLogDouble elapsed_before;   /* wall seconds of the earlier parts of a restarted run */
  PetscLogDouble elapsed_now;      /* wall seconds of this part, at the last checkpoint or the end */
  PetscLogDouble t_start;
  IndWarnings    warnings; /* of the run so far, for the summary */
};

PetscErrorCode IndAppCreate(MPI_Comm comm, IndApp *app);
PetscErrorCode IndAppDestroy(IndApp *app);
/* Hooks for verification problems (manufactured solutions, patch tests), set before IndAppRun. */
PetscErrorCode IndAppSetBodyForce(IndApp app, IndVectorFn fn, void *ctx);
PetscErrorCode IndAppAddBoundaryFunction(IndApp app, const char surface[], PetscInt mask, IndVectorFn fn, void *ctx);
/* Called after every accepted step of IndAppRun, after its output. */
PetscErrorCode IndAppSetStepMonitor(IndApp app, IndStepMonitor fn, void *ctx);
/* One attempt from the current state to pseudo-time t of the load program: on convergence the trial
   history and the contact state are committed; otherwise U is restored and nothing changes. */
PetscErrorCode IndAppSolveStep(IndApp app, PetscReal t, IndStepResult *step);
/* Applies the load from 0 to 1 in adaptive steps (-load_steps and friends), writing output after each,
   and a checkpoint every -checkpoint_every steps; a SIGTERM, SIGINT or SIGUSR1 ends it after the step
   under way with a checkpoint (see IndAppStoppedBy). */
PetscErrorCode IndAppRun(IndApp app);
/* The signal that stopped IndAppRun after writing a checkpoint, 0 when the run finished. */
int            IndAppStoppedBy(IndApp app);
/* The exit status of a run stopped by a signal with its checkpoint written (EX_TEMPFAIL): a job script
   resubmits on it. */
#define IND_EXIT_CHECKPOINTED 75
