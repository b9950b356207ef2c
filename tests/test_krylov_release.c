static const char help[] =
  "Krylov bases given back: after each solve of the Newton solver's KSP, GMRES's basis and the Chebyshev\n"
  "smoothers' estimators are freed, the preconditioner is kept, and the next solve is the same solve; with the\n"
  "solve's singular values asked for, the basis stays until IndSolverReleaseKrylovBasis. Run with -malloc_debug,\n"
  "so that PETSc counts what is held.\n";

#include "solver_test.h"

/* Exported by PETSc's library, declared only in its private petsc/private/petscimpl.h (as in galerkin.c). */
PETSC_EXTERN PetscErrorCode PetscObjectStateGet(PetscObject, PetscObjectState *);

/* bytes freed by giving back ksp's basis, or with estimators, every multigrid smoother's estimator's */
static PetscErrorCode Freed(KSP ksp, PetscBool estimators, PetscLogDouble *freed)
{
  PetscLogDouble before, after;
  PC             pc;
  PetscInt       levels = 0;

  PetscFunctionBeginUser;
  PetscCall(PetscMallocGetCurrentUsage(&before));
  if (!estimators) PetscCall(IndSolverReleaseKrylovBasis(ksp));
  else {
    PetscCall(KSPGetPC(ksp, &pc));
    PetscCall(PCMGGetLevels(pc, &levels));
    for (PetscInt l = 1; l < levels; ++l) {
      KSP smoother, est;
      PetscCall(PCMGGetSmoother(pc, l, &smoother));
      PetscCall(KSPChebyshevEstEigGetKSP(smoother, &est));
      if (est) PetscCall(IndSolverReleaseKrylovBasis(est));
    }
  }
  PetscCall(PetscMallocGetCurrentUsage(&after));
  *freed = before - after;
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  IndApp           app;
  KSP              ksp = NULL;
  Mat              J   = NULL, ops[8], after[8];
  Vec              b, x, x1, Uloc;
  PetscInt         its[4], nops, nafter, nloc, bad = 0;
  PetscLogDouble   left_outer, left_est, before2, after2, kept, released;
  PetscReal        emax, emin;
  PetscBool        counted, same[3];
  PetscObjectState state[8];
  double           vec;

  PetscFunctionBeginUser;
  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  PetscCall(PetscMallocGetDebug(&counted, NULL, NULL));
  PetscCheck(counted, PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONGSTATE, "run with -malloc_debug: nothing is counted");
  PetscCall(SolverTestCreate(1e-8, &app, &J, &ksp));
  PetscCall(KSPSetType(ksp, KSPGMRES)); /* the contact's solver; this case has none */
  PetscCall(KSPGMRESSetRestart(ksp, 100));
  PetscCall(SolverTestJacobianAtZero(app, J, &Uloc));
  PetscCall(MatCreateVecs(J, &x, &b));
  PetscCall(VecDuplicate(x, &x1));
  PetscCall(VecGetLocalSize(x, &nloc));
  vec = sizeof(PetscScalar) * (double)nloc;
  PetscCall(VecSet(b, 1.0));
  PetscCall(KSPSetOperators(ksp, J, J));
  PetscCall(SolveCounted(ksp, b, x1, &its[0]));
  PetscCall(SolverTestCoarseOperators(ksp, ops, &nops));
  for (PetscInt k = 0; k < nops; ++k) PetscCall(PetscObjectStateGet((PetscObject)ops[k], &state[k]));
  /* the solve gave its basis and the estimators' back itself: nothing left to free */
  PetscCall(Freed(ksp, PETSC_FALSE, &left_outer));
  PetscCall(Freed(ksp, PETSC_TRUE, &left_est));

  /* the preconditioner kept: a solve holds nothing after it that it did not hold before */
  PetscCall(KSPSetReusePreconditioner(ksp, PETSC_TRUE));
  PetscCall(PetscMallocGetCurrentUsage(&before2));
  PetscCall(SolveCounted(ksp, b, x, &its[1]));
  PetscCall(PetscMallocGetCurrentUsage(&after2));
  PetscCall(VecEqual(x, x1, &same[0]));

  /* singular values asked for: PETSc reads them from the basis's Hessenberg matrix after the solve, so it stays */
  PetscCall(KSPSetComputeSingularValues(ksp, PETSC_TRUE));
  PetscCall(PetscMallocGetCurrentUsage(&kept));
  PetscCall(SolveCounted(ksp, b, x, &its[2]));
  PetscCall(PetscMallocGetCurrentUsage(&released));
  kept = released - kept;
  PetscCall(KSPComputeExtremeSingularValues(ksp, &emax, &emin));
  PetscCall(VecEqual(x, x1, &same[1]));
  PetscCall(Freed(ksp, PETSC_FALSE, &released));
  PetscCall(KSPSetComputeSingularValues(ksp, PETSC_FALSE));
  PetscCall(SolveCounted(ksp, b, x, &its[3]));
  PetscCall(VecEqual(x, x1, &same[2]));
  PetscCall(SolverTestCoarseOperators(ksp, after, &nafter));

  PetscCall(PetscPrintf(PETSC_COMM_WORLD,
    "Krylov iterations %" PetscInt_FMT ", %" PetscInt_FMT ", %" PetscInt_FMT ", %" PetscInt_FMT
    "; the same solution: %s %s %s; largest singular value %g\n", its[0], its[1], its[2], its[3],
    same[0] ? "yes" : "no", same[1] ? "yes" : "no", same[2] ? "yes" : "no", (double)emax));
  PetscCall(PetscSynchronizedPrintf(PETSC_COMM_WORLD,
    "  vectors of this rank: left after a solve %.1f (estimators %.1f), held across a solve %.1f, kept for the singular"
    " values %.1f and freed by the call %.1f\n", left_outer / vec, left_est / vec, (after2 - before2) / vec,
    kept / vec, released / vec));
  PetscCall(PetscSynchronizedFlush(PETSC_COMM_WORLD, PETSC_STDOUT));
  /* Nothing left by a solve (less than a vector: GMRES's small arrays), and not before or after the next one; the
     basis kept (at least a vector per iteration) when asked and freed by the call; the same iterations, digits and
     coarse operators every time (a preconditioner set up again would have computed them anew). */
  if (its[0] < 2 || left_outer >= vec || left_est >= vec || PetscAbs(after2 - before2) >= vec) bad = 1;
  if (kept < its[0] * vec || released < its[0] * vec || !(emax > 0)) bad = 1;
  for (int k = 1; k < 4; ++k)
    if (its[k] != its[0]) bad = 1;
  if (!same[0] || !same[1] || !same[2] || nafter != nops) bad = 1;
  for (PetscInt k = 0; k < nops && !bad; ++k) {
    PetscObjectState st;
    PetscCall(PetscObjectStateGet((PetscObject)after[k], &st));
    if (after[k] != ops[k] || st != state[k]) bad = 1;
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &bad, 1, MPIU_INT, MPI_MAX, PETSC_COMM_WORLD));
  PetscCall(DMRestoreLocalVector(IndAppGetDM(app), &Uloc));
  PetscCall(VecDestroy(&x));
  PetscCall(VecDestroy(&x1));
  PetscCall(VecDestroy(&b));
  PetscCall(IndAppDestroy(&app));
  PetscCall(PetscFinalize());
  return (int)bad;
}
