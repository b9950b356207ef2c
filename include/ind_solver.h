#pragma once
/* One load step: Newton (SNES) on the assembled residual with Dirichlet rows, CG + GAMG with the
   rigid-body near-null space by default; every choice can be changed by PETSc options. */
#include <petscsnes.h>
#include "ind_assembly.h"
#include "ind_bc.h"

typedef struct _p_IndSolver *IndSolver;
struct _p_IndSolver {
  DM           dm;
  IndAssembly  assembly;
  IndBC        bc;
  SNES         snes;
  Mat          J;
  Vec          Uloc, Floc;
  PetscReal    load_factor; /* of the step being solved */
};

PetscErrorCode IndSolverCreate(DM dm, IndAssembly assembly, IndBC bc, IndSolver *solver);
PetscErrorCode IndSolverDestroy(IndSolver *solver);
/* Solves for U at the given load factor; U holds the initial guess. */
PetscErrorCode IndSolverSolve(IndSolver solver, PetscReal load_factor, Vec U, SNESConvergedReason *reason);
