#include <string.h>
#include "ind_keyjoin.h"

PetscInt IndKeyHash(const PetscReal key[3])
{
  PetscInt64 h = (PetscInt64)1469598103934665603ULL; /* FNV-1a over the bytes of the 3 coordinates */

  for (int d = 0; d < 3; ++d) {
    const PetscReal     x = key[d] + 0.0; /* -0.0 + 0.0 == +0.0 */
    const unsigned char *b = (const unsigned char *)&x;
    for (size_t k = 0; k < sizeof(x); ++k) {
      h ^= b[k];
      h = (PetscInt64)((unsigned long long)h * 1099511628211ULL);
    }
  }
  return (PetscInt)(((unsigned long long)h >> 1) % (unsigned long long)PETSC_MAX_INT);
}

static int KeyCompare(const PetscReal *a, const PetscReal *b)
{
  for (int d = 0; d < 3; ++d) {
    if (a[d] < b[d]) return -1;
    if (a[d] > b[d]) return 1;
  }
  return 0;
}

/* Entries moved to their hash's rank: key (3), then the payload (bs values, or the request's index). */
typedef struct {
  PetscInt   w; /* reals per entry */
  PetscReal *buf;
  PetscInt   n;
} Packed;

static PetscErrorCode Exchange(MPI_Comm comm, PetscInt w, PetscInt n, const PetscReal *rows, const PetscMPIInt *dest,
                               Packed *out, PetscMPIInt **order)
{
  PetscMPIInt size, *scount, *rcount, *sdisp, *rdisp, *fill;
  PetscReal  *send;
  PetscInt    nrecv = 0;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCall(PetscCalloc5(size, &scount, size, &rcount, size + 1, &sdisp, size + 1, &rdisp, size, &fill));
  for (PetscInt i = 0; i < n; ++i) scount[dest[i]] += (PetscMPIInt)w;
  PetscCallMPI(MPI_Alltoall(scount, 1, MPI_INT, rcount, 1, MPI_INT, comm));
  for (PetscMPIInt r = 0; r < size; ++r) {
    sdisp[r + 1] = sdisp[r] + scount[r];
    rdisp[r + 1] = rdisp[r] + rcount[r];
  }
  nrecv = rdisp[size] / w;
  PetscCall(PetscMalloc1(w * n + 1, &send));
  PetscCall(PetscMalloc1(w * nrecv + 1, &out->buf));
  if (order) PetscCall(PetscMalloc1(n + 1, order));
  for (PetscInt i = 0; i < n; ++i) {
    const PetscMPIInt pos = sdisp[dest[i]] + fill[dest[i]];
    PetscCall(PetscArraycpy(send + pos, rows + w * i, w));
    fill[dest[i]] += (PetscMPIInt)w;
    if (order) (*order)[i] = pos / (PetscMPIInt)w;
  }
  PetscCallMPI(MPI_Alltoallv(send, scount, sdisp, MPIU_REAL, out->buf, rcount, rdisp, MPIU_REAL, comm));
  out->w = w;
  out->n = nrecv;
  PetscCall(PetscFree(send));
  PetscCall(PetscFree5(scount, rcount, sdisp, rdisp, fill));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static int RowCompare(const void *a, const void *b)
{
  return KeyCompare((const PetscReal *)a, (const PetscReal *)b);
}

PetscErrorCode IndKeyJoin(MPI_Comm comm, PetscInt bs, PetscInt nfile, const PetscReal *keys_file,
                          const PetscReal *vals_file, PetscInt nwant, const PetscReal *keys_want, PetscReal *vals_want,
                          PetscInt *nmissing, PetscInt *nduplicate)
{
  PetscMPIInt size, *dest, *order;
  PetscReal  *rows, *answer;
  Packed      file, want, back;
  PetscInt    counts[2] = {0, 0};

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  /* The file's entries to the ranks of their keys, sorted there. */
  PetscCall(PetscMalloc2((3 + bs) * nfile + 1, &rows, PetscMax(nfile, nwant) + 1, &dest));
  for (PetscInt i = 0; i < nfile; ++i) {
    PetscCall(PetscArraycpy(rows + (3 + bs) * i, keys_file + 3 * i, 3));
    PetscCall(PetscArraycpy(rows + (3 + bs) * i + 3, vals_file + bs * i, bs));
    dest[i] = (PetscMPIInt)(IndKeyHash(keys_file + 3 * i) % size);
  }
  PetscCall(Exchange(comm, 3 + bs, nfile, rows, dest, &file, NULL));
  PetscCall(PetscFree2(rows, dest));
  qsort(file.buf, (size_t)file.n, sizeof(PetscReal) * (size_t)file.w, RowCompare);
  for (PetscInt i = 1; i < file.n; ++i)
    if (!KeyCompare(file.buf + file.w * (i - 1), file.buf + file.w * i)) counts[1]++;

  /* The requests to the same ranks, answered in the order they arrived, and sent back. */
  PetscCall(PetscMalloc1(nwant + 1, &dest));
  for (PetscInt i = 0; i < nwant; ++i) dest[i] = (PetscMPIInt)(IndKeyHash(keys_want + 3 * i) % size);
  PetscCall(Exchange(comm, 3, nwant, keys_want, dest, &want, &order));
  PetscCall(PetscMalloc1((bs + 1) * want.n + 1, &answer));
  for (PetscInt i = 0; i < want.n; ++i) {
    const PetscReal *hit = NULL;
    PetscInt         lo = 0, hi = file.n;
    while (lo < hi) {
      const PetscInt mid = (lo + hi) / 2;
      const int      c   = KeyCompare(file.buf + file.w * mid, want.buf + 3 * i);
      if (!c) {
        hit = file.buf + file.w * mid;
        break;
      }
      if (c < 0) lo = mid + 1;
      else hi = mid;
    }
    answer[(bs + 1) * i] = hit ? 1.0 : 0.0;
    if (hit) PetscCall(PetscArraycpy(answer + (bs + 1) * i + 1, hit + 3, bs));
    else PetscCall(PetscArrayzero(answer + (bs + 1) * i + 1, bs));
  }
  /* Back along the same routes: rank r answered our requests in the order we sent them. */
  {
    PetscMPIInt *scount, *rcount, *sdisp, *rdisp;
    PetscCall(PetscCalloc4(size, &scount, size, &rcount, size + 1, &sdisp, size + 1, &rdisp));
    for (PetscInt i = 0; i < nwant; ++i) rcount[dest[i]] += (PetscMPIInt)(bs + 1);
    PetscCallMPI(MPI_Alltoall(rcount, 1, MPI_INT, scount, 1, MPI_INT, comm));
    for (PetscMPIInt r = 0; r < size; ++r) {
      sdisp[r + 1] = sdisp[r] + scount[r];
      rdisp[r + 1] = rdisp[r] + rcount[r];
    }
    PetscCall(PetscMalloc1((bs + 1) * nwant + 1, &back.buf));
    PetscCallMPI(MPI_Alltoallv(answer, scount, sdisp, MPIU_REAL, back.buf, rcount, rdisp, MPIU_REAL, comm));
    PetscCall(PetscFree4(scount, rcount, sdisp, rdisp));
  }
  for (PetscInt i = 0; i < nwant; ++i) {
    const PetscReal *a = back.buf + (bs + 1) * order[i];
    if (a[0] == 0.0) counts[0]++;
    PetscCall(PetscArraycpy(vals_want + bs * i, a + 1, bs));
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, counts, 2, MPIU_INT, MPI_SUM, comm));
  *nmissing   = counts[0];
  *nduplicate = counts[1];
  PetscCall(PetscFree(answer));
  PetscCall(PetscFree(back.buf));
  PetscCall(PetscFree(order));
  PetscCall(PetscFree(dest));
  PetscCall(PetscFree(file.buf));
  PetscCall(PetscFree(want.buf));
  PetscFunctionReturn(PETSC_SUCCESS);
}
