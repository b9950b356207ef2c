static const char help[] =
  "A multigrid whose coarse operators and interpolations multiply row by row (IndSolverMultigridRowProducts)\n"
  "solves as before, keeps doing so through the numeric refresh of its coarse levels, and uses no inodes there;\n"
  "its coarse operators multiply by their 6 x 6 block rows (IndBlockMultInstall). In single precision\n"
  "(-newton_pc_single): every coarse operator reads single precision and every interpolation double, the finest\n"
  "smoother and residual multiply by the Jacobian's single-precision operator, and the solve takes the same\n"
  "iterations (one more at most) to the same solution.\n";

#include "solver_test.h"
#include "ind_blockmult.h"

/* Inode groups of the owned diagonal block of M (0: none, or M does not use them) */
static PetscErrorCode InodeCount(Mat M, PetscInt *count)
{
  Mat       Ad = M;
  PetscBool mpi;
  PetscInt *sizes, limit;

  PetscFunctionBeginUser;
  PetscCall(PetscObjectTypeCompare((PetscObject)M, MATMPIAIJ, &mpi));
  if (mpi) PetscCall(MatMPIAIJGetSeqAIJ(M, &Ad, NULL, NULL));
  *count = 0;
  PetscCall(MatInodeGetInodeSizes(Ad, count, &sizes, &limit));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Inode groups summed over the coarse operators above the coarsest, all ranks */
static PetscErrorCode CoarseInodes(KSP ksp, PetscInt *total)
{
  Mat      ops[8];
  PetscInt nops = 0, n;

  PetscFunctionBeginUser;
  *total = 0;
  PetscCall(SolverTestCoarseOperators(ksp, ops, &nops));
  for (PetscInt l = 0; l < nops; ++l) {
    PetscCall(InodeCount(ops[l], &n));
    *total += n;
  }
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, total, 1, MPIU_INT, MPI_SUM, PetscObjectComm((PetscObject)ksp)));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Of the coarse operators above the coarsest and the interpolations: how many are multiplied by block rows, and how
   many read single precision (operators, interpolations), on every rank; and whether the finest smoother's operator
   is S */
static PetscErrorCode CoarseCounts(KSP ksp, Mat S, PetscInt *blocks, PetscInt single[2], PetscBool *fine)
{
  PC       pc;
  PetscInt levels;

  PetscFunctionBeginUser;
  *blocks = single[0] = single[1] = 0;
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PCMGGetLevels(pc, &levels));
  for (PetscInt l = 1; l < levels; ++l) {
    KSP       smoother;
    Mat       M[2];
    PetscBool q[2];
    PetscCall(PCMGGetSmoother(pc, l, &smoother));
    PetscCall(KSPGetOperators(smoother, &M[0], NULL));
    PetscCall(PCMGGetInterpolation(pc, l, &M[1]));
    if (l == levels - 1) *fine = (PetscBool)(M[0] == S);
    for (int k = (l == levels - 1); k < 2; ++k) { /* the finest operator is the Jacobian (or S) */
      PetscCall(IndBlockMultActive(M[k], &q[0]));
      PetscCall(IndBlockMultGetSingle(M[k], &q[1]));
      PetscCall(MPIU_Allreduce(MPI_IN_PLACE, q, 2, MPIU_BOOL, MPI_LAND, PetscObjectComm((PetscObject)ksp)));
      *blocks += q[0];
      single[k] += q[1];
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode RelativeDifference(Vec x, Vec y, PetscReal *d)
{
  Vec       e;
  PetscReal ny;

  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(x, &e));
  PetscCall(VecWAXPY(e, -1.0, y, x));
  PetscCall(VecNorm(e, NORM_2, d));
  PetscCall(VecNorm(y, NORM_2, &ny));
  *d /= ny;
  PetscCall(VecDestroy(&e));
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  IndApp    app;
  KSP       ksp = NULL;
  PC        pc;
  Mat       J   = NULL;
  Vec       b, x, xref, Uloc;
  Mat       S;
  PetscInt  its[5], before, after, levels, blocks[4], single[4][2]; /* [0], [1] in double, [2], [3] in single */
  PetscReal d[4];
  PetscBool ok, fine[4];

  PetscFunctionBeginUser;
  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  PetscCall(SolverTestCreate(1e-10, &app, &J, &ksp));
  PetscCall(MatCreateVecs(J, &x, &b));
  PetscCall(VecDuplicate(x, &xref));
  PetscCall(VecSet(b, 1.0));
  PetscCall(SolverTestJacobianAtZero(app, J, &Uloc));

  /* a fresh hierarchy as PETSc makes it */
  PetscCall(KSPSetOperators(ksp, J, J));
  PetscCall(KSPSetReusePreconditioner(ksp, PETSC_FALSE));
  PetscCall(SolveCounted(ksp, b, xref, &its[0]));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PCMGGetLevels(pc, &levels));
  PetscCall(CoarseInodes(ksp, &before));

  /* the same hierarchy, row by row and its coarse operators by block rows */
  PetscCall(IndSolverMultigridRowProducts(ksp, PETSC_TRUE, NULL));
  PetscCall(KSPSetReusePreconditioner(ksp, PETSC_TRUE));
  PetscCall(SolveCounted(ksp, b, x, &its[1]));
  PetscCall(RelativeDifference(x, xref, &d[0]));
  PetscCall(CoarseCounts(ksp, NULL, &blocks[0], single[0], &fine[0]));

  /* the matrix assembled again: GAMG refreshes its coarse operators in place (and refactors the coarsest) */
  PetscCall(IndAssemblyJacobian(IndAppGetAssembly(app), Uloc, J));
  PetscCall(IndBCApplyJacobian(IndAppGetBC(app), J));
  PetscCall(KSPSetReusePreconditioner(ksp, PETSC_FALSE));
  PetscCall(SolveCounted(ksp, b, x, &its[2]));
  PetscCall(RelativeDifference(x, xref, &d[1]));
  PetscCall(CoarseInodes(ksp, &after));
  PetscCall(CoarseCounts(ksp, NULL, &blocks[1], single[1], &fine[1]));

  /* single precision: on the set-up hierarchy, then through a refresh of its coarse levels */
  PetscCall(IndBlockMultCreateSingleOperator(J, &S));
  PetscCall(IndSolverMultigridRowProducts(ksp, PETSC_TRUE, S));
  PetscCall(KSPSetReusePreconditioner(ksp, PETSC_TRUE));
  PetscCall(SolveCounted(ksp, b, x, &its[3]));
  PetscCall(RelativeDifference(x, xref, &d[2]));
  PetscCall(CoarseCounts(ksp, S, &blocks[2], single[2], &fine[2]));
  PetscCall(KSPSetReusePreconditioner(ksp, PETSC_FALSE));
  PetscCall(KSPSetUp(ksp));
  PetscCall(IndSolverMultigridRowProducts(ksp, PETSC_TRUE, S));
  PetscCall(SolveCounted(ksp, b, x, &its[4]));
  PetscCall(RelativeDifference(x, xref, &d[3]));
  PetscCall(CoarseCounts(ksp, S, &blocks[3], single[3], &fine[3]));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD,
    "single precision: Krylov iterations %" PetscInt_FMT " and %" PetscInt_FMT " (refreshed); solutions differ by "
    "%.2e and %.2e; coarse operators in single precision %" PetscInt_FMT " and %" PetscInt_FMT ", interpolations %"
    PetscInt_FMT " and %" PetscInt_FMT "; finest smoother on the single-precision operator %d and %d\n", its[3],
    its[4], (double)d[2], (double)d[3], single[2][0], single[3][0], single[2][1], single[3][1], (int)fine[2],
    (int)fine[3]));
  PetscCall(MatDestroy(&S));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD,
    "%" PetscInt_FMT " levels; Krylov iterations: fresh %" PetscInt_FMT ", row by row %" PetscInt_FMT
    ", refreshed %" PetscInt_FMT "; solutions differ by %.2e and %.2e; inode groups on the coarse operators %"
    PetscInt_FMT " before, %" PetscInt_FMT " after; coarse operators and interpolations by block rows %"
    PetscInt_FMT " and %" PetscInt_FMT "\n", levels, its[0], its[1], its[2], (double)d[0], (double)d[1], before,
    after, blocks[0], blocks[1]));
  ok = (PetscBool)(levels >= 3 && its[0] > 0 && its[1] == its[0] && its[2] == its[0] && d[0] < 1e-10 &&
                   d[1] < 1e-10 && before > 0 && after == 0 && blocks[0] == 2 * levels - 3 &&
                   blocks[1] == 2 * levels - 3 && PetscAbsInt(its[3] - its[0]) <= 1 &&
                   PetscAbsInt(its[4] - its[0]) <= 1 && d[2] < 1e-8 && d[3] < 1e-8 && single[0][0] == 0 &&
                   single[0][1] == 0 && single[1][0] == 0 && single[1][1] == 0 && single[2][0] == levels - 2 &&
                   single[3][0] == levels - 2 && single[2][1] == 0 && single[3][1] == 0 &&
                   blocks[2] == 2 * levels - 3 && blocks[3] == 2 * levels - 3 && fine[2] && fine[3]);
  PetscCall(DMRestoreLocalVector(IndAppGetDM(app), &Uloc));
  PetscCall(VecDestroy(&x));
  PetscCall(VecDestroy(&xref));
  PetscCall(VecDestroy(&b));
  PetscCall(IndAppDestroy(&app));
  PetscCall(PetscFinalize());
  return ok ? 0 : 1;
}
