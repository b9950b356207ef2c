static const char help[] = "GMRES's basis given back (IndSolverReleaseKrylovBasis): the memory of the longest solve's\n"
                           "basis is freed, the preconditioner is kept, and the next solve is the same solve. Run\n"
                           "with -malloc_debug, so that PETSc counts what is held.\n";

#include "solver_test.h"

/* Exported by PETSc's library, declared only in its private petsc/private/petscimpl.h (as in galerkin.c). */
PETSC_EXTERN PetscErrorCode PetscObjectStateGet(PetscObject, PetscObjectState *);

int main(int argc, char **argv)
{
  IndApp         app;
  KSP            ksp = NULL;
  Mat            J   = NULL, ops[8], after[8];
  Vec            b, x, x1, Uloc;
  PetscInt       its1, its2, nops, nafter, nloc, bad = 0;
  PetscLogDouble held, released;
  PetscBool      counted, same;
  PetscObjectState state[8];

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
  PetscCall(VecSet(b, 1.0));
  PetscCall(KSPSetOperators(ksp, J, J));
  PetscCall(SolveCounted(ksp, b, x1, &its1));
  PetscCall(SolverTestCoarseOperators(ksp, ops, &nops));
  for (PetscInt k = 0; k < nops; ++k) PetscCall(PetscObjectStateGet((PetscObject)ops[k], &state[k]));

  PetscCall(PetscMallocGetCurrentUsage(&held));
  PetscCall(IndSolverReleaseKrylovBasis(ksp));
  PetscCall(PetscMallocGetCurrentUsage(&released));
  released = held - released;

  PetscCall(KSPSetReusePreconditioner(ksp, PETSC_TRUE));
  PetscCall(SolveCounted(ksp, b, x, &its2));
  PetscCall(SolverTestCoarseOperators(ksp, after, &nafter));
  PetscCall(VecEqual(x, x1, &same));
  PetscCall(VecGetLocalSize(x, &nloc));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "Krylov iterations %" PetscInt_FMT " then %" PetscInt_FMT
    " after the basis was given back; the same solution: %s\n", its1, its2, same ? "yes" : "no"));
  PetscCall(PetscSynchronizedPrintf(PETSC_COMM_WORLD, "  freed %.0f B, %.1f vectors of this rank\n", released,
    released / (sizeof(PetscScalar) * (double)nloc)));
  PetscCall(PetscSynchronizedFlush(PETSC_COMM_WORLD, PETSC_STDOUT));
  /* at least a vector per iteration of the first solve; the same iterations, the same digits, the same coarse
     operators (a preconditioner set up again would have
     computed them anew) */
  if (its1 < 2 || its2 != its1 || !same || nafter != nops) bad = 1;
  for (PetscInt k = 0; k < nops && !bad; ++k) {
    PetscObjectState st;
    PetscCall(PetscObjectStateGet((PetscObject)after[k], &st));
    if (after[k] != ops[k] || st != state[k]) bad = 1;
  }
  if (released < (double)its1 * sizeof(PetscScalar) * nloc) bad = 1;
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &bad, 1, MPIU_INT, MPI_MAX, PETSC_COMM_WORLD));
  PetscCall(DMRestoreLocalVector(IndAppGetDM(app), &Uloc));
  PetscCall(VecDestroy(&x));
  PetscCall(VecDestroy(&x1));
  PetscCall(VecDestroy(&b));
  PetscCall(IndAppDestroy(&app));
  PetscCall(PetscFinalize());
  return (int)bad;
}
