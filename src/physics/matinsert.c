#include <stdint.h>
#include <petscsf.h>
#include "ind_matinsert.h"

/* MatSetValues searches every one of a cell's nd x nd columns in its row: on the paper case at h_tip 15
   that was 85% of the Jacobian, 2 us per P1 cell. The pattern never changes, so the search is done
   once: per cell and pair of nodes (a, b), where the 3 x 3 block starts within the rows of node a, in
   the diagonal or the off-diagonal part of the rank's AIJ matrix. The three rows of a node share
   their pattern and a node's three columns are consecutive (checked when the cache is built).

   A block of a row another rank owns went through MatSetValues' stash: on 2 ranks of the README's mesh the
   assembly then spent 31 to 36 ms a Jacobian (a quarter of it) packing, sending and searching the same 180k
   entries with their indices. Those blocks are now summed on this rank into one slot per distinct block, and
   only the values travel, by a star forest built once whose roots are the owner's positions.

   A block's position fits 16 bits (a row of a Q2 hexahedron's mesh has at most 375 columns; a longer row makes
   the cache give way to MatSetValues): the positions of the plastic cube at 824k dofs take 34 MB, not 67. REMOTE
   marks a block of another rank's rows, whose slot comes next in the cell's list of them. */
#define REMOTE INT16_MIN

struct _p_IndMatInsert {
  PetscInt        nb, ncell;
  const PetscInt *gnode;  /* the discretisation's global node numbers, ncell x nb (dofs 3 n + 0, 1, 2) */
  int16_t        *pos;    /* ncell x nb x nb: position in the row + 1, negated in the off-diagonal part; or REMOTE */
  PetscInt       *roff, *rslot; /* cell i's REMOTE blocks' slots: rslot[roff[i]..roff[i + 1]) in the cell's order */
  PetscInt        rstart, rend;
  Mat             Ad, Ao; /* the rank's diagonal and off-diagonal parts (Ao NULL on one rank) */
  PetscScalar    *ad, *ao;
  const PetscInt *iad, *iao;
  /* blocks of rows owned by other ranks: summed here (nsend slots of 9 values), received by their owner (nrecv) */
  PetscSF         sf;
  PetscInt        nsend, nrecv;
  PetscScalar    *sendv, *recvv;
  PetscInt       *recv_row, *recv_pos; /* local first row and position (as pos) of each received block */
};

/* The rank's pattern, to find blocks in. */
typedef struct {
  const PetscInt *iad, *jad, *iao, *jao, *garray;
  PetscInt        nga, cstart, ncol;
} Pattern;

/* Position of column col within local row r of a SeqAIJ structure, or -1. */
static PetscInt Find(const PetscInt *ia, const PetscInt *ja, PetscInt r, PetscInt col)
{
  PetscInt lo = ia[r], hi = ia[r + 1] - 1;
  while (lo <= hi) {
    const PetscInt mid = (lo + hi) / 2;
    if (ja[mid] == col) return mid - ia[r];
    if (ja[mid] < col) lo = mid + 1;
    else hi = mid - 1;
  }
  return -1;
}

/* The whole 3 x 3 block of rows r..r+2 from position p holds columns col..col+2. */
static PetscBool BlockFits(const PetscInt *ia, const PetscInt *ja, PetscInt r, PetscInt p, PetscInt col)
{
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j)
      if (ia[r + k] + p + j >= ia[r + k + 1] || ja[ia[r + k] + p + j] != col + j) return PETSC_FALSE;
  return PETSC_TRUE;
}

/* The block of local rows lr..lr+2 and global columns col..col+2, as a pos (p + 1 in the diagonal part, -(p + 1) in
   the off-diagonal one); false if the pattern has no such whole block. */
static PetscBool BlockPosition(const Pattern *pt, PetscInt lr, PetscInt col, PetscInt *pos)
{
  PetscInt p, lo = 0, hi = pt->nga - 1, jc = -1;

  if (col >= pt->cstart && col < pt->cstart + pt->ncol) {
    p    = Find(pt->iad, pt->jad, lr, col - pt->cstart);
    *pos = p + 1;
    return p >= 0 && p + 1 <= INT16_MAX && BlockFits(pt->iad, pt->jad, lr, p, col - pt->cstart);
  }
  while (lo <= hi) { /* garray is sorted */
    const PetscInt mid = (lo + hi) / 2;
    if (pt->garray[mid] == col) {
      jc = mid;
      break;
    }
    if (pt->garray[mid] < col) lo = mid + 1;
    else hi = mid - 1;
  }
  if (jc < 0 || jc + 2 >= pt->nga || pt->garray[jc + 2] != col + 2) return PETSC_FALSE;
  p    = Find(pt->iao, pt->jao, lr, jc);
  *pos = -(p + 1);
  return p >= 0 && p + 1 <= INT16_MAX && BlockFits(pt->iao, pt->jao, lr, p, jc);
}

static PetscBool AllRanks(MPI_Comm comm, PetscBool ok)
{
  PetscMPIInt all = ok ? 1 : 0;
  if (MPI_Allreduce(MPI_IN_PLACE, &all, 1, MPI_INT, MPI_MIN, comm)) return PETSC_FALSE;
  return all ? PETSC_TRUE : PETSC_FALSE;
}

/* The slots of the blocks of rows other ranks own (listed per cell), and the forest that carries their values to
   the owners, each of which finds where they go in its pattern. */
static PetscErrorCode BuildExchange(IndMatInsert m, Mat J, const Pattern *pt, PetscBool *ok)
{
  const PetscInt  nb = m->nb;
  const PetscInt *ranges;
  PetscInt        M, nkey = 0, nroot_multi, nleaf_multi, *cols, *rcols;
  PetscInt64     *keys;
  const PetscInt *degree, *mleaf;
  PetscSFNode    *remote, *vremote;
  const PetscSFNode *mremote;
  PetscSF         rows, multi;
  PetscMPIInt     size;
  MPI_Comm        comm = PetscObjectComm((PetscObject)J);

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCall(MatGetSize(J, &M, NULL));
  PetscCall(MatGetOwnershipRanges(J, &ranges));
  for (PetscInt k = 0; k < m->ncell * nb * nb; ++k) nkey += m->pos[k] == REMOTE;
  PetscCall(PetscMalloc1(nkey, &keys));
  nkey = 0;
  for (PetscInt i = 0; i < m->ncell; ++i)
    for (PetscInt a = 0; a < nb; ++a)
      for (PetscInt b = 0; b < nb; ++b)
        if (m->pos[(i * nb + a) * nb + b] == REMOTE)
          keys[nkey++] = (PetscInt64)(3 * m->gnode[i * nb + a]) * M + 3 * m->gnode[i * nb + b];
  PetscCall(PetscSortInt64(nkey, keys));
  m->nsend = 0;
  for (PetscInt k = 0; k < nkey; ++k)
    if (k == 0 || keys[k] != keys[m->nsend - 1]) keys[m->nsend++] = keys[k];
  PetscCall(PetscMalloc2(m->ncell + 1, &m->roff, nkey, &m->rslot));
  m->roff[0] = 0;
  for (PetscInt i = 0, k = 0; i < m->ncell; ++i) {
    for (PetscInt a = 0; a < nb; ++a)
      for (PetscInt b = 0; b < nb; ++b) {
        const PetscInt64 key = (PetscInt64)(3 * m->gnode[i * nb + a]) * M + 3 * m->gnode[i * nb + b];
        PetscInt         lo = 0, hi = m->nsend - 1;
        if (m->pos[(i * nb + a) * nb + b] != REMOTE) continue;
        while (lo < hi) {
          const PetscInt mid = (lo + hi) / 2;
          if (keys[mid] < key) lo = mid + 1;
          else hi = mid;
        }
        m->rslot[k++] = lo;
      }
    m->roff[i + 1] = k;
  }
  /* each slot a leaf of its first row on the owner; the owner gathers the slots' columns */
  PetscCall(PetscMalloc2(m->nsend, &remote, m->nsend, &cols));
  for (PetscInt k = 0; k < m->nsend; ++k) {
    const PetscInt row = (PetscInt)(keys[k] / M);
    PetscMPIInt    lo = 0, hi = size - 1;
    while (lo < hi) { /* the last rank whose range starts at or before row */
      const PetscMPIInt mid = (lo + hi + 1) / 2;
      if (ranges[mid] <= row) lo = mid;
      else hi = mid - 1;
    }
    remote[k].rank  = lo;
    remote[k].index = row - ranges[lo];
    cols[k]         = (PetscInt)(keys[k] % M);
  }
  PetscCall(PetscFree(keys));
  PetscCall(PetscSFCreate(comm, &rows));
  PetscCall(PetscSFSetGraph(rows, m->rend - m->rstart, m->nsend, NULL, PETSC_COPY_VALUES, remote, PETSC_COPY_VALUES));
  PetscCall(PetscSFSetUp(rows));
  PetscCall(PetscSFComputeDegreeBegin(rows, &degree));
  PetscCall(PetscSFComputeDegreeEnd(rows, &degree));
  m->nrecv = 0;
  for (PetscInt r = 0; r < m->rend - m->rstart; ++r) m->nrecv += degree[r];
  PetscCall(PetscMalloc1(m->nrecv, &rcols));
  PetscCall(PetscMalloc2(m->nrecv, &m->recv_row, m->nrecv, &m->recv_pos));
  PetscCall(PetscSFGatherBegin(rows, MPIU_INT, cols, rcols));
  PetscCall(PetscSFGatherEnd(rows, MPIU_INT, cols, rcols));
  *ok = PETSC_TRUE;
  for (PetscInt r = 0, s = 0; r < m->rend - m->rstart; ++r)
    for (PetscInt d = 0; d < degree[r]; ++d, ++s) {
      m->recv_row[s] = r;
      *ok = (PetscBool)(*ok && r % 3 == 0 && BlockPosition(pt, r, rcols[s], &m->recv_pos[s]));
    }
  /* the gather's own forest has a root for every (row, sender): the values' forest has 9 a block */
  PetscCall(PetscSFGetMultiSF(rows, &multi));
  PetscCall(PetscSFGetGraph(multi, &nroot_multi, &nleaf_multi, &mleaf, &mremote));
  *ok = (PetscBool)(*ok && nroot_multi == m->nrecv && nleaf_multi == m->nsend);
  for (PetscInt k = 0; mleaf && k < nleaf_multi; ++k) *ok = (PetscBool)(*ok && mleaf[k] == k);
  nleaf_multi = *ok ? m->nsend : 0; /* its set-up is collective: an empty forest where the pattern did not fit */
  PetscCall(PetscMalloc1(9 * nleaf_multi, &vremote));
  for (PetscInt k = 0; k < nleaf_multi; ++k)
    for (PetscInt j = 0; j < 9; ++j) {
      vremote[9 * k + j].rank  = mremote[k].rank;
      vremote[9 * k + j].index = 9 * mremote[k].index + j;
    }
  PetscCall(PetscSFCreate(comm, &m->sf));
  PetscCall(PetscSFSetGraph(m->sf, 9 * m->nrecv, 9 * nleaf_multi, NULL, PETSC_OWN_POINTER, vremote, PETSC_OWN_POINTER));
  PetscCall(PetscSFSetUp(m->sf));
  PetscCall(PetscSFDestroy(&rows));
  PetscCall(PetscFree(rcols));
  PetscCall(PetscFree2(remote, cols));
  PetscCall(PetscMalloc2(9 * m->nsend + 1, &m->sendv, 9 * m->nrecv + 1, &m->recvv));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndMatInsertCreate(IndDisc disc, Mat J, IndMatInsert *out)
{
  IndMatInsert    m;
  PetscBool       seq, mpi, ok = PETSC_TRUE, done;
  const PetscInt *jad, *jao = NULL;
  PetscInt        nr, nro;
  Pattern         pt = {0};
  MPI_Comm        comm = PetscObjectComm((PetscObject)J);

  PetscFunctionBeginUser;
  *out = NULL;
  PetscCall(PetscObjectBaseTypeCompare((PetscObject)J, MATSEQAIJ, &seq));
  PetscCall(PetscObjectBaseTypeCompare((PetscObject)J, MATMPIAIJ, &mpi));
  if (!AllRanks(comm, (PetscBool)(seq || mpi))) PetscFunctionReturn(PETSC_SUCCESS); /* another type: MatSetValues */
  PetscCall(PetscCalloc1(1, &m));
  {
    const IndDiscLayout *L;
    PetscCall(IndDiscGetLayout(disc, &L));
    m->nb    = L->nb;
    m->ncell = L->ncell;
    m->gnode = L->gnode;
  }
  PetscCall(MatGetOwnershipRange(J, &m->rstart, &m->rend));
  PetscCall(MatGetOwnershipRangeColumn(J, &pt.cstart, NULL));
  if (mpi) {
    PetscCall(MatMPIAIJGetSeqAIJ(J, &m->Ad, &m->Ao, &pt.garray));
    PetscCall(MatGetLocalSize(m->Ao, NULL, &pt.nga));
  } else m->Ad = J;
  PetscCall(MatGetRowIJ(m->Ad, 0, PETSC_FALSE, PETSC_FALSE, &nr, &pt.iad, &jad, &done));
  PetscCheck(done, PETSC_COMM_SELF, PETSC_ERR_SUP, "No row structure of the Jacobian");
  pt.jad  = jad;
  pt.ncol = nr;
  if (m->Ao) PetscCall(MatGetRowIJ(m->Ao, 0, PETSC_FALSE, PETSC_FALSE, &nro, &pt.iao, &jao, &done));
  pt.jao = jao;
  PetscCall(PetscMalloc1(m->ncell * m->nb * m->nb, &m->pos));
  for (PetscInt i = 0; i < m->ncell && ok; ++i) {
    const PetscInt *g = m->gnode + i * m->nb;
    for (PetscInt a = 0; a < m->nb && ok; ++a) {
      const PetscInt row = 3 * g[a];
      for (PetscInt b = 0; b < m->nb && ok; ++b) {
        PetscInt p = REMOTE; /* a row of another rank: a slot, below */
        if (row >= m->rstart && row < m->rend) ok = BlockPosition(&pt, row - m->rstart, 3 * g[b], &p);
        m->pos[(i * m->nb + a) * m->nb + b] = (int16_t)p;
      }
    }
  }
  ok = AllRanks(comm, ok);
  if (ok && mpi) {
    PetscCall(BuildExchange(m, J, &pt, &ok));
    ok = AllRanks(comm, ok);
  }
  PetscCall(MatRestoreRowIJ(m->Ad, 0, PETSC_FALSE, PETSC_FALSE, &nr, &pt.iad, &jad, &done));
  if (m->Ao) PetscCall(MatRestoreRowIJ(m->Ao, 0, PETSC_FALSE, PETSC_FALSE, &nro, &pt.iao, &jao, &done));
  if (!ok) PetscCall(IndMatInsertDestroy(&m)); /* a pattern not of node blocks: MatSetValues */
  /* every value is now added in place or sent by the forest: none is stashed, so none is looked for */
  if (ok && mpi) PetscCall(MatSetOption(J, MAT_NO_OFF_PROC_ENTRIES, PETSC_TRUE));
  *out = m;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndMatInsertDestroy(IndMatInsert *m)
{
  PetscFunctionBeginUser;
  if (!*m) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscFree((*m)->pos));
  PetscCall(PetscFree2((*m)->roff, (*m)->rslot));
  PetscCall(PetscSFDestroy(&(*m)->sf));
  PetscCall(PetscFree2((*m)->sendv, (*m)->recvv));
  PetscCall(PetscFree2((*m)->recv_row, (*m)->recv_pos));
  PetscCall(PetscFree(*m));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndMatInsertBegin(IndMatInsert m, Mat J)
{
  PetscInt        n;
  PetscBool       done;
  const PetscInt *ja;

  PetscFunctionBeginUser;
  PetscCall(MatZeroEntries(J));
  if (m->nsend) PetscCall(PetscArrayzero(m->sendv, 9 * m->nsend));
  PetscCall(MatSeqAIJGetArray(m->Ad, &m->ad));
  PetscCall(MatGetRowIJ(m->Ad, 0, PETSC_FALSE, PETSC_FALSE, &n, &m->iad, &ja, &done));
  if (m->Ao) {
    PetscCall(MatSeqAIJGetArray(m->Ao, &m->ao));
    PetscCall(MatGetRowIJ(m->Ao, 0, PETSC_FALSE, PETSC_FALSE, &n, &m->iao, &ja, &done));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* row k of the block at local rows lr.. and position p (as pos) in the open arrays */
static inline PetscScalar *BlockRow(IndMatInsert m, PetscInt lr, PetscInt p, int k)
{
  return p > 0 ? m->ad + m->iad[lr + k] + p - 1 : m->ao + m->iao[lr + k] - p - 1;
}

/* the 3 x 3 block b (row stride ld) added at local rows lr.. and position p of the open arrays */
static inline void AddBlock(IndMatInsert m, PetscInt lr, PetscInt p, const PetscScalar *b, PetscInt ld)
{
  for (int k = 0; k < 3; ++k) {
    PetscScalar *vr = BlockRow(m, lr, p, k);
    vr[0] += b[k * ld + 0];
    vr[1] += b[k * ld + 1];
    vr[2] += b[k * ld + 2];
  }
}

void IndMatInsertPrefetch(IndMatInsert m, PetscInt i)
{
#if defined(__GNUC__)
  const PetscInt  nb = m->nb;
  const PetscInt *g  = m->gnode + i * nb;
  const int16_t  *pos = m->pos + i * nb * nb;

  for (PetscInt a = 0; a < nb; ++a) {
    const PetscInt lr = 3 * g[a] - m->rstart;
    for (PetscInt b = 0; b < nb; ++b) {
      const PetscInt p = pos[a * nb + b];
      if (p == REMOTE) continue;
      for (int k = 0; k < 3; ++k) __builtin_prefetch(BlockRow(m, lr, p, k), 1, 3);
    }
  }
#else
  (void)m;
  (void)i;
#endif
}

PetscErrorCode IndMatInsertCell(IndMatInsert m, PetscInt i, const PetscReal *Ke)
{
  const PetscInt  nb = m->nb, nd = 3 * nb;
  const PetscInt *g  = m->gnode + i * nb, *slot = m->roff ? m->rslot + m->roff[i] : NULL;
  const int16_t  *pos = m->pos + i * nb * nb;

  PetscFunctionBeginUser;
  for (PetscInt a = 0; a < nb; ++a) {
    const PetscInt lr = 3 * g[a] - m->rstart;
    for (PetscInt b = 0; b < nb; ++b) {
      const PetscInt   p  = pos[a * nb + b];
      const PetscReal *Kb = Ke + 3 * a * nd + 3 * b;
      if (p == REMOTE) { /* a row of another rank: summed in its slot, sent at assembly */
        PetscScalar *v = m->sendv + 9 * *slot++;
        for (int k = 0; k < 3; ++k)
          for (int j = 0; j < 3; ++j) v[3 * k + j] += Kb[k * nd + j];
        continue;
      }
      AddBlock(m, lr, p, Kb, nd);
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndMatInsertEnd(IndMatInsert m, Mat J)
{
  PetscInt        n;
  PetscBool       done;
  const PetscInt *ja = NULL;

  PetscFunctionBeginUser;
  if (m->sf) {
    PetscCall(PetscSFReduceBegin(m->sf, MPIU_SCALAR, m->sendv, m->recvv, MPI_REPLACE));
    PetscCall(PetscSFReduceEnd(m->sf, MPIU_SCALAR, m->sendv, m->recvv, MPI_REPLACE));
    for (PetscInt s = 0; s < m->nrecv; ++s) AddBlock(m, m->recv_row[s], m->recv_pos[s], m->recvv + 9 * s, 3);
  }
  PetscCall(MatRestoreRowIJ(m->Ad, 0, PETSC_FALSE, PETSC_FALSE, &n, &m->iad, &ja, &done));
  PetscCall(MatSeqAIJRestoreArray(m->Ad, &m->ad));
  if (m->Ao) {
    PetscCall(MatRestoreRowIJ(m->Ao, 0, PETSC_FALSE, PETSC_FALSE, &n, &m->iao, &ja, &done));
    PetscCall(MatSeqAIJRestoreArray(m->Ao, &m->ao));
  }
  PetscCall(MatAssemblyBegin(J, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(J, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(PETSC_SUCCESS);
}
