static const char help[] =
  "Products by block rows (IndBlockMultInstall: A x, w + A x, A^T x) against PETSc's own products of the same\n"
  "matrix: 3 x 3 blocks (a Q1 box's node pattern), 6 x 6, 3 x 6 (GAMG's interpolation) and 5 x 5 blocks, with\n"
  "the vector units and with the portable loops, a pattern that stops being made of blocks (multiplied row by\n"
  "row), and empty block rows. Parallel: the diagonal block. In single precision (IndBlockMultSetSingle and the\n"
  "operator of IndBlockMultCreateSingleOperator): within float rounding of the double products, not equal to them,\n"
  "following every change of the values, and leaving the matrix's own products in double.\n"
  "  -n n   nodes per edge of the box (default 7)\n";

#include <petscmat.h>
#include "ind_common.h"
#include "ind_blockmult.h"

/* A matrix with rbs rows and cbs columns per node of an n x n x n box, each node coupled to its 27 neighbours by
   dense rbs x cbs blocks, values from a fixed formula; rows of the node skip (a node number, or -1) are left
   empty. Distributed by nodes. */
static PetscErrorCode BoxMatrix(MPI_Comm comm, PetscInt n, PetscInt rbs, PetscInt cbs, PetscInt skip, Mat *A)
{
  PetscInt     nnode = n * n * n, nloc = PETSC_DECIDE, lo, hi;
  PetscScalar *v;
  PetscInt    *cols;

  PetscFunctionBeginUser;
  PetscCall(PetscSplitOwnership(comm, &nloc, &nnode));
  PetscCall(MatCreate(comm, A));
  PetscCall(MatSetSizes(*A, rbs * nloc, cbs * nloc, rbs * nnode, cbs * nnode));
  PetscCall(MatSetBlockSizes(*A, rbs, cbs));
  PetscCall(MatSetType(*A, MATAIJ));
  PetscCall(MatSeqAIJSetPreallocation(*A, 27 * cbs, NULL));
  PetscCall(MatMPIAIJSetPreallocation(*A, 27 * cbs, NULL, 27 * cbs, NULL));
  PetscCall(MatSetOption(*A, MAT_USE_INODES, PETSC_FALSE));
  PetscCall(MatGetOwnershipRange(*A, &lo, &hi));
  PetscCall(PetscMalloc2(27 * rbs * cbs, &v, 27 * cbs, &cols));
  for (PetscInt node = lo / rbs; node < hi / rbs; ++node) {
    const PetscInt i = node % n, j = (node / n) % n, k = node / (n * n);
    PetscInt       rows[6], nc = 0;
    if (node == skip) continue;
    for (PetscInt r = 0; r < rbs; ++r) rows[r] = rbs * node + r;
    for (PetscInt dk = -1; dk <= 1; ++dk)
      for (PetscInt dj = -1; dj <= 1; ++dj)
        for (PetscInt di = -1; di <= 1; ++di) {
          const PetscInt ii = i + di, jj = j + dj, kk = k + dk;
          if (ii < 0 || jj < 0 || kk < 0 || ii >= n || jj >= n || kk >= n) continue;
          for (PetscInt d = 0; d < cbs; ++d) cols[nc++] = cbs * ((kk * n + jj) * n + ii) + d;
        }
    for (PetscInt q = 0; q < rbs * nc; ++q) v[q] = PetscSinReal((PetscReal)(7 * q + 3 * node + 1)) + (q % 5 ? 0 : 2);
    PetscCall(MatSetValues(*A, rbs, rows, nc, cols, v, INSERT_VALUES));
  }
  PetscCall(PetscFree2(v, cols));
  PetscCall(MatAssemblyBegin(*A, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(*A, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode FillCos(Vec x, PetscInt shift)
{
  PetscInt     lo, hi;
  PetscScalar *xa;

  PetscFunctionBeginUser;
  PetscCall(VecGetOwnershipRange(x, &lo, &hi));
  PetscCall(VecGetArray(x, &xa));
  for (PetscInt i = lo; i < hi; ++i) xa[i - lo] = PetscCosReal((PetscReal)(3 * i + shift));
  PetscCall(VecRestoreArray(x, &xa));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* |y - z| / |z|, the larger of *diff and it kept in *diff */
static PetscErrorCode Worst(Vec y, Vec z, PetscReal *diff)
{
  PetscReal nz, d;

  PetscFunctionBeginUser;
  PetscCall(VecAXPY(y, -1.0, z));
  PetscCall(VecNorm(y, NORM_2, &d));
  PetscCall(VecNorm(z, NORM_2, &nz));
  *diff = PetscMax(*diff, d / nz);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The largest relative difference between A's and B's products A x, w + A x (w apart and w = y) and A^T x, for
   fixed x and w; and whether every rank multiplied A by block rows */
static PetscErrorCode Compare(Mat A, Mat B, PetscReal *diff, PetscBool *blocks)
{
  Vec x, w, y, z, xt, yt, zt;

  PetscFunctionBeginUser;
  *diff = 0;
  PetscCall(MatCreateVecs(A, &x, &y));
  PetscCall(VecDuplicate(y, &z));
  PetscCall(VecDuplicate(y, &w));
  PetscCall(MatCreateVecs(A, &yt, &xt));
  PetscCall(VecDuplicate(yt, &zt));
  PetscCall(FillCos(x, 1));
  PetscCall(FillCos(w, 2));
  PetscCall(FillCos(xt, 5));
  PetscCall(MatMult(A, x, y));
  PetscCall(MatMult(B, x, z));
  PetscCall(Worst(y, z, diff));
  PetscCall(MatMultAdd(A, x, w, y));
  PetscCall(MatMultAdd(B, x, w, z));
  PetscCall(Worst(y, z, diff));
  PetscCall(VecCopy(w, y));
  PetscCall(VecCopy(w, z));
  PetscCall(MatMultAdd(A, x, y, y));
  PetscCall(MatMultAdd(B, x, z, z));
  PetscCall(Worst(y, z, diff));
  PetscCall(MatMultTranspose(A, xt, yt));
  PetscCall(MatMultTranspose(B, xt, zt));
  PetscCall(Worst(yt, zt, diff));
  PetscCall(IndBlockMultActive(A, blocks));
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, blocks, 1, MPIU_BOOL, MPI_LAND, PetscObjectComm((PetscObject)A)));
  PetscCall(VecDestroy(&zt));
  PetscCall(VecDestroy(&yt));
  PetscCall(VecDestroy(&xt));
  PetscCall(VecDestroy(&w));
  PetscCall(VecDestroy(&z));
  PetscCall(VecDestroy(&y));
  PetscCall(VecDestroy(&x));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* One case: A made, a copy for PETSc's product before the install, compared with and without vector units. */
static PetscErrorCode Case(const char *name, PetscInt n, PetscInt rbs, PetscInt cbs, PetscInt skip,
                           PetscBool expect_blocks, PetscBool *ok)
{
  Mat       A, B;
  PetscBool installed, blocks[2];
  PetscReal diff[2];

  PetscFunctionBeginUser;
  PetscCall(BoxMatrix(PETSC_COMM_WORLD, n, rbs, cbs, skip, &A));
  PetscCall(MatDuplicate(A, MAT_COPY_VALUES, &B));
  PetscCall(IndBlockMultInstall(A, &installed));
  PetscCall(Compare(A, B, &diff[0], &blocks[0]));
  PetscCall(IndBlockMultUseVectorUnits(A, PETSC_FALSE));
  PetscCall(Compare(A, B, &diff[1], &blocks[1]));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD,
                        "%s: installed %d, by blocks %d / %d, largest difference %.1e (vector) %.1e (loops)\n",
                        name, (int)installed, (int)blocks[0], (int)blocks[1], (double)diff[0], (double)diff[1]));
  *ok = (PetscBool)(*ok && installed && blocks[0] == expect_blocks && blocks[1] == expect_blocks && diff[0] < 1e-14 &&
                    diff[1] < 1e-14);
  PetscCall(MatDestroy(&B));
  PetscCall(MatDestroy(&A));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Single-precision products of one case: within float rounding of PETSc's (and not equal: the copy is read), again
   after each way the values change (assembly, scaling, zeroed rows and columns), with vector units and loops. */
static PetscErrorCode SingleCase(const char *name, PetscInt n, PetscInt rbs, PetscInt cbs, PetscBool *ok)
{
  Mat       A, B;
  PetscBool installed, set, blocks;
  PetscReal diff[5], lo = PETSC_MAX_REAL, hi = 0;
  PetscInt  rstart, row;

  PetscFunctionBeginUser;
  PetscCall(BoxMatrix(PETSC_COMM_WORLD, n, rbs, cbs, -1, &A));
  PetscCall(BoxMatrix(PETSC_COMM_WORLD, n, rbs, cbs, -1, &B));
  PetscCall(IndBlockMultInstall(A, &installed));
  PetscCall(IndBlockMultSetSingle(A, PETSC_TRUE, &set));
  PetscCall(Compare(A, B, &diff[0], &blocks));
  PetscCall(IndBlockMultUseVectorUnits(A, PETSC_FALSE));
  PetscCall(Compare(A, B, &diff[1], &blocks));
  PetscCall(IndBlockMultUseVectorUnits(A, PETSC_TRUE));
  /* new values: assembled again (one entry changed on each rank), scaled, rows and columns zeroed */
  PetscCall(MatGetOwnershipRange(A, &rstart, NULL));
  PetscCall(MatSetValue(A, rstart, cbs * (rstart / rbs), 100.0, ADD_VALUES)); /* in the node's own block */
  PetscCall(MatSetValue(B, rstart, cbs * (rstart / rbs), 100.0, ADD_VALUES));
  PetscCall(MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyBegin(B, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(B, MAT_FINAL_ASSEMBLY));
  PetscCall(Compare(A, B, &diff[2], &blocks));
  PetscCall(MatScale(A, 3.0));
  PetscCall(MatScale(B, 3.0));
  PetscCall(Compare(A, B, &diff[3], &blocks));
  if (rbs == cbs) {
    row = rstart + 1;
    PetscCall(MatZeroRowsColumns(A, 1, &row, 7.0, NULL, NULL));
    PetscCall(MatZeroRowsColumns(B, 1, &row, 7.0, NULL, NULL));
  }
  PetscCall(Compare(A, B, &diff[4], &blocks));
  for (int k = 0; k < 5; ++k) {
    lo = PetscMin(lo, diff[k]);
    hi = PetscMax(hi, diff[k]);
  }
  PetscCall(PetscPrintf(PETSC_COMM_WORLD,
    "%s in single precision: set %d, by blocks %d, differences %.1e (vector) %.1e (loops), after new values "
    "%.1e (assembly) %.1e (scaled) %.1e (rows zeroed)\n", name, (int)set, (int)blocks, (double)diff[0],
    (double)diff[1], (double)diff[2], (double)diff[3], (double)diff[4]));
  /* float rounding is 6e-8 an entry; a copy left stale by new values would differ by O(1) */
  *ok = (PetscBool)(*ok && installed && set && blocks && lo > 1e-12 && hi < 1e-6);
  PetscCall(MatDestroy(&B));
  PetscCall(MatDestroy(&A));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The single-precision operator of a matrix: its products within float rounding of the matrix's, which stay in
   double (equal to a copy's to round-off of the same order) before and after. */
static PetscErrorCode SingleOperatorCase(PetscInt n, PetscBool *ok)
{
  Mat       A, B, S;
  Vec       x, y, z;
  PetscBool installed;
  PetscReal d[3], nz;

  PetscFunctionBeginUser;
  PetscCall(BoxMatrix(PETSC_COMM_WORLD, n, 3, 3, -1, &A));
  PetscCall(BoxMatrix(PETSC_COMM_WORLD, n, 3, 3, -1, &B));
  PetscCall(IndBlockMultInstall(A, &installed));
  PetscCall(IndBlockMultCreateSingleOperator(A, &S));
  PetscCall(MatCreateVecs(A, &x, &y));
  PetscCall(VecDuplicate(y, &z));
  PetscCall(FillCos(x, 1));
  PetscCall(MatMult(B, x, z));
  PetscCall(VecNorm(z, NORM_2, &nz));
  PetscCall(MatMult(A, x, y));
  PetscCall(VecAXPY(y, -1.0, z));
  PetscCall(VecNorm(y, NORM_2, &d[0]));
  PetscCall(MatMult(S, x, y));
  PetscCall(VecAXPY(y, -1.0, z));
  PetscCall(VecNorm(y, NORM_2, &d[1]));
  PetscCall(MatMult(A, x, y));
  PetscCall(VecAXPY(y, -1.0, z));
  PetscCall(VecNorm(y, NORM_2, &d[2]));
  for (int k = 0; k < 3; ++k) d[k] /= nz;
  PetscCall(PetscPrintf(PETSC_COMM_WORLD,
    "single-precision operator: matrix %.1e, operator %.1e, matrix after it %.1e from PETSc's product\n",
    (double)d[0], (double)d[1], (double)d[2]));
  *ok = (PetscBool)(*ok && installed && d[0] < 1e-14 && d[2] < 1e-14 && d[1] > 1e-12 && d[1] < 1e-6);
  PetscCall(VecDestroy(&z));
  PetscCall(VecDestroy(&y));
  PetscCall(VecDestroy(&x));
  PetscCall(MatDestroy(&S));
  PetscCall(MatDestroy(&B));
  PetscCall(MatDestroy(&A));
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  PetscInt  n  = 7;
  PetscBool ok = PETSC_TRUE;

  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  PetscCall(PetscOptionsGetInt(NULL, NULL, "-n", &n, NULL));
  PetscCall(Case("3 x 3 blocks", n, 3, 3, -1, PETSC_TRUE, &ok));
  PetscCall(Case("6 x 6 blocks", n, 6, 6, -1, PETSC_TRUE, &ok));
  PetscCall(Case("3 x 6 blocks", n, 3, 6, -1, PETSC_TRUE, &ok));
  PetscCall(Case("5 x 5 blocks (portable loops only)", n, 5, 5, -1, PETSC_TRUE, &ok));
  /* the first node's and the last node's rows empty: their products are 0 */
  PetscCall(Case("3 x 3 blocks, first node empty", n, 3, 3, 0, PETSC_TRUE, &ok));
  PetscCall(Case("3 x 3 blocks, last node empty", n, 3, 3, n * n * n - 1, PETSC_TRUE, &ok));
  PetscCall(Case("3 x 6 blocks, last node empty", n, 3, 6, n * n * n - 1, PETSC_TRUE, &ok));
  {
    /* a pattern that stops being made of blocks: one entry more in one row, the matrix reassembled */
    Mat       A, B;
    PetscBool installed, blocks[2];
    PetscReal diff[2];
    PetscInt  lo, hi;
    PetscCall(BoxMatrix(PETSC_COMM_WORLD, n, 3, 3, -1, &A));
    PetscCall(BoxMatrix(PETSC_COMM_WORLD, n, 3, 3, -1, &B)); /* not a copy: MatDuplicate would copy the product */
    PetscCall(IndBlockMultInstall(A, &installed));
    PetscCall(Compare(A, A, &diff[0], &blocks[0]));
    PetscCall(MatSetOption(A, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_FALSE));
    PetscCall(MatSetOption(B, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_FALSE));
    PetscCall(MatGetOwnershipRange(A, &lo, &hi));
    {
      const PetscInt last = hi - 1; /* this rank's last row: its first column is then in its own block */
      PetscCall(MatSetValue(A, last, lo, 0.25, ADD_VALUES));
      PetscCall(MatSetValue(B, last, lo, 0.25, ADD_VALUES));
    }
    PetscCall(MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY));
    PetscCall(MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY));
    PetscCall(MatAssemblyBegin(B, MAT_FINAL_ASSEMBLY));
    PetscCall(MatAssemblyEnd(B, MAT_FINAL_ASSEMBLY));
    PetscCall(Compare(A, B, &diff[1], &blocks[1]));
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "pattern changed: by blocks %d before, %d after; difference %.1e\n",
                          (int)blocks[0], (int)blocks[1], (double)diff[1]));
    ok = (PetscBool)(ok && blocks[0] && !blocks[1] && diff[1] < 1e-14);
    PetscCall(MatDestroy(&B));
    PetscCall(MatDestroy(&A));
  }
  PetscCall(SingleCase("3 x 3 blocks", n, 3, 3, &ok));
  PetscCall(SingleCase("6 x 6 blocks", n, 6, 6, &ok));
  PetscCall(SingleCase("3 x 6 blocks", n, 3, 6, &ok));
  PetscCall(SingleCase("5 x 5 blocks", n, 5, 5, &ok));
  PetscCall(SingleOperatorCase(n, &ok));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s\n", ok ? "all block products agree" : "FAILED"));
  PetscCall(PetscFinalize());
  return ok ? 0 : 1;
}
