#include "galerkin_impl.h"

/* C's pattern: the compact numbering of the coarse blocks, the rows' sets of blocks, their exchange between ranks, and
   C made with exactly that pattern. */

/* The sources' block columns (global on entry) in a compact numbering of the coarse blocks the rank's rows reach,
   with the rank's own coarse blocks (C's rows) among them. C's rows that other ranks own (ghost rows) are the other
   blocks of the rank's own rows of P, numbered in global order, so grouped by owner. */
PetscErrorCode IndGalerkinCompactColumns(IndGalerkinPlan *pl)
{
  PetscInt n = pl->nown, *all;

  PetscFunctionBegin;
  for (int s = 0; s < IND_GALERKIN_NSOURCE; ++s)
    if (pl->src[s].M) n += pl->src[s].bi[pl->src[s].nrow];
  PetscCall(PetscMalloc1(n + 1, &all));
  n = 0;
  for (PetscInt j = 0; j < pl->nown; ++j) all[n++] = pl->cb0 + j;
  for (int s = 0; s < IND_GALERKIN_NSOURCE; ++s)
    if (pl->src[s].M) {
      PetscCall(PetscArraycpy(all + n, pl->src[s].bj, pl->src[s].bi[pl->src[s].nrow]));
      n += pl->src[s].bi[pl->src[s].nrow];
    }
  PetscCall(PetscSortRemoveDupsInt(&n, all));
  pl->ncomp = n;
  PetscCall(PetscMalloc2(n + 1, &pl->cglob, n + 1, &pl->crow));
  PetscCall(PetscArraycpy(pl->cglob, all, n));
  PetscCall(PetscFree(all));
  for (int s = 0; s < IND_GALERKIN_NSOURCE; ++s)
    for (PetscInt q = 0; pl->src[s].M && q < pl->src[s].bi[pl->src[s].nrow]; ++q) {
      PetscInt loc;
      PetscCall(PetscFindInt(pl->src[s].bj[q], n, pl->cglob, &loc));
      pl->src[s].bj[q] = loc;
    }
  for (PetscInt J = 0; J < n; ++J) {
    const PetscInt G = pl->cglob[J];
    pl->crow[J]      = (G >= pl->cb0 && G < pl->cb0 + pl->nown) ? G - pl->cb0 : -1;
  }
  for (int s = IND_GALERKIN_DIAG; s <= IND_GALERKIN_OFF; ++s)
    for (PetscInt q = 0; pl->src[s].M && q < pl->src[s].bi[pl->src[s].nrow]; ++q)
      if (pl->crow[pl->src[s].bj[q]] == -1) pl->crow[pl->src[s].bj[q]] = -2;
  pl->ngr = 0;
  for (PetscInt J = 0; J < n; ++J)
    if (pl->crow[J] == -2) pl->crow[J] = -(2 + pl->ngr++);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* s |= the n ascending, distinct values v; *work (*nwork long) is grown as needed */
PetscErrorCode IndGalerkinSetMerge(IndGalerkinSet *s, PetscInt n, const PetscInt *v, PetscInt **work, PetscInt *nwork)
{
  PetscInt i = 0, j = 0, k = 0, *w;

  PetscFunctionBegin;
  if (s->n + n > *nwork) {
    PetscCall(PetscFree(*work));
    *nwork = 2 * (s->n + n);
    PetscCall(PetscMalloc1(*nwork, work));
  }
  w = *work;
  while (i < s->n && j < n) {
    if (s->v[i] < v[j]) w[k++] = s->v[i++];
    else if (s->v[i] > v[j]) w[k++] = v[j++];
    else w[k++] = s->v[i++], ++j;
  }
  while (i < s->n) w[k++] = s->v[i++];
  while (j < n) w[k++] = v[j++];
  if (k > s->cap) {
    PetscCall(PetscFree(s->v));
    s->cap = PetscMax(k, 2 * s->cap);
    PetscCall(PetscMalloc1(s->cap, &s->v));
  }
  PetscCall(PetscArraycpy(s->v, w, k));
  s->n = k;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The patterns of the ghost rows go to their owners, who merge them into their rows; the plan keeps what the
   numeric phase sends and where each received block goes. */
PetscErrorCode IndGalerkinExchangePatterns(IndGalerkinPlan *pl, Mat P, IndGalerkinSet *sets)
{
  MPI_Comm        comm = PetscObjectComm((PetscObject)P);
  PetscMPIInt     size, *icount, *idispl, *ircount, *irdispl;
  const PetscInt *ranges, cb2 = pl->cbs * pl->cbs;
  PetscInt       *sbuf, *rbuf, ns = 0, nr = 0, r = 0, b = 0;

  PetscFunctionBegin;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCall(PetscCalloc4(size, &pl->scount, size + 1, &pl->sdispl, size, &pl->rcount, size + 1, &pl->rdispl));
  PetscCall(PetscCalloc4(size, &icount, size + 1, &idispl, size, &ircount, size + 1, &irdispl));
  PetscCall(MatGetOwnershipRangesColumn(P, &ranges));
  for (PetscInt J = 0, g = 0; J < pl->ncomp; ++J) {
    if (pl->crow[J] > -2) continue;
    while (pl->cglob[J] * pl->cbs >= ranges[r + 1]) ++r;
    icount[r] += (PetscMPIInt)(2 + sets[pl->nown + g].n);
    pl->scount[r] += (PetscMPIInt)(sets[pl->nown + g].n * cb2);
    ++g;
  }
  for (PetscMPIInt q = 0; q < size; ++q) {
    idispl[q + 1]     = idispl[q] + icount[q];
    pl->sdispl[q + 1] = pl->sdispl[q] + pl->scount[q];
  }
  ns = idispl[size];
  PetscCall(PetscMalloc1(ns + 1, &sbuf));
  for (PetscInt J = 0, g = 0, k = 0; J < pl->ncomp; ++J) {
    if (pl->crow[J] > -2) continue;
    sbuf[k++] = pl->cglob[J];
    sbuf[k++] = sets[pl->nown + g].n;
    for (PetscInt c = 0; c < sets[pl->nown + g].n; ++c) sbuf[k++] = sets[pl->nown + g].v[c];
    ++g;
  }
  PetscCallMPI(MPI_Alltoall(icount, 1, MPI_INT, ircount, 1, MPI_INT, comm));
  for (PetscMPIInt q = 0; q < size; ++q) irdispl[q + 1] = irdispl[q] + ircount[q];
  nr = irdispl[size];
  PetscCall(PetscMalloc1(nr + 1, &rbuf));
  PetscCallMPI(MPI_Alltoallv(sbuf, icount, idispl, MPIU_INT, rbuf, ircount, irdispl, MPIU_INT, comm));
  PetscCall(PetscFree(sbuf));
  {
    PetscInt *work = NULL, nwork = 0;
    pl->nrb = 0;
    for (PetscMPIInt q = 0; q < size; ++q)
      for (PetscInt k = irdispl[q]; k < irdispl[q + 1]; k += 2 + rbuf[k + 1]) {
        const PetscInt j = rbuf[k] - pl->cb0, n = rbuf[k + 1];
        PetscCheck(j >= 0 && j < pl->nown, PETSC_COMM_SELF, PETSC_ERR_PLIB, "A Galerkin row sent to the wrong rank");
        PetscCall(IndGalerkinSetMerge(&sets[j], n, rbuf + k + 2, &work, &nwork));
        pl->nrb += n;
        pl->rcount[q] += (PetscMPIInt)(n * cb2);
      }
    PetscCall(PetscFree(work));
  }
  for (PetscMPIInt q = 0; q < size; ++q) pl->rdispl[q + 1] = pl->rdispl[q] + pl->rcount[q];
  PetscCall(PetscMalloc3(pl->nrb + 1, &pl->rrow, pl->nrb + 1, &pl->rk, pl->nrb * cb2 + 1, &pl->rv));
  for (PetscInt k = 0; k < nr; k += 2 + rbuf[k + 1]) {
    const PetscInt j = rbuf[k] - pl->cb0;
    for (PetscInt c = 0; c < rbuf[k + 1]; ++c, ++b) {
      PetscInt loc;
      PetscCall(PetscFindInt(rbuf[k + 2 + c], sets[j].n, sets[j].v, &loc));
      pl->rrow[b] = j;
      pl->rk[b]   = loc;
    }
  }
  PetscCall(PetscFree(rbuf));
  PetscCall(PetscFree4(icount, idispl, ircount, irdispl));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* C with exactly the pattern pl->ci, pl->cj (its crows block rows of crbs rows, sorted global coarse blocks), and where
   each block row's blocks sit in C's local arrays: its rows are consecutive there with one length, the blocks left of
   the rank's coarse columns and right of them in the off-process array, the others in the diagonal one, each in
   column order. Rows and columns are laid out as A's rows and P's columns (A P), or both as P's columns (P^T A P). */
PetscErrorCode IndGalerkinCreateC(IndGalerkinPlan *pl, Mat A, Mat P, Mat C)
{
  const PetscInt  cbs = pl->cbs, rbs = pl->crbs, cb0 = pl->cb0, nown = pl->nown, crows = pl->crows;
  Mat             Cd, Co;
  MatType         type;
  const PetscInt *garray, *id, *jd, *io = NULL, *jo = NULL;
  PetscInt        M, N, *dnnz, *onnz, *cols, maxrow = 0, rstart, nd_rows, no_rows;
  PetscScalar    *zeros;
  PetscBool       done, ok = PETSC_TRUE;

  PetscFunctionBegin;
  PetscCall(MatGetSize(A, &M, NULL));
  PetscCall(MatGetSize(P, NULL, &N));
  PetscCall(MatSetSizes(C, crows * rbs, nown * cbs, pl->ab ? M : N, N));
  PetscCall(MatSetBlockSizes(C, rbs, cbs));
  PetscCall(MatGetType(A, &type));
  PetscCall(MatSetType(C, type));
  /* C's arrays are allocated first and its rows set one at a time, as PETSc's own CSR preallocation does, but without
     a CSR copy of the whole pattern: freed under C, its 4 bytes an entry left a hole that the heap, which gives nothing
     back (doc/performance.md), kept resident (37 MiB a rank under sphere_800k's first A P on 2 ranks). */
  PetscCall(PetscMalloc2(crows * rbs + 1, &dnnz, crows * rbs + 1, &onnz));
  for (PetscInt j = 0; j < crows; ++j) {
    const PetscInt *v = pl->cj + pl->ci[j], nc = pl->ci[j + 1] - pl->ci[j];
    PetscInt        nd = 0;
    for (PetscInt k = 0; k < nc; ++k) nd += v[k] >= cb0 && v[k] < cb0 + nown;
    for (PetscInt r = 0; r < rbs; ++r) dnnz[j * rbs + r] = nd * cbs, onnz[j * rbs + r] = (nc - nd) * cbs;
    maxrow = PetscMax(maxrow, nc * cbs);
  }
  PetscCall(MatSeqAIJSetPreallocation(C, 0, dnnz));
  PetscCall(MatMPIAIJSetPreallocation(C, 0, dnnz, 0, onnz));
  PetscCall(PetscFree2(dnnz, onnz));
  PetscCall(MatGetOwnershipRange(C, &rstart, NULL));
  PetscCall(PetscMalloc1(maxrow + 1, &cols));
  PetscCall(PetscCalloc1(maxrow + 1, &zeros));
  for (PetscInt j = 0; j < crows; ++j) {
    const PetscInt n = pl->ci[j + 1] - pl->ci[j];
    for (PetscInt k = 0; k < n; ++k)
      for (PetscInt c = 0; c < cbs; ++c) cols[k * cbs + c] = pl->cj[pl->ci[j] + k] * cbs + c;
    for (PetscInt r = 0; r < rbs; ++r) {
      const PetscInt row = rstart + j * rbs + r;
      PetscCall(MatSetValues(C, 1, &row, n * cbs, cols, zeros, INSERT_VALUES));
    }
  }
  PetscCall(PetscFree(cols));
  PetscCall(PetscFree(zeros));
  PetscCall(MatSetOption(C, MAT_NO_OFF_PROC_ENTRIES, PETSC_TRUE));
  PetscCall(MatAssemblyBegin(C, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(C, MAT_FINAL_ASSEMBLY));
  PetscCall(MatSetOption(C, MAT_NO_OFF_PROC_ENTRIES, PETSC_FALSE));
  PetscCall(MatSetOption(C, MAT_NEW_NONZERO_LOCATION_ERR, PETSC_TRUE));

  PetscCall(IndGalerkinLocalParts(C, &Cd, &Co, &garray));
  PetscCall(MatGetRowIJ(Cd, 0, PETSC_FALSE, PETSC_FALSE, &nd_rows, &id, &jd, &done));
  if (Co) PetscCall(MatGetRowIJ(Co, 0, PETSC_FALSE, PETSC_FALSE, &no_rows, &io, &jo, &done));
  PetscCall(PetscMalloc4(crows + 1, &pl->dpos, crows + 1, &pl->opos, crows + 1, &pl->nleft, crows + 1, &pl->ndiag));
  for (PetscInt j = 0; j < crows && ok; ++j) {
    const PetscInt *v = pl->cj + pl->ci[j], nc = pl->ci[j + 1] - pl->ci[j];
    PetscInt        nl = 0, nd = 0;
    while (nl < nc && v[nl] < cb0) ++nl;
    while (nl + nd < nc && v[nl + nd] < cb0 + nown) ++nd;
    pl->nleft[j] = nl, pl->ndiag[j] = nd;
    pl->dpos[j] = id[j * rbs];
    pl->opos[j] = io ? io[j * rbs] : 0;
    ok = (PetscBool)(io || nd == nc);
    for (PetscInt r = 0; r <= rbs && ok; ++r) {
      if (id[j * rbs + r] != pl->dpos[j] + r * nd * cbs) ok = PETSC_FALSE;
      if (io && io[j * rbs + r] != pl->opos[j] + r * (nc - nd) * cbs) ok = PETSC_FALSE;
    }
    for (PetscInt k = 0; k < nd && ok; ++k) ok = (PetscBool)(jd[pl->dpos[j] + k * cbs] == (v[nl + k] - cb0) * cbs);
    for (PetscInt k = 0; k < nc - nd && ok; ++k)
      ok = (PetscBool)(garray[jo[pl->opos[j] + k * cbs]] == (k < nl ? v[k] : v[k + nd]) * cbs);
  }
  pl->dnz = id[nd_rows];
  pl->onz = io ? io[no_rows] : 0;
  PetscCall(MatRestoreRowIJ(Cd, 0, PETSC_FALSE, PETSC_FALSE, &nd_rows, &id, &jd, &done));
  if (Co) PetscCall(MatRestoreRowIJ(Co, 0, PETSC_FALSE, PETSC_FALSE, &no_rows, &io, &jo, &done));
  PetscCheck(ok, PETSC_COMM_SELF, PETSC_ERR_PLIB, "A Galerkin product's arrays are not laid out as its pattern");
  PetscFunctionReturn(PETSC_SUCCESS);
}

