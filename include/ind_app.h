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

/* How each step's Newton iteration starts: from the last increment extrapolated when there is one
   (else the tangent response), always from the tangent response, or from the prescribed values alone. */
typedef enum { IND_PREDICTOR_EXTRAPOLATE, IND_PREDICTOR_TANGENT, IND_PREDICTOR_NONE } IndPredictor;
extern const char *const IndPredictorTypes[];

/* What one attempt at a load step did. */
typedef struct {
  PetscReal           t;         /* pseudo-time of the load program aimed at */
  PetscReal           lambda;    /* its load factor */
  PetscReal           depth;     /* indenter depth, nm (0 without an indenter) */
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
  IndPredictor predictor;
  IndLoadPath  path;
  PetscBool    quiet;
  IndStepMonitor monitor;
  void          *monitor_ctx;
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
/* Applies the load from 0 to 1 in adaptive steps (-load_steps and friends), writing output after each. */
PetscErrorCode IndAppRun(IndApp app);
