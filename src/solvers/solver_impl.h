#pragma once
/* Private to src/solvers/: the fields of IndSolver. Other groups use the accessors of
   ind_solver.h. */
#include "ind_solver.h"
#include "pcreuse.h"

struct _p_IndSolver {
  DM           dm;
  IndAssembly  assembly;
  IndBC        bc;
  IndContact   contact; /* NULL without an indenter */
  SNES         snes;
  Mat          J;
  Mat          Jsingle; /* J's products in single precision, for the finest smoother (NULL: -newton_pc_single 0) */
  Vec          Uloc, Floc, Ubc;
  PetscReal    load_factor; /* of the step being solved */
  PetscInt     nfailed;     /* quadrature points, all ranks, whose return map failed in the last residual */
  PetscInt     nplastic;    /* quadrature points, all ranks, yielding in the last residual */
  PetscInt     stall_its;   /* Newton fails after this many iterations without a new smallest residual */
  PetscReal    fmin;        /* smallest residual norm of the current Newton solve */
  PetscInt     itmin;       /* its iteration */
  PetscBool    stalled;     /* the last Newton solve was stopped by the stall test */
  IndBordered  border;      /* load control (NULL: depth control) */
  IndPCReuse   reuse;       /* when the multigrid is rebuilt */
  PetscBool    keep_rigid;  /* J keeps its rigid-body modes after the multigrid's first set-up (it rebuilds P) */
};
