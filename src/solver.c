#include "ind_solver.h"

/* The free rows see the prescribed values, not U's, on constrained dofs: the residual of a free row
   then does not depend on constrained entries of U, so the Jacobian with those rows and columns
   replaced by the identity is its exact derivative (and -snes_test_jacobian can check it). */
static PetscErrorCode FormResidual(SNES snes, Vec U, Vec F, void *ctx)
{
  IndSolver s = (IndSolver)ctx;
  PetscInt  counts[2];

  PetscFunctionBeginUser;
  PetscCall(VecCopy(U, s->Ubc));
  PetscCall(IndBCApplySolution(s->bc, s->load_factor, s->Ubc));
  PetscCall(DMGlobalToLocal(s->dm, s->Ubc, INSERT_VALUES, s->Uloc));
  PetscCall(IndAssemblyResidual(s->assembly, s->Uloc, s->Floc));
  PetscCall(VecZeroEntries(F));
  PetscCall(DMLocalToGlobal(s->dm, s->Floc, ADD_VALUES, F));
  if (s->contact) PetscCall(IndContactResidual(s->contact, s->Ubc, F));
  PetscCall(IndBCApplyResidual(s->bc, s->load_factor, U, F));
  counts[0] = s->assembly->nfailed;
  counts[1] = s->assembly->nplastic;
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, counts, 2, MPIU_INT, MPI_SUM, PetscObjectComm((PetscObject)s->dm)));
  s->nfailed  = counts[0];
  s->nplastic = counts[1];
  /* On every rank, so that all of them leave the Newton iteration together; the load step is cut. */
  if (snes && s->nfailed) PetscCall(SNESSetFunctionDomainError(snes));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode FormJacobian(SNES snes, Vec U, Mat A, Mat P, void *ctx)
{
  IndSolver s = (IndSolver)ctx;

  PetscFunctionBeginUser;
  (void)snes;
  PetscCall(VecCopy(U, s->Ubc));
  PetscCall(IndBCApplySolution(s->bc, s->load_factor, s->Ubc));
  PetscCall(DMGlobalToLocal(s->dm, s->Ubc, INSERT_VALUES, s->Uloc));
  PetscCall(IndAssemblyJacobian(s->assembly, s->Uloc, P));
  if (s->contact) PetscCall(IndContactJacobian(s->contact, s->Ubc, P));
  PetscCall(IndBCApplyJacobian(s->bc, P));
  if (A != P) {
    PetscCall(MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY));
    PetscCall(MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Semi-smooth Newton can cycle for ever between contact states (stick, slip, open) of a few nodes,
   with the same residuals coming back every 2 to 5 iterations. Stopping after -newton_stall_its
   iterations without a new smallest residual lets the contact loop retry with a smaller rho (or the
   load step be cut) long before -snes_max_it. */
static PetscErrorCode ConvergedUnlessStalled(SNES snes, PetscInt it, PetscReal xnorm, PetscReal snorm, PetscReal fnorm, SNESConvergedReason *reason, void *ctx)
{
  IndSolver s = (IndSolver)ctx;

  PetscFunctionBeginUser;
  PetscCall(SNESConvergedDefault(snes, it, xnorm, snorm, fnorm, reason, NULL));
  if (it == 0) {
    s->fmin    = fnorm;
    s->itmin   = 0;
    s->stalled = PETSC_FALSE;
  } else if (fnorm < 0.99 * s->fmin) {
    s->fmin  = fnorm;
    s->itmin = it;
  }
  if (*reason == SNES_CONVERGED_ITERATING && s->stall_its > 0 && it - s->itmin >= s->stall_its) {
    *reason    = SNES_DIVERGED_DTOL;
    s->stalled = PETSC_TRUE;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndSolverCreate(DM dm, IndAssembly assembly, IndBC bc, IndContact contact, PetscReal depth_max, IndSolver *out)
{
  IndSolver    s;
  KSP          ksp;
  PC           pc;
  MatNullSpace rigid;

  PetscFunctionBeginUser;
  PetscCall(PetscCalloc1(1, &s));
  s->dm       = dm;
  s->assembly = assembly;
  s->bc       = bc;
  s->contact  = contact;
  PetscCall(DMCreateLocalVector(dm, &s->Uloc));
  PetscCall(DMCreateLocalVector(dm, &s->Floc));
  PetscCall(DMCreateGlobalVector(dm, &s->Ubc));
  PetscCall(PetscLogEventBegin(IndLog.preallocate, 0, 0, 0, 0));
  PetscCall(IndAssemblyCreateMatrix(assembly, &s->J));
  PetscCall(PetscLogEventEnd(IndLog.preallocate, 0, 0, 0, 0));
  PetscCall(PetscLogEventBegin(IndLog.near_null, 0, 0, 0, 0));
  {
    /* Our own node positions: DMPlexCreateRigidBody projects through a path that took 8.4 s of a
       12.4 s setup at 64k cells in PETSc 3.18. */
    Vec      nodes, blocked;
    PetscInt n;
    PetscCall(IndDiscNodeCoordinates(assembly->disc, &nodes));
    PetscCall(VecGetLocalSize(nodes, &n));
    PetscCall(VecCreateMPI(PetscObjectComm((PetscObject)dm), n, PETSC_DETERMINE, &blocked));
    PetscCall(VecSetBlockSize(blocked, 3));
    PetscCall(VecCopy(nodes, blocked));
    PetscCall(MatNullSpaceCreateRigidBody(blocked, &rigid));
    PetscCall(MatSetNearNullSpace(s->J, rigid));
    PetscCall(MatNullSpaceDestroy(&rigid));
    PetscCall(VecDestroy(&blocked));
    PetscCall(VecDestroy(&nodes));
  }
  PetscCall(PetscLogEventEnd(IndLog.near_null, 0, 0, 0, 0));

  PetscCall(SNESCreate(PetscObjectComm((PetscObject)dm), &s->snes));
  PetscCall(SNESSetFunction(s->snes, NULL, FormResidual, s));
  PetscCall(SNESSetJacobian(s->snes, s->J, s->J, FormJacobian, s));
  PetscCall(SNESGetKSP(s->snes, &ksp));
  /* The frictional part of the augmented contact Jacobian is not symmetric. */
  PetscCall(KSPSetType(ksp, contact && contact->variant == IND_UZAWA_AUGMENTED && contact->mu > 0 ? KSPGMRES : KSPCG));
  /* Tighter than Newton's own 1e-8 so a linear step converges in one Newton iteration. */
  PetscCall(KSPSetTolerances(ksp, 1e-10, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PCSetType(pc, PCGAMG));
  /* The graph and prolongator of GAMG dominate its setup; the mesh does not change between Newton
     iterations, so they are built once (-pc_gamg_reuse_interpolation 0 to rebuild). */
  PetscCall(PCGAMGSetReuseInterpolation(pc, PETSC_TRUE));
  /* With the interpolation, GAMG would also keep the eigenvalue estimate of its first (elastic)
     setup for the Chebyshev smoothers; once points yield that estimate no longer fits and CG saw an
     indefinite preconditioner in 7 of 13 steps of inputs/plastic_block.opts. Smoothers that estimate
     their own at each setup: no failure, and still 30% faster than rebuilding the interpolation. */
  PetscCall(PCGAMGSetUseSAEstEig(pc, PETSC_FALSE));
  if (contact) {
    /* Full semi-smooth Newton steps: a backtracking line search crawls in steps of 0.1 when a node
       leaves the contact (the residual's kink), e.g. 149 iterations for the last unloading step of
       an elastic sphere where full steps take 11. */
    SNESLineSearch ls;
    PetscCall(SNESGetLineSearch(s->snes, &ls));
    PetscCall(SNESLineSearchSetType(ls, SNESLINESEARCHBASIC));
  }
  s->stall_its = 10;
  PetscOptionsBegin(PetscObjectComm((PetscObject)dm), NULL, "Newton", "Solver");
  PetscCall(PetscOptionsInt("-newton_stall_its", "Newton fails after this many iterations without a 1% smaller residual (0: never)", "", s->stall_its, &s->stall_its, NULL));
  PetscOptionsEnd();
  PetscCheck(s->stall_its >= 0, PetscObjectComm((PetscObject)dm), PETSC_ERR_ARG_OUTOFRANGE, "-newton_stall_its must be >= 0, got %" PetscInt_FMT, s->stall_its);
  PetscCall(SNESSetConvergenceTest(s->snes, ConvergedUnlessStalled, s, NULL));
  PetscCall(SNESSetFromOptions(s->snes));
  if (contact) {
    /* rho from the stiffness of the undeformed body, before any condition touches its diagonal */
    PetscCall(VecZeroEntries(s->Uloc));
    PetscCall(IndAssemblyJacobian(assembly, s->Uloc, s->J));
    PetscCall(IndContactSetUp(contact, s->J, depth_max));
  }
  *out = s;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndSolverSolve(IndSolver s, PetscReal load_factor, Vec U, IndSolveResult *r)
{
  IndContact c           = s->contact;
  PetscReal  last_change = PETSC_MAX_REAL, last_load = 0, atol = 0, rtol = 0, stol = 0;
  PetscInt   maxit = 0, maxf = 0;
  PetscBool  augmented = c && c->variant == IND_UZAWA_AUGMENTED ? PETSC_TRUE : PETSC_FALSE;
  Vec        Usave = NULL;
  /* rho grows once the reactions change by less than grow_below; grown_at is the change at the last
     growth (0: the last outer iteration did not grow rho) */
  PetscReal  grow_below = 1e-2, grown_at = 0;
  PetscBool  solved_once = PETSC_FALSE, first_failed = PETSC_FALSE;
  PetscBool  rho_changed = PETSC_TRUE; /* rho differs from the last successful outer iteration's */
  /* rho is lowered (after a failed Newton solve or a cycle) no further than rho_min / 100 */
  const PetscReal rho_floor = c ? 1e-2 * c->rho_min * (1 + 1e-12) : 0;

  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(r, sizeof(*r)));
  s->load_factor = load_factor;
  PetscCall(IndBCSetUp(s->bc));
  /* Starting on the prescribed values makes the Newton correction vanish on constrained rows, which
     is what zeroing their columns in the Jacobian assumes. */
  PetscCall(IndBCApplySolution(s->bc, load_factor, U));
  if (c) {
    /* Later outer iterations start from small residuals (the multipliers barely move), and a
       tolerance relative to those alone would ask Newton for round-off, where the projection's kinks
       make it cycle. Their floor is 1e-3 rtol times the step's first residual. */
    Vec       F;
    PetscReal fnorm;
    PetscCall(SNESGetTolerances(s->snes, &atol, &rtol, &stol, &maxit, &maxf));
    PetscCall(DMGetGlobalVector(s->dm, &F));
    PetscCall(FormResidual(NULL, U, F, s));
    PetscCall(VecNorm(F, NORM_2, &fnorm));
    PetscCall(DMRestoreGlobalVector(s->dm, &F));
    PetscCall(SNESSetTolerances(s->snes, PetscMax(atol, 1e-3 * rtol * fnorm), rtol, stol, maxit, maxf));
  }
  if (augmented) {
    c->rho_scale = c->rho_start;
    PetscCall(DMGetGlobalVector(s->dm, &Usave));
  }
  for (PetscInt k = 1; k <= (c ? c->max_outer : 1); ++k) {
    PetscInt its, lits;
    if (augmented) {
      PetscCall(VecCopy(U, Usave));
      PetscCall(IndContactSaveReactions(c));
    }
    PetscCall(SNESSolve(s->snes, NULL, U));
    PetscCall(SNESGetConvergedReason(s->snes, &r->reason));
    PetscCall(SNESGetIterationNumber(s->snes, &its));
    PetscCall(SNESGetLinearSolveIterations(s->snes, &lits));
    r->newton += its;
    r->linear += lits;
    r->outer = k;
    if (r->reason <= 0 && r->reason != SNES_DIVERGED_FUNCTION_DOMAIN && augmented && c->rho_scale > rho_floor) {
      /* Newton failed at a rho too large for it here: redo this outer iteration from its start
         with rho ten times smaller (down to rho_min / 100, where the augmented loop is close to the
         fixed point's robust one). */
      PetscCall(VecCopy(Usave, U));
      PetscCall(IndContactRestoreReactions(c));
      c->rho_scale *= 0.1;
      if (!solved_once) first_failed = PETSC_TRUE;
      /* Growing at this change was too early: without a tighter threshold rho grew straight back and
         Newton stalled again, every other outer iteration (Berkovich unloading: 3 to 5 times a step,
         10 to 18 Newton iterations each). */
      if (grown_at > 0) grow_below = PetscMin(grow_below, 0.1 * grown_at);
      grown_at    = 0;
      rho_changed = PETSC_TRUE;
      if (c->monitor) PetscCall(PetscPrintf(c->comm, "    uzawa %2" PetscInt_FMT ": newton %2" PetscInt_FMT " failed (%s), retried with rho scale %g\n", k, its, s->stalled ? "stalled" : SNESConvergedReasons[r->reason], (double)c->rho_scale));
      continue;
    }
    if (r->reason <= 0) {
      if (c) PetscCall(SNESSetTolerances(s->snes, atol, rtol, stol, maxit, maxf));
      if (Usave) PetscCall(DMRestoreGlobalVector(s->dm, &Usave));
      if (r->reason == SNES_DIVERGED_FUNCTION_DOMAIN) PetscCall(PetscSNPrintf(r->why, sizeof(r->why), "return map failed at %" PetscInt_FMT " quadrature points", s->nfailed));
      else if (s->stalled) PetscCall(PetscSNPrintf(r->why, sizeof(r->why), "Newton stalled: no smaller residual in %" PetscInt_FMT " iterations (-newton_stall_its)%s", s->stall_its, c ? " in the contact loop" : ""));
      else PetscCall(PetscSNPrintf(r->why, sizeof(r->why), "Newton: %s after %" PetscInt_FMT " iterations%s", SNESConvergedReasons[r->reason], its, c ? " in the contact loop" : ""));
      PetscFunctionReturn(PETSC_SUCCESS);
    }
    if (!c) {
      r->converged = PETSC_TRUE;
      PetscFunctionReturn(PETSC_SUCCESS);
    }
    if (augmented && !solved_once) {
      /* Steps alike follow one another (the top of an unloading curve: each first Newton solve
         stalled at rho_min, 13 wasted iterations a step), so the next step starts where this one's
         first solve succeeded, and back up tenfold (to rho_min) after a step that needed no retry. */
      c->rho_start = first_failed ? c->rho_scale : PetscMin(c->rho_min, 10.0 * c->rho_start);
      solved_once  = PETSC_TRUE;
    }
    PetscCall(IndContactUpdate(c, U, &r->contact));
    if (c->monitor)
      PetscCall(PetscPrintf(c->comm, "    uzawa %2" PetscInt_FMT ": newton %2" PetscInt_FMT "  contact %5" PetscInt_FMT " (stick %5" PetscInt_FMT ", slip %5" PetscInt_FMT ")  load %.6e uN  penetration %.3e nm  reaction change %.3e  rho scale %g\n", k, its, r->contact.contact, r->contact.stick, r->contact.slip,
                            (double)(r->contact.load * 1e-3), (double)r->contact.penetration, (double)r->contact.change, (double)c->rho_scale));
    if (r->contact.change <= c->rtol && r->contact.penetration <= c->pen_atol) {
      r->converged = PETSC_TRUE;
      PetscCall(SNESSetTolerances(s->snes, atol, rtol, stol, maxit, maxf));
      if (Usave) PetscCall(DMRestoreGlobalVector(s->dm, &Usave));
      PetscFunctionReturn(PETSC_SUCCESS);
    }
    grown_at = 0;
    if (augmented && !rho_changed && r->contact.change > 0.99 * last_change && PetscAbsReal(r->contact.load - last_load) < 0.1 * r->contact.change * PetscAbsReal(r->contact.load) &&
        c->rho_scale > rho_floor) {
      /* The reactions change as much as last time at an unchanged rho, yet their sum stays put: the
         outer loop cycles (a node flipping in and out of the contact; at rho 100 on the h_tip 10
         paper case, a 2-cycle at a change of 2.3e-5 with the load fixed to 7 digits, until the
         50-iteration limit cut the step). A smaller rho damps the flip. A constant change with a
         falling load is progress instead: a last reaction decaying geometrically as the contact
         opens, which a smaller rho would only slow down. */
      c->rho_scale *= 0.1;
      grow_below  = PetscMin(grow_below, 0.1 * r->contact.change);
      rho_changed = PETSC_TRUE;
      if (c->monitor) PetscCall(PetscPrintf(c->comm, "    uzawa: reaction change stagnates, rho scale lowered to %g\n", (double)c->rho_scale));
    } else if (augmented && r->contact.change < grow_below && c->rho_scale < c->rho_max) {
      /* Once the contact state has settled (reactions within 1% of the last), Newton copes with a
         larger rho, which speeds up the remaining outer iterations; before, a larger rho mostly
         made Newton stall (Berkovich unloading: at every step). */
      c->rho_scale = PetscMin(c->rho_max, 10.0 * c->rho_scale);
      grown_at     = PetscMax(r->contact.change, PETSC_SMALL);
      rho_changed  = PETSC_TRUE;
    } else rho_changed = PETSC_FALSE;
    /* A growing change means rho is past the fixed point's stability limit: halve it, for good. */
    if (c->variant == IND_UZAWA_FIXED_POINT && r->contact.change > last_change) {
      c->rho_scale *= 0.5;
      if (c->monitor) PetscCall(PetscPrintf(c->comm, "    uzawa: reaction change grew, rho halved (scale now %g)\n", (double)c->rho_scale));
    }
    last_change = r->contact.change;
    last_load   = r->contact.load;
  }
  if (Usave) PetscCall(DMRestoreGlobalVector(s->dm, &Usave));
  PetscCall(SNESSetTolerances(s->snes, atol, rtol, stol, maxit, maxf));
  PetscCall(PetscSNPrintf(r->why, sizeof(r->why), "contact loop: %" PetscInt_FMT " outer iterations, reaction change %.2e (-contact_uzawa_rtol %.1e), penetration %.2e nm (limit %.2e)", c->max_outer, (double)r->contact.change, (double)c->rtol, (double)r->contact.penetration, (double)c->pen_atol));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndSolverPredict(IndSolver s, PetscReal t_old, PetscReal t_new, Vec U)
{
  KSP                ksp;
  Vec                G, r, du;
  KSPConvergedReason reason;

  PetscFunctionBeginUser;
  PetscCall(IndBCSetUp(s->bc));
  PetscCall(DMGetGlobalVector(s->dm, &G));
  PetscCall(DMGetGlobalVector(s->dm, &r));
  PetscCall(DMGetGlobalVector(s->dm, &du));
  /* The tangent at the accepted state, before the boundary conditions zero its constrained columns:
     those columns times the increment of the prescribed values are the linearised load. */
  s->load_factor = t_old;
  PetscCall(VecCopy(U, s->Ubc));
  PetscCall(IndBCApplySolution(s->bc, t_old, s->Ubc));
  PetscCall(DMGlobalToLocal(s->dm, s->Ubc, INSERT_VALUES, s->Uloc));
  PetscCall(IndAssemblyJacobian(s->assembly, s->Uloc, s->J));
  PetscCall(VecZeroEntries(G));
  PetscCall(IndBCApplySolution(s->bc, t_new - t_old, G));
  PetscCall(MatMult(s->J, G, r));
  PetscCall(IndBCApplyJacobian(s->bc, s->J));
  PetscCall(IndBCApplySolution(s->bc, 0.0, r));
  PetscCall(VecScale(r, -1.0));
  PetscCall(SNESGetKSP(s->snes, &ksp));
  PetscCall(KSPSetOperators(ksp, s->J, s->J));
  PetscCall(KSPSolve(ksp, r, du));
  PetscCall(KSPGetConvergedReason(ksp, &reason));
  /* A failed predictor only costs Newton iterations: fall back to the prescribed values alone. */
  if (reason > 0) PetscCall(VecAXPY(U, 1.0, du));
  PetscCall(VecAXPY(U, 1.0, G));
  PetscCall(DMRestoreGlobalVector(s->dm, &G));
  PetscCall(DMRestoreGlobalVector(s->dm, &r));
  PetscCall(DMRestoreGlobalVector(s->dm, &du));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndSolverEvaluate(IndSolver s, Vec U)
{
  Vec F;

  PetscFunctionBeginUser;
  PetscCall(DMGetGlobalVector(s->dm, &F));
  PetscCall(FormResidual(NULL, U, F, s));
  PetscCall(DMRestoreGlobalVector(s->dm, &F));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndSolverDestroy(IndSolver *s)
{
  PetscFunctionBeginUser;
  if (!*s) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(SNESDestroy(&(*s)->snes));
  PetscCall(MatDestroy(&(*s)->J));
  PetscCall(VecDestroy(&(*s)->Uloc));
  PetscCall(VecDestroy(&(*s)->Floc));
  PetscCall(VecDestroy(&(*s)->Ubc));
  PetscCall(PetscFree(*s));
  PetscFunctionReturn(PETSC_SUCCESS);
}
