#pragma once
/* Shared by the solver tests: the app whose Newton KSP they drive, and one linear solve from zero with its
   iteration count. */
#include "ind_app.h"

/* The app of the command line's options, its Jacobian and its Newton KSP (tolerance rtol, at most 500 iterations).
   The test decides when the preconditioner is built, not the solver's rule (src/solvers/pcreuse.h). */
static inline PetscErrorCode SolverTestCreate(PetscReal rtol, IndApp *app, Mat *J, KSP *ksp)
{
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsSetValue(NULL, "-snes_lag_preconditioner", "1"));
  PetscCall(IndAppCreate(PETSC_COMM_WORLD, app));
  *J = IndSolverGetJacobian(IndAppGetSolver(*app));
  PetscCall(SNESGetKSP(IndSolverGetSNES(IndAppGetSolver(*app)), ksp));
  PetscCall(KSPSetTolerances(*ksp, rtol, PETSC_DEFAULT, PETSC_DEFAULT, 500));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Iterations of one solve of ksp (its preconditioner set up before, or anew); -1 when it does not converge. */
static inline PetscErrorCode SolveCounted(KSP ksp, Vec b, Vec x, PetscInt *its)
{
  KSPConvergedReason reason;

  PetscFunctionBeginUser;
  PetscCall(VecZeroEntries(x));
  PetscCall(KSPSolve(ksp, b, x));
  PetscCall(KSPGetConvergedReason(ksp, &reason));
  PetscCall(KSPGetIterationNumber(ksp, its));
  if (reason <= 0) *its = -1;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The app's conditions set up and its Jacobian at zero displacement, with the conditions applied; *Uloc (zero) is the
   DM's local vector, to be given back with DMRestoreLocalVector. */
static inline PetscErrorCode SolverTestJacobianAtZero(IndApp app, Mat J, Vec *Uloc)
{
  PetscFunctionBeginUser;
  PetscCall(IndBCSetUp(IndAppGetBC(app)));
  PetscCall(DMGetLocalVector(IndAppGetDM(app), Uloc));
  PetscCall(VecZeroEntries(*Uloc));
  PetscCall(IndAssemblyJacobian(IndAppGetAssembly(app), *Uloc, J));
  PetscCall(IndBCApplyJacobian(IndAppGetBC(app), J));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The coarse operators of ksp's multigrid above its coarsest (levels 1 .. levels - 2; the coarsest may be moved to
   one rank): *n of them in ops (at least 8 long), borrowed */
static inline PetscErrorCode SolverTestCoarseOperators(KSP ksp, Mat ops[], PetscInt *n)
{
  PC       pc;
  PetscInt levels;

  PetscFunctionBeginUser;
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PCMGGetLevels(pc, &levels));
  *n = 0;
  for (PetscInt l = 1; l < levels - 1 && *n < 8; ++l) {
    KSP smoother;
    PetscCall(PCMGGetSmoother(pc, l, &smoother));
    PetscCall(KSPGetOperators(smoother, &ops[(*n)++], NULL));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}
