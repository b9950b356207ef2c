#include "galerkin_impl.h"

#define IND_GALERKIN_PLAN  "IndGalerkinPlan"
#define IND_GALERKIN_PETSC "IndGalerkinPetsc"

/* Exported by PETSc's library, declared only in its private petsc/private/petscimpl.h (as in blockmult.c). */
PETSC_EXTERN PetscErrorCode PetscObjectStateGet(PetscObject, PetscObjectState *);

/* PETSc's product set-up for the type of the matrix the products are installed on */
typedef struct {
  PetscErrorCode (*petsc)(Mat);
} Hook;

PetscErrorCode IndGalerkinLocalParts(Mat M, Mat *Md, Mat *Mo, const PetscInt **garray)
{
  PetscBool mpi;

  PetscFunctionBegin;
  PetscCall(PetscObjectTypeCompare((PetscObject)M, MATMPIAIJ, &mpi));
  *Md = M, *Mo = NULL, *garray = NULL;
  if (mpi) PetscCall(MatMPIAIJGetSeqAIJ(M, Md, Mo, garray));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Whether every group of rbs rows of the SeqAIJ block B has one pattern of whole blocks of cbs columns; with
   garray, B's columns are compressed and their global ones must be whole blocks too. */
static PetscErrorCode BlockFits(Mat B, PetscInt rbs, PetscInt cbs, const PetscInt *garray, PetscBool *fits)
{
  const PetscInt *ia, *ja;
  PetscInt        m, n;
  PetscBool       done;

  PetscFunctionBegin;
  PetscCall(MatGetLocalSize(B, &m, &n));
  *fits = (PetscBool)(m % rbs == 0 && n % cbs == 0);
  for (PetscInt c = 0; garray && *fits && c < n; c += cbs)
    for (PetscInt d = 0; d < cbs; ++d)
      if (garray[c + d] != garray[c] + d || garray[c] % cbs) *fits = PETSC_FALSE;
  if (!*fits) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(MatGetRowIJ(B, 0, PETSC_FALSE, PETSC_FALSE, &m, &ia, &ja, &done));
  PetscCheck(done, PETSC_COMM_SELF, PETSC_ERR_PLIB, "No row structure of a matrix block");
  for (PetscInt i = 0; i < m / rbs && *fits; ++i) *fits = IndBlockRowsGroupFits(ia, ja, rbs, cbs, i);
  PetscCall(MatRestoreRowIJ(B, 0, PETSC_FALSE, PETSC_FALSE, &m, &ia, &ja, &done));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MatFits(Mat M, PetscInt rbs, PetscInt cbs, PetscBool *fits)
{
  Mat             Md, Mo;
  const PetscInt *garray;
  PetscInt        c0;

  PetscFunctionBegin;
  PetscCall(IndGalerkinLocalParts(M, &Md, &Mo, &garray));
  PetscCall(MatGetOwnershipRangeColumn(M, &c0, NULL));
  *fits = (PetscBool)(c0 % cbs == 0);
  if (*fits) PetscCall(BlockFits(Md, rbs, cbs, NULL, fits));
  if (*fits && Mo) PetscCall(BlockFits(Mo, rbs, cbs, garray, fits));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Whether P^T A P (and A P) can be made by blocks, on every rank. */
static PetscErrorCode Eligible(Mat A, Mat P, PetscBool *ok)
{
  PetscBool aseq, ampi, pseq, pmpi;
  PetscInt  fbs, fbs2, cbs;

  PetscFunctionBegin;
  PetscCall(PetscObjectTypeCompare((PetscObject)A, MATSEQAIJ, &aseq));
  PetscCall(PetscObjectTypeCompare((PetscObject)A, MATMPIAIJ, &ampi));
  PetscCall(PetscObjectTypeCompare((PetscObject)P, MATSEQAIJ, &pseq));
  PetscCall(PetscObjectTypeCompare((PetscObject)P, MATMPIAIJ, &pmpi));
  PetscCall(MatGetBlockSizes(A, &fbs, &fbs2));
  PetscCall(MatGetBlockSizes(P, NULL, &cbs));
  /* blocks of at most 8 x 8 (RowsNumericT's copy of a block of A) */
  *ok = (PetscBool)(((aseq && pseq) || (ampi && pmpi)) && fbs == fbs2 && fbs > 1 && cbs > 1 && fbs <= 8 && cbs <= 8);
  if (*ok) PetscCall(MatFits(A, fbs, fbs, ok));
  if (*ok) PetscCall(MatFits(P, fbs, cbs, ok));
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, ok, 1, MPIU_BOOL, MPI_LAND, PetscObjectComm((PetscObject)A)));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode PlanDestroy(void *ctx)
{
  IndGalerkinPlan *pl = (IndGalerkinPlan *)ctx;

  PetscFunctionBegin;
  for (int s = 0; s < IND_GALERKIN_NSOURCE; ++s) PetscCall(PetscFree2(pl->src[s].bi, pl->src[s].bj));
  if (pl->Pg) PetscCall(MatDestroySubMatrices(1, &pl->Pg));
  PetscCall(ISDestroy(&pl->gis));
  PetscCall(ISDestroy(&pl->allcols));
  PetscCall(PetscFree2(pl->cglob, pl->crow));
  PetscCall(PetscFree2(pl->ci, pl->cj));
  PetscCall(PetscFree4(pl->dpos, pl->opos, pl->nleft, pl->ndiag));
  PetscCall(PetscFree3(pl->gi, pl->gj, pl->gv));
  PetscCall(PetscFree4(pl->scount, pl->sdispl, pl->rcount, pl->rdispl));
  PetscCall(PetscFree3(pl->rrow, pl->rk, pl->rv));
  PetscCall(PetscFree2(pl->slot, pl->list));
  PetscCall(PetscFree(pl->apv));
  PetscCall(PetscFree(pl));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The sources of the rows of P that A reaches (for the present P): P's diagonal and off-process blocks, and the
   ghost rows; with structure, their blocks by rows in global coarse blocks. */
static PetscErrorCode SetSources(IndGalerkinPlan *pl, Mat P, PetscBool structure)
{
  Mat             Pd, Po;
  const PetscInt *garray;
  PetscInt        c0;

  PetscFunctionBegin;
  PetscCall(IndGalerkinLocalParts(P, &Pd, &Po, &garray));
  PetscCall(MatGetOwnershipRangeColumn(P, &c0, NULL));
  pl->src[IND_GALERKIN_DIAG].M     = Pd;
  pl->src[IND_GALERKIN_OFF].M      = Po;
  pl->src[IND_GALERKIN_GHOST].M    = pl->Pg ? pl->Pg[0] : NULL;
  pl->src[IND_GALERKIN_DIAG].row0  = pl->src[IND_GALERKIN_OFF].row0 = 0;
  pl->src[IND_GALERKIN_DIAG].nrow  = pl->src[IND_GALERKIN_OFF].nrow = pl->nfb;
  pl->src[IND_GALERKIN_GHOST].row0 = pl->nfb;
  pl->src[IND_GALERKIN_GHOST].nrow = pl->ngb;
  for (int s = 0; structure && s < IND_GALERKIN_NSOURCE; ++s) {
    IndGalerkinSource *ps = &pl->src[s];
    const PetscInt    *ia, *ja, fbs = pl->fbs, cbs = pl->cbs;
    PetscInt           n;
    PetscBool          done, fits;
    if (!ps->M) continue;
    /* the ghost rows are rows that fit on their owners; checked all the same */
    PetscCall(BlockFits(ps->M, fbs, cbs, s == IND_GALERKIN_OFF ? garray : NULL, &fits));
    PetscCheck(fits, PETSC_COMM_SELF, PETSC_ERR_PLIB, "Rows of P not made of whole blocks");
    PetscCall(MatGetRowIJ(ps->M, 0, PETSC_FALSE, PETSC_FALSE, &n, &ia, &ja, &done));
    PetscCall(PetscMalloc2(ps->nrow + 1, &ps->bi, ia[n] / (fbs * cbs) + 1, &ps->bj));
    ps->bi[0] = 0;
    for (PetscInt K = 0; K < ps->nrow; ++K) {
      const PetscInt s0 = ia[K * fbs], nb = (ia[K * fbs + 1] - s0) / cbs;
      for (PetscInt k = 0; k < nb; ++k) {
        const PetscInt col = ja[s0 + k * cbs];
        ps->bj[ps->bi[K] + k] = (s == IND_GALERKIN_DIAG ? col + c0 : s == IND_GALERKIN_OFF ? garray[col] : col) / cbs;
      }
      ps->bi[K + 1] = ps->bi[K] + nb;
    }
    PetscCall(MatRestoreRowIJ(ps->M, 0, PETSC_FALSE, PETSC_FALSE, &n, &ia, &ja, &done));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The sources' row starts and values (get true) for a phase, or their release */
static PetscErrorCode SourceArrays(IndGalerkinPlan *pl, PetscBool get)
{
  PetscFunctionBegin;
  for (int s = 0; s < IND_GALERKIN_NSOURCE; ++s) {
    IndGalerkinSource *ps = &pl->src[s];
    const PetscInt    *ja;
    PetscInt           n;
    PetscBool          done;
    if (!ps->M) continue;
    if (get) {
      PetscCall(MatGetRowIJ(ps->M, 0, PETSC_FALSE, PETSC_FALSE, &n, &ps->ia, &ja, &done));
      PetscCall(MatSeqAIJGetArrayRead(ps->M, &ps->va));
    } else {
      PetscCall(MatSeqAIJRestoreArrayRead(ps->M, &ps->va));
      PetscCall(MatRestoreRowIJ(ps->M, 0, PETSC_FALSE, PETSC_FALSE, &n, &ps->ia, &ja, &done));
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A's diagonal and off-process blocks' rows and values (get true), or their release */
static PetscErrorCode AArrays(Mat A, const PetscInt *ia[2], const PetscInt *ja[2], const PetscScalar *av[2],
                              PetscBool get)
{
  Mat             M[2];
  const PetscInt *garray;
  PetscInt        n;
  PetscBool       done;

  PetscFunctionBegin;
  PetscCall(IndGalerkinLocalParts(A, &M[0], &M[1], &garray));
  for (int p = 0; p < 2; ++p) {
    if (!M[p]) continue;
    if (get) {
      PetscCall(MatGetRowIJ(M[p], 0, PETSC_FALSE, PETSC_FALSE, &n, &ia[p], &ja[p], &done));
      if (av) PetscCall(MatSeqAIJGetArrayRead(M[p], &av[p]));
    } else {
      if (av) PetscCall(MatSeqAIJRestoreArrayRead(M[p], &av[p]));
      PetscCall(MatRestoreRowIJ(M[p], 0, PETSC_FALSE, PETSC_FALSE, &n, &ia[p], &ja[p], &done));
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode GetPlan(Mat C, IndGalerkinPlan **pl)
{
  PetscContainer container;

  PetscFunctionBegin;
  PetscCall(PetscObjectQuery((PetscObject)C, IND_GALERKIN_PLAN, (PetscObject *)&container));
  PetscCheck(container, PETSC_COMM_SELF, PETSC_ERR_PLIB, "A Galerkin product without its plan");
  PetscCall(PetscContainerGetPointer(container, (void **)pl));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Numeric(Mat C)
{
  Mat                A, P, Cd, Co;
  IndGalerkinPlan   *pl;
  const PetscInt    *garray, *ia[2] = {NULL, NULL}, *ja[2] = {NULL, NULL};
  const PetscScalar *av[2] = {NULL, NULL};
  PetscScalar       *cd, *co = NULL;
  PetscObjectState   st;
  PetscLogDouble     flops;
  PetscBool          refresh;
  PetscMPIInt        size;
  MPI_Comm           comm = PetscObjectComm((PetscObject)C);

  PetscFunctionBegin;
  PetscCall(MatProductGetMats(C, &A, &P, NULL));
  PetscCall(GetPlan(C, &pl));
  PetscCall(MatGetNonzeroState(A, &st));
  PetscCheck(st == pl->anz, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONGSTATE,
             "The pattern of a matrix changed after its Galerkin product was made");
  PetscCall(MatGetNonzeroState(P, &st));
  PetscCheck(st == pl->pnz, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONGSTATE,
             "The pattern of an interpolation changed after its Galerkin product was made");
  /* P's values are read in place; only the copies of its ghost rows follow a change */
  PetscCall(PetscObjectStateGet((PetscObject)P, &st));
  refresh = (PetscBool)(st != pl->pstate);
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &refresh, 1, MPIU_BOOL, MPI_LOR, comm));
  if (refresh && pl->Pg) PetscCall(MatCreateSubMatrices(P, 1, &pl->gis, &pl->allcols, MAT_REUSE_MATRIX, &pl->Pg));
  pl->pstate = st;
  PetscCall(SetSources(pl, P, PETSC_FALSE));
  PetscCall(SourceArrays(pl, PETSC_TRUE));
  PetscCall(AArrays(A, ia, ja, av, PETSC_TRUE));
  PetscCall(IndGalerkinLocalParts(C, &Cd, &Co, &garray));
  PetscCall(MatSeqAIJGetArray(Cd, &cd));
  if (Co) PetscCall(MatSeqAIJGetArray(Co, &co));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  if (pl->ab) IndGalerkinProductNumeric(pl, ia, ja, av, cd, co, &flops); /* sets every block */
  else {
    PetscCall(PetscArrayzero(cd, pl->dnz));
    if (co) PetscCall(PetscArrayzero(co, pl->onz));
    PetscCall(PetscArrayzero(pl->gv, pl->gi[pl->ngr] * pl->cbs * pl->cbs));
    IndGalerkinRowsNumeric(pl, ia, ja, av, cd, co, &flops);
  }
  if (size > 1 && !pl->ab) {
    const PetscInt cb2 = pl->cbs * pl->cbs;
    PetscCallMPI(MPI_Alltoallv(pl->gv, pl->scount, pl->sdispl, MPIU_SCALAR, pl->rv, pl->rcount, pl->rdispl, MPIU_SCALAR,
                               comm));
    for (PetscInt b = 0; b < pl->nrb; ++b) {
      PetscInt           ld;
      PetscScalar       *c = IndGalerkinOwnedBlock(pl, cd, co, pl->rrow[b], pl->rk[b], &ld);
      const PetscScalar *v = pl->rv + b * cb2;
      for (PetscInt r = 0; r < pl->cbs; ++r)
        for (PetscInt k = 0; k < pl->cbs; ++k) c[r * ld + k] += v[r * pl->cbs + k];
    }
  }
  if (Co) PetscCall(MatSeqAIJRestoreArray(Co, &co));
  PetscCall(MatSeqAIJRestoreArray(Cd, &cd));
  PetscCall(AArrays(A, ia, ja, av, PETSC_FALSE));
  PetscCall(SourceArrays(pl, PETSC_FALSE));
  PetscCall(MatAssemblyBegin(C, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(C, MAT_FINAL_ASSEMBLY));
  PetscCall(PetscLogFlops(flops));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The plan of C = P^T A P (ab false) or A P, on C, with the rows of P that A reaches and their compact columns */
static PetscErrorCode PlanCreate(Mat C, PetscBool ab, IndGalerkinPlan **plan)
{
  Mat              A, P, Ad, Ao;
  const PetscInt  *garray;
  IndGalerkinPlan *pl;
  PetscInt         m, c0, c1, N;
  PetscContainer   container;

  PetscFunctionBegin;
  PetscCall(MatProductGetMats(C, &A, &P, NULL));
  PetscCall(PetscNew(&pl));
  pl->ab = ab;
  PetscCall(PetscContainerCreate(PETSC_COMM_SELF, &container));
  PetscCall(PetscContainerSetPointer(container, pl));
  PetscCall(PetscContainerSetUserDestroy(container, PlanDestroy));
  PetscCall(PetscObjectCompose((PetscObject)C, IND_GALERKIN_PLAN, (PetscObject)container));
  PetscCall(PetscContainerDestroy(&container));
  PetscCall(MatGetBlockSize(A, &pl->fbs));
  PetscCall(MatGetBlockSizes(P, NULL, &pl->cbs));
  PetscCall(IndGalerkinLocalParts(A, &Ad, &Ao, &garray));
  PetscCall(MatGetLocalSize(A, &m, NULL));
  pl->nfb = m / pl->fbs;
  if (Ao) {
    PetscInt no;
    PetscCall(MatGetLocalSize(Ao, NULL, &no));
    pl->ngb = no / pl->fbs;
  }
  PetscCall(MatGetNonzeroState(A, &pl->anz));
  PetscCall(MatGetNonzeroState(P, &pl->pnz));
  PetscCall(PetscObjectStateGet((PetscObject)P, &pl->pstate));
  PetscCall(MatGetOwnershipRangeColumn(P, &c0, &c1));
  pl->cb0  = c0 / pl->cbs;
  pl->nown = (c1 - c0) / pl->cbs;
  PetscCall(MatGetSize(P, NULL, &N));
  if (Ao) {
    PetscCall(ISCreateGeneral(PETSC_COMM_SELF, pl->ngb * pl->fbs, garray, PETSC_COPY_VALUES, &pl->gis));
    PetscCall(ISCreateStride(PETSC_COMM_SELF, N, 0, 1, &pl->allcols));
    PetscCall(MatCreateSubMatrices(P, 1, &pl->gis, &pl->allcols, MAT_INITIAL_MATRIX, &pl->Pg));
  }
  PetscCall(SetSources(pl, P, PETSC_TRUE));
  PetscCall(IndGalerkinCompactColumns(pl));
  PetscCall(PetscMalloc2(pl->ncomp + 1, &pl->slot, pl->ncomp + 1, &pl->list));
  for (PetscInt J = 0; J < pl->ncomp; ++J) pl->slot[J] = -1;
  *plan = pl;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The rest of the plan and C itself, from its pattern in pl->ci, pl->cj */
static PetscErrorCode PlanFinish(Mat C, IndGalerkinPlan *pl)
{
  Mat A, P;

  PetscFunctionBegin;
  PetscCall(MatProductGetMats(C, &A, &P, NULL));
  PetscCall(IndGalerkinCreateC(pl, A, P, C));
  PetscCall(PetscMalloc1(pl->maxap * pl->fbs * pl->cbs + 1, &pl->apv));
  PetscCall(MatSetOperation(C, MATOP_PRODUCTNUMERIC, (void (*)(void))Numeric));
  PetscCall(IndGalerkinInstall(C));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* C = P^T A P: each fine block row's row of A P, added to the C rows (sets) of its P row's blocks, some of which other
   ranks own */
static PetscErrorCode Symbolic(Mat C)
{
  Mat              A, P;
  const PetscInt  *ia[2] = {NULL, NULL}, *ja[2] = {NULL, NULL};
  IndGalerkinPlan *pl;
  IndGalerkinSet  *sets;
  PetscInt        *glist, *work = NULL, nwork = 0, ngtotal = 0;

  PetscFunctionBegin;
  PetscCall(MatProductGetMats(C, &A, &P, NULL));
  PetscCall(PlanCreate(C, PETSC_FALSE, &pl));
  PetscCall(PetscCalloc1(pl->nown + pl->ngr + 1, &sets));
  PetscCall(PetscMalloc1(pl->ncomp + 1, &glist));
  PetscCall(AArrays(A, ia, ja, NULL, PETSC_TRUE));
  for (PetscInt i = 0; i < pl->nfb; ++i) {
    PetscInt nap;
    PetscCall(IndGalerkinApPattern(pl, ia, ja, i, &nap));
    pl->maxap = PetscMax(pl->maxap, nap);
    for (PetscInt e = 0; e < nap; ++e) glist[e] = pl->cglob[pl->list[e]];
    for (int s = IND_GALERKIN_DIAG; s <= IND_GALERKIN_OFF; ++s) {
      const IndGalerkinSource *ps = &pl->src[s];
      for (PetscInt q = 0; ps->M && q < ps->bi[i + 1] - ps->bi[i]; ++q) {
        const PetscInt row = pl->crow[ps->bj[ps->bi[i] + q]];
        PetscCall(IndGalerkinSetMerge(&sets[row >= 0 ? row : pl->nown - row - 2], nap, glist, &work, &nwork));
      }
    }
  }
  PetscCall(AArrays(A, ia, ja, NULL, PETSC_FALSE));
  PetscCall(PetscFree(work));
  PetscCall(PetscFree(glist));

  PetscCall(IndGalerkinExchangePatterns(pl, P, sets));
  for (PetscInt g = 0; g < pl->ngr; ++g) ngtotal += sets[pl->nown + g].n;
  PetscCall(PetscMalloc3(pl->ngr + 1, &pl->gi, ngtotal + 1, &pl->gj, ngtotal * pl->cbs * pl->cbs + 1, &pl->gv));
  pl->gi[0] = 0;
  for (PetscInt g = 0; g < pl->ngr; ++g) {
    PetscCall(PetscArraycpy(pl->gj + pl->gi[g], sets[pl->nown + g].v, sets[pl->nown + g].n));
    pl->gi[g + 1] = pl->gi[g] + sets[pl->nown + g].n;
  }
  {
    PetscInt total = 0;
    for (PetscInt j = 0; j < pl->nown; ++j) total += sets[j].n;
    PetscCall(PetscMalloc2(pl->nown + 1, &pl->ci, total + 1, &pl->cj));
  }
  pl->ci[0] = 0;
  for (PetscInt j = 0; j < pl->nown; ++j) {
    PetscCall(PetscArraycpy(pl->cj + pl->ci[j], sets[j].v, sets[j].n));
    pl->ci[j + 1] = pl->ci[j] + sets[j].n;
  }
  pl->crows = pl->nown;
  pl->crbs  = pl->cbs;
  for (PetscInt s = 0; s < pl->nown + pl->ngr; ++s) PetscCall(PetscFree(sets[s].v));
  PetscCall(PetscFree(sets));
  PetscCall(PlanFinish(C, pl));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* C = A P: C's block row i is row i of A P, whose blocks ApPattern lists in order */
static PetscErrorCode SymbolicAB(Mat C)
{
  Mat              A, P;
  const PetscInt  *ia[2] = {NULL, NULL}, *ja[2] = {NULL, NULL};
  IndGalerkinPlan *pl;
  PetscInt         total = 0;

  PetscFunctionBegin;
  PetscCall(MatProductGetMats(C, &A, &P, NULL));
  PetscCall(PlanCreate(C, PETSC_TRUE, &pl));
  pl->crows = pl->nfb;
  pl->crbs  = pl->fbs;
  PetscCall(AArrays(A, ia, ja, NULL, PETSC_TRUE));
  for (int pass = 0; pass < 2; ++pass) {
    if (pass) PetscCall(PetscMalloc2(pl->nfb + 1, &pl->ci, total + 1, &pl->cj));
    if (pass) pl->ci[0] = 0;
    for (PetscInt i = 0; i < pl->nfb; ++i) {
      PetscInt nap;
      PetscCall(IndGalerkinApPattern(pl, ia, ja, i, &nap));
      pl->maxap = PetscMax(pl->maxap, nap);
      if (!pass) total += nap;
      else {
        for (PetscInt e = 0; e < nap; ++e) pl->cj[pl->ci[i] + e] = pl->cglob[pl->list[e]];
        pl->ci[i + 1] = pl->ci[i] + nap;
      }
    }
  }
  PetscCall(AArrays(A, ia, ja, NULL, PETSC_FALSE));
  PetscCall(PlanFinish(C, pl));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* PETSc's product set-up, replaced for A's PtAP with P where the products by blocks apply */
static PetscErrorCode Dispatch(Mat C)
{
  Mat            A, P;
  MatProductType type;
  PetscContainer container = NULL;
  Hook          *hook;
  PetscBool      ok = PETSC_FALSE;

  PetscFunctionBegin;
  PetscCall(MatProductGetType(C, &type));
  PetscCall(MatProductGetMats(C, &A, &P, NULL));
  PetscCall(PetscObjectQuery((PetscObject)A, IND_GALERKIN_PETSC, (PetscObject *)&container));
  /* A P only with the products installed on A (GAMG's smoothing of its interpolation), not on P */
  if (type == MATPRODUCT_PtAP || (type == MATPRODUCT_AB && container)) PetscCall(Eligible(A, P, &ok));
  if (ok) {
    PetscCall(PetscInfo(C, "%s by blocks\n", type == MATPRODUCT_AB ? "A P" : "P^T A P"));
    PetscCall(MatSetOperation(C, MATOP_PRODUCTSYMBOLIC,
                              type == MATPRODUCT_AB ? (void (*)(void))SymbolicAB : (void (*)(void))Symbolic));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  if (!container) PetscCall(PetscObjectQuery((PetscObject)P, IND_GALERKIN_PETSC, (PetscObject *)&container));
  PetscCheck(container, PETSC_COMM_SELF, PETSC_ERR_PLIB, "A product routed to the Galerkin products without them");
  PetscCall(PetscContainerGetPointer(container, (void **)&hook));
  PetscCall(hook->petsc(C));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndGalerkinInstall(Mat A)
{
  PetscBool      seq, mpi;
  PetscContainer container;
  Hook          *hook;

  PetscFunctionBegin;
  PetscCall(PetscObjectTypeCompare((PetscObject)A, MATSEQAIJ, &seq));
  PetscCall(PetscObjectTypeCompare((PetscObject)A, MATMPIAIJ, &mpi));
  if (!seq && !mpi) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscObjectQuery((PetscObject)A, IND_GALERKIN_PETSC, (PetscObject *)&container));
  if (container) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscNew(&hook));
  PetscCall(MatGetOperation(A, MATOP_PRODUCTSETFROMOPTIONS, (void (**)(void)) & hook->petsc));
  PetscCheck(hook->petsc, PETSC_COMM_SELF, PETSC_ERR_PLIB, "An AIJ matrix without PETSc's product set-up");
  PetscCall(PetscContainerCreate(PETSC_COMM_SELF, &container));
  PetscCall(PetscContainerSetPointer(container, hook));
  PetscCall(PetscContainerSetUserDestroy(container, PetscContainerUserDestroyDefault));
  PetscCall(PetscObjectCompose((PetscObject)A, IND_GALERKIN_PETSC, (PetscObject)container));
  PetscCall(PetscContainerDestroy(&container));
  /* PETSc calls A's own set-up when A and P share it, and otherwise the function composed for their two types:
     both are Dispatch */
  PetscCall(MatSetOperation(A, MATOP_PRODUCTSETFROMOPTIONS, (void (*)(void))Dispatch));
  PetscCall(PetscObjectComposeFunction((PetscObject)A, seq ? "MatProductSetFromOptions_seqaij_seqaij_C"
                                                           : "MatProductSetFromOptions_mpiaij_mpiaij_C", Dispatch));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndGalerkinByBlocks(Mat C, PetscBool *by_blocks)
{
  PetscContainer container;

  PetscFunctionBegin;
  PetscCall(PetscObjectQuery((PetscObject)C, IND_GALERKIN_PLAN, (PetscObject *)&container));
  *by_blocks = (PetscBool)(container != NULL);
  PetscFunctionReturn(PETSC_SUCCESS);
}
