#include "ind_blockmult.h"
#include "blockmult_kernels.h"

#define IND_BLOCKMULT_KEY "IndBlockMult"
#define IND_SINGLE_OF_KEY "IndBlockMultSingleOf"

/* PETSc counts every change of an object in its state (MatAssemblyEnd, MatZeroRowsColumns, a numeric product, an
   array restored for writing); PETSc's library exports the function, but only its private header
   petsc/private/petscimpl.h declares it. */
PETSC_EXTERN PetscErrorCode PetscObjectStateGet(PetscObject, PetscObjectState *);

/* The block index of one SeqAIJ matrix, for the nonzero pattern it was built on. */
typedef struct {
  PetscObjectState nzstate; /* MatGetNonzeroState at the build */
  PetscBool        built;
  PetscBool        blocks; /* the pattern is made of whole blocks */
  PetscBool        simd;   /* the vector kernels (where the CPU has them) */
  PetscInt        *bi, *bj;
  IndBlockRows     rows; /* the block sizes, and bi and bj */
  /* The single-precision copy of the values, read instead of them while single is set. */
  PetscBool        single;
  float           *af;
  PetscInt         naf;
  Mat              outer;     /* the matrix whose local block this is (not referenced: it owns this one) */
  PetscObjectState state[2]; /* of this block and of outer, when af was copied */
} BlockIndex;

static PetscErrorCode BlockIndexDestroy(void *ctx)
{
  BlockIndex *ix = (BlockIndex *)ctx;

  PetscFunctionBegin;
  PetscCall(PetscFree2(ix->bi, ix->bj));
  PetscCall(PetscFree(ix->af));
  PetscCall(PetscFree(ix));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Build(Mat A, BlockIndex *ix)
{
  PetscInt        m, n, nr, rbs, cbs;
  const PetscInt *ia, *ja;
  PetscBool       done;

  PetscFunctionBegin;
  PetscCall(PetscFree2(ix->bi, ix->bj));
  PetscCall(MatGetNonzeroState(A, &ix->nzstate));
  PetscCall(MatGetLocalSize(A, &m, &n));
  PetscCall(MatGetBlockSizes(A, &rbs, &cbs));
  ix->built       = PETSC_TRUE;
  ix->blocks      = (PetscBool)(rbs > 1 && cbs > 1 && m % rbs == 0 && n % cbs == 0);
  ix->rows.rbs    = rbs;
  ix->rows.cbs    = cbs;
  ix->rows.ngroup = ix->blocks ? m / rbs : 0;
  ix->rows.bi = ix->rows.bj = NULL;
  if (!ix->blocks) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(MatGetRowIJ(A, 0, PETSC_FALSE, PETSC_FALSE, &nr, &ia, &ja, &done));
  PetscCheck(done && nr == m, PETSC_COMM_SELF, PETSC_ERR_PLIB, "No row structure of a matrix block");
  for (PetscInt i = 0; i < ix->rows.ngroup && ix->blocks; ++i) ix->blocks = IndBlockRowsGroupFits(ia, ja, rbs, cbs, i);
  if (ix->blocks) {
    PetscCall(PetscMalloc2(ix->rows.ngroup + 1, &ix->bi, ia[m] / (rbs * cbs) + 1, &ix->bj));
    ix->bi[0] = 0;
    for (PetscInt i = 0; i < ix->rows.ngroup; ++i) {
      const PetscInt s = ia[rbs * i], nb = (ia[rbs * i + 1] - s) / cbs;
      for (PetscInt k = 0; k < nb; ++k) ix->bj[ix->bi[i] + k] = ja[s + cbs * k];
      ix->bi[i + 1] = ix->bi[i] + nb;
    }
    ix->rows.bi = ix->bi;
    ix->rows.bj = ix->bj;
  }
  PetscCall(MatRestoreRowIJ(A, 0, PETSC_FALSE, PETSC_FALSE, &nr, &ia, &ja, &done));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The index of A for its present pattern: made at the first product (also on a copy, which MatDuplicate gives
   the same products without the index), rebuilt when the pattern has changed. */
static PetscErrorCode GetIndex(Mat A, BlockIndex **out)
{
  PetscContainer   c;
  BlockIndex      *ix = NULL;
  PetscObjectState st;

  PetscFunctionBegin;
  PetscCall(PetscObjectQuery((PetscObject)A, IND_BLOCKMULT_KEY, (PetscObject *)&c));
  if (!c) {
    PetscCall(PetscNew(&ix));
    ix->simd = IndBlockRowsCpuSimd();
    PetscCall(PetscContainerCreate(PETSC_COMM_SELF, &c));
    PetscCall(PetscContainerSetPointer(c, ix));
    PetscCall(PetscContainerSetUserDestroy(c, BlockIndexDestroy));
    PetscCall(PetscObjectCompose((PetscObject)A, IND_BLOCKMULT_KEY, (PetscObject)c));
    PetscCall(PetscContainerDestroy(&c));
  } else PetscCall(PetscContainerGetPointer(c, (void **)&ix));
  PetscCall(MatGetNonzeroState(A, &st));
  if (!ix->built || st != ix->nzstate) PetscCall(Build(A, ix));
  *out = ix;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The single-precision copy of A's nz values a, made again when A or the matrix it is a block of has changed
   since it was made. */
static PetscErrorCode SingleValues(Mat A, BlockIndex *ix, const PetscScalar *a, PetscInt nz)
{
  PetscObjectState st[2] = {0, 0};

  PetscFunctionBegin;
  PetscCall(PetscObjectStateGet((PetscObject)A, &st[0]));
  if (ix->outer) PetscCall(PetscObjectStateGet((PetscObject)ix->outer, &st[1]));
  if (ix->af && ix->naf == nz && st[0] == ix->state[0] && st[1] == ix->state[1]) PetscFunctionReturn(PETSC_SUCCESS);
  if (ix->naf != nz || !ix->af) {
    PetscCall(PetscFree(ix->af));
    PetscCall(PetscMalloc1(nz + 1, &ix->af));
    ix->naf = nz;
  }
  for (PetscInt k = 0; k < nz; ++k) ix->af[k] = (float)PetscRealPart(a[k]);
  ix->state[0] = st[0];
  ix->state[1] = st[1];
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* y = w + A x (w NULL: y = A x), or y = A^T x */
static PetscErrorCode Product(Mat A, Vec xx, Vec ww, Vec yy, PetscBool transpose)
{
  BlockIndex        *ix = NULL;
  const PetscScalar *a, *x, *w = NULL;
  const float       *af = NULL;
  PetscScalar       *y;
  const PetscInt    *ia, *ja;
  PetscInt           m, n;
  PetscBool          done;

  PetscFunctionBegin;
  PetscCall(GetIndex(A, &ix));
  PetscCall(MatGetLocalSize(A, &m, &n));
  PetscCall(MatGetRowIJ(A, 0, PETSC_FALSE, PETSC_FALSE, &m, &ia, &ja, &done));
  PetscCheck(done, PETSC_COMM_SELF, PETSC_ERR_PLIB, "No row structure of a matrix block");
  PetscCall(MatSeqAIJGetArrayRead(A, &a));
  if (ix->single) {
    PetscCall(SingleValues(A, ix, a, ia[m]));
    af = ix->af;
  }
  PetscCall(VecGetArrayRead(xx, &x));
  /* w may be y: read through the same array */
  if (ww && ww != yy) PetscCall(VecGetArrayRead(ww, &w));
  if (ww == yy) PetscCall(VecGetArray(yy, &y));
  else PetscCall(VecGetArrayWrite(yy, &y));
  if (ww == yy) w = y;
  if (transpose) {
    if (ix->blocks) IndBlockRowsMultTranspose(&ix->rows, ix->simd, n, ia, a, af, x, y);
    else IndRowsMultTranspose(m, n, ia, ja, a, af, x, y);
  } else {
    if (ix->blocks) IndBlockRowsMult(&ix->rows, ix->simd, ia, a, af, x, w, y);
    else IndRowsMult(m, ia, ja, a, af, x, w, y);
  }
  if (ww == yy) PetscCall(VecRestoreArray(yy, &y));
  else PetscCall(VecRestoreArrayWrite(yy, &y));
  if (ww && ww != yy) PetscCall(VecRestoreArrayRead(ww, &w));
  PetscCall(VecRestoreArrayRead(xx, &x));
  PetscCall(MatSeqAIJRestoreArrayRead(A, &a));
  PetscCall(PetscLogFlops(2.0 * ia[m]));
  PetscCall(MatRestoreRowIJ(A, 0, PETSC_FALSE, PETSC_FALSE, &m, &ia, &ja, &done));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MultByBlocks(Mat A, Vec x, Vec y)
{
  PetscFunctionBegin;
  PetscCall(Product(A, x, NULL, y, PETSC_FALSE));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MultAddByBlocks(Mat A, Vec x, Vec w, Vec y)
{
  PetscFunctionBegin;
  PetscCall(Product(A, x, w, y, PETSC_FALSE));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MultTransposeByBlocks(Mat A, Vec x, Vec y)
{
  PetscFunctionBegin;
  PetscCall(Product(A, x, NULL, y, PETSC_TRUE));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The rank's rows with the rank's columns: the whole matrix on one rank, the diagonal block on several (its
   products are the part of MPIAIJ's that overlaps the ghost values' exchange). */
static PetscErrorCode LocalBlock(Mat J, Mat *A)
{
  PetscBool seq, mpi;

  PetscFunctionBegin;
  *A = NULL;
  PetscCall(PetscObjectTypeCompare((PetscObject)J, MATSEQAIJ, &seq));
  PetscCall(PetscObjectTypeCompare((PetscObject)J, MATMPIAIJ, &mpi));
  if (seq) *A = J;
  else if (mpi) PetscCall(MatMPIAIJGetSeqAIJ(J, A, NULL, NULL));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndBlockMultInstall(Mat J, PetscBool *installed)
{
  Mat      A;
  PetscInt rbs, cbs;

  PetscFunctionBegin;
  *installed = PETSC_FALSE;
  PetscCall(LocalBlock(J, &A));
  if (!A) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(MatGetBlockSizes(A, &rbs, &cbs));
  if (rbs < 2 || cbs < 2) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(MatSetOperation(A, MATOP_MULT, (void (*)(void))MultByBlocks));
  PetscCall(MatSetOperation(A, MATOP_MULT_ADD, (void (*)(void))MultAddByBlocks));
  PetscCall(MatSetOperation(A, MATOP_MULT_TRANSPOSE, (void (*)(void))MultTransposeByBlocks));
  *installed = PETSC_TRUE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndBlockMultUseVectorUnits(Mat J, PetscBool use)
{
  Mat         A;
  BlockIndex *ix;

  PetscFunctionBegin;
  PetscCall(LocalBlock(J, &A));
  if (!A) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(GetIndex(A, &ix));
  ix->simd = (PetscBool)(use && IndBlockRowsCpuSimd());
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The index of J's local block if a product has made one (NULL otherwise); makes none. */
static PetscErrorCode ExistingIndex(Mat J, BlockIndex **ix)
{
  Mat            A;
  PetscContainer c = NULL;

  PetscFunctionBegin;
  *ix = NULL;
  PetscCall(LocalBlock(J, &A));
  if (A) PetscCall(PetscObjectQuery((PetscObject)A, IND_BLOCKMULT_KEY, (PetscObject *)&c));
  if (c) PetscCall(PetscContainerGetPointer(c, (void **)ix));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndBlockMultActive(Mat J, PetscBool *active)
{
  BlockIndex *ix;

  PetscFunctionBegin;
  PetscCall(ExistingIndex(J, &ix));
  *active = (PetscBool)(ix && ix->built && ix->blocks);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A's local block's index, with A as the matrix it is a block of (NULL: A has no products by block rows) */
static PetscErrorCode SingleIndex(Mat J, BlockIndex **ix)
{
  Mat  A;
  void (*mult)(void);

  PetscFunctionBegin;
  *ix = NULL;
  PetscCall(LocalBlock(J, &A));
  if (!A) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(MatGetOperation(A, MATOP_MULT, &mult));
  if (mult != (void (*)(void))MultByBlocks) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(GetIndex(A, ix));
  (*ix)->outer = J;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndBlockMultSetSingle(Mat J, PetscBool single, PetscBool *set)
{
  BlockIndex *ix;

  PetscFunctionBegin;
  if (set) *set = PETSC_FALSE;
#if defined(PETSC_USE_REAL_DOUBLE) && !defined(PETSC_USE_COMPLEX)
  PetscCall(SingleIndex(J, &ix));
  if (!ix) PetscFunctionReturn(PETSC_SUCCESS);
  ix->single = single;
  if (!single) {
    PetscCall(PetscFree(ix->af));
    ix->naf = 0;
  }
  if (set) *set = PETSC_TRUE;
#else
  (void)J, (void)single, (void)ix;
#endif
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndBlockMultGetSingle(Mat J, PetscBool *single)
{
  BlockIndex *ix;

  PetscFunctionBegin;
  PetscCall(ExistingIndex(J, &ix));
  *single = (PetscBool)(ix && ix->single);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* J's product with J's local block read in single precision for the length of it (the off-process columns and
   the exchange of their values are MPIAIJ's own, in double). */
static PetscErrorCode SingleOperatorMult(Mat S, Vec x, Vec y)
{
  Mat            J;
  BlockIndex    *ix;
  PetscErrorCode ierr;

  PetscFunctionBegin;
  PetscCall(MatShellGetContext(S, &J));
  PetscCall(SingleIndex(J, &ix));
  if (ix) ix->single = PETSC_TRUE;
  ierr = MatMult(J, x, y);
  if (ix) ix->single = PETSC_FALSE;
  PetscCall(ierr);
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode SingleOperatorDiagonal(Mat S, Vec d)
{
  Mat J;

  PetscFunctionBegin;
  PetscCall(MatShellGetContext(S, &J));
  PetscCall(MatGetDiagonal(J, d));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndBlockMultCreateSingleOperator(Mat J, Mat *S)
{
  PetscInt m, n, M, N;

  PetscFunctionBegin;
  PetscCall(MatGetLocalSize(J, &m, &n));
  PetscCall(MatGetSize(J, &M, &N));
  PetscCall(MatCreateShell(PetscObjectComm((PetscObject)J), m, n, M, N, J, S));
  PetscCall(MatSetBlockSizesFromMats(*S, J, J));
  /* the shell holds J (its context is only a pointer) */
  PetscCall(PetscObjectCompose((PetscObject)*S, IND_SINGLE_OF_KEY, (PetscObject)J));
  PetscCall(MatShellSetOperation(*S, MATOP_MULT, (void (*)(void))SingleOperatorMult));
  PetscCall(MatShellSetOperation(*S, MATOP_GET_DIAGONAL, (void (*)(void))SingleOperatorDiagonal));
  PetscFunctionReturn(PETSC_SUCCESS);
}
