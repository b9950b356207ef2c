#include "ind_loadpath.h"

PetscErrorCode IndLoadPathSetFromOptions(MPI_Comm comm, IndLoadPath *lp)
{
  PetscInt steps = 1;

  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(lp, sizeof(*lp)));
  lp->cutback      = 0.5;
  lp->growth       = 1.5;
  lp->easy_its     = 5;
  lp->max_cutbacks = 10;
  PetscOptionsBegin(comm, NULL, "Load stepping", "Load");
  PetscCall(PetscOptionsInt("-load_steps", "Number of load steps when none is cut back", "", steps, &steps, NULL));
  lp->dt_initial = 1.0 / PetscMax(steps, 1);
  lp->dt_max     = lp->dt_initial;
  lp->dt_min     = lp->dt_initial / 1024;
  PetscCall(PetscOptionsReal("-load_max_increment", "Largest load-factor increment a step may grow to", "", lp->dt_max, &lp->dt_max, NULL));
  PetscCall(PetscOptionsReal("-load_min_increment", "Smallest load-factor increment before giving up", "", lp->dt_min, &lp->dt_min, NULL));
  PetscCall(PetscOptionsReal("-load_cutback", "Factor on the increment after a failed step", "", lp->cutback, &lp->cutback, NULL));
  PetscCall(PetscOptionsReal("-load_growth", "Factor on the increment after an easy step", "", lp->growth, &lp->growth, NULL));
  PetscCall(PetscOptionsInt("-load_easy_its", "Newton iterations at or below which a step is easy", "", lp->easy_its, &lp->easy_its, NULL));
  PetscCall(PetscOptionsInt("-load_max_cutbacks", "Failed attempts in a row before the run stops", "", lp->max_cutbacks, &lp->max_cutbacks, NULL));
  PetscOptionsEnd();
  PetscCheck(steps >= 1, comm, PETSC_ERR_ARG_OUTOFRANGE, "-load_steps must be >= 1, got %" PetscInt_FMT, steps);
  PetscCheck(lp->dt_max > 0 && lp->dt_max <= 1, comm, PETSC_ERR_ARG_OUTOFRANGE, "-load_max_increment must lie in (0, 1], got %g", (double)lp->dt_max);
  PetscCheck(lp->dt_min > 0 && lp->dt_min <= lp->dt_initial, comm, PETSC_ERR_ARG_OUTOFRANGE, "-load_min_increment must lie in (0, 1/-load_steps = %g], got %g", (double)lp->dt_initial, (double)lp->dt_min);
  PetscCheck(lp->cutback > 0 && lp->cutback < 1, comm, PETSC_ERR_ARG_OUTOFRANGE, "-load_cutback must lie in (0, 1), got %g", (double)lp->cutback);
  PetscCheck(lp->growth >= 1, comm, PETSC_ERR_ARG_OUTOFRANGE, "-load_growth must be >= 1, got %g", (double)lp->growth);
  PetscCheck(lp->max_cutbacks >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-load_max_cutbacks must be >= 0, got %" PetscInt_FMT, lp->max_cutbacks);
  lp->dt = PetscMin(lp->dt_initial, lp->dt_max);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Relative slack on reaching t = 1, so that N steps of 1/N end exactly at 1, not one ulp short. */
#define IND_LOAD_END_TOL 1e-9

PetscBool IndLoadPathDone(const IndLoadPath *lp)
{
  return lp->t >= 1.0 ? PETSC_TRUE : PETSC_FALSE;
}

PetscReal IndLoadPathTarget(const IndLoadPath *lp)
{
  const PetscReal t = lp->t + lp->dt;
  return t >= 1.0 - IND_LOAD_END_TOL * lp->dt ? 1.0 : t;
}

void IndLoadPathAccept(IndLoadPath *lp, PetscInt its)
{
  lp->t = IndLoadPathTarget(lp);
  lp->accepted++;
  lp->cutbacks_in_a_row = 0;
  if (its <= lp->easy_its) lp->dt = PetscMin(lp->dt * lp->growth, lp->dt_max);
}

PetscErrorCode IndLoadPathReject(IndLoadPath *lp, MPI_Comm comm, const char why[])
{
  PetscFunctionBeginUser;
  lp->cutbacks++;
  lp->cutbacks_in_a_row++;
  PetscCheck(lp->cutbacks_in_a_row <= lp->max_cutbacks, comm, PETSC_ERR_NOT_CONVERGED, "Load step from load factor %g failed %" PetscInt_FMT " times in a row (last: %s); raise -load_max_cutbacks or refine -load_steps", (double)lp->t, lp->cutbacks_in_a_row, why);
  lp->dt *= lp->cutback;
  PetscCheck(lp->dt >= lp->dt_min * (1 - IND_LOAD_END_TOL), comm, PETSC_ERR_NOT_CONVERGED, "Load step from load factor %g failed (%s) and the increment %g would fall below -load_min_increment %g", (double)lp->t, why, (double)lp->dt, (double)lp->dt_min);
  PetscFunctionReturn(PETSC_SUCCESS);
}
