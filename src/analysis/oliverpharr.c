#include <math.h>
#include <stdlib.h>
#include "ind_oliverpharr.h"

void IndOPParamsDefault(IndOPParams *p)
{
  p->fraction    = 0.5;
  p->epsilon     = 0.75;
  p->beta        = 1.034;
  p->E_indenter  = 0;
  p->nu_indenter = 0.07;
  p->nu_sample   = 0.3;
}

/* log-log regression of P on (h - h_f) for a fixed h_f; returns the misfit sum of squares in P. */
static PetscReal FitGivenHf(const PetscReal *h, const PetscReal *P, PetscInt n, PetscReal hf, PetscReal *alpha,
  PetscReal *m)
{
  PetscReal sx = 0, sy = 0, sxx = 0, sxy = 0, rss = 0;
  for (PetscInt i = 0; i < n; ++i) {
    const PetscReal x = PetscLogReal(h[i] - hf), y = PetscLogReal(P[i]);
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  *m     = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  *alpha = PetscExpReal((sy - *m * sx) / n);
  for (PetscInt i = 0; i < n; ++i) rss += PetscSqr(P[i] - *alpha * PetscPowReal(h[i] - hf, *m));
  return rss;
}

/* Gauss-Newton on (alpha, h_f, m) for the misfit in P itself, from the log-fit's values. */
static void Polish(const PetscReal *h, const PetscReal *P, PetscInt n, PetscReal hmin, PetscReal *alpha,
  PetscReal *hf, PetscReal *m)
{
  for (int it = 0; it < 50; ++it) {
    PetscReal JTJ[3][3] = {{0}}, JTr[3] = {0}, d[3], det;
    for (PetscInt i = 0; i < n; ++i) {
      const PetscReal x = h[i] - *hf, f = *alpha * PetscPowReal(x, *m), r = P[i] - f;
      const PetscReal J[3] = {f / *alpha, -*m * f / x, f * PetscLogReal(x)};
      for (int a = 0; a < 3; ++a) {
        JTr[a] += J[a] * r;
        for (int b = 0; b < 3; ++b) JTJ[a][b] += J[a] * J[b];
      }
    }
    det = JTJ[0][0] * (JTJ[1][1] * JTJ[2][2] - JTJ[1][2] * JTJ[2][1]) - JTJ[0][1] * (JTJ[1][0] * JTJ[2][2]
      - JTJ[1][2] * JTJ[2][0]) + JTJ[0][2] * (JTJ[1][0] * JTJ[2][1] - JTJ[1][1] * JTJ[2][0]);
    if (!(PetscAbsReal(det) > 0)) return;
    for (int a = 0; a < 3; ++a) { /* Cramer's rule */
      PetscReal M[3][3];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) M[i][j] = j == a ? JTr[i] : JTJ[i][j];
      d[a] = (M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) - M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0])
        + M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0])) / det;
    }
    if (*hf + d[1] >= hmin || *alpha + d[0] <= 0) return; /* keep h_f below the data */
    *alpha += d[0];
    *hf += d[1];
    *m += d[2];
    if (PetscAbsReal(d[1]) <= 1e-14 * (1 + PetscAbsReal(*hf)) && PetscAbsReal(d[2]) <= 1e-14 * PetscAbsReal(*m)) return;
  }
}

int IndOliverPharr(const PetscReal *h, const PetscReal *P, PetscInt n, const IndOPParams *p, IndAreaFn area,
  void *ctx, IndOPResult *r)
{
  PetscInt  imax = 0, k = 0;
  PetscReal *hsel, *Psel, hmin = PETSC_MAX_REAL, hmax_sel = -PETSC_MAX_REAL, lo, hi, a, b, fa, fb, al, m;
  const PetscReal g = 0.5 * (PetscSqrtReal(5.0) - 1);

  PetscMemzero(r, sizeof(*r));
  if (!(p->fraction > 0 && p->fraction <= 1 && p->epsilon > 0 && p->beta > 0) || n < 1) return 3;
  for (PetscInt i = 1; i < n; ++i)
    if (P[i] > P[imax]) imax = i;
  r->P_max = P[imax];
  r->h_max = h[imax];
  hsel = (PetscReal *)malloc(2 * (size_t)(n - imax) * sizeof(PetscReal));
  if (!hsel) return 3;
  Psel = hsel + (n - imax);
  /* A load below 1e-12 P_max is zero to any solver tolerance (a node left touching at round-off
     force when the indenter is back at the surface): it carries no unloading data. */
  for (PetscInt i = imax; i < n; ++i)
    if (P[i] >= (1 - p->fraction) * r->P_max && P[i] > 1e-12 * r->P_max) {
      hsel[k] = h[i];
      Psel[k] = P[i];
      hmin     = PetscMin(hmin, h[i]);
      hmax_sel = PetscMax(hmax_sel, h[i]);
      k++;
    }
  r->npoints = k;
  if (k < 3 || !(hmax_sel > hmin)) {
    free(hsel);
    return 1;
  }
  /* golden section for h_f below the fitted depths, then Gauss-Newton on all three parameters */
  lo = hmin - 20 * (hmax_sel - hmin);
  hi = hmin - 1e-9 * (hmax_sel - hmin);
  a  = hi - g * (hi - lo);
  b  = lo + g * (hi - lo);
  fa = FitGivenHf(hsel, Psel, k, a, &al, &m);
  fb = FitGivenHf(hsel, Psel, k, b, &al, &m);
  for (int it = 0; it < 200 && hi - lo > 1e-13 * (hmax_sel - hmin); ++it) {
    if (fa < fb) {
      hi = b;
      b  = a;
      fb = fa;
      a  = hi - g * (hi - lo);
      fa = FitGivenHf(hsel, Psel, k, a, &al, &m);
    } else {
      lo = a;
      a  = b;
      fa = fb;
      b  = lo + g * (hi - lo);
      fb = FitGivenHf(hsel, Psel, k, b, &al, &m);
    }
  }
  r->h_f = 0.5 * (lo + hi);
  (void)FitGivenHf(hsel, Psel, k, r->h_f, &r->alpha, &r->m);
  Polish(hsel, Psel, k, hmin, &r->alpha, &r->h_f, &r->m);
  {
    PetscReal rss = 0;
    for (PetscInt i = 0; i < k; ++i) rss += PetscSqr(Psel[i] - r->alpha * PetscPowReal(hsel[i] - r->h_f, r->m));
    r->rms = PetscSqrtReal(rss / k);
  }
  free(hsel);
  if (!(r->m > 0 && r->alpha > 0)) return 2;
  r->S   = r->m * r->alpha * PetscPowReal(r->h_max - r->h_f, r->m - 1);
  r->h_c = r->h_max - p->epsilon * r->P_max / r->S;
  r->A   = area(r->h_c, ctx);
  if (!(r->A > 0)) return 4; /* h_c at or below the tip: H and E_r would divide by no area */
  IndOPFromArea(p, r, r->A, &r->H, &r->E_r, &r->E);
  return 0;
}

void IndOPFromArea(const IndOPParams *p, const IndOPResult *fit, PetscReal A, PetscReal *H, PetscReal *E_r,
  PetscReal *E)
{
  *H   = 1000.0 * fit->P_max / A;
  *E_r = 1000.0 * PetscSqrtReal(PETSC_PI) / (2 * p->beta) * fit->S / PetscSqrtReal(A);
  /* 1/E_r = (1 - nu^2)/E + (1 - nu_i^2)/E_i, with E_i = infinity for a rigid indenter */
  {
    const PetscReal c = 1.0 / *E_r - (p->E_indenter > 0 ? (1 - p->nu_indenter * p->nu_indenter) / p->E_indenter : 0.0);
    *E = c > 0 ? (1 - p->nu_sample * p->nu_sample) / c : NAN; /* E_r above what the indenter allows */
  }
}
