#include "contact_impl.h"

/* The couplings of the contact with the Newton solve, by name (as PETSc's KSPRegister, ind_registry.h): a new
   one is a file with its create function and an entry in IndContactCouplingRegistry. */
PetscErrorCode IndContactCreate_FixedPoint(IndContact);
PetscErrorCode IndContactCreate_Newton(IndContact);

IndRegistry IndContactCouplingRegistry = {
  .builtin = (const IndRegistryEntry[]){{"fixed_point", (IndRegistryFn)IndContactCreate_FixedPoint},
                                        {"newton", (IndRegistryFn)IndContactCreate_Newton},
                                        {NULL, NULL}}
};

PetscErrorCode IndContactSetCoupling(IndContact c, const char name[])
{
  IndRegistryFn fn;
  PetscErrorCode (*create)(IndContact);

  PetscFunctionBeginUser;
  PetscCall(IndRegistryGet(&IndContactCouplingRegistry, c->comm, "-contact_uzawa", name, &fn));
  create = (PetscErrorCode(*)(IndContact))fn;
  PetscCall(PetscMemzero(&c->ops, sizeof(c->ops)));
  PetscCall((*create)(c));
  PetscFunctionReturn(PETSC_SUCCESS);
}

IND_GETTER(PetscBool, IndContactJacobianIsSymmetric, IndContact, o->ops.jacobian ? PETSC_FALSE : PETSC_TRUE)
IND_GETTER(PetscBool, IndContactReactionsFromResidual, IndContact, o->ops.residual_multipliers)
IND_GETTER(PetscInt, IndContactOuterMax, IndContact, o->max_outer)

PetscErrorCode IndContactOuterConverged(IndContact c, PetscInt k, PetscInt its, PetscReal atol,
                                        const IndContactSummary *r, PetscBool *converged)
{
  PetscFunctionBeginUser;
  if (c->monitor)
    PetscCall(PetscPrintf(c->comm,
      "    outer %2" PetscInt_FMT ": newton %2" PetscInt_FMT "  contact %5" PetscInt_FMT " (stick %5" PetscInt_FMT
      ", slip %5" PetscInt_FMT ")  load %.6e uN  penetration %.3e nm  reaction change %.3e  rho scale %g\n", k, its,
      r->contact, r->stick, r->slip, (double)(r->load * 1e-3), (double)r->penetration, (double)r->change,
      (double)c->rho_scale));
  /* With reactions from the residual, the change is the complementarity residual, part of the residual Newton
     has just driven below its tolerance; relative to a vanishing reaction (the last node leaving the contact) it
     could never be small, so Newton's absolute tolerance also accepts it. */
  *converged = (r->change <= c->rtol || (c->ops.residual_multipliers && r->mismatch <= atol))
    && r->penetration <= c->pen_atol ? PETSC_TRUE : PETSC_FALSE;
  if (k == 1) c->last_change = PETSC_MAX_REAL;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndContactOuterNext(IndContact c, PetscInt its, const IndContactSummary *r, PetscBool *stuck,
                                   char why[], size_t len)
{
  PetscFunctionBeginUser;
  *stuck = PETSC_FALSE;
  if (c->ops.after_outer) PetscCall(c->ops.after_outer(c, its, r, stuck, why, len));
  c->last_change = r->change;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndContactOuterFailure(IndContact c, const IndContactSummary *r, char why[], size_t len)
{
  PetscFunctionBeginUser;
  PetscCall(PetscSNPrintf(why, len,
    "contact loop: %" PetscInt_FMT " outer iterations, reaction change %.2e (-contact_uzawa_rtol %.1e), "
    "penetration %.2e nm (limit %.2e)", c->max_outer, (double)r->change, (double)c->rtol, (double)r->penetration,
    (double)c->pen_atol));
  PetscFunctionReturn(PETSC_SUCCESS);
}
