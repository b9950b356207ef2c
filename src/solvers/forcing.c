#include "forcing.h"

/* The safeguard of Kelley (Iterative Methods for Linear and Nonlinear Equations, SIAM 1995, section 6.3) against
   oversolving the last Newton iterations. With Newton converging quadratically, the last linear solve starts from a
   residual only a little above the target and still reduced it by the full -ksp_rtol (1e-5): on the graded hexahedra
   of the Kick and scratch tests that solve took 150 to 220 GMRES iterations, 3 to 4 times the first ones, to remove
   a residual the Newton solve no longer needed to remove. Asking that solve for gamma times the rest of the way
   leaves the Newton iterations as they were while gamma is small enough for the preconditioned residual, which the
   Krylov method measures, to stand for the true one. */
PetscReal IndForcingTerm(PetscReal eta_min, PetscReal gamma, PetscReal ttol, PetscReal fnorm)
{
  const PetscReal eta_max = 0.1;

  if (!(gamma > 0) || !(ttol > 0) || !(fnorm > 0)) return eta_min;
  return PetscMax(eta_min, PetscMin(eta_max, gamma * ttol / fnorm));
}
