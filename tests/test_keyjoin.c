static const char help[] = "The key join returns each requested key's values whatever ranks held them, and counts\n"
                           "keys the file lacks or holds twice.\n";

#include "ind_keyjoin.h"
#include "unit_report.h"

/* A global set of n distinct keys on a grid, each with bs values f(key); the first layer has z = -0.0. */
static void Key(PetscInt i, PetscReal key[3])
{
  key[0] = (PetscReal)(i % 7) * 0.1 - 0.3;
  key[1] = (PetscReal)((i / 7) % 5) * 1.7e3;
  key[2] = -(PetscReal)(i / 35) / 3.0;
}

static PetscReal Value(const PetscReal key[3], PetscInt k)
{
  return key[0] + 10 * key[1] - 100 * key[2] + 1e-3 * (PetscReal)k;
}

int main(int argc, char **argv)
{
  const PetscInt bs = 4, n = 7 * 5 * 6;
  PetscMPIInt    rank, size;
  PetscReal     *kf, *vf, *kw, *vw, worst = 0;
  PetscInt       nf = 0, nw = 0, missing, duplicate;

  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  PetscCallMPI(MPI_Comm_rank(PETSC_COMM_WORLD, &rank));
  PetscCallMPI(MPI_Comm_size(PETSC_COMM_WORLD, &size));
  PetscCall(PetscMalloc4(3 * (n + 1), &kf, bs * (n + 1), &vf, 3 * (n + 1), &kw, bs * (n + 1), &vw));
  /* The file's part: every size-th key from the end; the requests: another split, in another order. */
  for (PetscInt i = n - 1 - rank; i >= 0; i -= size) {
    Key(i, kf + 3 * nf);
    for (PetscInt k = 0; k < bs; ++k) vf[bs * nf + k] = Value(kf + 3 * nf, k);
    nf++;
  }
  for (PetscInt i = 0; i < n; ++i)
    if ((i * 11 + 3) % size == rank) {
      Key(i, kw + 3 * nw);
      if (i % 2) kw[3 * nw + 2] += 0.0; /* +0.0 asks for the file's -0.0 */
      nw++;
    }
  PetscCall(IndKeyJoin(PETSC_COMM_WORLD, bs, nf, kf, vf, nw, kw, vw, &missing, &duplicate));
  for (PetscInt i = 0; i < nw; ++i)
    for (PetscInt k = 0; k < bs; ++k) worst = PetscMax(worst, PetscAbsReal(vw[bs * i + k] - Value(kw + 3 * i, k)));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &worst, 1, MPIU_REAL, MPIU_MAX, PETSC_COMM_WORLD));
  if (!rank) {
    Report("values of every requested key", worst, 0);
    Report("keys missing", (PetscReal)missing, 0);
    Report("keys held twice", (PetscReal)duplicate, 0);
  }

  /* A key the file lacks (the last rank asks for it) and a key it holds twice (rank 0 repeats one). */
  if (rank == size - 1) {
    kw[0] = 12345.0;
    kw[1] = kw[2] = 0;
  }
  if (!rank) {
    Key(5, kf + 3 * nf);
    for (PetscInt k = 0; k < bs; ++k) vf[bs * nf + k] = 0;
    nf++;
  }
  PetscCall(IndKeyJoin(PETSC_COMM_WORLD, bs, nf, kf, vf, nw, kw, vw, &missing, &duplicate));
  if (!rank) {
    Report("a key the file lacks is counted (1 expected)", PetscAbsReal((PetscReal)missing - 1), 0);
    Report("a key held twice is counted (1 expected)", PetscAbsReal((PetscReal)duplicate - 1), 0);
  }
  PetscCall(PetscFree4(kf, vf, kw, vw));
  PetscCall(PetscFinalize());
  return failures ? 1 : 0;
}
