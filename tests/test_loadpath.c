static const char help[] = "Unit test of the adaptive load stepping: exact end point, cutback, growth, the "
  "errors, and the steps whose fields are written.\n";

#include "ind_loadpath.h"

#define EXPECT(cond, ...) PetscCheck(cond, PETSC_COMM_SELF, PETSC_ERR_PLIB, __VA_ARGS__)

int main(int argc, char **argv)
{
  IndLoadPath    lp;
  PetscErrorCode err;
  PetscInt       n = 0;

  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  /* Ten equal steps end exactly at 1, although 10 * 0.1 is not 1 in floating point. */
  PetscCall(PetscOptionsSetValue(NULL, "-load_steps", "10"));
  PetscCall(IndLoadPathSetFromOptions(PETSC_COMM_SELF, PETSC_FALSE, &lp));
  while (!IndLoadPathDone(&lp)) {
    IndLoadPathAccept(&lp, 10);
    n++;
  }
  EXPECT(n == 10 && lp.t == 1.0, "10 steps of 0.1: %" PetscInt_FMT " steps, end %.17g", n, (double)lp.t);

  /* A failure halves the increment; easy steps grow it by 1.5 up to the initial increment. */
  PetscCall(IndLoadPathSetFromOptions(PETSC_COMM_SELF, PETSC_FALSE, &lp));
  PetscCall(IndLoadPathReject(&lp, PETSC_COMM_SELF, "test", NULL));
  EXPECT(PetscAbsReal(IndLoadPathTarget(&lp) - 0.05) < 1e-15, "after a cutback the target is %g, not 0.05",
    (double)IndLoadPathTarget(&lp));
  IndLoadPathAccept(&lp, 2);
  EXPECT(PetscAbsReal(lp.dt - 0.075) < 1e-15, "an easy step grows 0.05 to %g, not 0.075", (double)lp.dt);
  IndLoadPathAccept(&lp, 2);
  EXPECT(PetscAbsReal(lp.dt - 0.1) < 1e-15, "growth is capped at the initial increment: %g", (double)lp.dt);
  IndLoadPathAccept(&lp, 20);
  EXPECT(PetscAbsReal(lp.dt - 0.1) < 1e-15 && lp.cutbacks == 1 && lp.cutbacks_in_a_row == 0,
    "a hard step keeps the increment");

  /* Ten cutbacks in a row reach -load_min_increment (initial / 1024); the eleventh is an error. */
  PetscCall(IndLoadPathSetFromOptions(PETSC_COMM_SELF, PETSC_FALSE, &lp));
  PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
  for (n = 0; n < 10; ++n) PetscCall(IndLoadPathReject(&lp, PETSC_COMM_SELF, "test", NULL));
  err = IndLoadPathReject(&lp, PETSC_COMM_SELF, "test", NULL);
  EXPECT(err == PETSC_ERR_NOT_CONVERGED, "the 11th cutback in a row must fail, returned %d", (int)err);

  /* A limit (the contact's edge) shortens the next step only, not below the smallest increment, and a limit past
     the target leaves it. */
  PetscCall(IndLoadPathSetFromOptions(PETSC_COMM_SELF, PETSC_FALSE, &lp));
  IndLoadPathLimit(&lp, 0.5);
  EXPECT(PetscAbsReal(IndLoadPathTarget(&lp) - 0.1) < 1e-15, "a limit past the target moved it to %g",
    (double)IndLoadPathTarget(&lp));
  IndLoadPathLimit(&lp, 0.03);
  EXPECT(PetscAbsReal(IndLoadPathTarget(&lp) - 0.03) < 1e-15, "a limit of 0.03 gave the target %g",
    (double)IndLoadPathTarget(&lp));
  IndLoadPathAccept(&lp, 2);
  EXPECT(lp.cutbacks == 0 && PetscAbsReal(lp.dt - 0.045) < 1e-15, "a limited step is no cut-back and grows back");
  IndLoadPathLimit(&lp, lp.t + 1e-9);
  EXPECT(PetscAbsReal(lp.dt - lp.dt_min) < 1e-15, "a limit below -load_min_increment gave %g, not %g",
    (double)lp.dt, (double)lp.dt_min);

  /* Non-physical settings are refused. */
  PetscCall(PetscOptionsSetValue(NULL, "-load_growth", "0.5"));
  err = IndLoadPathSetFromOptions(PETSC_COMM_SELF, PETSC_FALSE, &lp);
  EXPECT(err == PETSC_ERR_ARG_OUTOFRANGE, "-load_growth 0.5 must be refused");
  PetscCall(PetscOptionsClearValue(NULL, "-load_growth"));
  PetscCall(PetscOptionsSetValue(NULL, "-load_edge_steps", "-1"));
  err = IndLoadPathSetFromOptions(PETSC_COMM_SELF, PETSC_FALSE, &lp);
  EXPECT(err == PETSC_ERR_ARG_OUTOFRANGE, "-load_edge_steps -1 must be refused");
  PetscCall(PetscOptionsClearValue(NULL, "-load_edge_steps"));
  PetscCall(PetscOptionsSetValue(NULL, "-load_steps", "0"));
  err = IndLoadPathSetFromOptions(PETSC_COMM_SELF, PETSC_FALSE, &lp);
  EXPECT(err == PETSC_ERR_ARG_OUTOFRANGE, "-load_steps 0 must be refused");
  PetscCall(PetscPopErrorHandler());
  PetscCall(PetscOptionsClearValue(NULL, "-load_steps"));
  /* Load, hold, unload: steps land on the segments' ends, lambda goes 0 -> 1 -> 1 -> 0. */
  PetscCall(PetscOptionsSetValue(NULL, "-load_steps", "4"));
  PetscCall(PetscOptionsSetValue(NULL, "-load_hold", "0.5"));
  PetscCall(IndLoadPathSetFromOptions(PETSC_COMM_SELF, PETSC_TRUE, &lp));
  {
    const PetscReal t_expect[] = {0.25, 0.5, 0.75, 1.0, 1.25, 1.5, 1.75, 2.0, 2.25, 2.5};
    const PetscReal l_expect[] = {0.25, 0.5, 0.75, 1.0, 1.0, 1.0, 0.75, 0.5, 0.25, 0.0};
    n = 0;
    while (!IndLoadPathDone(&lp)) {
      const PetscReal t = IndLoadPathTarget(&lp);
      EXPECT(n < 10 && PetscAbsReal(t - t_expect[n]) < 1e-14 && PetscAbsReal(IndLoadPathFactor(&lp,
        t) - l_expect[n]) < 1e-14, "program step %" PetscInt_FMT ": t %g, lambda %g", n, (double)t,
        (double)IndLoadPathFactor(&lp, t));
      EXPECT(IndLoadPathUnloading(&lp, t) == (n >= 6 ? PETSC_TRUE : PETSC_FALSE),
        "unloading flag at step %" PetscInt_FMT, n);
      IndLoadPathAccept(&lp, 10);
      n++;
    }
    EXPECT(n == 10, "load-hold-unload took %" PetscInt_FMT " steps, not 10", n);
  }
  /* A cut step near a segment's end still lands on it. */
  PetscCall(IndLoadPathSetFromOptions(PETSC_COMM_SELF, PETSC_TRUE, &lp));
  lp.t  = 0.9;
  lp.dt = 0.1 + 1e-12;
  EXPECT(IndLoadPathTarget(&lp) == 1.0, "a step ending 1e-12 past the end of loading is clamped onto it");
  IndLoadPathFinish(&lp);
  EXPECT(IndLoadPathDone(&lp), "Finish ends the program");
  PetscCall(PetscOptionsClearValue(NULL, "-load_hold"));
  /* Unloading in steps of its own: 2 load steps, then 1/8 growing by 1.5 after every accepted step
     (hard or not) up to the loading increment 1/2; a cut step still grows from its cut size. */
  PetscCall(PetscOptionsSetValue(NULL, "-load_steps", "2"));
  PetscCall(PetscOptionsSetValue(NULL, "-load_unload_steps", "8"));
  PetscCall(PetscOptionsSetValue(NULL, "-load_unload_growth", "1.5"));
  PetscCall(IndLoadPathSetFromOptions(PETSC_COMM_SELF, PETSC_TRUE, &lp));
  {
    const PetscReal t_expect[] = {0.5, 1.0, 1.125, 1.3125, 1.59375, 1.6640625, 1.98046875, 2.0};
    for (n = 0; n < 8; ++n) {
      const PetscReal t = IndLoadPathTarget(&lp);
      EXPECT(PetscAbsReal(t - t_expect[n]) < 1e-14, "unloading program step %" PetscInt_FMT ": t %.17g, not %g", n,
        (double)t, (double)t_expect[n]);
      if (n == 4) {
        PetscCall(IndLoadPathReject(&lp, PETSC_COMM_SELF, "test", NULL));
        EXPECT(PetscAbsReal(IndLoadPathTarget(&lp) - 1.453125) < 1e-14, "cut unloading step: target %g",
          (double)IndLoadPathTarget(&lp));
      }
      IndLoadPathAccept(&lp, 50);
    }
    EXPECT(IndLoadPathDone(&lp), "the unloading program ends at t = 2");
  }
  PetscCall(PetscOptionsClearValue(NULL, "-load_unload_growth"));
  PetscCall(PetscOptionsClearValue(NULL, "-load_unload_steps"));
  /* A scratch between loading and unloading: 2 load steps, 4 equal slide steps at full load (a cut one
     grows by 1.5 back to the slide's increment 1/4, never to the loading one 1/2), then unloading. */
  PetscCall(IndLoadPathSetFromOptions(PETSC_COMM_SELF, PETSC_TRUE, &lp));
  IndLoadPathSetScratch(&lp, 4);
  {
    const PetscReal t_expect[] = {0.5, 1.0, 1.25, 1.375, 1.5625, 1.8125, 2.0, 2.5, 3.0};
    const PetscReal l_expect[] = {0.5, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 0.5, 0.0};
    const PetscReal f_expect[] = {0.0, 0.0, 0.25, 0.375, 0.5625, 0.8125, 1.0, 1.0, 1.0};
    n = 0;
    while (!IndLoadPathDone(&lp)) {
      PetscReal t;
      if (n == 3) PetscCall(IndLoadPathReject(&lp, PETSC_COMM_SELF, "test", NULL)); /* the slide's 0.25 -> 0.125 */
      t = IndLoadPathTarget(&lp);
      EXPECT(n < 9 && PetscAbsReal(t - t_expect[n]) < 1e-14 && PetscAbsReal(IndLoadPathFactor(&lp,
        t) - l_expect[n]) < 1e-14 &&
               PetscAbsReal(IndLoadPathScratchFraction(&lp, t) - f_expect[n]) < 1e-14,
             "scratch program step %" PetscInt_FMT ": t %.17g, lambda %g, slid %g", n, (double)t,
             (double)IndLoadPathFactor(&lp, t), (double)IndLoadPathScratchFraction(&lp, t));
      EXPECT(IndLoadPathScratching(&lp, t) == (n >= 2 && n <= 6 ? PETSC_TRUE : PETSC_FALSE),
        "scratching flag at %" PetscInt_FMT, n);
      EXPECT(IndLoadPathUnloading(&lp, t) == (n >= 7 ? PETSC_TRUE : PETSC_FALSE), "unloading flag at %" PetscInt_FMT,
        n);
      IndLoadPathAccept(&lp, 2);
      n++;
    }
    EXPECT(n == 9, "load-scratch-unload took %" PetscInt_FMT " steps, not 9", n);
  }
  PetscCall(PetscOptionsClearValue(NULL, "-load_steps"));
  /* Field steps (-output_fields_every 3) of 4 load, 2 hold and 4 unload steps: every third, the ends of the
     loading (4) and of the hold (6), and the last (10); StepsLeft counts them before the first step. */
  PetscCall(PetscOptionsSetValue(NULL, "-load_steps", "4"));
  PetscCall(PetscOptionsSetValue(NULL, "-load_hold", "0.5"));
  PetscCall(IndLoadPathSetFromOptions(PETSC_COMM_SELF, PETSC_TRUE, &lp));
  {
    const PetscInt expect[] = {3, 4, 6, 9, 10};
    PetscInt       k        = 0;
    EXPECT(IndLoadPathStepsLeft(&lp, 3, 100) == 5 && IndLoadPathStepsLeft(&lp, 1, 100) == 10 &&
             IndLoadPathStepsLeft(&lp, 3, 2) == 2, "steps left: %" PetscInt_FMT " field steps of %" PetscInt_FMT,
           IndLoadPathStepsLeft(&lp, 3, 100), IndLoadPathStepsLeft(&lp, 1, 100));
    while (!IndLoadPathDone(&lp)) {
      IndLoadPathAccept(&lp, 10);
      EXPECT(IndLoadPathFieldStep(&lp, 1), "every = 1 writes step %" PetscInt_FMT, lp.accepted);
      if (IndLoadPathFieldStep(&lp, 3)) {
        EXPECT(k < 5 && lp.accepted == expect[k], "field step %" PetscInt_FMT " is not expected", lp.accepted);
        k++;
      }
    }
    EXPECT(k == 5, "%" PetscInt_FMT " field steps, not 5", k);
  }
  /* The indenter leaving the surface ends the unloading early: that step is the last, so it is written. */
  PetscCall(IndLoadPathSetFromOptions(PETSC_COMM_SELF, PETSC_TRUE, &lp));
  for (n = 0; n < 7; ++n) IndLoadPathAccept(&lp, 10);
  EXPECT(!IndLoadPathFieldStep(&lp, 5) && !IndLoadPathAtSegmentEnd(&lp), "step 7 (unloading) is no field step");
  IndLoadPathFinish(&lp);
  EXPECT(IndLoadPathFieldStep(&lp, 5) && IndLoadPathAtSegmentEnd(&lp), "a finished program's last step is written");
  PetscCall(PetscOptionsClearValue(NULL, "-load_hold"));
  PetscCall(PetscOptionsClearValue(NULL, "-load_steps"));
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "load path: end point, cutback, growth, cap and error paths behave\n"));
  PetscCall(PetscFinalize());
  return 0;
}
