#pragma once
/* Shared by the solver tests: one linear solve from zero and its iteration count. */
#include <petscksp.h>

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
