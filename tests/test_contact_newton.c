static const char help[] = "Unit tests of the semi-smooth Newton contact: which rows a node gets in each state, and "
  "the\n"
                            "node's complementarity function against its derivative.\n";

#include "contact_node.h"
#include "contact_impl.h" /* a unit test of the contact group: it builds a contact node by hand */

#include "unit_report.h"

/* A node's three rows of a stiffness with 7 columns, its own dofs at columns 2, 3, 4. */
#define NC 7
static const PetscInt diag[3] = {2, 3, 4};

static void RandomRows(unsigned long long *seed, PetscReal K[3 * NC])
{
  for (int k = 0; k < 3 * NC; ++k) K[k] = 2 * Rand(seed) - 1;
}

/* The row decisions of IndContactNewtonRows, on closed forms. */
static void CheckRows(void)
{
  unsigned long long seed = 7;
  PetscReal          K[3 * NC], out[3 * NC], P[9] = {0}, B[9], worst;
  const PetscReal    n[3] = {0.6, 0, -0.8};

  RandomRows(&seed, K);
  for (int k = 0; k < 9; ++k) B[k] = 2 * Rand(&seed) - 1;
  /* open: D = 0, so P = B = 0 and the equilibrium rows stand */
  {
    const PetscReal Z[9] = {0};
    IndContactNewtonRows(Z, Z, 0, NC, diag, K, out);
    worst = 0;
    for (int k = 0; k < 3 * NC; ++k) worst = PetscMax(worst, PetscAbsReal(out[k] - K[k]));
    Report("open node keeps its equilibrium rows", worst, 0);
  }
  /* stick: D = I, P = I: only B at the node's own columns */
  for (int k = 0; k < 3; ++k) P[4 * k] = 1;
  IndContactNewtonRows(P, B, 0, NC, diag, K, out);
  worst = 0;
  for (int a = 0; a < 3; ++a)
    for (int j = 0; j < NC; ++j) {
      PetscReal expect = 0;
      for (int b = 0; b < 3; ++b)
        if (j == diag[b]) expect = B[3 * a + b];
      worst = PetscMax(worst, PetscAbsReal(out[a * NC + j] - expect));
    }
  Report("sticking node: a Dirichlet-like row on gap and slip only", worst, 1e-15);
  /* frictionless contact: P = n n^T, the normal part of the rows is replaced, the tangential kept */
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) P[3 * a + b] = n[a] * n[b];
  IndContactNewtonRows(P, B, 0, NC, diag, K, out);
  worst = 0;
  for (int j = 0; j < NC; ++j) {
    PetscReal nK = 0, nO = 0, nB = 0, tK[3], tO[3];
    for (int a = 0; a < 3; ++a) {
      nK += n[a] * K[a * NC + j];
      nO += n[a] * out[a * NC + j];
      for (int b = 0; b < 3; ++b)
        if (j == diag[b]) nB += n[a] * B[3 * a + b];
    }
    for (int a = 0; a < 3; ++a) {
      tK[a] = K[a * NC + j] - n[a] * nK;
      tO[a] = out[a * NC + j] - n[a] * nO;
      for (int b = 0; b < 3; ++b)
        if (j == diag[b]) tO[a] -= B[3 * a + b] - n[a] * nB;
      worst = PetscMax(worst, PetscAbsReal(tO[a] - tK[a]));
    }
    worst = PetscMax(worst, PetscAbsReal(nO - nB));
  }
  Report("frictionless contact: normal row replaced, tangential rows kept", worst, 1e-14);
  /* a component held by a boundary condition contributes no multiplier */
  {
    const PetscReal Z[9] = {0};
    IndContactNewtonRows(Z, Z, 2, NC, diag, K, out);
    worst = 0;
    for (int j = 0; j < NC; ++j) worst = PetscMax(worst,
      PetscAbsReal(out[NC + j]) + PetscAbsReal(out[j] - K[j]) + PetscAbsReal(out[2 * NC + j] - K[2 * NC + j]));
    Report("a held component's row carries no multiplier", worst, 0);
  }
}

/* One contact node of a rigid indenter, alone: what IndContactNodeSolve needs. */
static void MakeNode(IndIndenterType type, PetscReal radius, PetscReal mu, struct _p_IndContact *c, PetscReal X[3],
  PetscReal Uc[3], PetscReal *kdiag)
{
  PetscMemzero(c, sizeof(*c));
  c->indenter.type   = type;
  c->indenter.radius = radius;
  c->indenter.depth  = 10;
  if (IndIndenterSetUp(&c->indenter)) failures++;
  c->mu          = mu;
  c->gap_current = PETSC_TRUE;
  c->rho_scale   = 1;
  c->n           = 1;
  c->X           = X;
  c->Uc          = Uc;
  c->kdiag       = kdiag;
  c->depth_c     = 9;
}

/* C(u, lambda) = lambda - f(u, lambda): its derivative in lambda is I - Q D Q^T, in the node's own
   displacement -df/du (IndContactNodeStiffness); both against central differences of larger step,
   at random states, counted by the status they fall in. */
static void CheckNodeDerivative(const char *name, IndIndenterType type, PetscReal radius, PetscReal mu)
{
  unsigned long long   seed = 99;
  struct _p_IndContact c;
  PetscReal            X[3], Uc[3] = {0, 0, 0}, kdiag = 50, worst_l = 0, worst_u = 0;
  PetscInt             count[3] = {0, 0, 0};
  char                 what[160];

  MakeNode(type, radius, mu, &c, X, Uc, &kdiag);
  for (int trial = 0; trial < 600; ++trial) {
    PetscScalar    u[3];
    PetscReal      L[3], B[9], h = 1e-4;
    IndContactNode ns;
    X[0] = 20 * (2 * Rand(&seed) - 1);
    X[1] = 20 * (2 * Rand(&seed) - 1);
    X[2] = 0;
    for (int d = 0; d < 3; ++d) u[d] = 3 * (2 * Rand(&seed) - 1);
    L[0] = 100 * (2 * Rand(&seed) - 1);
    L[1] = 100 * (2 * Rand(&seed) - 1);
    L[2] = -300 * Rand(&seed);
    IndContactNodeSolve(&c, 0, u, L, &ns);
    count[ns.status]++;
    IndContactNodeStiffness(&c, 0, u, L, B);
    for (int b = 0; b < 3; ++b) {
      PetscScalar    up[3] = {u[0], u[1], u[2]}, um[3] = {u[0], u[1], u[2]};
      PetscReal      Lp[3] = {L[0], L[1], L[2]}, Lm[3] = {L[0], L[1], L[2]}, P[9];
      IndContactNode a, z;
      up[b] += h;
      um[b] -= h;
      IndContactNodeSolve(&c, 0, up, L, &a);
      IndContactNodeSolve(&c, 0, um, L, &z);
      if (a.status != ns.status || z.status != ns.status) continue; /* across a kink */
      for (int r = 0; r < 3; ++r) worst_u = PetscMax(worst_u,
        PetscAbsReal(B[3 * r + b] + (a.f[r] - z.f[r]) / (2 * h)) / (1 + PetscAbsReal(B[3 * r + b])));
      /* d f / d lambda = Q D Q^T */
      for (int r = 0; r < 3; ++r)
        for (int s = 0; s < 3; ++s) {
          P[3 * r + s] = 0;
          for (int k = 0; k < 3; ++k) {
            const PetscReal Q[3][3] = {{ns.n[0], ns.t1[0], ns.t2[0]}, {ns.n[1], ns.t1[1], ns.t2[1]}, {ns.n[2],
              ns.t1[2], ns.t2[2]}};
            for (int m = 0; m < 3; ++m) P[3 * r + s] += Q[r][k] * ns.D[3 * k + m] * Q[s][m];
          }
        }
      Lp[b] += h;
      Lm[b] -= h;
      IndContactNodeSolve(&c, 0, u, Lp, &a);
      IndContactNodeSolve(&c, 0, u, Lm, &z);
      if (a.status != ns.status || z.status != ns.status) continue;
      for (int r = 0; r < 3; ++r) worst_l = PetscMax(worst_l, PetscAbsReal(P[3 * r + b] - (a.f[r] - z.f[r]) / (2 * h)));
    }
  }
  snprintf(what, sizeof(what), "%s: d f/d lambda = Q D Q^T (open %d, stick %d, slip %d)", name, (int)count[0],
    (int)count[1], (int)count[2]);
  Report(what, worst_l, 1e-7);
  snprintf(what, sizeof(what), "%s: d f/d u, frame rotation included", name);
  Report(what, worst_u, 1e-5);
  if (!count[0] || !count[2] || (mu > 0 && !count[1])) {
    printf("  %s: some contact status never reached  FAIL\n", name);
    failures++;
  }
}

/* The semi-smooth Newton iteration of one node held by a spring of stiffness k at rest at z = 0, with
   a flat punch pressed to z = -2: lambda = k u, and Newton on C(u) = lambda(u) - f(u, lambda(u))
   lands on the punch (u = -2) in one step from a penetrating start and two from an open one. */
static void CheckOneNodeNewton(void)
{
  struct _p_IndContact c;
  PetscReal            X[3] = {0, 0, 0}, Uc[3] = {0, 0, 0}, kdiag = 50, worst = 0;
  PetscInt             worst_its = 0;

  MakeNode(IND_INDENTER_FLAT, 100, 0.0, &c, X, Uc, &kdiag);
  c.depth_c = c.indenter.depth = 2; /* the punch face at z = -2 */
  for (int start = 0; start < 2; ++start) {
    PetscScalar u[3] = {0, 0, start ? -10.0 : 1.0};
    PetscInt    its  = 0;
    for (; its < 10; ++its) {
      PetscReal      L[3], P[9] = {0}, B[9], J, F;
      IndContactNode ns;
      const PetscReal k = 30, K[3] = {0, 0, k};
      L[0] = L[1] = 0;
      L[2] = k * PetscRealPart(u[2]);
      IndContactNodeSolve(&c, 0, u, L, &ns);
      F = L[2] - ns.f[2];
      if (PetscAbsReal(F) < 1e-6) break; /* nN, of forces of 100: the central differences of the stiffness */
      IndContactNodeStiffness(&c, 0, u, L, B);
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b)
          for (int m = 0; m < 3; ++m) {
            const PetscReal Q[3][3] = {{ns.n[0], ns.t1[0], ns.t2[0]}, {ns.n[1], ns.t1[1], ns.t2[1]}, {ns.n[2],
              ns.t1[2], ns.t2[2]}};
            for (int q = 0; q < 3; ++q) P[3 * a + b] += Q[a][m] * ns.D[3 * m + q] * Q[b][q];
          }
      J = (1 - P[8]) * K[2] + B[8];
      u[2] -= F / J;
    }
    worst     = PetscMax(worst, PetscAbsReal(PetscRealPart(u[2]) + 2));
    worst_its = PetscMax(worst_its, its);
  }
  Report("one node onto a punch: exact position from open and from deep", worst, 1e-8);
  Report("one node onto a punch: Newton steps (at most 2)", (PetscReal)worst_its, 2);
}

/* The stiffness's decision: central differences (the frame turning with the node) on a smooth
   surface; at a kink (a node on the axis inside a sharp pyramid, where the nearest face jumps) the
   frame held fixed, rho Q D G. */
static void CheckKinkDecision(void)
{
  struct _p_IndContact c;
  PetscReal            X[3] = {0, 0, 0}, Uc[3] = {0, 0, 0}, kdiag = 50, B[9], worst = 0;
  const PetscReal      L[3] = {0, 0, -100};
  PetscScalar          u[3] = {0, 0, 0};
  PetscBool            smooth;
  IndContactNode       ns;

  MakeNode(IND_INDENTER_BERKOVICH, 0, 0.0, &c, X, Uc, &kdiag); /* apex 10 below the surface: deep */
  smooth = IndContactNodeStiffness(&c, 0, u, L, B);
  IndContactNodeSolve(&c, 0, u, L, &ns);
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      PetscReal expect = 0; /* frictionless sliding: D = e0 e0^T, so rho n n^T */
      expect = c.rho_scale * kdiag * ns.n[a] * ns.n[b] * ns.D[0];
      worst  = PetscMax(worst, PetscAbsReal(B[3 * a + b] - expect));
    }
  Report("apex of a sharp Berkovich: kink found, frame held (|B - rho n n^T|)", smooth ? 1.0 : worst, 1e-10);
  MakeNode(IND_INDENTER_SPHERE, 30, 0.0, &c, X, Uc, &kdiag);
  X[0] = 3;
  smooth = IndContactNodeStiffness(&c, 0, u, L, B);
  Report("inside a sphere: no kink, central differences", smooth ? 0.0 : 1.0, 0);
}

int main(int argc, char **argv)
{
  PetscFunctionBeginUser;
  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  CheckRows();
  CheckNodeDerivative("sphere R = 30, mu = 0.3", IND_INDENTER_SPHERE, 30, 0.3);
  CheckNodeDerivative("berkovich R = 5, mu = 0.5", IND_INDENTER_BERKOVICH, 5, 0.5);
  CheckNodeDerivative("cone R = 0 (sharp), frictionless", IND_INDENTER_CONE, 0, 0.0);
  CheckOneNodeNewton();
  CheckKinkDecision();
  printf("%s: %d failure(s)\n", failures ? "FAILED" : "passed", (int)failures);
  PetscCall(PetscFinalize());
  return failures ? 1 : 0;
}
