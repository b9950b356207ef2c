#pragma once
/* Private to src/solvers/: the fields of IndApp. Other groups use the accessors of
   ind_app.h. */
#include "ind_app.h"
#include "ind_predictor.h"
#include "ind_loadcontrol.h"

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
  IndPredictor   predictor; /* the start of each step's Newton iteration, and the last increment */
  IndLoadControl control;   /* -load_force (NULL: the depth is prescribed) */
  Vec            U;         /* displacement (nm), global */
  Vec            Uprev;     /* U of the last accepted step, to retry from */
  PetscReal      depth_start; /* load control: the depth the step's Newton iteration starts from (-1: none) */
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
