#include "galerkin_impl.h"

/* The loops over the rank's fine block rows. For fine block row i: its row of blocks of A P, made from A's row i by
   blocks against the rows of P that each block reaches, then that row times each block of P's row i, added to the C
   row of that block's coarse column. Blocks are read in place: a group of rows shares one length (its pattern), so
   the block at position k of group K has its rows len apart from ia[K fbs] + k bs. */

/* Block row K of source s: its first value and row length, and its blocks q0 .. q1 - 1 */
static inline const PetscScalar *SourceRow(const IndGalerkinSource *ps, PetscInt fbs, PetscInt K, PetscInt *len,
                                           PetscInt *q0, PetscInt *q1)
{
  const PetscInt Kl = K - ps->row0, s0 = ps->ia[Kl * fbs];

  *len = ps->ia[Kl * fbs + 1] - s0;
  *q0  = ps->bi[Kl];
  *q1  = ps->bi[Kl + 1];
  return ps->va + s0;
}

PetscErrorCode IndGalerkinApPattern(IndGalerkinPlan *pl, const PetscInt *ia[2], const PetscInt *ja[2], PetscInt row,
                                    PetscInt *nap)
{
  const PetscInt fbs = pl->fbs;

  PetscFunctionBegin;
  *nap = 0;
  for (int part = 0; part < 2; ++part) {
    if (!ia[part]) continue;
    const PetscInt s0 = ia[part][row * fbs], nb = (ia[part][row * fbs + 1] - s0) / fbs, off = part ? pl->nfb : 0;
    for (PetscInt kb = 0; kb < nb; ++kb) {
      const PetscInt K = off + ja[part][s0 + kb * fbs] / fbs;
      int            first, last;
      IndGalerkinSources(pl, K, &first, &last);
      for (int s = first; s <= last; ++s) {
        const IndGalerkinSource *ps = &pl->src[s];
        if (!ps->M) continue;
        for (PetscInt q = ps->bi[K - ps->row0]; q < ps->bi[K - ps->row0 + 1]; ++q)
          if (pl->slot[ps->bj[q]] < 0) pl->slot[ps->bj[q]] = *nap, pl->list[(*nap)++] = ps->bj[q];
      }
    }
  }
  for (PetscInt i = 0; i < *nap; ++i) pl->slot[pl->list[i]] = -1;
  PetscCall(PetscSortInt(*nap, pl->list));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscScalar *IndGalerkinOwnedBlock(const IndGalerkinPlan *pl, PetscScalar *cd, PetscScalar *co, PetscInt j, PetscInt k,
                                   PetscInt *ld)
{
  const PetscInt n = pl->ci[j + 1] - pl->ci[j], nl = pl->nleft[j], nd = pl->ndiag[j], cbs = pl->cbs;

  if (k >= nl && k < nl + nd) {
    *ld = nd * cbs;
    return cd + pl->dpos[j] + (k - nl) * cbs;
  }
  *ld = (n - nd) * cbs;
  return co + pl->opos[j] + (k < nl ? k : k - nd) * cbs;
}

/* ap (fbs x cbs) += a (fbs x fbs) p (fbs x cbs, row stride pld) */
IND_INLINE void ApAdd(const PetscInt fbs, const PetscInt cbs, const PetscScalar *a, const PetscScalar *p, PetscInt pld,
                      PetscScalar *ap)
{
  for (PetscInt r = 0; r < fbs; ++r)
    for (PetscInt t = 0; t < fbs; ++t) {
      const PetscScalar v = a[r * fbs + t];
      for (PetscInt c = 0; c < cbs; ++c) ap[r * cbs + c] += v * p[t * pld + c];
    }
}

/* c (cbs x cbs, row stride ld) += p^T (p fbs x cbs, row stride pld) ap (fbs x cbs) */
IND_INLINE void PtApAdd(const PetscInt fbs, const PetscInt cbs, const PetscScalar *p, PetscInt pld,
                        const PetscScalar *ap, PetscScalar *c, PetscInt ld)
{
  for (PetscInt r = 0; r < cbs; ++r)
    for (PetscInt t = 0; t < fbs; ++t) {
      const PetscScalar v = p[t * pld + r];
      for (PetscInt k = 0; k < cbs; ++k) c[r * ld + k] += v * ap[t * cbs + k];
    }
}

/* Row i of A P into pl->apv, its blocks (compact, ascending) in pl->list */
IND_INLINE PetscInt ApRow(IndGalerkinPlan *pl, const PetscInt *ia[2], const PetscInt *ja[2], const PetscScalar *av[2],
                          PetscInt i, PetscLogDouble *nab, const PetscInt fbs, const PetscInt cbs)
{
  const PetscInt bsz = fbs * cbs;
  PetscInt      *slot = pl->slot, *list = pl->list, nap = 0;
  PetscScalar   *apv = pl->apv, a[64];

  for (int part = 0; part < 2; ++part) {
    if (!ia[part]) continue;
    const PetscInt s0 = ia[part][i * fbs], len = ia[part][i * fbs + 1] - s0, off = part ? pl->nfb : 0;
    for (PetscInt kb = 0; kb < len / fbs; ++kb) {
      const PetscInt K = off + ja[part][s0 + kb * fbs] / fbs;
      int            first, last;
      for (PetscInt r = 0; r < fbs; ++r)
        for (PetscInt t = 0; t < fbs; ++t) a[r * fbs + t] = av[part][s0 + r * len + kb * fbs + t];
      IndGalerkinSources(pl, K, &first, &last);
      for (int s = first; s <= last; ++s) {
        PetscInt           plen, q0, q1;
        const PetscScalar *prow;
        if (!pl->src[s].M) continue;
        prow = SourceRow(&pl->src[s], fbs, K, &plen, &q0, &q1);
        for (PetscInt q = q0; q < q1; ++q) {
          const PetscInt L = pl->src[s].bj[q];
          PetscInt       e = slot[L];
          if (e < 0) {
            e = slot[L]   = nap;
            list[nap++]   = L;
            for (PetscInt z = 0; z < bsz; ++z) apv[e * bsz + z] = 0;
          }
          ApAdd(fbs, cbs, a, prow + (q - q0) * cbs, plen, apv + e * bsz);
        }
        *nab += q1 - q0;
      }
    }
  }
  /* ascending, as C's rows are (a few blocks: an insertion sort) */
  for (PetscInt k = 1; k < nap; ++k) {
    const PetscInt v = list[k];
    PetscInt       m = k;
    for (; m > 0 && list[m - 1] > v; --m) list[m] = list[m - 1];
    list[m] = v;
  }
  return nap;
}

IND_INLINE void RowsNumericT(IndGalerkinPlan *pl, const PetscInt *ia[2], const PetscInt *ja[2],
                             const PetscScalar *av[2], PetscScalar *cd, PetscScalar *co, PetscLogDouble *flops,
                             const PetscInt fbs, const PetscInt cbs)
{
  const PetscInt bsz = fbs * cbs, cb2 = cbs * cbs;
  PetscLogDouble nab = 0, ncb = 0;

  for (PetscInt i = 0; i < pl->nfb; ++i) {
    const PetscInt nap = ApRow(pl, ia, ja, av, i, &nab, fbs, cbs);
    for (int s = IND_GALERKIN_DIAG; s <= IND_GALERKIN_OFF; ++s) {
      PetscInt           plen, q0, q1;
      const PetscScalar *prow;
      if (!pl->src[s].M) continue;
      prow = SourceRow(&pl->src[s], fbs, i, &plen, &q0, &q1);
      for (PetscInt q = q0; q < q1; ++q) {
        const PetscInt  row = pl->crow[pl->src[s].bj[q]], g = -row - 2;
        const PetscInt *cols = row >= 0 ? pl->cj + pl->ci[row] : pl->gj + pl->gi[g];
        PetscInt        k    = 0;
        for (PetscInt e = 0; e < nap; ++e) {
          const PetscInt G  = pl->cglob[pl->list[e]];
          PetscInt       ld = cbs;
          PetscScalar   *c;
          while (cols[k] < G) ++k; /* present: C's pattern holds every block of A P's rows */
          if (row >= 0) c = IndGalerkinOwnedBlock(pl, cd, co, row, k, &ld);
          else c = pl->gv + (pl->gi[g] + k) * cb2;
          PtApAdd(fbs, cbs, prow + (q - q0) * cbs, plen, pl->apv + pl->slot[pl->list[e]] * bsz, c, ld);
        }
        ncb += nap;
      }
    }
    for (PetscInt e = 0; e < nap; ++e) pl->slot[pl->list[e]] = -1;
  }
  *flops = 2.0 * (nab * fbs * fbs * cbs + ncb * fbs * cbs * cbs);
}

void IndGalerkinRowsNumeric(IndGalerkinPlan *pl, const PetscInt *ia[2], const PetscInt *ja[2], const PetscScalar *av[2],
                            PetscScalar *cd, PetscScalar *co, PetscLogDouble *flops)
{
  if (pl->fbs == 3 && pl->cbs == 6) RowsNumericT(pl, ia, ja, av, cd, co, flops, 3, 6);
  else if (pl->fbs == 6 && pl->cbs == 6) RowsNumericT(pl, ia, ja, av, cd, co, flops, 6, 6);
  else RowsNumericT(pl, ia, ja, av, cd, co, flops, pl->fbs, pl->cbs);
}

IND_INLINE void ProductNumericT(IndGalerkinPlan *pl, const PetscInt *ia[2], const PetscInt *ja[2],
                                const PetscScalar *av[2], PetscScalar *cd, PetscScalar *co, PetscLogDouble *flops,
                                const PetscInt fbs, const PetscInt cbs)
{
  const PetscInt bsz = fbs * cbs;
  PetscLogDouble nab = 0;

  for (PetscInt i = 0; i < pl->nfb; ++i) {
    const PetscInt nap = ApRow(pl, ia, ja, av, i, &nab, fbs, cbs);
    /* C's block row i has the blocks of A P's row i, in the same order */
    for (PetscInt e = 0; e < nap; ++e) {
      PetscInt           ld;
      PetscScalar       *c  = IndGalerkinOwnedBlock(pl, cd, co, i, e, &ld);
      const PetscScalar *ap = pl->apv + pl->slot[pl->list[e]] * bsz;
      for (PetscInt r = 0; r < fbs; ++r)
        for (PetscInt k = 0; k < cbs; ++k) c[r * ld + k] = ap[r * cbs + k];
    }
    for (PetscInt e = 0; e < nap; ++e) pl->slot[pl->list[e]] = -1;
  }
  *flops = 2.0 * nab * fbs * fbs * cbs;
}

void IndGalerkinProductNumeric(IndGalerkinPlan *pl, const PetscInt *ia[2], const PetscInt *ja[2],
                               const PetscScalar *av[2], PetscScalar *cd, PetscScalar *co, PetscLogDouble *flops)
{
  if (pl->fbs == 3 && pl->cbs == 6) ProductNumericT(pl, ia, ja, av, cd, co, flops, 3, 6);
  else if (pl->fbs == 6 && pl->cbs == 6) ProductNumericT(pl, ia, ja, av, cd, co, flops, 6, 6);
  else ProductNumericT(pl, ia, ja, av, cd, co, flops, pl->fbs, pl->cbs);
}
