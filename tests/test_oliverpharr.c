static const char help[] = "Unit test of the Oliver-Pharr analysis on synthetic power-law unloading curves.\n";

#include "ind_oliverpharr.h"
#include "ind_indenter.h"

static PetscInt failures = 0;

static void Report(const char *what, PetscReal worst, PetscReal tol)
{
  const PetscBool ok = worst <= tol ? PETSC_TRUE : PETSC_FALSE;
  if (!ok) failures++;
  printf("  %-56s worst %.2e (tol %.0e)%s\n", what, (double)worst, (double)tol, ok ? "" : "  FAIL");
}

static PetscReal Area(PetscReal hc, void *ctx)
{
  return IndIndenterArea((const IndIndenter *)ctx, hc);
}

/* A loading branch P = C h^2 to h_max, then the unloading P = alpha (h - h_f)^m, n points each. */
static void Curve(PetscReal hmax, PetscReal hf, PetscReal m, PetscInt n, PetscReal *h, PetscReal *P, PetscReal *alpha)
{
  const PetscReal Pmax = 5000.0; /* uN */
  *alpha = Pmax / PetscPowReal(hmax - hf, m);
  for (PetscInt i = 0; i < n; ++i) {
    h[i] = hmax * (i + 1) / n;
    P[i] = Pmax * PetscSqr(h[i] / hmax);
  }
  for (PetscInt i = 1; i <= n; ++i) {
    h[n - 1 + i] = hmax - (hmax - hf) * i / n;
    P[n - 1 + i] = *alpha * PetscPowReal(h[n - 1 + i] - hf, m);
  }
}

int main(int argc, char **argv)
{
  IndIndenter b;
  IndOPParams p;
  PetscReal   h[400], P[400];
  PetscReal   worst = 0, worst_fit = 0;

  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  PetscMemzero(&b, sizeof(b));
  b.type   = IND_INDENTER_BERKOVICH;
  b.radius = 50;
  IndIndenterSetUp(&b);
  IndOPParamsDefault(&p);
  printf("Oliver-Pharr on exact power-law unloading curves (rounded Berkovich, R = 50 nm)\n");
  {
    const PetscReal hmaxs[3] = {300, 500, 800}, ms[3] = {1.2, 1.45, 2.0}, hfs[3] = {0.4, 0.7, 0.85};
    for (int a = 0; a < 3; ++a)
      for (int c = 0; c < 3; ++c) {
        const PetscReal hmax = hmaxs[a], m = ms[c], hf = hfs[(a + c) % 3] * hmax;
        PetscReal       alpha, S, hc, A, H, Er;
        IndOPResult     r;
        Curve(hmax, hf, m, 100, h, P, &alpha);
        if (IndOliverPharr(h, P, 200, &p, Area, &b, &r)) {
          failures++;
          continue;
        }
        S  = m * alpha * PetscPowReal(hmax - hf, m - 1);
        hc = hmax - 0.75 * 5000 / S;
        A  = IndIndenterArea(&b, hc);
        H  = 1000 * 5000 / A;
        Er = 1000 * PetscSqrtReal(PETSC_PI) / (2 * 1.034) * S / PetscSqrtReal(A);
        worst_fit = PetscMax(worst_fit, PetscMax(PetscAbsReal(r.m / m - 1), PetscAbsReal(r.h_f - hf) / hmax));
        worst     = PetscMax(worst, PetscMax(PetscAbsReal(r.S / S - 1), PetscMax(PetscAbsReal(r.H / H - 1),
          PetscAbsReal(r.E_r / Er - 1))));
        if (a == 1 && c == 1) printf("  e.g. h_max %g nm, h_f %g nm, m %g: S %.6g uN/nm, h_c %.6g nm, A %.6g nm^2, H "
          "%.6g GPa, E_r %.6g GPa (%d points fitted)\n", (double)hmax, (double)hf, (double)m, (double)r.S,
          (double)r.h_c, (double)r.A, (double)r.H, (double)r.E_r, (int)r.npoints);
      }
  }
  Report("fitted m and h_f", worst_fit, 1e-8);
  Report("S, H and E_r against the closed forms", worst, 1e-6);
  {
    /* Sample modulus: a rigid indenter gives E = (1 - nu^2) E_r; a diamond one removes its share. */
    IndOPResult fit = {0};
    PetscReal   H, Er, E;
    fit.P_max = 1000;
    fit.S     = 20; /* E_r = 17 GPa, below the diamond's modulus */
    IndOPFromArea(&p, &fit, 1e6, &H, &Er, &E);
    Report("rigid indenter: E = (1 - nu^2) E_r", PetscAbsReal(E / ((1 - 0.09) * Er) - 1), 1e-14);
    p.E_indenter = 1141;
    IndOPFromArea(&p, &fit, 1e6, &H, &Er, &E);
    Report("diamond indenter: 1/E_r = (1-nu^2)/E + (1-nu_i^2)/E_i",
      PetscAbsReal(1 / Er - ((1 - 0.09) / E + (1 - 0.0049) / 1141)) * Er, 1e-14);
    Report("H = P_max / A", PetscAbsReal(H - 1000 * 1000 / 1e6), 1e-14);
  }
  {
    IndOPResult r;
    const PetscReal hh[2] = {1, 2}, pp[2] = {1, 0};
    if (IndOliverPharr(hh, pp, 2, &p, Area, &b, &r) != 1) failures++; /* too few points */
  }
  printf("%s: %d failure(s)\n", failures ? "FAIL" : "ok", (int)failures);
  PetscCall(PetscFinalize());
  return failures ? 1 : 0;
}
