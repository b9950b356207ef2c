static const char help[] =
  "Galerkin products by blocks (IndGalerkinInstall) against PETSc's own. Random matrices made of blocks, whose rows\n"
  "reach other ranks' rows and columns: P^T A P and A P equal to PETSc's to round-off, with PETSc's patterns and\n"
  "block sizes, made again after A's values change (reuse), and PETSc's product used for an interpolation that is\n"
  "not made of blocks. Then the solver's GAMG: its coarse operators above the coarsest made by blocks, equal to\n"
  "PETSc's products of the same interpolations, and the same Krylov iterations and solution.\n";

#include "solver_test.h"
#include "ind_galerkin.h"

/* |X - Y|_F / |Y|_F, and whether X and Y have as many stored entries (the same pattern, as products of one pattern) */
static PetscErrorCode Compare(Mat X, Mat Y, PetscReal *d, PetscBool *same_nz)
{
  Mat       E;
  MatInfo   ix, iy;
  PetscReal ny;

  PetscFunctionBeginUser;
  PetscCall(MatDuplicate(Y, MAT_COPY_VALUES, &E));
  PetscCall(MatAXPY(E, -1.0, X, DIFFERENT_NONZERO_PATTERN));
  PetscCall(MatNorm(E, NORM_FROBENIUS, d));
  PetscCall(MatNorm(Y, NORM_FROBENIUS, &ny));
  *d /= ny;
  PetscCall(MatDestroy(&E));
  PetscCall(MatGetInfo(X, MAT_GLOBAL_SUM, &ix));
  PetscCall(MatGetInfo(Y, MAT_GLOBAL_SUM, &iy));
  *same_nz = (PetscBool)(ix.nz_used == iy.nz_used);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* P: n nodes a rank (a multiple of 4) of rbs rows; node i in aggregate i / 4 and, for odd i, also in the next one,
   blocks of cbs columns (the aggregates spread over the ranks as the nodes are) */
static PetscErrorCode RandomInterpolation(PetscInt n, PetscInt rbs, PetscInt cbs, PetscRandom rnd, Mat *P)
{
  PetscInt N, Na, rstart;

  PetscFunctionBeginUser;
  PetscCall(MatCreate(PETSC_COMM_WORLD, P));
  PetscCall(MatSetSizes(*P, rbs * n, cbs * (n / 4), PETSC_DETERMINE, PETSC_DETERMINE));
  PetscCall(MatSetBlockSizes(*P, rbs, cbs));
  PetscCall(MatSetType(*P, MATAIJ));
  PetscCall(MatSeqAIJSetPreallocation(*P, 2 * cbs, NULL));
  PetscCall(MatMPIAIJSetPreallocation(*P, 2 * cbs, NULL, 2 * cbs, NULL));
  PetscCall(MatGetSize(*P, &N, &Na));
  PetscCall(MatGetOwnershipRange(*P, &rstart, NULL));
  N /= rbs, Na /= cbs;
  for (PetscInt i = rstart / rbs; i < rstart / rbs + n; ++i)
    for (PetscInt a = i / 4; a <= PetscMin(Na - 1, i / 4 + (i % 2)); ++a) {
      PetscScalar v[64];
      PetscInt    r[8], c[8];
      for (PetscInt k = 0; k < rbs; ++k) r[k] = rbs * i + k;
      for (PetscInt k = 0; k < cbs; ++k) c[k] = cbs * a + k;
      for (PetscInt k = 0; k < rbs * cbs; ++k) PetscCall(PetscRandomGetValue(rnd, &v[k]));
      PetscCall(MatSetValues(*P, rbs, r, cbs, c, v, INSERT_VALUES));
    }
  PetscCall(MatAssemblyBegin(*P, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(*P, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A: n nodes a rank, 3 x 3 blocks, node i coupled to i - 2 .. i + 2 (across ranks); P as RandomInterpolation's */
static PetscErrorCode RandomPair(PetscInt n, PetscInt cbs, PetscRandom rnd, Mat *A, Mat *P)
{
  PetscInt N, rstart;

  PetscFunctionBeginUser;
  PetscCall(MatCreateAIJ(PETSC_COMM_WORLD, 3 * n, 3 * n, PETSC_DETERMINE, PETSC_DETERMINE, 15, NULL, 15, NULL, A));
  PetscCall(MatSetBlockSize(*A, 3));
  PetscCall(MatGetSize(*A, &N, NULL));
  PetscCall(MatGetOwnershipRange(*A, &rstart, NULL));
  N /= 3;
  for (PetscInt i = rstart / 3; i < rstart / 3 + n; ++i)
    for (PetscInt j = PetscMax(0, i - 2); j <= PetscMin(N - 1, i + 2); ++j) {
      PetscScalar v[9];
      PetscInt    r[3] = {3 * i, 3 * i + 1, 3 * i + 2}, c[3] = {3 * j, 3 * j + 1, 3 * j + 2};
      for (int k = 0; k < 9; ++k) PetscCall(PetscRandomGetValue(rnd, &v[k]));
      PetscCall(MatSetValues(*A, 3, r, 3, c, v, INSERT_VALUES));
    }
  PetscCall(MatAssemblyBegin(*A, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(*A, MAT_FINAL_ASSEMBLY));
  PetscCall(RandomInterpolation(n, 3, cbs, rnd, P));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* P^T A P of a fresh random pair with blocks of cbs columns, against PETSc's: difference, same pattern, by blocks */
static PetscErrorCode FreshPtAP(PetscInt cbs, PetscRandom rnd, PetscReal *d, PetscBool *same, PetscBool *blocks)
{
  Mat A, A2, P, C[2];

  PetscFunctionBeginUser;
  PetscCall(RandomPair(48, cbs, rnd, &A, &P));
  PetscCall(MatDuplicate(A, MAT_COPY_VALUES, &A2));
  PetscCall(IndGalerkinInstall(A));
  PetscCall(MatPtAP(A, P, MAT_INITIAL_MATRIX, 2.0, &C[0]));
  PetscCall(MatPtAP(A2, P, MAT_INITIAL_MATRIX, 2.0, &C[1]));
  PetscCall(Compare(C[0], C[1], d, same));
  PetscCall(IndGalerkinByBlocks(C[0], blocks));
  for (int k = 0; k < 2; ++k) PetscCall(MatDestroy(&C[k]));
  PetscCall(MatDestroy(&P));
  PetscCall(MatDestroy(&A2));
  PetscCall(MatDestroy(&A));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The products of random matrices: d[0..5] the differences from PETSc's (P^T A P, again after A changed, A P, P^T A P
   with an interpolation of scalar columns, with blocks of 4 columns, and the next level's product of the first), ok
   whether patterns, block sizes and routes were as expected */
static PetscErrorCode RandomProducts(PetscReal d[6], PetscBool *ok)
{
  PetscRandom rnd;
  Mat         A, A2, P, P2, C[2], D[2], G[2];
  PetscBool   same[6], blocks[7];
  PetscInt    rbs, cbs;

  PetscFunctionBeginUser;
  PetscCall(PetscRandomCreate(PETSC_COMM_SELF, &rnd));
  PetscCall(PetscRandomSetInterval(rnd, -1.0, 1.0));
  PetscCall(PetscRandomSetSeed(rnd, 7));
  PetscCall(PetscRandomSeed(rnd));
  PetscCall(RandomPair(48, 6, rnd, &A, &P));
  PetscCall(MatDuplicate(A, MAT_COPY_VALUES, &A2)); /* a copy has PETSc's products */
  PetscCall(IndGalerkinInstall(A));

  PetscCall(MatPtAP(A, P, MAT_INITIAL_MATRIX, 2.0, &C[0]));
  PetscCall(MatPtAP(A2, P, MAT_INITIAL_MATRIX, 2.0, &C[1]));
  PetscCall(Compare(C[0], C[1], &d[0], &same[0]));
  PetscCall(IndGalerkinByBlocks(C[0], &blocks[0]));
  PetscCall(IndGalerkinByBlocks(C[1], &blocks[1]));
  PetscCall(MatGetBlockSizes(C[0], &rbs, &cbs));

  /* the next level: C's own products (6 x 6 blocks), against PETSc's of the copy's C */
  PetscCall(RandomInterpolation(12, 6, 6, rnd, &P2));
  PetscCall(MatPtAP(C[0], P2, MAT_INITIAL_MATRIX, 2.0, &G[0]));
  PetscCall(MatPtAP(C[1], P2, MAT_INITIAL_MATRIX, 2.0, &G[1]));
  PetscCall(Compare(G[0], G[1], &d[5], &same[5]));
  PetscCall(IndGalerkinByBlocks(G[0], &blocks[5]));
  PetscCall(IndGalerkinByBlocks(G[1], &blocks[6]));

  /* new values in A's pattern: the product made again in place */
  PetscCall(MatScale(A, -3.0));
  PetscCall(MatShift(A, 5.0));
  PetscCall(MatScale(A2, -3.0));
  PetscCall(MatShift(A2, 5.0));
  PetscCall(MatPtAP(A, P, MAT_REUSE_MATRIX, 2.0, &C[0]));
  PetscCall(MatPtAP(A2, P, MAT_REUSE_MATRIX, 2.0, &C[1]));
  PetscCall(Compare(C[0], C[1], &d[1], &same[1]));

  PetscCall(MatMatMult(A, P, MAT_INITIAL_MATRIX, 2.0, &D[0]));
  PetscCall(MatMatMult(A2, P, MAT_INITIAL_MATRIX, 2.0, &D[1]));
  PetscCall(Compare(D[0], D[1], &d[2], &same[2]));
  PetscCall(IndGalerkinByBlocks(D[0], &blocks[2]));

  /* blocks of 4 columns: the loops for any block size (3 x 6 and 6 x 6 have their own); an interpolation whose
     columns are not grouped: PETSc's product */
  PetscCall(FreshPtAP(4, rnd, &d[4], &same[4], &blocks[4]));
  PetscCall(FreshPtAP(1, rnd, &d[3], &same[3], &blocks[3]));

  *ok = (PetscBool)(same[0] && same[1] && same[2] && same[3] && same[4] && same[5] && blocks[0] && !blocks[1] &&
                    blocks[2] && !blocks[3] && blocks[4] && blocks[5] && !blocks[6] && rbs == 6 && cbs == 6);
  PetscCall(PetscPrintf(PETSC_COMM_WORLD,
    "random blocks: P^T A P differs from PETSc's by %.2e (by blocks %d, PETSc's %d, block sizes %" PetscInt_FMT
    " x %" PetscInt_FMT "), the next level %.2e (by blocks %d, from PETSc's %d), after A changed %.2e; A P %.2e (by "
    "blocks %d); 3 x 4 blocks %.2e (by blocks %d); scalar columns %.2e (by blocks %d); same patterns %d %d %d %d %d "
    "%d\n", (double)d[0], (int)blocks[0], (int)blocks[1], rbs, cbs, (double)d[5], (int)blocks[5], (int)blocks[6],
    (double)d[1], (double)d[2], (int)blocks[2], (double)d[4], (int)blocks[4], (double)d[3], (int)blocks[3],
    (int)same[0], (int)same[1], (int)same[2], (int)same[3], (int)same[4], (int)same[5]));
  for (int k = 0; k < 2; ++k) {
    PetscCall(MatDestroy(&C[k]));
    PetscCall(MatDestroy(&D[k]));
    PetscCall(MatDestroy(&G[k]));
  }
  PetscCall(MatDestroy(&P2));
  PetscCall(MatDestroy(&P));
  PetscCall(MatDestroy(&A2));
  PetscCall(MatDestroy(&A));
  PetscCall(PetscRandomDestroy(&rnd));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Copies of the coarse operators of levels 1 .. levels - 2 (not the finest, nor the coarsest that GAMG moves to one
   rank), and how many of them were made by blocks */
static PetscErrorCode CoarseCopies(KSP ksp, Mat copies[], PetscInt *n, PetscInt *by_blocks)
{
  Mat ops[8];

  PetscFunctionBeginUser;
  PetscCall(SolverTestCoarseOperators(ksp, ops, n));
  *by_blocks = 0;
  for (PetscInt l = 0; l < *n; ++l) {
    PetscBool b;
    PetscCall(IndGalerkinByBlocks(ops[l], &b));
    *by_blocks += b;
    PetscCall(MatDuplicate(ops[l], MAT_COPY_VALUES, &copies[l]));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  IndApp       app;
  KSP          ksp = NULL;
  Mat          J = NULL, J2, ours[8], theirs[8];
  MatNullSpace nsp;
  Vec          b, x, x2, Uloc;
  PetscInt     its[2], n[2], by_blocks[2];
  PetscReal    d[6], dl = 0, dx;
  PetscBool    ok, same = PETSC_TRUE;

  PetscFunctionBeginUser;
  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  PetscCall(RandomProducts(d, &ok));
  ok = (PetscBool)(ok && d[0] < 1e-13 && d[1] < 1e-13 && d[2] < 1e-13 && d[3] < 1e-13 && d[4] < 1e-13 &&
                   d[5] < 1e-13);

  /* the solver's multigrid on its Jacobian (products by blocks, the solver's default), then on a copy of it that has
     PETSc's products, with the interpolations the first set-up made */
  PetscCall(SolverTestCreate(1e-10, &app, &J, &ksp));
  PetscCall(MatCreateVecs(J, &x, &b));
  PetscCall(VecDuplicate(x, &x2));
  PetscCall(VecSet(b, 1.0));
  PetscCall(SolverTestJacobianAtZero(app, J, &Uloc));
  PetscCall(KSPSetOperators(ksp, J, J));
  PetscCall(SolveCounted(ksp, b, x, &its[0]));
  PetscCall(CoarseCopies(ksp, ours, &n[0], &by_blocks[0]));

  PetscCall(MatDuplicate(J, MAT_COPY_VALUES, &J2));
  PetscCall(MatGetNearNullSpace(J, &nsp));
  PetscCall(MatSetNearNullSpace(J2, nsp));
  PetscCall(KSPSetOperators(ksp, J2, J2));
  PetscCall(SolveCounted(ksp, b, x2, &its[1]));
  PetscCall(CoarseCopies(ksp, theirs, &n[1], &by_blocks[1]));
  for (PetscInt l = 0; l < PetscMin(n[0], n[1]); ++l) {
    PetscReal dd;
    PetscBool s;
    PetscCall(Compare(ours[l], theirs[l], &dd, &s));
    dl   = PetscMax(dl, dd);
    same = (PetscBool)(same && s);
  }
  PetscCall(VecAXPY(x2, -1.0, x));
  PetscCall(VecNorm(x2, NORM_2, &dx));
  PetscCall(VecNorm(x, NORM_2, &d[0]));
  dx /= d[0];
  PetscCall(PetscPrintf(PETSC_COMM_WORLD,
    "multigrid: %" PetscInt_FMT " coarse operators above the coarsest, %" PetscInt_FMT " by blocks (%" PetscInt_FMT
    " with PETSc's products); they differ from PETSc's by %.2e at most, same patterns %d; Krylov iterations %"
    PetscInt_FMT " and %" PetscInt_FMT "; solutions differ by %.2e\n", n[0], by_blocks[0], by_blocks[1], (double)dl,
    (int)same, its[0], its[1], (double)dx));
  ok = (PetscBool)(ok && n[0] >= 1 && n[0] == n[1] && by_blocks[0] == n[0] && by_blocks[1] == 0 && dl < 1e-12 &&
                   same && its[0] > 0 && its[0] == its[1] && dx < 1e-8);
  for (PetscInt l = 0; l < n[0]; ++l) PetscCall(MatDestroy(&ours[l]));
  for (PetscInt l = 0; l < n[1]; ++l) PetscCall(MatDestroy(&theirs[l]));
  PetscCall(KSPSetOperators(ksp, J, J));
  PetscCall(MatDestroy(&J2));
  PetscCall(DMRestoreLocalVector(IndAppGetDM(app), &Uloc));
  PetscCall(VecDestroy(&x));
  PetscCall(VecDestroy(&x2));
  PetscCall(VecDestroy(&b));
  PetscCall(IndAppDestroy(&app));
  PetscCall(PetscFinalize());
  return ok ? 0 : 1;
}
