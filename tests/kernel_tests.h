#pragma once
/* Helpers of the constitutive kernels' unit tests (test_plasticity.c, test_densification.c): a named check
   against a tolerance, and central differences of an update at one point. */
#include "ind_plasticity.h"

/* Prints the check's worst error and fails (naming the check) when it exceeds tol. */
#define CHECK_TOL(name, worst, tol) \
  do { \
    PetscCall(PetscPrintf(PETSC_COMM_SELF, "  %-58s worst %.2e (tol %.0e)\n", name, (double)(worst), (double)(tol))); \
    PetscCheck((worst) <= (tol), PETSC_COMM_SELF, PETSC_ERR_PLIB, "%s: worst error %g exceeds %g", name, \
      (double)(worst), (double)(tol)); \
  } while (0)

/* A kernel with IndPlasticUpdate's arguments and contract. */
typedef IndPlasticStatus (*IndUpdateFn)(const IndPlasticParams *m, const PetscReal eps[6], const IndPlasticState *old,
                                        IndPlasticState *new_state, PetscReal sigma[6], PetscReal D[36],
                                        PetscReal *dp);

/* Dfd[6 i + b] = (sigma_i(eps + h e_b) - sigma_i(eps - h e_b)) / (2 h) from the history old. *kink is set when a
   difference point yields and eps does not, or the reverse (yielding: dp > 0 at eps): the stencil then straddles
   the elastic/plastic kink, and there is no derivative to compare with. */
static inline PetscErrorCode CentralDifferenceTangent(IndUpdateFn update, const IndPlasticParams *m,
                                                      const IndPlasticState *old, const PetscReal eps[6], PetscReal h,
                                                      PetscBool yielding, PetscReal Dfd[36], PetscBool *kink)
{
  PetscFunctionBeginUser;
  *kink = PETSC_FALSE;
  for (int b = 0; b < 6; ++b) {
    IndPlasticState st;
    PetscReal       ep[6], em[6], sp[6], sm[6], dpp, dpm;

    for (int i = 0; i < 6; ++i) ep[i] = em[i] = eps[i];
    ep[b] += h;
    em[b] -= h;
    PetscCheck(update(m, ep, old, &st, sp, NULL, &dpp) == IND_PLASTIC_OK &&
                 update(m, em, old, &st, sm, NULL, &dpm) == IND_PLASTIC_OK,
               PETSC_COMM_SELF, PETSC_ERR_NOT_CONVERGED, "the update did not converge %g from eps in component %d",
               (double)h, b);
    if ((dpp > 0) != yielding || (dpm > 0) != yielding) *kink = PETSC_TRUE;
    for (int i = 0; i < 6; ++i) Dfd[6 * i + b] = (sp[i] - sm[i]) / (2.0 * h);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}
