#include "ind_loadpath.h"

PetscErrorCode IndLoadPathSetFromOptions(MPI_Comm comm, PetscBool unload_default, IndLoadPath *lp)
{
  PetscInt steps = 1, unload_steps = 0;

  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(lp, sizeof(*lp)));
  lp->cutback      = 0.5;
  lp->growth       = 1.5;
  lp->easy_its     = 5;
  lp->max_cutbacks = 10;
  lp->unload       = unload_default;
  lp->unload_growth = 1.2;
  lp->force_rtol    = 1e-7;
  lp->edge_steps    = 0;
  PetscOptionsBegin(comm, NULL, IND_TITLE "Load program and stepping (-load_*)", "Load");
  PetscCall(IndOptionsReal("-load_depth", "Largest indenter depth, reached at the end of loading", "nm",
    "required with -indenter_type", lp->depth_max, &lp->depth_max, NULL));
  PetscCall(IndOptionsReal("-load_force", "Load control: the largest load, reached at the end of loading; the depth "
    "follows (-load_depth is then the largest depth allowed)", "uN", "none: depth control", lp->force_max,
    &lp->force_max, NULL));
  PetscCall(IndOptionsReal("-load_force_rtol", "Load control: each step's load within this fraction of -load_force", "",
    NULL, lp->force_rtol, &lp->force_rtol, NULL));
  PetscCall(IndOptionsReal("-load_unload_to", "Load control: unloading ends at this fraction of -load_force (0: the "
    "indenter leaves)", "", NULL, lp->unload_to, &lp->unload_to, NULL));
  PetscCall(IndOptionsReal("-load_hold", "Length of the hold at full load, in units of the loading segment", "", NULL,
    lp->hold, &lp->hold, NULL));
  PetscCall(IndOptionsBool("-load_unload", "Unload after loading (and holding)", lp->unload, &lp->unload, NULL));
  PetscCall(IndOptionsInt("-load_steps", "Number of loading steps when none is cut back", NULL, steps, &steps, NULL));
  unload_steps = steps;
  PetscCall(IndOptionsInt("-load_unload_steps",
    "The first unloading increment is 1/N of the depth: Oliver-Pharr fits the top of the unloading curve, which falls "
    "steeply", "-load_steps", unload_steps, &unload_steps, NULL));
  PetscCall(IndOptionsReal("-load_unload_growth",
    "Factor on the increment after each accepted unloading step (up to the loading increment)", "", NULL,
    lp->unload_growth, &lp->unload_growth, NULL));
  lp->dt_initial = 1.0 / PetscMax(steps, 1);
  lp->dt_unload  = 1.0 / PetscMax(unload_steps, 1);
  lp->dt_max     = lp->dt_initial;
  lp->dt_min     = PetscMin(lp->dt_initial, lp->dt_unload) / 1024;
  PetscCall(IndOptionsReal("-load_max_increment", "Largest load-factor increment a step may grow to", "",
    "1/-load_steps", lp->dt_max, &lp->dt_max, NULL));
  PetscCall(IndOptionsReal("-load_min_increment", "Smallest load-factor increment before giving up", "",
    "1/1024 of the smaller first increment", lp->dt_min, &lp->dt_min, NULL));
  PetscCall(IndOptionsReal("-load_cutback", "Factor on the increment after a failed step", "", NULL, lp->cutback,
    &lp->cutback, NULL));
  PetscCall(IndOptionsReal("-load_growth", "Factor on the increment after an easy step", "", NULL, lp->growth,
    &lp->growth, NULL));
  PetscCall(IndOptionsInt("-load_easy_its", "Newton iterations at or below which a step is easy", NULL, lp->easy_its,
    &lp->easy_its, NULL));
  PetscCall(IndOptionsReal("-load_edge_steps",
    "Loading steps at least this many per node spacing the contact's edge crosses, so that the step error follows "
    "the mesh (0: no limit)", "", NULL, lp->edge_steps, &lp->edge_steps, NULL));
  PetscCall(IndOptionsInt("-load_max_cutbacks", "Failed attempts in a row before the run stops", NULL, lp->max_cutbacks,
    &lp->max_cutbacks, NULL));
  PetscOptionsEnd();
  PetscCheck(steps >= 1, comm, PETSC_ERR_ARG_OUTOFRANGE, "-load_steps must be >= 1, got %" PetscInt_FMT, steps);
  PetscCheck(unload_steps >= 1, comm, PETSC_ERR_ARG_OUTOFRANGE, "-load_unload_steps must be >= 1, got %" PetscInt_FMT,
    unload_steps);
  PetscCheck(lp->hold >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-load_hold must be >= 0, got %g", (double)lp->hold);
  PetscCheck(lp->depth_max >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-load_depth must be >= 0 (nm), got %g",
    (double)lp->depth_max);
  PetscCheck(lp->force_max >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-load_force must be >= 0 (uN), got %g",
    (double)lp->force_max);
  PetscCheck(lp->force_rtol > 0 && lp->force_rtol < 1, comm, PETSC_ERR_ARG_OUTOFRANGE,
    "-load_force_rtol must lie in (0, 1), got %g",
             (double)lp->force_rtol);
  PetscCheck(lp->unload_to >= 0 && lp->unload_to < 1, comm, PETSC_ERR_ARG_OUTOFRANGE,
    "-load_unload_to must lie in [0, 1), got %g",
             (double)lp->unload_to);
  PetscCheck(lp->force_max > 0 || lp->unload_to == 0, comm, PETSC_ERR_ARG_WRONG,
    "-load_unload_to needs load control: -load_force");
  PetscCheck(lp->force_max == 0 || lp->depth_max > 0, comm, PETSC_ERR_ARG_WRONG,
             "-load_force needs -load_depth > 0 (nm): the largest depth the indenter may reach to carry it");
  lp->t_end = 1.0 + lp->hold + (lp->unload ? 1.0 : 0.0);
  PetscCheck(lp->dt_max > 0 && lp->dt_max <= 1, comm, PETSC_ERR_ARG_OUTOFRANGE,
    "-load_max_increment must lie in (0, 1], got %g", (double)lp->dt_max);
  PetscCheck(lp->dt_min > 0 && lp->dt_min <= PetscMin(lp->dt_initial, lp->dt_unload), comm, PETSC_ERR_ARG_OUTOFRANGE,
    "-load_min_increment must lie in (0, 1/-load_steps = %g] and (0, 1/-load_unload_steps = %g], got %g",
    (double)lp->dt_initial, (double)lp->dt_unload, (double)lp->dt_min);
  PetscCheck(lp->cutback > 0 && lp->cutback < 1, comm, PETSC_ERR_ARG_OUTOFRANGE,
    "-load_cutback must lie in (0, 1), got %g", (double)lp->cutback);
  PetscCheck(lp->unload_growth >= 1, comm, PETSC_ERR_ARG_OUTOFRANGE, "-load_unload_growth must be >= 1, got %g",
    (double)lp->unload_growth);
  PetscCheck(lp->growth >= 1, comm, PETSC_ERR_ARG_OUTOFRANGE, "-load_growth must be >= 1, got %g", (double)lp->growth);
  PetscCheck(lp->easy_its >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-load_easy_its must be >= 0, got %" PetscInt_FMT,
    lp->easy_its);
  PetscCheck(lp->edge_steps >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-load_edge_steps must be >= 0, got %g",
    (double)lp->edge_steps);
  PetscCheck(lp->max_cutbacks >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE,
    "-load_max_cutbacks must be >= 0, got %" PetscInt_FMT, lp->max_cutbacks);
  lp->dt = PetscMin(lp->dt_initial, lp->dt_max);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Relative slack on reaching t = 1, so that N steps of 1/N end exactly at 1, not one ulp short. */
#define IND_LOAD_END_TOL 1e-9

PetscBool IndLoadPathDone(const IndLoadPath *lp)
{
  return lp->t >= lp->t_end ? PETSC_TRUE : PETSC_FALSE;
}

void IndLoadPathSetScratch(IndLoadPath *lp, PetscInt steps)
{
  lp->scratch    = 1.0;
  lp->dt_scratch = 1.0 / PetscMax(steps, 1);
  lp->dt_min     = PetscMin(lp->dt_min, lp->dt_scratch / 1024);
  lp->t_end      = 1.0 + lp->hold + lp->scratch + (lp->unload ? 1.0 : 0.0);
}

PetscReal IndLoadPathFactor(const IndLoadPath *lp, PetscReal t)
{
  const PetscReal top = 1.0 + lp->hold + lp->scratch; /* end of the segments at full load */
  if (t <= 1.0) return t;
  if (t <= top) return 1.0;
  return PetscMax(0.0, 1.0 - (t - top));
}

PetscBool IndLoadPathUnloading(const IndLoadPath *lp, PetscReal t)
{
  return lp->unload && t > 1.0 + lp->hold + lp->scratch ? PETSC_TRUE : PETSC_FALSE;
}

PetscReal IndLoadPathScratchFraction(const IndLoadPath *lp, PetscReal t)
{
  if (lp->scratch <= 0) return 0.0;
  return PetscMin(1.0, PetscMax(0.0, (t - 1.0 - lp->hold) / lp->scratch));
}

PetscBool IndLoadPathScratching(const IndLoadPath *lp, PetscReal t)
{
  return lp->scratch > 0 && t > 1.0 + lp->hold && t <= 1.0 + lp->hold + lp->scratch ? PETSC_TRUE : PETSC_FALSE;
}

void IndLoadPathFinish(IndLoadPath *lp)
{
  lp->t = lp->t_end;
}

/* The next step's end, clamped onto the end of the current segment when it would pass it or stop
   just short of it. */
PetscReal IndLoadPathTarget(const IndLoadPath *lp)
{
  const PetscReal ends[4] = {1.0, 1.0 + lp->hold, 1.0 + lp->hold + lp->scratch, lp->t_end}, t = lp->t + lp->dt;
  for (int k = 0; k < 4; ++k)
    if (lp->t < ends[k] && t >= ends[k] - IND_LOAD_END_TOL * lp->dt) return ends[k];
  return t;
}

void IndLoadPathLimit(IndLoadPath *lp, PetscReal t_max)
{
  if (t_max < IndLoadPathTarget(lp)) lp->dt = PetscMax(t_max - lp->t, lp->dt_min);
}

void IndLoadPathAccept(IndLoadPath *lp, PetscInt its)
{
  const PetscReal next = IndLoadPathTarget(lp) + 0.5 * lp->dt_min; /* inside the segment of the next step */

  lp->t = IndLoadPathTarget(lp);
  lp->accepted++;
  lp->cutbacks_in_a_row = 0;
  if (IndLoadPathScratching(lp, next)) {
    /* Sliding: equal steps (the friction's path dependence is followed step by step), cut where
       they fail and grown back to the scratch's own increment. */
    if (lp->t <= 1.0 + lp->hold + 0.5 * lp->dt_min) lp->dt = lp->dt_scratch;
    else if (its <= lp->easy_its) lp->dt = PetscMin(lp->dt * lp->growth, lp->dt_scratch);
  } else if (IndLoadPathUnloading(lp, next)) {
    /* Unloading: fine steps at the top of the curve, where the load falls fastest and Oliver-Pharr
       fits it, growing geometrically since the curve flattens (whatever Newton needed: the
       contact shrinks as unloading goes on). */
    if (lp->t <= 1.0 + lp->hold + lp->scratch + 0.5 * lp->dt_min) lp->dt = lp->dt_unload;
    else lp->dt = PetscMin(lp->dt * lp->unload_growth, PetscMax(lp->dt_max, lp->dt_unload));
  } else if (its <= lp->easy_its) lp->dt = PetscMin(lp->dt * lp->growth, lp->dt_max);
}

PetscBool IndLoadPathAtSegmentEnd(const IndLoadPath *lp)
{
  /* Accepted steps end exactly on a segment's end (IndLoadPathTarget), so equality is the test. */
  const PetscReal ends[4] = {1.0, 1.0 + lp->hold, 1.0 + lp->hold + lp->scratch, lp->t_end};
  for (int k = 0; k < 4; ++k)
    if (lp->t == ends[k]) return PETSC_TRUE;
  return PETSC_FALSE;
}

PetscBool IndLoadPathFieldStep(const IndLoadPath *lp, PetscInt every)
{
  if (every <= 1 || lp->accepted % every == 0) return PETSC_TRUE;
  return IndLoadPathAtSegmentEnd(lp) || IndLoadPathDone(lp) ? PETSC_TRUE : PETSC_FALSE;
}

PetscInt IndLoadPathStepsLeft(const IndLoadPath *lp, PetscInt every, PetscInt limit)
{
  IndLoadPath copy = *lp;
  PetscInt    n    = 0;

  while (!IndLoadPathDone(&copy) && n < limit) {
    IndLoadPathAccept(&copy, copy.easy_its + 1); /* not easy: no growth beyond the program's own */
    if (IndLoadPathFieldStep(&copy, every)) n++;
  }
  return n;
}

PetscErrorCode IndLoadPathReject(IndLoadPath *lp, MPI_Comm comm, const char why[], const char remedy[])
{
  PetscFunctionBeginUser;
  lp->cutbacks++;
  lp->cutbacks_in_a_row++;
  PetscCheck(lp->cutbacks_in_a_row <= lp->max_cutbacks, comm, PETSC_ERR_NOT_CONVERGED,
    "Load step from load factor %.6g failed %" PetscInt_FMT " times in a row (last: %s); %s", (double)lp->t,
    lp->cutbacks_in_a_row, why, remedy ? remedy : "raise -load_max_cutbacks or refine -load_steps");
  lp->dt *= lp->cutback;
  PetscCheck(lp->dt >= lp->dt_min * (1 - IND_LOAD_END_TOL), comm, PETSC_ERR_NOT_CONVERGED,
    "Load step from load factor %.6g failed (%s) and the increment %.6g would fall below -load_min_increment %.6g%s%s",
    (double)lp->t, why, (double)lp->dt, (double)lp->dt_min, remedy ? "; " : "", remedy ? remedy : "");
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndLoadPathState(void *obj, IndStateFile f)
{
  IndLoadPath *lp   = (IndLoadPath *)obj;
  PetscReal    s[7] = {lp->t, lp->dt, (PetscReal)lp->accepted, (PetscReal)lp->cutbacks,
                       (PetscReal)lp->cutbacks_in_a_row, (PetscReal)lp->rejected_newton, (PetscReal)lp->rejected_linear};

  PetscFunctionBeginUser;
  PetscCall(IndStateReals(f, "position", 7, s));
  lp->t                 = s[0];
  lp->dt                = s[1];
  lp->accepted          = (PetscInt)s[2];
  lp->cutbacks          = (PetscInt)s[3];
  lp->cutbacks_in_a_row = (PetscInt)s[4];
  lp->rejected_newton   = (PetscInt)s[5];
  lp->rejected_linear   = (PetscInt)s[6];
  PetscFunctionReturn(PETSC_SUCCESS);
}
