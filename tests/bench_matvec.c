static const char help[] =
  "Throughput of the matrix-vector product that bounds a Krylov iteration (doc/performance.md): the 27-node\n"
  "pattern of a Q1 box of n^3 cells in 3 x 3 blocks, as the Jacobian of the plastic cube stores it, multiplied\n"
  "as AIJ with PETSc's inode kernel (rows of a node side by side), as AIJ row by row (-jac_inodes 0), as AIJ by\n"
  "block rows (the Jacobian's choice, -jac_block_products: with the CPU's vector units and with portable loops;\n"
  "in single precision as the multigrid reads it, -newton_pc_single) and as BAIJ with 3 x 3 blocks, beside a\n"
  "streaming read of the AIJ arrays. Prints one table; not a test.\n"
  "  -n n         cells per edge (default 64: 823,875 dofs)\n"
  "  -repeat r    products timed (the fastest is reported; default 10)\n";

#include <petscmat.h>
#include "ind_common.h"
#include "ind_blockmult.h"
#include <petsctime.h>

/* The fastest of r products y = A x, in seconds. */
static PetscErrorCode Product(Mat A, Vec x, Vec y, PetscInt r, PetscLogDouble *best)
{
  PetscLogDouble t0, t1;

  PetscFunctionBeginUser;
  *best = 1e30;
  for (PetscInt k = 0; k < r; ++k) {
    PetscCall(PetscTime(&t0));
    PetscCall(MatMult(A, x, y));
    PetscCall(PetscTime(&t1));
    *best = PetscMin(*best, t1 - t0);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode BoxPattern(PetscInt n, Mat *A)
{
  const PetscInt m = n + 1, nnode = m * m * m;

  PetscFunctionBeginUser;
  PetscCall(MatCreateSeqAIJ(PETSC_COMM_SELF, 3 * nnode, 3 * nnode, 81, NULL, A));
  PetscCall(MatSetBlockSize(*A, 3));
  for (PetscInt node = 0; node < nnode; ++node) {
    const PetscInt i = node % m, j = (node / m) % m, k = node / (m * m);
    PetscInt       rows[3] = {3 * node, 3 * node + 1, 3 * node + 2}, cols[81], nc = 0;
    PetscScalar    v[3 * 81];
    for (PetscInt dk = -1; dk <= 1; ++dk)
      for (PetscInt dj = -1; dj <= 1; ++dj)
        for (PetscInt di = -1; di <= 1; ++di) {
          const PetscInt ii = i + di, jj = j + dj, kk = k + dk;
          if (ii < 0 || jj < 0 || kk < 0 || ii >= m || jj >= m || kk >= m) continue;
          for (PetscInt d = 0; d < 3; ++d) cols[nc++] = 3 * ((kk * m + jj) * m + ii) + d;
        }
    for (PetscInt q = 0; q < 3 * nc; ++q) v[q] = 1.0 / (1 + q % 7);
    PetscCall(MatSetValues(*A, 3, rows, nc, cols, v, INSERT_VALUES));
  }
  PetscCall(MatAssemblyBegin(*A, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(*A, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  PetscInt           n = 64, repeat = 10, nr;
  Mat                A, B, C, D;
  Vec                x, y, z;
  const PetscInt    *ia, *ja;
  const PetscScalar *a;
  PetscBool          done;
  PetscLogDouble     t0, t1, inode, rows, blocks, grouped[2], single[2], read = 1e30;
  PetscReal          diff[6], sum = 0;
  PetscBool          installed;

  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  PetscCall(PetscOptionsGetInt(NULL, NULL, "-n", &n, NULL));
  PetscCall(PetscOptionsGetInt(NULL, NULL, "-repeat", &repeat, NULL));
  PetscCall(BoxPattern(n, &A));
  PetscCall(MatDuplicate(A, MAT_COPY_VALUES, &B));
  PetscCall(MatSetOption(B, MAT_USE_INODES, PETSC_FALSE));
  PetscCall(MatConvert(A, MATSEQBAIJ, MAT_INITIAL_MATRIX, &C));
  PetscCall(MatDuplicate(B, MAT_COPY_VALUES, &D));
  PetscCall(MatSetBlockSize(D, 3));
  PetscCall(IndBlockMultInstall(D, &installed));
  PetscCheck(installed, PETSC_COMM_SELF, PETSC_ERR_PLIB, "no products by block rows");
  PetscCall(MatCreateVecs(A, &x, &y));
  PetscCall(VecDuplicate(y, &z));
  PetscCall(VecSetRandom(x, NULL));
  PetscCall(Product(A, x, y, repeat, &inode));
  PetscCall(Product(B, x, z, repeat, &rows));
  PetscCall(VecAXPY(z, -1, y));
  PetscCall(VecNorm(z, NORM_INFINITY, &diff[0]));
  PetscCall(Product(C, x, z, repeat, &blocks));
  PetscCall(VecAXPY(z, -1, y));
  PetscCall(VecNorm(z, NORM_INFINITY, &diff[1]));
  for (int k = 0; k < 2; ++k) {
    PetscCall(IndBlockMultUseVectorUnits(D, (PetscBool)(k == 0)));
    PetscCall(Product(D, x, z, repeat, &grouped[k]));
    PetscCall(VecAXPY(z, -1, y));
    PetscCall(VecNorm(z, NORM_INFINITY, &diff[2 + k]));
  }
  PetscCall(IndBlockMultSetSingle(D, PETSC_TRUE, NULL));
  for (int k = 0; k < 2; ++k) {
    PetscCall(IndBlockMultUseVectorUnits(D, (PetscBool)(k == 0)));
    PetscCall(Product(D, x, z, repeat, &single[k]));
    PetscCall(VecAXPY(z, -1, y));
    PetscCall(VecNorm(z, NORM_INFINITY, &diff[4 + k]));
  }
  PetscCall(MatGetRowIJ(A, 0, PETSC_FALSE, PETSC_FALSE, &nr, &ia, &ja, &done));
  PetscCheck(done, PETSC_COMM_SELF, PETSC_ERR_SUP, "no row structure");
  PetscCall(MatSeqAIJGetArrayRead(A, &a));
  for (PetscInt r = 0; r < repeat; ++r) {
    /* the values and column indices streamed once, as any product must read them */
    PetscScalar s[4] = {0, 0, 0, 0};
    PetscInt    js   = 0, k;
    PetscCall(PetscTime(&t0));
    for (k = 0; k + 4 <= ia[nr]; k += 4) {
      s[0] += a[k];
      s[1] += a[k + 1];
      s[2] += a[k + 2];
      s[3] += a[k + 3];
      js += ja[k] + ja[k + 1] + ja[k + 2] + ja[k + 3];
    }
    PetscCall(PetscTime(&t1));
    sum += s[0] + s[1] + s[2] + s[3] + js;
    read = PetscMin(read, t1 - t0);
  }
  {
    const double nnz = (double)ia[nr], aij = nnz * (sizeof(PetscScalar) + sizeof(PetscInt));
    PetscCall(PetscPrintf(PETSC_COMM_SELF,
                          "n %" PetscInt_FMT ", %" PetscInt_FMT " dofs, %.0f entries, AIJ arrays %.0f MB "
                          "(products agree to %.1e, %.1e, %.1e and %.1e; in single precision to %.1e and %.1e; "
                          "checksum %g)\n",
                          n, nr, nnz, aij / 1e6, (double)diff[0], (double)diff[1], (double)diff[2], (double)diff[3],
                          (double)diff[4], (double)diff[5], (double)sum));
    PetscCall(PetscPrintf(PETSC_COMM_SELF, "| product | s | GB/s of the AIJ arrays |\n|---|---|---|\n"));
    PetscCall(PetscPrintf(PETSC_COMM_SELF, "| AIJ, inode kernel (PETSc's default) | %.4f | %.2f |\n", inode,
                          aij / inode / 1e9));
    PetscCall(PetscPrintf(PETSC_COMM_SELF, "| AIJ, row by row (-jac_inodes 0 -jac_block_products 0) | %.4f | %.2f |\n",
                          rows, aij / rows / 1e9));
    PetscCall(PetscPrintf(PETSC_COMM_SELF, "| AIJ, by block rows (-jac_block_products), vector units | %.4f | %.2f |\n",
                          grouped[0], aij / grouped[0] / 1e9));
    PetscCall(PetscPrintf(PETSC_COMM_SELF, "| AIJ, by block rows, portable loops | %.4f | %.2f |\n", grouped[1],
                          aij / grouped[1] / 1e9));
    PetscCall(PetscPrintf(PETSC_COMM_SELF, "| AIJ, by block rows, single precision, vector units | %.4f | %.2f |\n",
                          single[0], aij / single[0] / 1e9));
    PetscCall(PetscPrintf(PETSC_COMM_SELF, "| AIJ, by block rows, single precision, portable loops | %.4f | %.2f |\n",
                          single[1], aij / single[1] / 1e9));
    PetscCall(PetscPrintf(PETSC_COMM_SELF, "| BAIJ, 3 x 3 blocks | %.4f | %.2f |\n", blocks,
                          aij / blocks / 1e9));
    PetscCall(PetscPrintf(PETSC_COMM_SELF, "| the AIJ arrays read, no product | %.4f | %.2f |\n", read,
                          aij / read / 1e9));
  }
  PetscCall(MatSeqAIJRestoreArrayRead(A, &a));
  PetscCall(MatRestoreRowIJ(A, 0, PETSC_FALSE, PETSC_FALSE, &nr, &ia, &ja, &done));
  PetscCall(VecDestroy(&z));
  PetscCall(VecDestroy(&y));
  PetscCall(VecDestroy(&x));
  PetscCall(MatDestroy(&D));
  PetscCall(MatDestroy(&C));
  PetscCall(MatDestroy(&B));
  PetscCall(MatDestroy(&A));
  PetscCall(PetscFinalize());
  return 0;
}
