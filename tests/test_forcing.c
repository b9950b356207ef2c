static const char help[] = "Unit test of the linear tolerance inside a Newton solve (src/solvers/forcing.c): -ksp_rtol "
  "far from the Newton target, gamma times the rest of the way near it, never looser than 0.1.\n";

#include "forcing.h"

#define EXPECT(cond, ...) PetscCheck(cond, PETSC_COMM_SELF, PETSC_ERR_PLIB, __VA_ARGS__)

static PetscErrorCode Expect(PetscReal eta_min, PetscReal gamma, PetscReal ttol, PetscReal fnorm, PetscReal want)
{
  const PetscReal got = IndForcingTerm(eta_min, gamma, ttol, fnorm);

  PetscFunctionBeginUser;
  EXPECT(PetscAbsReal(got - want) <= 1e-15 * want, "eta_min %g, gamma %g, ttol %g, fnorm %g: %.17g, not %.17g",
    (double)eta_min, (double)gamma, (double)ttol, (double)fnorm, (double)got, (double)want);
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  /* The first iterations of a step (residual 1e8 times the target): the solve's own tolerance. */
  PetscCall(Expect(1e-5, 0.01, 2.3e-6, 232.0, 1e-5));
  /* The last iteration of the Kick test's first step, 2.28e-5 against a target of 2.3e-6: gamma 0.01 asks for a
     linear residual of a hundredth of the target, a reduction by 1e-3, looser than 1e-5. */
  PetscCall(Expect(1e-5, 0.01, 2.3e-6, 2.28e-5, 0.01 * 2.3e-6 / 2.28e-5));
  /* Just above the target: never looser than 0.1. */
  PetscCall(Expect(1e-5, 0.5, 1.0, 1.01, 0.1));
  /* A user's -ksp_rtol looser than the safeguard's is kept. */
  PetscCall(Expect(0.2, 0.01, 1.0, 2.0, 0.2));
  PetscCall(Expect(1e-3, 0.01, 1e-6, 1e-3, 1e-3));
  /* gamma 0 turns it off; a target or residual that is zero, negative or NaN leaves the solve's tolerance. */
  PetscCall(Expect(1e-5, 0.0, 1e-6, 1e-5, 1e-5));
  PetscCall(Expect(1e-5, 0.01, 0.0, 1e-5, 1e-5));
  PetscCall(Expect(1e-5, 0.01, 1e-6, 0.0, 1e-5));
  PetscCall(Expect(1e-5, 0.01, -1.0, 1e-5, 1e-5));
  PetscCall(Expect(1e-5, 0.01, 1e-6, (PetscReal)NAN, 1e-5));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "forcing term: all decisions as expected\n"));
  PetscCall(PetscFinalize());
  return 0;
}
