static const char help[] =
  "The axisymmetric model's direct solve leaves the held rows out of the factorization (src/solvers/heldlu.c):\n"
  "it must stay exact when a free row changes its couplings after the first set-up and when the held rows\n"
  "change.\n";

#include "ind_app.h"
#include "heldlu.h"

static PetscErrorCode Zero(const PetscReal x[3], PetscReal v[3], void *ctx)
{
  (void)x;
  (void)ctx;
  v[0] = v[1] = v[2] = 0;
  return PETSC_SUCCESS;
}

/* |J x - b| / |b| after solving J x = b with ksp, b = 1 */
static PetscErrorCode SolveResidual(KSP ksp, Mat J, PetscReal *rel)
{
  Vec       b, x, r;
  PetscReal nb, nr;

  PetscFunctionBeginUser;
  PetscCall(MatCreateVecs(J, &x, &b));
  PetscCall(VecDuplicate(b, &r));
  PetscCall(VecSet(b, 1.0));
  PetscCall(KSPSolve(ksp, b, x));
  PetscCall(MatMult(J, x, r));
  PetscCall(VecAXPY(r, -1.0, b));
  PetscCall(VecNorm(r, NORM_2, &nr));
  PetscCall(VecNorm(b, NORM_2, &nb));
  *rel = nr / nb;
  PetscCall(VecDestroy(&x));
  PetscCall(VecDestroy(&b));
  PetscCall(VecDestroy(&r));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Tangent(IndApp app, Vec Uloc, Mat J)
{
  PetscFunctionBeginUser;
  PetscCall(IndBCSetUp(IndAppGetBC(app)));
  PetscCall(IndAssemblyJacobian(IndAppGetAssembly(app), Uloc, J));
  PetscCall(IndBCApplyJacobian(IndAppGetBC(app), J));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Held rows of the whole system, and the free block's size the solver factored */
static PetscErrorCode Sizes(IndApp app, KSP ksp, PetscInt *held, PetscInt *free)
{
  PC       pc;
  KSP      inner;
  Mat      A;
  PetscInt n;

  PetscFunctionBeginUser;
  PetscCall(IndBCGetRows(IndAppGetBC(app), &n, NULL, NULL));
  PetscCall(MPIU_Allreduce(&n, held, 1, MPIU_INT, MPI_SUM, PETSC_COMM_WORLD));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(IndHeldLUGetFreeKSP(pc, &inner));
  PetscCheck(inner, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "the section's solver is not the held-rows LU");
  PetscCall(KSPGetOperators(inner, &A, NULL));
  PetscCall(MatGetSize(A, free, NULL));
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  IndApp    app;
  KSP       ksp, redistribute;
  PC        pc;
  Mat       J;
  Vec       U;
  PetscInt  N, held[2], nfree[2], first;
  PetscReal res[3], res_redistribute;
  PetscBool ok;

  PetscFunctionBeginUser;
  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  PetscCall(IndAppCreate(PETSC_COMM_WORLD, &app));
  J = IndSolverGetJacobian(IndAppGetSolver(app));
  PetscCall(MatGetSize(J, &N, NULL));
  PetscCall(SNESGetKSP(IndSolverGetSNES(IndAppGetSolver(app)), &ksp));
  PetscCall(KSPCreate(PETSC_COMM_WORLD, &redistribute));
  PetscCall(KSPSetType(redistribute, KSPPREONLY));
  PetscCall(KSPGetPC(redistribute, &pc));
  PetscCall(PCSetType(pc, PCREDISTRIBUTE));
  {
    KSP sub;
    PC  subpc;
    PetscCall(PCRedistributeGetKSP(pc, &sub));
    PetscCall(KSPSetType(sub, KSPPREONLY));
    PetscCall(KSPGetPC(sub, &subpc));
    PetscCall(PCSetType(subpc, PCLU));
    PetscCall(PCFactorSetMatSolverType(subpc, MATSOLVERMUMPS));
  }
  PetscCall(DMGetLocalVector(IndAppGetDM(app), &U));
  PetscCall(VecZeroEntries(U));

  /* First set-up: the first free row of the last rank only on its diagonal, as a node's row in contact can be */
  PetscCall(Tangent(app, U, J));
  {
    const PetscInt *rows;
    PetscInt        n, rstart, rend, mine = -1;
    PetscMPIInt     rank, size;
    PetscCall(MPI_Comm_rank(PETSC_COMM_WORLD, &rank));
    PetscCall(MPI_Comm_size(PETSC_COMM_WORLD, &size));
    PetscCall(IndBCGetRows(IndAppGetBC(app), &n, &rows, NULL));
    PetscCall(MatGetOwnershipRange(J, &rstart, &rend));
    for (PetscInt r = rstart; r < rend && rank == size - 1 && mine < 0; ++r) {
      PetscBool isheld = PETSC_FALSE;
      for (PetscInt k = 0; k < n; ++k) isheld = isheld || rows[k] == r;
      if (!isheld) mine = r;
    }
    PetscCall(MPIU_Allreduce(&mine, &first, 1, MPIU_INT, MPI_MAX, PETSC_COMM_WORLD));
    PetscCall(MatZeroRowsColumns(J, rank == size - 1 ? 1 : 0, &first, 2.0, NULL, NULL));
  }
  PetscCall(KSPSetOperators(ksp, J, J));
  PetscCall(KSPSetOperators(redistribute, J, J));
  PetscCall(SolveResidual(ksp, J, &res[0]));
  PetscCall(SolveResidual(redistribute, J, &res_redistribute));
  PetscCall(Sizes(app, ksp, &held[0], &nfree[0]));

  /* The same matrix assembled again: that row coupled as every other */
  PetscCall(Tangent(app, U, J));
  PetscCall(SolveResidual(ksp, J, &res[1]));
  PetscCall(SolveResidual(redistribute, J, &res_redistribute));

  /* A condition more (the sides held radially): other held rows, another free block */
  PetscCall(IndBCAddFunction(IndAppGetBC(app), "sides", 1, Zero, NULL));
  PetscCall(IndBCInvalidate(IndAppGetBC(app)));
  PetscCall(Tangent(app, U, J));
  PetscCall(SolveResidual(ksp, J, &res[2]));
  PetscCall(Sizes(app, ksp, &held[1], &nfree[1]));

  PetscCall(PetscPrintf(PETSC_COMM_WORLD,
    "%" PetscInt_FMT " dofs, %" PetscInt_FMT " held, free block %" PetscInt_FMT "; |Jx - b|/|b|: %.2e on the first "
    "set-up, %.2e after a free row's couplings changed (PCREDISTRIBUTE, which keeps its first rows: %.2e); "
    "with the sides held too (%" PetscInt_FMT " held, free block %" PetscInt_FMT "): %.2e\n", N, held[0], nfree[0],
    (double)res[0], (double)res[1], (double)res_redistribute, held[1], nfree[1], (double)res[2]));
  ok = res[0] < 1e-10 && res[1] < 1e-10 && res[2] < 1e-10 && nfree[0] == N - held[0] && nfree[1] == N - held[1] &&
       held[1] > held[0] && 3 * held[0] > N ? PETSC_TRUE : PETSC_FALSE;
  PetscCall(DMRestoreLocalVector(IndAppGetDM(app), &U));
  PetscCall(KSPDestroy(&redistribute));
  PetscCall(IndAppDestroy(&app));
  PetscCall(PetscFinalize());
  return ok ? 0 : 1;
}
