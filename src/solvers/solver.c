#include "solver_impl.h"
#include "ind_solver.h"
#include "ind_options.h"
#include "bordered.h"
#include "heldlu.h"
#include "linesearch.h"
#include "pcreuse.h"
#include "ind_blockmult.h"
#include "ind_galerkin.h"

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
  if (s->border) PetscCall(IndBorderedResidual(s->border));
  PetscCall(IndBCApplyResidual(s->bc, s->load_factor, U, F));
  IndAssemblyGetPointCounts(s->assembly, &counts[0], &counts[1]);
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, counts, 2, MPIU_INT, MPI_SUM, PetscObjectComm((PetscObject)s->dm)));
  s->nfailed  = counts[0];
  s->nplastic = counts[1];
  /* On every rank, so that all of them leave the Newton iteration together; the load step is cut. */
  if (snes && s->nfailed) PetscCall(SNESSetFunctionDomainError(snes));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The semi-smooth Newton contact's multipliers are the residual at the displacement: evaluates it
   at U unless the last residual was there already. Newton's own iteration evaluates the residual at
   U just before the Jacobian; a Jacobian test, or the end of a line search, may not have. */
static PetscErrorCode RefreshMultipliers(IndSolver s, Vec U)
{
  PetscBool current;
  Vec       F;

  PetscFunctionBeginUser;
  if (!s->contact || !IndContactReactionsFromResidual(s->contact)) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(VecCopy(U, s->Ubc));
  PetscCall(IndBCApplySolution(s->bc, s->load_factor, s->Ubc));
  PetscCall(IndContactMultipliersCurrent(s->contact, s->Ubc, &current));
  if (current) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(DMGetGlobalVector(s->dm, &F));
  PetscCall(FormResidual(NULL, U, F, s));
  PetscCall(DMRestoreGlobalVector(s->dm, &F));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The levels of ksp's multigrid preconditioner; 0 for another preconditioner, or a multigrid not set up yet. */
static PetscErrorCode MultigridLevels(KSP ksp, PC *pc, PetscInt *levels)
{
  PetscBool mg;

  PetscFunctionBeginUser;
  *levels = 0;
  PetscCall(KSPGetPC(ksp, pc));
  PetscCall(PetscObjectTypeCompareAny((PetscObject)*pc, &mg, PCMG, PCGAMG, ""));
  if (mg) PetscCall(PCMGGetLevels(*pc, levels));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* On the Newton iterations that keep the preconditioner (src/solvers/pcreuse.h, or SNES's lag), the
   multigrid keeps its coarse levels, but its finest level smooths with the matrix just assembled in
   place, with the Jacobi diagonal and Chebyshev bounds of the old one: a smoother for another
   operator, which can amplify what it should damp. On a plastic cube at 824k dofs the first lagged
   solve took 97 Krylov iterations instead of 15. Setting the finest smoother's operators again makes
   it set itself up on the new matrix at its next use (its diagonal and eigenvalue estimate, about
   ten products; the same solve then takes 20). When the preconditioner is rebuilt instead, the
   multigrid sets them again itself, and the smoother still sets up once. */
PetscErrorCode IndSolverRefreshFineSmoother(KSP ksp)
{
  PetscInt levels;
  KSP      smoother;
  PC       pc;
  Mat      A, P;

  PetscFunctionBeginUser;
  PetscCall(MultigridLevels(ksp, &pc, &levels));
  if (levels < 1) PetscFunctionReturn(PETSC_SUCCESS); /* not set up yet: it will be, on this matrix */
  PetscCall(PCMGGetSmoother(pc, levels - 1, &smoother));
  PetscCall(KSPGetOperators(smoother, &A, &P));
  PetscCall(KSPSetOperators(smoother, A, P));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Each Chebyshev smoother estimates its largest eigenvalue with a few GMRES iterations when its operator changes (at
   every Newton iteration on the finest level), and GMRES then keeps their basis until the next estimate, under the
   outer solve's basis and the residual's kept decomposition: sphere_800k on 1 rank held 2,311 MB of PETSc's
   allocations at its largest, 2,200 with these bases given back. Every smoother's estimate is done once its
   multigrid has been applied (the finest one's at its first use), so the outer solve gives them back at its first
   iteration. */
static PetscErrorCode ReleaseSmootherEstimators(KSP ksp, PetscInt it, PetscReal rnorm, void *ctx)
{
  PetscInt levels;
  PC       pc;

  PetscFunctionBeginUser;
  (void)rnorm, (void)ctx;
  if (it) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(MultigridLevels(ksp, &pc, &levels));
  for (PetscInt l = 1; l < levels; ++l) {
    KSP smoother, est;
    PetscCall(PCMGGetSmoother(pc, l, &smoother));
    PetscCall(KSPChebyshevEstEigGetKSP(smoother, &est));
    if (est) PetscCall(IndSolverReleaseKrylovBasis(est));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* After each linear solve, its Krylov basis is given back: the line search's residuals that follow keep their points'
   decomposition of C for the next Jacobian (src/physics/assembly.c), and with the basis of a long solve under them
   sphere_800k peaked there (1 rank: 2,200 MB of PETSc's allocations at the largest, 2,129 with the basis given
   back). Once per load step, before, the basis of the step's longest solve stayed under all its residuals. Each
   solve grows it again, ten vectors at a time. Not when the user asked for the solve's eigenvalues or singular values
   (-ksp_view_eigenvalues ...): PETSc reads them from GMRES's Hessenberg matrix after this hook, and the release
   frees that with the vectors. */
static PetscErrorCode SolveDone(KSP ksp, void *ctx)
{
  PetscBool ev, sv;

  PetscFunctionBeginUser;
  (void)ctx;
  PetscCall(KSPGetComputeEigenvalues(ksp, &ev));
  PetscCall(KSPGetComputeSingularValues(ksp, &sv));
  if (!ev && !sv) PetscCall(IndSolverReleaseKrylovBasis(ksp));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* GAMG's coarse operators are AIJ matrices whose rows come in groups of 6 with one column pattern (a block of
   rigid-body modes per aggregate), so PETSc multiplies them with its inode kernel, which on the machines measured
   was 1.4 to 2.4 times slower than the plain row-by-row product (doc/performance.md). The coarse levels cost a
   third of a V-cycle on the README's case. The option set after GAMG made a matrix holds for the numeric
   products that refresh it (MAT_REUSE_MATRIX) until the hierarchy is built anew. Their blocks (6 x 6, and 3 x 6 in
   the interpolations) are read faster still by block rows, as the Jacobian's 3 x 3 ones (IndBlockMultInstall).
   In single precision the products with the operators read about half the bytes; only the preconditioner sees
   them, and the Krylov method's products with the Jacobian stay in double, so each solve meets its tolerance as
   before. */
PetscErrorCode IndSolverMultigridRowProducts(KSP ksp, PetscBool blocks, Mat single)
{
  PC       pc;
  PetscInt levels;

  PetscFunctionBeginUser;
  PetscCall(MultigridLevels(ksp, &pc, &levels));
  /* not the coarsest: its direct solver factors with the inode layout it was set up with */
  for (PetscInt l = 1; l < levels; ++l) {
    KSP       smoother;
    Mat       M[3];
    PetscBool aij, set, finest = (PetscBool)(l == levels - 1);
    PetscCall(PCMGGetSmoother(pc, l, &smoother));
    PetscCall(KSPGetOperatorsSet(smoother, &set, NULL));
    if (!set) continue; /* a level not set up (yet, or since KSPReset) */
    PetscCall(KSPGetOperators(smoother, &M[0], &M[1]));
    PetscCall(PCMGGetInterpolation(pc, l, &M[2]));
    if (finest && single) {
      Mat of;
      PetscCall(MatShellGetContext(single, &of));
      /* its residual too: with the Jacobian read once for the Krylov method and once for the residual, each cycle
         would read it in double and in single precision, more bytes than it saves (doc/performance.md) */
      if (of == M[1]) {
        if (M[0] != single) PetscCall(KSPSetOperators(smoother, single, M[1]));
        PetscCall(PCMGSetResidual(pc, l, PCMGResidualDefault, single));
      }
    }
    for (int k = 0; k < 3; ++k) {
      PetscBool installed;
      if (finest && k < 2) continue; /* the Jacobian, or its single-precision operator */
      PetscCall(PetscObjectBaseTypeCompareAny((PetscObject)M[k], &aij, MATSEQAIJ, MATMPIAIJ, ""));
      if (aij) PetscCall(MatSetOption(M[k], MAT_USE_INODES, PETSC_FALSE));
      if (aij && blocks) PetscCall(IndBlockMultInstall(M[k], &installed));
      /* not the interpolations: their copies cost 38 MiB a rank of sphere_800k on 2 ranks for under 1% of the README
         run's time (doc/performance.md) */
      if (aij && blocks) PetscCall(IndBlockMultSetSingle(M[k], (PetscBool)(single != NULL && k < 2), NULL));
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The multigrid's matrices multiplied as the Jacobian is: after each Jacobian, and on a hierarchy the rebuild rule
   builds afresh before its first solve (its hook), not only at the next Jacobian. */
static PetscErrorCode MultigridAsJacobian(KSP ksp, void *ctx)
{
  IndSolver s = (IndSolver)ctx;

  PetscFunctionBeginUser;
  PetscCall(IndSolverMultigridRowProducts(ksp, IndAssemblyJacobianBlockProducts(s->assembly), s->Jsingle));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The six rigid-body modes of the mesh's nodes, GAMG's near null space. Our own node positions:
   DMPlexCreateRigidBody projects through a path that took 8.4 s of a 12.4 s setup at 64k cells in PETSc 3.18. */
static PetscErrorCode CreateRigidBodyModes(IndSolver s, MatNullSpace *rigid)
{
  Vec      nodes, blocked;
  PetscInt n;

  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(IndLog.near_null, 0, 0, 0, 0));
  PetscCall(IndDiscNodeCoordinates(IndAssemblyGetDisc(s->assembly), &nodes));
  PetscCall(VecGetLocalSize(nodes, &n));
  PetscCall(VecCreateMPI(PetscObjectComm((PetscObject)s->dm), n, PETSC_DETERMINE, &blocked));
  PetscCall(VecSetBlockSize(blocked, 3));
  PetscCall(VecCopy(nodes, blocked));
  PetscCall(MatNullSpaceCreateRigidBody(blocked, rigid));
  PetscCall(VecDestroy(&blocked));
  PetscCall(VecDestroy(&nodes));
  PetscCall(PetscLogEventEnd(IndLog.near_null, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode AttachRigidBodyModes(IndSolver s)
{
  MatNullSpace rigid;

  PetscFunctionBeginUser;
  PetscCall(MatGetNearNullSpace(s->J, &rigid));
  if (rigid) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(CreateRigidBodyModes(s, &rigid));
  PetscCall(MatSetNearNullSpace(s->J, rigid));
  PetscCall(MatNullSpaceDestroy(&rigid));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A multigrid built afresh: GAMG builds its interpolation from the rigid-body modes at its first set-up (and after
   a reset), and reuses it at every later one; until a reset the six vectors are not needed (37 MB of the plastic
   cube's 2.52 GB at 824k dofs), unless the user had the interpolation rebuilt (-pc_gamg_reuse_interpolation 0). */
static PetscErrorCode FreshMultigrid(KSP ksp, void *ctx)
{
  IndSolver s = (IndSolver)ctx;

  PetscFunctionBeginUser;
  if (!IndAssemblyJacobianInodes(s->assembly)) PetscCall(MultigridAsJacobian(ksp, s));
  if (!s->keep_rigid) PetscCall(MatSetNearNullSpace(s->J, NULL));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode FormJacobian(SNES snes, Vec U, Mat A, Mat P, void *ctx)
{
  IndSolver s = (IndSolver)ctx;

  PetscFunctionBeginUser;
  PetscCall(RefreshMultipliers(s, U));
  PetscCall(VecCopy(U, s->Ubc));
  PetscCall(IndBCApplySolution(s->bc, s->load_factor, s->Ubc));
  PetscCall(DMGlobalToLocal(s->dm, s->Ubc, INSERT_VALUES, s->Uloc));
  PetscCall(IndAssemblyJacobian(s->assembly, s->Uloc, P));
  if (s->border) PetscCall(IndBorderedBodyJacobian(s->border, P));
  if (s->contact)
    PetscCall(IndContactJacobian(s->contact, s->Ubc, P, s->border ? IndBorderedDepthDerivative(s->border) : NULL));
  PetscCall(IndBCApplyJacobian(s->bc, P));
  if (s->border) { /* constrained rows do not move */
    PetscCall(IndBCApplySolution(s->bc, 0.0, IndBorderedDepthDerivative(s->border)));
    PetscCall(IndBCApplySolution(s->bc, 0.0, IndBorderedLoadDerivative(s->border)));
  }
  {
    KSP ksp;
    PetscCall(SNESGetKSP(snes, &ksp));
    PetscCall(IndSolverRefreshFineSmoother(ksp));
    if (!IndAssemblyJacobianInodes(s->assembly)) PetscCall(MultigridAsJacobian(ksp, s));
  }
  if (A != P) {
    PetscCall(MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY));
    PetscCall(MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The residual of the whole system: under load control the load equation's beside equilibrium. */
static PetscReal SystemNorm(IndSolver s, PetscReal fnorm)
{
  return s->border ? PetscSqrtReal(fnorm * fnorm + PetscSqr(IndBorderedLoadResidual(s->border))) : fnorm;
}

/* Semi-smooth Newton can cycle for ever between contact states (stick, slip, open) of a few nodes,
   with the same residuals coming back every 2 to 5 iterations. Stopping after -newton_stall_its
   iterations without a new smallest residual lets the load step be cut long before -snes_max_it. */
static PetscErrorCode ConvergedUnlessStalled(SNES snes, PetscInt it, PetscReal xnorm, PetscReal snorm,
  PetscReal fnorm, SNESConvergedReason *reason, void *ctx)
{
  IndSolver s = (IndSolver)ctx;

  PetscFunctionBeginUser;
  fnorm = SystemNorm(s, fnorm);
  PetscCall(SNESConvergedDefault(snes, it, xnorm, snorm, fnorm, reason, NULL));
  /* A load short of its tolerance is not converged, however small the step or the residual */
  if (s->border && *reason > 0 && !IndBorderedLoadMet(s->border)) *reason = SNES_CONVERGED_ITERATING;
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

/* A section's systems are 2D: a sparse LU's fill grows as n log n there. On a Kick's-law section (14,400 cells,
   43k dofs, 2 ranks) GAMG took 128 GMRES iterations per Newton iteration (the hoop stiffness, E / r^2 beside the
   axis, is not the Laplacian-like operator it coarsens) and the run 212 s; MUMPS's LU 25 s. A factorization
   serves one Newton iteration: a lagged one would be one sweep of a stale inverse, and Newton converge linearly
   (278 Newton iterations instead of 151). The held rows (the hoop third of the unknowns everywhere, the axis's
   radial ones, the user's conditions) are left out of the factorization (src/solvers/heldlu.h). Without MUMPS
   the 3D defaults stay. */
static PetscErrorCode AxisymmetricSolverDefaults(SNES snes, IndBC bc)
{
  KSP       ksp;
  PC        pc;
  PetscBool mumps;

  PetscFunctionBeginUser;
  PetscCall(PetscHasExternalPackage("mumps", &mumps));
  if (!mumps) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(SNESGetKSP(snes, &ksp));
  PetscCall(KSPSetType(ksp, KSPPREONLY));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(IndHeldLUSetUp(pc, bc));
  PetscCall(SNESSetLagPreconditioner(snes, 1));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The multigrid's level smoothers scale each row by its largest entry (Jacobi's rowmax), unless
   -mg_levels_pc_jacobi_type says otherwise. That is the diagonal itself wherever the diagonal is the row's largest
   entry, as in elasticity, plasticity and the contact rows at moderate friction (the paper's case at mu 0.1: the same
   iterations and answers in every digit printed); but a sliding node's row loses its diagonal at high friction (less
   mu times its coupling to the normal direction), where the diagonal scaling stalled GMRES at the turn to unloading
   from mu = 2 on (doc/performance.md, "High friction"). */
static PetscErrorCode SmootherScaling(SNES snes)
{
  const char *prefix;
  char        name[256], value[64];
  PetscBool   set;

  PetscFunctionBeginUser;
  PetscCall(SNESGetOptionsPrefix(snes, &prefix));
  PetscCall(PetscSNPrintf(name, sizeof(name), "-%smg_levels_pc_jacobi_type", prefix ? prefix : ""));
  PetscCall(PetscOptionsHasName(NULL, NULL, name, &set));
  if (!set) PetscCall(PetscOptionsSetValue(NULL, name, "rowmax"));
  /* read once here: a run whose preconditioner has no Jacobi smoother (a direct solve) is not told it went unused */
  PetscCall(PetscOptionsGetString(NULL, NULL, name, value, sizeof(value), &set));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndSolverCreate(DM dm, IndAssembly assembly, IndBC bc, IndContact contact, PetscReal depth_max,
  IndSolver *out)
{
  IndSolver    s;
  KSP          ksp;
  PC           pc;
  PetscBool    single = PETSC_TRUE, galerkin = PETSC_TRUE;

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
  PetscCall(AttachRigidBodyModes(s));

  PetscCall(SNESCreate(PetscObjectComm((PetscObject)dm), &s->snes));
  { /* the residual's vector now, not at the first solve, so that the step's first residual can be handed over */
    Vec F;
    PetscCall(DMCreateGlobalVector(dm, &F));
    PetscCall(SNESSetFunction(s->snes, F, FormResidual, s));
    PetscCall(VecDestroy(&F));
  }
  PetscCall(SNESSetJacobian(s->snes, s->J, s->J, FormJacobian, s));
  PetscCall(SNESGetKSP(s->snes, &ksp));
  /* The contact rows of the semi-smooth Newton Jacobian make it unsymmetric. */
  PetscCall(KSPSetType(ksp, contact && !IndContactJacobianIsSymmetric(contact) ? KSPGMRES : KSPCG));
  /* A restart every 30 iterations (PETSc's) cost the paper case at h_tip 6 (58k dofs, 25 iterations
     per solve on average, more at the top of the unloading) 8% of its Krylov iterations. */
  PetscCall(KSPGMRESSetRestart(ksp, 100));
  /* Inexact Newton: each linear solve reduces the residual 1e3 times. The contact's active set and the
     plastic zone, not the accuracy of each direction, set the Newton iterations: on the README's case
     1e-5 took 252 Newton and 5,629 Krylov iterations, 1e-3 255 and 3,400, 1e-2 more Newton iterations
     for no less time; Eisenstat-Walker's loose first solves cost far more Newton ones (doc/performance.md). */
  PetscCall(KSPSetTolerances(ksp, 1e-3, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT));
  /* Other preconditioners than a multigrid (-pc_type lu on a small mesh) serve two Newton iterations; a multigrid
     follows the rule of src/solvers/pcreuse.h instead (below). */
  PetscCall(SNESSetLagPreconditioner(s->snes, 2));
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
  if (IndAssemblyIsAxisymmetric(assembly)) PetscCall(AxisymmetricSolverDefaults(s->snes, bc));
  if (contact) {
    /* Semi-smooth Newton is only locally convergent: at a reversal (the top of an unloading curve)
       full steps cycled between stick and slip until the step was cut, three times in a row on the
       paper case at h_tip 15. Backtracking on |F|^2 took every step there, but its full steps overshot
       the energy's minimum along the line while points yielded: the step to the critical point
       (src/solvers/linesearch.h) took the README's case in 251 Newton iterations instead of 293. */
    SNESLineSearch ls;
    PetscCall(SNESGetLineSearch(s->snes, &ls));
    PetscCall(IndLineSearchSetCriticalPoint(ls));
  }
  s->stall_its = 10;
  PetscOptionsBegin(PetscObjectComm((PetscObject)dm), NULL, IND_TITLE "Newton", "Solver");
  PetscCall(IndOptionsInt("-newton_stall_its",
    "Newton fails after this many iterations without a 1% smaller residual (0: never)",
                          NULL, s->stall_its, &s->stall_its, NULL));
  PetscCall(IndOptionsBool("-newton_pc_single",
    "The multigrid's products in single precision: its smoothers and coarse operators, not its interpolations (the "
    "Krylov method's stay in double; needs -jac_block_products)", single, &single, NULL));
  PetscCall(IndOptionsBool("-newton_pc_galerkin_blocks",
    "The multigrid's coarse operators P^T A P computed by blocks, not by PETSc's AIJ product (the same operators, "
    "faster and in less memory; doc/performance.md)", galerkin, &galerkin, NULL));
  PetscOptionsEnd();
  if (galerkin) PetscCall(IndGalerkinInstall(s->J));
  if (single && IndAssemblyJacobianBlockProducts(assembly))
    PetscCall(IndBlockMultCreateSingleOperator(s->J, &s->Jsingle));
  PetscCheck(s->stall_its >= 0, PetscObjectComm((PetscObject)dm), PETSC_ERR_ARG_OUTOFRANGE,
    "-newton_stall_its must be >= 0, got %" PetscInt_FMT, s->stall_its);
  PetscCall(SNESSetConvergenceTest(s->snes, ConvergedUnlessStalled, s, NULL));
  PetscCall(SmootherScaling(s->snes));
  PetscCall(SNESSetFromOptions(s->snes));
  PetscCall(KSPMonitorSet(ksp, ReleaseSmootherEstimators, NULL, NULL));
  {
    /* The multigrid is rebuilt when the Krylov iterations of keeping it would cost more
       (src/solvers/pcreuse.h), unless the user chose SNES's fixed lag. */
    PetscBool   lag;
    const char *prefix;
    PetscBool   reuse = PETSC_TRUE;
    PetscCall(SNESGetOptionsPrefix(s->snes, &prefix));
    PetscCall(PetscOptionsHasName(NULL, prefix, "-snes_lag_preconditioner", &lag));
    PetscCall(IndPCReuseCreate(ksp, (PetscBool)!lag, &s->reuse));
    PetscCall(KSPGetOptionsPrefix(ksp, &prefix));
    PetscCall(PetscOptionsGetBool(NULL, prefix, "-pc_gamg_reuse_interpolation", &reuse, NULL));
    s->keep_rigid = (PetscBool)!reuse;
    PetscCall(IndPCReuseSetFreshHook(s->reuse, FreshMultigrid, s));
    PetscCall(IndPCReuseSetSolvedHook(s->reuse, SolveDone, NULL));
  }
  if (contact) {
    /* rho from the stiffness of the undeformed body, before any condition touches its diagonal */
    PetscCall(VecZeroEntries(s->Uloc));
    PetscCall(IndAssemblyJacobian(assembly, s->Uloc, s->J));
    PetscCall(IndBCSetUp(bc));
    PetscCall(IndContactSetUp(contact, bc, s->J, depth_max));
  }
  *out = s;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* GMRES keeps the basis its longest solve grew (ten vectors at a time): a solve of 51 iterations in the second step
   of the paper's case at h_tip 3 held 55 vectors a rank, 76 MB, for the rest of the run, under every later transient
   (the field output's, where the run's memory peaked). PETSc frees GMRES's basis and Hessenberg matrix, and not the
   preconditioner, when its restart changes. */
PetscErrorCode IndSolverReleaseKrylovBasis(KSP ksp)
{
  PetscBool gmres;
  PetscInt  restart;

  PetscFunctionBeginUser;
  PetscCall(PetscObjectTypeCompare((PetscObject)ksp, KSPGMRES, &gmres));
  if (!gmres) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(KSPGMRESGetRestart(ksp, &restart));
  PetscCall(KSPGMRESSetRestart(ksp, restart + 1));
  PetscCall(KSPGMRESSetRestart(ksp, restart));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* F, the residual at the start of a step, is the first one Newton needs: newtonls takes it rather than evaluating it
   again (37 of the README run's 399 residuals). A point whose return map failed is left for SNES to find again, so
   that it cuts the step. Only newtonls is offered it: a type that ignored the offer would keep it for a later
   solve at another displacement. */
static PetscErrorCode OfferInitialResidual(IndSolver s, Vec F)
{
  PetscBool newtonls;

  PetscFunctionBeginUser;
  if (s->nfailed) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscObjectTypeCompare((PetscObject)s->snes, SNESNEWTONLS, &newtonls));
  if (newtonls) PetscCall(SNESSetInitialFunction(s->snes, F));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndSolverSolve(IndSolver s, PetscReal load_factor, Vec U, IndSolveResult *r)
{
  IndContact c           = s->contact;
  PetscReal  atol = 0, rtol = 0, stol = 0, step_atol = 0;
  PetscInt   maxit = 0, maxf = 0;
  PetscInt   border_linear = s->border ? IndBorderedLinearIterations(s->border) : 0;
  Vec        F     = NULL;

  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(r, sizeof(*r)));
  s->load_factor = load_factor;
  PetscCall(IndBCSetUp(s->bc));
  /* Starting on the prescribed values makes the Newton correction vanish on constrained rows, which
     is what zeroing their columns in the Jacobian assumes. */
  PetscCall(IndBCApplySolution(s->bc, load_factor, U));
  if (c) {
    /* A later outer iteration starts from a small residual, and a tolerance relative to it alone
       would ask Newton for round-off, where the projection's kinks make it cycle. Its floor is 1e-3
       rtol times the step's first residual. */
    PetscReal fnorm;
    PetscCall(SNESGetTolerances(s->snes, &atol, &rtol, &stol, &maxit, &maxf));
    PetscCall(DMGetGlobalVector(s->dm, &F));
    PetscCall(FormResidual(NULL, U, F, s));
    PetscCall(VecNorm(F, NORM_2, &fnorm));
    fnorm     = SystemNorm(s, fnorm);
    step_atol = PetscMax(atol, 1e-3 * rtol * fnorm);
    PetscCall(SNESSetTolerances(s->snes, step_atol, rtol, stol, maxit, maxf));
    PetscCall(OfferInitialResidual(s, F));
  }
  for (PetscInt k = 1; k <= (c ? IndContactOuterMax(c) : 1); ++k) {
    PetscInt  its, lits;
    PetscBool converged, stuck;
    PetscCall(SNESSolve(s->snes, NULL, U));
    PetscCall(SNESGetConvergedReason(s->snes, &r->reason));
    PetscCall(SNESGetIterationNumber(s->snes, &its));
    PetscCall(SNESGetLinearSolveIterations(s->snes, &lits));
    r->newton += its;
    r->linear += lits;
    r->outer = k;
    if (r->reason <= 0) {
      if (r->reason == SNES_DIVERGED_FUNCTION_DOMAIN) PetscCall(PetscSNPrintf(r->why, sizeof(r->why),
        "return map failed at %" PetscInt_FMT " quadrature points", s->nfailed));
      else if (s->stalled) PetscCall(PetscSNPrintf(r->why, sizeof(r->why),
        "Newton stalled: no smaller residual in %" PetscInt_FMT " iterations (-newton_stall_its)%s", s->stall_its,
        c ? " with contact" : ""));
      else PetscCall(PetscSNPrintf(r->why, sizeof(r->why), "Newton: %s after %" PetscInt_FMT " iterations%s",
        SNESConvergedReasons[r->reason], its, c ? " with contact" : ""));
      break;
    }
    if (!c) {
      r->converged = PETSC_TRUE;
      break;
    }
    PetscCall(RefreshMultipliers(s, U));
    PetscCall(IndContactUpdate(c, U, &r->contact));
    PetscCall(IndContactOuterConverged(c, k, its, step_atol, &r->contact, &converged));
    if (converged && (!s->border || IndBorderedLoadMet(s->border))) {
      r->converged = PETSC_TRUE;
      break;
    }
    PetscCall(IndContactOuterNext(c, its, &r->contact, &stuck, r->why, sizeof(r->why)));
    if (stuck) break;
  }
  if (s->border) r->linear += IndBorderedLinearIterations(s->border) - border_linear;
  if (c) {
    PetscCall(SNESSetTolerances(s->snes, atol, rtol, stol, maxit, maxf));
    PetscCall(DMRestoreGlobalVector(s->dm, &F));
    if (!r->converged && r->reason > 0 && !r->why[0])
      PetscCall(IndContactOuterFailure(c, &r->contact, r->why, sizeof(r->why)));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Solves the predictor's system J du = b with the Newton iteration's solver and adds du to U. Eisenstat-Walker's
   tolerance hook reads the SNES's residual, which does not exist before its first solve and is not this system's:
   off for this solve. A failed solve only costs Newton iterations: U is left as it was. */
static PetscErrorCode AddPredictorSolution(IndSolver s, Vec b, Vec du, Vec U)
{
  KSP                ksp;
  KSPConvergedReason reason;
  PetscBool          ew;

  PetscFunctionBeginUser;
  PetscCall(SNESGetKSP(s->snes, &ksp));
  PetscCall(KSPSetOperators(ksp, s->J, s->J));
  PetscCall(SNESKSPGetUseEW(s->snes, &ew));
  PetscCall(SNESKSPSetUseEW(s->snes, PETSC_FALSE));
  PetscCall(VecZeroEntries(du));
  PetscCall(KSPSolve(ksp, b, du));
  PetscCall(SNESKSPSetUseEW(s->snes, ew));
  PetscCall(KSPGetConvergedReason(ksp, &reason));
  if (reason > 0) PetscCall(VecAXPY(U, 1.0, du));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndSolverPredict(IndSolver s, PetscReal t_old, PetscReal t_new, Vec U)
{
  Vec       G, r, du;
  PetscReal gnorm;

  PetscFunctionBeginUser;
  PetscCall(IndBCSetUp(s->bc));
  PetscCall(DMGetGlobalVector(s->dm, &G));
  PetscCall(VecZeroEntries(G));
  PetscCall(IndBCApplySolution(s->bc, t_new - t_old, G));
  PetscCall(VecNorm(G, NORM_INFINITY, &gnorm));
  if (gnorm == 0) {
    /* Nothing prescribed moves (an indenter alone): the tangent response is zero, and the solve
       would only cost a Jacobian and a preconditioner setup. */
    PetscCall(DMRestoreGlobalVector(s->dm, &G));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(DMGetGlobalVector(s->dm, &r));
  PetscCall(DMGetGlobalVector(s->dm, &du));
  /* The tangent at the accepted state, before the boundary conditions zero its constrained columns:
     those columns times the increment of the prescribed values are the linearised load. */
  s->load_factor = t_old;
  PetscCall(VecCopy(U, s->Ubc));
  PetscCall(IndBCApplySolution(s->bc, t_old, s->Ubc));
  PetscCall(DMGlobalToLocal(s->dm, s->Ubc, INSERT_VALUES, s->Uloc));
  PetscCall(IndAssemblyJacobian(s->assembly, s->Uloc, s->J));
  PetscCall(MatMult(s->J, G, r));
  PetscCall(IndBCApplyJacobian(s->bc, s->J));
  PetscCall(IndBCApplySolution(s->bc, 0.0, r));
  PetscCall(VecScale(r, -1.0));
  PetscCall(AddPredictorSolution(s, r, du, U));
  PetscCall(VecAXPY(U, 1.0, G));
  PetscCall(DMRestoreGlobalVector(s->dm, &G));
  PetscCall(DMRestoreGlobalVector(s->dm, &r));
  PetscCall(DMRestoreGlobalVector(s->dm, &du));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndSolverPredictUnloading(IndSolver s, PetscReal rise, Vec U)
{
  Vec             X, B, du;
  PetscInt        n = 0, nbc, *rows;
  const PetscInt *bcrows;

  PetscFunctionBeginUser;
  if (!s->contact || rise <= 0) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(IndBCSetUp(s->bc));
  PetscCall(DMGetGlobalVector(s->dm, &X));
  PetscCall(DMGetGlobalVector(s->dm, &B));
  PetscCall(DMGetGlobalVector(s->dm, &du));
  PetscCall(VecZeroEntries(X));
  PetscCall(VecZeroEntries(B));
  PetscCall(IndBCGetRows(s->bc, &nbc, &bcrows, NULL));
  PetscCall(PetscMalloc1(nbc + 3 * IndContactGetSize(s->contact) + 1, &rows));
  for (PetscInt i = 0; i < nbc; ++i) rows[n++] = bcrows[i];
  PetscCall(IndContactReversalRows(s->contact, X, &n, rows));
  PetscCall(VecScale(X, rise));
  /* The elastic tangent at the accepted state, assembled into the Jacobian (the first Newton iteration assembles
     it again), held where the indenter and the conditions hold the body. */
  PetscCall(DMGlobalToLocal(s->dm, U, INSERT_VALUES, s->Uloc));
  PetscCall(IndAssemblyElasticJacobian(s->assembly, s->Uloc, s->J));
  PetscCall(MatZeroRowsColumns(s->J, n, rows, 1.0, X, B));
  PetscCall(PetscFree(rows));
  PetscCall(AddPredictorSolution(s, B, du, U));
  PetscCall(DMRestoreGlobalVector(s->dm, &X));
  PetscCall(DMRestoreGlobalVector(s->dm, &B));
  PetscCall(DMRestoreGlobalVector(s->dm, &du));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndSolverSetLoadControl(IndSolver s, PetscReal depth_max, PetscReal load_tol)
{
  SNESLineSearch ls;
  Vec            U;

  PetscFunctionBeginUser;
  PetscCall(DMGetGlobalVector(s->dm, &U));
  PetscCall(IndBorderedCreate(s->contact, U, depth_max, load_tol, &s->border));
  PetscCall(DMRestoreGlobalVector(s->dm, &U));
  PetscCall(SNESGetLineSearch(s->snes, &ls));
  PetscCall(SNESLineSearchSetType(ls, SNESLINESEARCHSHELL));
  PetscCall(SNESLineSearchShellSetUserFunc(ls, IndBorderedLineSearch, s->border));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndSolverSetLoadTarget(IndSolver s, PetscReal load)
{
  PetscFunctionBeginUser;
  PetscCall(IndBorderedSetTarget(s->border, load));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscBool IndSolverLoadOutOfReach(IndSolver s, PetscReal *load)
{
  *load = s->border ? IndBorderedLoad(s->border) : 0;
  return s->border ? IndBorderedOutOfReach(s->border) : PETSC_FALSE;
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

PetscErrorCode IndSolverCommit(IndSolver s, Vec U)
{
  PetscInt n;

  PetscFunctionBeginUser;
  PetscCall(VecCopy(U, s->Ubc));
  PetscCall(IndBCApplySolution(s->bc, s->load_factor, s->Ubc));
  PetscCall(DMGlobalToLocal(s->dm, s->Ubc, INSERT_VALUES, s->Uloc));
  PetscCall(IndAssemblyCommit(s->assembly, s->Uloc));
  IndAssemblyGetPointCounts(s->assembly, NULL, &n);
  PetscCallMPI(MPI_Allreduce(&n, &s->nplastic, 1, MPIU_INT, MPI_SUM, PetscObjectComm((PetscObject)s->dm)));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndSolverDestroy(IndSolver *s)
{
  PetscFunctionBeginUser;
  if (!*s) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(IndBorderedDestroy(&(*s)->border));
  PetscCall(IndPCReuseDestroy(&(*s)->reuse));
  PetscCall(SNESDestroy(&(*s)->snes));
  PetscCall(MatDestroy(&(*s)->Jsingle));
  PetscCall(MatDestroy(&(*s)->J));
  PetscCall(VecDestroy(&(*s)->Uloc));
  PetscCall(VecDestroy(&(*s)->Floc));
  PetscCall(VecDestroy(&(*s)->Ubc));
  PetscCall(PetscFree(*s));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndSolverElasticStiffness(IndSolver s, Vec U, Mat *K)
{
  MatNullSpace nsp;

  PetscFunctionBeginUser;
  PetscCall(MatDuplicate(s->J, MAT_DO_NOT_COPY_VALUES, K));
  /* its own: J's are let go once the multigrid has its interpolation */
  PetscCall(CreateRigidBodyModes(s, &nsp));
  PetscCall(MatSetNearNullSpace(*K, nsp));
  PetscCall(MatNullSpaceDestroy(&nsp));
  PetscCall(DMGlobalToLocal(s->dm, U, INSERT_VALUES, s->Uloc));
  PetscCall(IndAssemblyElasticJacobian(s->assembly, s->Uloc, *K));
  PetscFunctionReturn(PETSC_SUCCESS);
}

IND_GETTER(PetscInt, IndSolverPlasticPoints, IndSolver, o->nplastic)
IND_GETTER(PetscInt, IndSolverFailedPoints, IndSolver, o->nfailed)
IND_GETTER(SNES, IndSolverGetSNES, IndSolver, o->snes)
IND_GETTER(Mat, IndSolverGetJacobian, IndSolver, o->J)

PetscErrorCode IndSolverState(void *obj, IndStateFile f)
{
  IndSolver s = (IndSolver)obj;
  KSP       ksp;

  PetscFunctionBeginUser;
  if (!IndStateReading(f)) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(SNESGetKSP(s->snes, &ksp));
  PetscCall(KSPReset(ksp));
  PetscCall(IndPCReuseReset(s->reuse)); /* the next set-up builds the interpolation anew, from the rigid-body modes */
  PetscCall(AttachRigidBodyModes(s));
  PetscFunctionReturn(PETSC_SUCCESS);
}
