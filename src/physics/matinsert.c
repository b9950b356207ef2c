#include "ind_matinsert.h"

/* MatSetValues searches every one of a cell's nd x nd columns in its row: on the paper case at h_tip 15
   that was 85% of the Jacobian, 2 us per P1 cell. The pattern never changes, so the search is done
   once: per cell and pair of nodes (a, b), where the 3 x 3 block starts within the rows of node a, in
   the diagonal or the off-diagonal part of the rank's AIJ matrix. The three rows of a node share
   their pattern and a node's three columns are consecutive (checked when the cache is built). */
struct _p_IndMatInsert {
  PetscInt        nb, ncell;
  const PetscInt *gidx;   /* the discretisation's global indices, ncell x 3 nb */
  PetscInt       *pos;    /* ncell x nb x nb: position in the row + 1, negated in the off-diagonal part; 0: not owned */
  PetscInt        rstart, rend;
  Mat             Ad, Ao; /* the rank's diagonal and off-diagonal parts (Ao NULL on one rank) */
  PetscScalar    *ad, *ao;
  const PetscInt *iad, *iao;
  PetscInt        noff;   /* blocks of rows owned by other ranks, set with MatSetValues */
};

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

PetscErrorCode IndMatInsertCreate(IndDisc disc, Mat J, IndMatInsert *out)
{
  IndMatInsert    m;
  PetscBool       seq, mpi, ok = PETSC_TRUE, done;
  const PetscInt *garray = NULL, *iad, *jad, *iao = NULL, *jao = NULL;
  PetscInt        nr, nro, nga = 0, cstart;
  MPI_Comm        comm = PetscObjectComm((PetscObject)J);

  PetscFunctionBeginUser;
  *out = NULL;
  PetscCall(PetscObjectBaseTypeCompare((PetscObject)J, MATSEQAIJ, &seq));
  PetscCall(PetscObjectBaseTypeCompare((PetscObject)J, MATMPIAIJ, &mpi));
  {
    PetscMPIInt any = (seq || mpi) ? 1 : 0;
    PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &any, 1, MPI_INT, MPI_MIN, comm));
    if (!any) PetscFunctionReturn(PETSC_SUCCESS); /* another matrix type (-jac_mat_type): MatSetValues */
  }
  PetscCall(PetscCalloc1(1, &m));
  {
    const IndDiscLayout *L;
    PetscCall(IndDiscGetLayout(disc, &L));
    m->nb    = L->nb;
    m->ncell = L->ncell;
    m->gidx  = L->gidx;
  }
  PetscCall(MatGetOwnershipRange(J, &m->rstart, &m->rend));
  PetscCall(MatGetOwnershipRangeColumn(J, &cstart, NULL));
  if (mpi) {
    PetscCall(MatMPIAIJGetSeqAIJ(J, &m->Ad, &m->Ao, &garray));
    PetscCall(MatGetLocalSize(m->Ao, NULL, &nga));
  } else m->Ad = J;
  PetscCall(MatGetRowIJ(m->Ad, 0, PETSC_FALSE, PETSC_FALSE, &nr, &iad, &jad, &done));
  PetscCheck(done, PETSC_COMM_SELF, PETSC_ERR_SUP, "No row structure of the Jacobian");
  if (m->Ao) PetscCall(MatGetRowIJ(m->Ao, 0, PETSC_FALSE, PETSC_FALSE, &nro, &iao, &jao, &done));
  PetscCall(PetscMalloc1(m->ncell * m->nb * m->nb, &m->pos));
  for (PetscInt i = 0; i < m->ncell && ok; ++i) {
    const PetscInt *g = m->gidx + i * 3 * m->nb;
    for (PetscInt a = 0; a < m->nb && ok; ++a) {
      const PetscInt row = g[3 * a];
      for (PetscInt b = 0; b < m->nb && ok; ++b) {
        const PetscInt col = g[3 * b];
        PetscInt      *pos = m->pos + (i * m->nb + a) * m->nb + b, p;
        if (row < m->rstart || row >= m->rend) {
          *pos = 0;
          continue;
        }
        if (col >= cstart && col < cstart + nr) {
          p  = Find(iad, jad, row - m->rstart, col - cstart);
          ok = p >= 0 && BlockFits(iad, jad, row - m->rstart, p, col - cstart) ? PETSC_TRUE : PETSC_FALSE;
          *pos = p + 1;
        } else {
          PetscInt lo = 0, hi = nga - 1, jc = -1;
          while (lo <= hi) { /* garray is sorted */
            const PetscInt mid = (lo + hi) / 2;
            if (garray[mid] == col) {
              jc = mid;
              break;
            }
            if (garray[mid] < col) lo = mid + 1;
            else hi = mid - 1;
          }
          ok = jc >= 0 && jc + 2 < nga && garray[jc + 2] == col + 2 ? PETSC_TRUE : PETSC_FALSE;
          if (ok) {
            p  = Find(iao, jao, row - m->rstart, jc);
            ok = p >= 0 && BlockFits(iao, jao, row - m->rstart, p, jc) ? PETSC_TRUE : PETSC_FALSE;
            *pos = -(p + 1);
          }
        }
      }
    }
  }
  PetscCall(MatRestoreRowIJ(m->Ad, 0, PETSC_FALSE, PETSC_FALSE, &nr, &iad, &jad, &done));
  if (m->Ao) PetscCall(MatRestoreRowIJ(m->Ao, 0, PETSC_FALSE, PETSC_FALSE, &nro, &iao, &jao, &done));
  {
    PetscMPIInt all = ok ? 1 : 0;
    PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &all, 1, MPI_INT, MPI_MIN, comm));
    ok = all ? PETSC_TRUE : PETSC_FALSE;
  }
  if (!ok) PetscCall(IndMatInsertDestroy(&m)); /* a pattern not of node blocks: MatSetValues */
  *out = m;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndMatInsertDestroy(IndMatInsert *m)
{
  PetscFunctionBeginUser;
  if (!*m) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscFree((*m)->pos));
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
  PetscCall(MatSeqAIJGetArray(m->Ad, &m->ad));
  PetscCall(MatGetRowIJ(m->Ad, 0, PETSC_FALSE, PETSC_FALSE, &n, &m->iad, &ja, &done));
  if (m->Ao) {
    PetscCall(MatSeqAIJGetArray(m->Ao, &m->ao));
    PetscCall(MatGetRowIJ(m->Ao, 0, PETSC_FALSE, PETSC_FALSE, &n, &m->iao, &ja, &done));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndMatInsertCell(IndMatInsert m, Mat J, PetscInt i, const PetscReal *Ke)
{
  const PetscInt  nb = m->nb, nd = 3 * nb;
  const PetscInt *g  = m->gidx + i * nd, *pos = m->pos + i * nb * nb;

  PetscFunctionBeginUser;
  for (PetscInt a = 0; a < nb; ++a) {
    const PetscInt lr = g[3 * a] - m->rstart;
    for (PetscInt b = 0; b < nb; ++b) {
      const PetscInt   p  = pos[a * nb + b];
      const PetscReal *Kb = Ke + 3 * a * nd + 3 * b;
      if (p == 0) { /* a row of another rank: stashed, sent at assembly */
        PetscScalar B[9];
        for (int k = 0; k < 3; ++k)
          for (int j = 0; j < 3; ++j) B[3 * k + j] = Kb[k * nd + j];
        PetscCall(MatSetValues(J, 3, g + 3 * a, 3, g + 3 * b, B, ADD_VALUES));
        continue;
      }
      {
        PetscScalar    *v  = p > 0 ? m->ad : m->ao;
        const PetscInt *ia = p > 0 ? m->iad : m->iao, o = (p > 0 ? p : -p) - 1;
        for (int k = 0; k < 3; ++k) {
          PetscScalar *vr = v + ia[lr + k] + o;
          vr[0] += Kb[k * nd + 0];
          vr[1] += Kb[k * nd + 1];
          vr[2] += Kb[k * nd + 2];
        }
      }
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
