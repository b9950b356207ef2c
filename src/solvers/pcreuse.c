#include "pcreuse.h"
#include "ind_solver.h"
#include "ind_options.h"

void IndRebuildCountInit(IndRebuildCount *c, PetscReal cost)
{
  c->cost   = cost;
  c->fewest = -1;
  c->excess = 0;
  c->force  = PETSC_TRUE;
}

PetscBool IndRebuildDue(const IndRebuildCount *c)
{
  return (PetscBool)(c->force || c->excess >= c->cost);
}

/* The fewest iterations any solve with this preconditioner took is what it can do: a first solve of a hard
   right-hand side does not set the bar high for the later ones. */
void IndRebuildCountRecord(IndRebuildCount *c, PetscBool fresh, PetscInt its, PetscBool converged)
{
  if (fresh) {
    c->fewest = its;
    c->excess = 0;
  } else {
    if (its > c->fewest) c->excess += (PetscReal)(its - c->fewest);
    else c->fewest = its;
  }
  c->force = converged ? PETSC_FALSE : PETSC_TRUE;
}

struct _p_IndPCReuse {
  KSP              ksp;
  PetscBool        active;
  IndRebuildCount  count;
  PetscBool        governed, fresh; /* of the solve under way */
  PetscInt         solves, builds;
  PetscErrorCode (*fresh_hook)(KSP, void *); /* IndPCReuseSetFreshHook */
  void            *fresh_ctx;
  PetscErrorCode (*solved_hook)(KSP, void *); /* IndPCReuseSetSolvedHook */
  void            *solved_ctx;
};

static PetscErrorCode IsMultigrid(KSP ksp, PetscBool *mg)
{
  PC pc;

  PetscFunctionBeginUser;
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PetscObjectTypeCompareAny((PetscObject)pc, mg, PCMG, PCGAMG, ""));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode PreSolve(KSP ksp, Vec b, Vec x, void *ctx)
{
  IndPCReuse r = (IndPCReuse)ctx;
  PetscBool  mg;

  PetscFunctionBeginUser;
  (void)b, (void)x;
  PetscCall(IsMultigrid(ksp, &mg));
  r->governed = (PetscBool)(r->active && mg);
  if (!r->governed) PetscFunctionReturn(PETSC_SUCCESS);
  r->fresh = IndRebuildDue(&r->count);
  r->solves++;
  if (r->fresh) r->builds++;
  PetscCall(KSPSetReusePreconditioner(ksp, (PetscBool)!r->fresh));
  /* A multigrid kept on a matrix assembled again in place smooths with the old matrix's Jacobi diagonal and
     Chebyshev bounds, a smoother for another operator (IndSolverRefreshFineSmoother). */
  if (!r->fresh) PetscCall(IndSolverRefreshFineSmoother(ksp));
  if (r->fresh && r->fresh_hook) { /* KSPSolve's own set-up then finds it done */
    PetscCall(KSPSetUp(ksp));
    PetscCall(r->fresh_hook(ksp, r->fresh_ctx));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode PostSolve(KSP ksp, Vec b, Vec x, void *ctx)
{
  IndPCReuse         r = (IndPCReuse)ctx;
  KSPConvergedReason reason;
  PetscInt           its;

  PetscFunctionBeginUser;
  (void)b, (void)x;
  if (r->governed) {
    PetscCall(KSPGetIterationNumber(ksp, &its));
    PetscCall(KSPGetConvergedReason(ksp, &reason));
    IndRebuildCountRecord(&r->count, r->fresh, its, (PetscBool)(reason > 0));
  }
  if (r->solved_hook) PetscCall(r->solved_hook(ksp, r->solved_ctx));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndPCReuseCreate(KSP ksp, PetscBool active, IndPCReuse *out)
{
  IndPCReuse r;
  PetscReal  cost = 15;

  PetscFunctionBeginUser;
  PetscOptionsBegin(PetscObjectComm((PetscObject)ksp), NULL, IND_TITLE "Newton's preconditioner", "Solver");
  PetscCall(IndOptionsReal("-newton_pc_rebuild_cost",
    "Multigrid rebuilt once the Krylov iterations it costs beyond its best sum to this (0: every solve)", "",
                           "15", cost, &cost, NULL));
  PetscOptionsEnd();
  PetscCheck(cost >= 0, PetscObjectComm((PetscObject)ksp), PETSC_ERR_ARG_OUTOFRANGE,
    "-newton_pc_rebuild_cost must be >= 0, got %g", (double)cost);
  PetscCall(PetscCalloc1(1, &r));
  r->ksp    = ksp;
  r->active = active;
  IndRebuildCountInit(&r->count, cost);
  PetscCall(KSPSetPreSolve(ksp, PreSolve, r));
  PetscCall(KSPSetPostSolve(ksp, PostSolve, r));
  *out = r;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndPCReuseSetFreshHook(IndPCReuse r, PetscErrorCode (*fn)(KSP, void *), void *ctx)
{
  PetscFunctionBeginUser;
  r->fresh_hook = fn;
  r->fresh_ctx  = ctx;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndPCReuseSetSolvedHook(IndPCReuse r, PetscErrorCode (*fn)(KSP, void *), void *ctx)
{
  PetscFunctionBeginUser;
  r->solved_hook = fn;
  r->solved_ctx  = ctx;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndPCReuseReset(IndPCReuse r)
{
  PetscFunctionBeginUser;
  IndRebuildCountInit(&r->count, r->count.cost);
  PetscFunctionReturn(PETSC_SUCCESS);
}

void IndPCReuseGetCounts(IndPCReuse r, PetscInt *solves, PetscInt *builds)
{
  if (solves) *solves = r->solves;
  if (builds) *builds = r->builds;
}

PetscErrorCode IndPCReuseDestroy(IndPCReuse *r)
{
  PetscFunctionBeginUser;
  if (!*r) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(KSPSetPreSolve((*r)->ksp, NULL, NULL));
  PetscCall(KSPSetPostSolve((*r)->ksp, NULL, NULL));
  PetscCall(PetscFree(*r));
  PetscFunctionReturn(PETSC_SUCCESS);
}
