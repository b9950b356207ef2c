static const char help[] = "Load control's bordered Newton step: exact on a linear bordered system, the decisions\n"
                           "without contact and at the depth limits, and Newton's convergence on a Hertzian node.\n";

#include "bordered.h"
#include "unit_report.h"

/* Solves the 3x3 system A x = r by Cramer's rule. */
static void Solve3(const PetscReal A[9], const PetscReal r[3], PetscReal x[3])
{
  const PetscReal det = A[0] * (A[4] * A[8] - A[5] * A[7]) - A[1] * (A[3] * A[8] - A[5] * A[6]) +
                        A[2] * (A[3] * A[7] - A[4] * A[6]);
  for (int k = 0; k < 3; ++k) {
    PetscReal B[9];
    for (int i = 0; i < 9; ++i) B[i] = (i % 3 == k) ? r[i / 3] : A[i];
    x[k] = (B[0] * (B[4] * B[8] - B[5] * B[7]) - B[1] * (B[3] * B[8] - B[5] * B[6]) +
            B[2] * (B[3] * B[7] - B[4] * B[6])) / det;
  }
}

/* A random (unsymmetric, diagonally dominant) J, F_d, p, F and c: the step (dU, dd) from the increment
   solves [J F_d; p^T 0] [dU; dd] = -[F; c]. */
static PetscReal LinearBordered(unsigned long long *seed)
{
  PetscReal J[9], Fd[3], p[3], F[3], c, Y[3], b[3], pY = 0, pb = 0, dd, worst = 0;

  for (int i = 0; i < 9; ++i) J[i] = Rand(seed) - 0.5 + (i % 4 == 0 ? 4.0 : 0.0);
  for (int i = 0; i < 3; ++i) Fd[i] = -(1 + Rand(seed)), p[i] = 1 + Rand(seed), F[i] = Rand(seed) - 0.5;
  c = Rand(seed) - 0.5;
  Solve3(J, F, Y);
  Solve3(J, Fd, b);
  for (int i = 0; i < 3; ++i) pY += p[i] * Y[i], pb += p[i] * b[i];
  if (!(pb < 0)) return 0; /* not a contact's stiffness: skipped, counted by the caller */
  dd = IndBorderedDepthIncrement(c, pY, pb, 0, 10, 1e9);
  {
    PetscReal dU[3], load = c;
    for (int i = 0; i < 3; ++i) dU[i] = -(Y[i] + dd * b[i]);
    for (int i = 0; i < 3; ++i) {
      PetscReal row = F[i] + Fd[i] * dd;
      for (int j = 0; j < 3; ++j) row += J[3 * i + j] * dU[j];
      worst = PetscMax(worst, PetscAbsReal(row));
      load += p[i] * dU[i];
    }
    worst = PetscMax(worst, PetscAbsReal(load));
  }
  return worst;
}

/* One node on a spring k pushed by a Hertzian contact: F(u, d) = k u - a s^1.5, s = max(d - u, 0) the
   overlap; the load the body carries is P = k u. Bordered Newton from rest (no contact) to P*; returns
   the iterations, -1 when not converged in 50, and the depth found. */
static PetscInt HertzNode(PetscReal target, PetscReal *depth)
{
  const PetscReal k = 3.0, a = 2.0, dmax = 100;
  PetscReal       u = 0, d = 0;

  for (PetscInt it = 0; it < 50; ++it) {
    const PetscReal s = PetscMax(d - u, 0.0), phi = a * PetscPowReal(s, 1.5), dphi = 1.5 * a * PetscSqrtReal(s);
    const PetscReal F = k * u - phi, c = k * u - target, J = k + dphi, Fd = -dphi, p = k;
    const PetscReal Y = F / J, b = Fd / J;
    PetscReal       dd;
    if (PetscAbsReal(F) < 1e-12 && PetscAbsReal(c) < 1e-12 * target) {
      *depth = d;
      return it;
    }
    dd = IndBorderedDepthIncrement(c, p * Y, p * b, u - d, d, dmax);
    u -= Y + dd * b;
    d += dd;
  }
  return -1;
}

int main(int argc, char **argv)
{
  unsigned long long seed = 7;
  PetscReal          worst = 0;
  PetscInt           used = 0;

  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  for (int trial = 0; trial < 200; ++trial) {
    const PetscReal w = LinearBordered(&seed);
    if (w > 0) used++;
    worst = PetscMax(worst, w);
  }
  printf("bordered step on %d random linear systems (%d with a contact's stiffness)\n", 200, (int)used);
  Report("residual of both equations after one step", worst, 1e-12);
  Report("systems with a contact's stiffness (of 200, want >= 150)", used >= 150 ? 0 : 1, 0);

  /* decisions without a stiffness and at the limits */
  Report("no contact, load short: to the nearest node, 1e-6 of the range further",
         PetscAbsReal(IndBorderedDepthIncrement(-5, 0, 0, 2.0, 10, 100) - (2.0 + 1e-4)), 1e-14);
  Report("no contact, load short, node already overlapping: a 1e-6 step",
         PetscAbsReal(IndBorderedDepthIncrement(-5, 0, 0, -1.0, 10, 100) - 1e-4), 1e-14);
  Report("no contact, load met or over: the depth stays", PetscAbsReal(IndBorderedDepthIncrement(0, 0, 0, 2, 10, 100)) +
         PetscAbsReal(IndBorderedDepthIncrement(3, 0, 0, 2, 10, 100)), 0);
  Report("a step past the largest depth stops there",
         PetscAbsReal(IndBorderedDepthIncrement(-1000, 0, -1, 0, 10, 100) - 90), 0);
  Report("a step above depth 0 stops there", PetscAbsReal(IndBorderedDepthIncrement(1000, 0, -1, 0, 10, 100) + 10), 0);
  Report("a contact's stiffness: dd = (c - pY) / pb",
         PetscAbsReal(IndBorderedDepthIncrement(-6, 1, -2, 0, 10, 100) - 3.5), 1e-15);

  /* Newton on the Hertzian node: from rest to loads from 1e-3 to 1e2 (the depth limit, 100, carries 352) */
  {
    PetscInt  most = 0, failed = 0;
    PetscReal err  = 0;
    for (PetscReal target = 1e-3; target < 2e2; target *= 10) {
      PetscReal      d;
      const PetscInt its = HertzNode(target, &d);
      if (its < 0) failed++;
      else {
        const PetscReal exact = target / 3.0 + PetscPowReal(target / 2.0, 2.0 / 3.0);
        err  = PetscMax(err, PetscAbsReal(d - exact) / exact);
        most = PetscMax(most, its);
      }
    }
    printf("Hertzian node from rest to P* = 1e-3 .. 1e2: at most %d Newton iterations\n", (int)most);
    Report("Hertzian node: depth against the closed form (relative)", err, 1e-10);
    Report("Hertzian node: loads not reached in 50 iterations", (PetscReal)failed, 0);
    Report("Hertzian node: iterations beyond 15", (PetscReal)PetscMax(most - 15, 0), 0);
  }
  PetscCall(PetscFinalize());
  return failures ? 1 : 0;
}
