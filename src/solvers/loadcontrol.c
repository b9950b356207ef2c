#include "ind_loadcontrol.h"

struct _p_IndLoadControl {
  PetscReal load_last;  /* the load of the last accepted step, uN */
  PetscReal slope_last; /* its dP/dh, uN/nm (0: unknown) */
};

PetscErrorCode IndLoadControlCreate(IndLoadControl *out)
{
  PetscFunctionBeginUser;
  PetscCall(PetscNew(out));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndLoadControlDestroy(IndLoadControl *lc)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFree(*lc));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscReal IndLoadControlStartDepth(IndLoadControl lc, const IndLoadPath *lp, PetscReal lambda, PetscReal target,
                                   PetscReal d_c, PetscBool sliding)
{
  PetscReal d0 = d_c;
  if (!sliding) {
    if (lc->slope_last > 0) d0 = d_c + (target - lc->load_last) / lc->slope_last;
    else if (lp->accepted == 0) d0 = lp->depth_max * lambda;
  }
  return PetscMin(PetscMax(d0, 0.0), lp->depth_max);
}

void IndLoadControlAccept(IndLoadControl lc, PetscReal load, PetscReal dd)
{
  if (dd != 0 && (load - lc->load_last) / dd > 0) lc->slope_last = (load - lc->load_last) / dd;
  lc->load_last = load;
}

PetscErrorCode IndLoadControlState(void *obj, IndStateFile f)
{
  IndLoadControl lc   = (IndLoadControl)obj;
  PetscReal      s[2] = {lc->load_last, lc->slope_last};

  PetscFunctionBeginUser;
  PetscCall(IndStateReals(f, "last", 2, s));
  lc->load_last  = s[0];
  lc->slope_last = s[1];
  PetscFunctionReturn(PETSC_SUCCESS);
}
