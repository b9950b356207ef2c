#include "contact_impl.h"

/* The paper's Uzawa loop (doc/theory.md section 2.4): the reactions are frozen during each Newton solve, a
   load on the contact nodes, and updated between solves by the bi-potential predictor-corrector. The
   Jacobian is the body's alone, symmetric. */

static PetscErrorCode Residual(IndContact c, Vec U, Vec F)
{
  PetscScalar *f;

  PetscFunctionBeginUser;
  (void)U;
  PetscCall(VecGetArray(F, &f));
  for (PetscInt i = 0; i < c->n; ++i)
    for (int d = 0; d < 3; ++d) f[c->row[i] + d] -= c->R[3 * i + d];
  PetscCall(VecRestoreArray(F, &f));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A growing change means rho is past the fixed point's stability limit: halve it, for good. */
static PetscErrorCode AfterOuter(IndContact c, PetscInt its, const IndContactSummary *r, PetscBool *stuck,
                                 char why[], size_t len)
{
  PetscFunctionBeginUser;
  (void)its, (void)why, (void)len;
  *stuck = PETSC_FALSE;
  if (r->change > c->last_change) {
    c->rho_scale *= 0.5;
    if (c->monitor) PetscCall(PetscPrintf(c->comm, "    outer: reaction change grew, rho halved (scale now %g)\n",
      (double)c->rho_scale));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndContactCreate_FixedPoint(IndContact c)
{
  PetscFunctionBeginUser;
  c->ops.residual    = Residual;
  c->ops.after_outer = AfterOuter;
  /* The fixed point diverges once rho exceeds 2 / (largest eigenvalue of the contact compliance), about the
     stiffness diagonal. */
  c->rho_scale = 0.3;
  c->max_outer = 200;
  PetscFunctionReturn(PETSC_SUCCESS);
}
