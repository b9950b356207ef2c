#pragma once
/* When the multigrid of the Newton iterations is built again (src/solvers/pcreuse.c).

   A multigrid set up for one Jacobian still preconditions the next ones (its finest smoother set up on the
   current matrix, its coarse levels the old one's): the linear solves take a few more Krylov iterations, and a
   set-up is saved. A set-up costs about as much as 15 Krylov iterations (GAMG with its interpolation kept:
   16 on the README's case, 17 on the plastic cube at 824k dofs, 15 on the paper case at h_tip 6). So the
   preconditioner is kept while the Krylov iterations it costs beyond the fewest it has taken, summed over the
   solves since it was built, stay below that cost, and built again once they reach it: the rent-or-buy rule,
   whose total is never more than twice that of the best choice made in hindsight. The choice depends on
   iteration counts only, never on clocks: a run repeated gives the same answers.

   A fixed lag (every other Newton iteration, before) rebuilt where nothing had changed, and kept a preconditioner
   that had stopped fitting for as long as it had kept one that fitted. The rule also carries a preconditioner
   from one load step to the next, where most of it still fits. */
#include <petscksp.h>
#include "ind_common.h"

/* The decision's whole state, pure (unit-tested on its own). */
typedef struct {
  PetscReal cost;   /* a rebuild's cost in Krylov iterations; 0 rebuilds for every solve */
  PetscInt  fewest; /* the fewest Krylov iterations of a solve with the current preconditioner; -1: none yet */
  PetscReal excess; /* the iterations beyond fewest, summed over the solves with it */
  PetscBool force;  /* the next solve builds it (none yet, a failed solve, a restart) */
} IndRebuildCount;

void      IndRebuildCountInit(IndRebuildCount *c, PetscReal cost);
/* whether the next solve should build the preconditioner */
PetscBool IndRebuildDue(const IndRebuildCount *c);
/* a solve done: with a preconditioner just built (fresh) or kept, its iterations, whether it converged */
void      IndRebuildCountRecord(IndRebuildCount *c, PetscBool fresh, PetscInt its, PetscBool converged);

typedef struct _p_IndPCReuse *IndPCReuse;

/* Installs the rule on ksp's solves (a pre- and post-solve hook) and reads -newton_pc_rebuild_cost. With
   active false, or with a preconditioner other than a multigrid (a factorization kept would be a stale inverse),
   the rebuilds are left to SNES's lag; the finest smoother of a kept multigrid is refreshed either way. */
PetscErrorCode IndPCReuseCreate(KSP ksp, PetscBool active, IndPCReuse *r);
/* fn(ksp, ctx) on a multigrid built afresh by the rule, before the solve uses it (the multigrid is set up in the
   pre-solve hook, then handed to fn): for what must be done to a new hierarchy's matrices. */
PetscErrorCode IndPCReuseSetFreshHook(IndPCReuse r, PetscErrorCode (*fn)(KSP, void *), void *ctx);
/* fn(ksp, ctx) after every solve, under the rule or not: for what a solve leaves that the next one does not need. */
PetscErrorCode IndPCReuseSetSolvedHook(IndPCReuse r, PetscErrorCode (*fn)(KSP, void *), void *ctx);
/* The next solve builds the preconditioner (after KSPReset, a restart). */
PetscErrorCode IndPCReuseReset(IndPCReuse r);
/* Solves, and builds of the preconditioner among them, under the rule so far. */
void           IndPCReuseGetCounts(IndPCReuse r, PetscInt *solves, PetscInt *builds);
PetscErrorCode IndPCReuseDestroy(IndPCReuse *r);
