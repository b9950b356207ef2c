/* Unit test of the constitutive kernel (src/physics/plasticity.c) against the closed forms of doc/theory.md
   section 1. Every expected value is computed here from a closed form; no numbers are pasted.
   Exits non-zero, with the failing check named, on the first failure. */
#include <math.h>
#include <string.h>
#include "ind_plasticity.h"
#include "ind_hardening.h"
#include "kernel_tests.h"

/* E = 70 GPa, nu = 0.3 throughout. */
static const PetscReal YOUNG = 70.0, POISSON = 0.3;

typedef enum { VOCE, LINEAR } Kind;

static IndPlasticParams Law(Kind law, PetscReal R0, PetscReal Rs, PetscReal gamma, PetscReal h, PetscReal H)
{
  IndPlasticParams m;

  memset(&m, 0, sizeof(m));
  m.kappa = YOUNG / (3.0 * (1.0 - 2.0 * POISSON));
  m.mu    = YOUNG / (2.0 * (1.0 + POISSON));
  m.R0    = R0;
  m.H     = H;
  if (law == LINEAR) IndHardeningSetLinear(&m, h);
  else IndHardeningSetVoce(&m, Rs, gamma);
  return m;
}

static PetscReal Young(const IndPlasticParams *m)
{
  return 9.0 * m->kappa * m->mu / (3.0 * m->kappa + m->mu);
}

/* splitmix64: deterministic on every platform, unlike rand(). */
static PetscReal Uniform(unsigned long long *s)
{
  unsigned long long z = (*s += 0x9e3779b97f4a7c15ULL);
  z                    = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z                    = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  z ^= z >> 31;
  return (PetscReal)(z >> 11) * 0x1.0p-53;
}

static PetscReal Normal(unsigned long long *s)
{
  const PetscReal u = 1.0 - Uniform(s), v = Uniform(s);
  return PetscSqrtReal(-2.0 * PetscLogReal(u)) * PetscCosReal(2.0 * PETSC_PI * v);
}

/* Norm of a symmetric tensor given by its 6 tensor components. */
static PetscReal TensorNorm(const PetscReal t[6])
{
  return PetscSqrtReal(t[0] * t[0] + t[1] * t[1] + t[2] * t[2] + 2.0 * (t[3] * t[3] + t[4] * t[4] + t[5] * t[5]));
}

static void RandomDeviator(unsigned long long *s, PetscReal scale, PetscReal t[6])
{
  PetscReal mean;

  for (int i = 0; i < 6; ++i) t[i] = scale * Normal(s);
  mean = (t[0] + t[1] + t[2]) / 3.0;
  for (int i = 0; i < 3; ++i) t[i] -= mean;
}

/* von Mises distance of the stress from the current yield surface centre: sqrt(3/2) |s - x|. */
static PetscReal Equivalent(const PetscReal sigma[6], const PetscReal x[6])
{
  const PetscReal mean = (sigma[0] + sigma[1] + sigma[2]) / 3.0;
  PetscReal       eta[6];

  for (int i = 0; i < 6; ++i) eta[i] = sigma[i] - (i < 3 ? mean : 0.0) - x[i];
  return PetscSqrtReal(1.5) * TensorNorm(eta);
}

static PetscErrorCode Update(const IndPlasticParams *m, const PetscReal eps[6], const IndPlasticState *old,
  IndPlasticState *st, PetscReal sigma[6], PetscReal D[36], PetscReal *dp)
{
  PetscFunctionBeginUser;
  PetscCheck(IndPlasticUpdate(m, eps, old, st, sigma, D, dp) == IND_PLASTIC_OK, PETSC_COMM_SELF,
    PETSC_ERR_NOT_CONVERGED, "IndPlasticUpdate did not converge at eps = [%g %g %g %g %g %g]", (double)eps[0],
    (double)eps[1], (double)eps[2], (double)eps[3], (double)eps[4], (double)eps[5]);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Strain-driven uniaxial stress: Newton on the lateral strain with the consistent tangent until
   sigma_yy = sigma_zz = 0 (they stay equal by symmetry). */
static PetscErrorCode UniaxialStep(const IndPlasticParams *m, PetscReal exx, PetscReal *lat,
  const IndPlasticState *old, IndPlasticState *st, PetscReal sigma[6], PetscReal *dp)
{
  PetscReal D[36];

  PetscFunctionBeginUser;
  for (int k = 0;; ++k) {
    const PetscReal eps[6] = {exx, *lat, *lat, 0, 0, 0};

    PetscCall(Update(m, eps, old, st, sigma, D, dp));
    if (PetscAbsReal(sigma[1]) <= 1e-14 * PetscAbsReal(sigma[0])) break;
    PetscCheck(k < 50, PETSC_COMM_SELF, PETSC_ERR_NOT_CONVERGED,
      "Lateral strain iteration stalls at exx = %g: sigma_yy = %g", (double)exx, (double)sigma[1]);
    *lat -= sigma[1] / (D[7] + D[8]);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Monotonic tension: sigma_xx = R(p) + H p (elastic: E exx), and with the flow direction fixed the
   backward Euler result does not depend on the step size. */
static PetscErrorCode TestUniaxial(const char *name, const IndPlasticParams *m)
{
  IndPlasticState st, one;
  PetscReal       lat = 0.0, sigma[6], dp, worst = 0.0, worst_ep = 0.0, lat1 = 0.0, sigma1[6];
  const PetscReal emax = 0.02;
  const int       nsteps = 40;
  char            label[128];

  PetscFunctionBeginUser;
  memset(&st, 0, sizeof(st));
  for (int k = 1; k <= nsteps; ++k) {
    const PetscReal exx = emax * k / nsteps;
    PetscReal       expected;

    PetscCall(UniaxialStep(m, exx, &lat, &st, &st, sigma, &dp));
    expected = st.p > 0 ? IndPlasticR(m, st.p) + m->H * st.p : Young(m) * exx;
    worst    = PetscMax(worst, PetscAbsReal(sigma[0] - expected) / PetscAbsReal(expected));
    /* eps_p = sqrt(3/2) p n with n = sqrt(2/3) (1, -1/2, -1/2): eps_p,xx = p */
    if (st.p > 0) worst_ep = PetscMax(worst_ep, PetscAbsReal(st.eps_p[0] - st.p) / st.p);
  }
  PetscCheck(st.p > 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "%s: uniaxial test never yielded", name);
  PetscCall(PetscSNPrintf(label, sizeof(label), "uniaxial %s: sigma_xx = R(p) + H p", name));
  CHECK_TOL(label, worst, 1e-10);
  PetscCall(PetscSNPrintf(label, sizeof(label), "uniaxial %s: eps_p,xx = p", name));
  CHECK_TOL(label, worst_ep, 1e-10);

  memset(&one, 0, sizeof(one));
  PetscCall(UniaxialStep(m, emax, &lat1, &one, &one, sigma1, &dp));
  PetscCall(PetscSNPrintf(label, sizeof(label), "uniaxial %s: 1 step vs %d steps (sigma_xx, p)", name, nsteps));
  CHECK_TOL(label, PetscMax(PetscAbsReal(sigma1[0] - sigma[0]) / PetscAbsReal(sigma[0]),
    PetscAbsReal(one.p - st.p) / st.p), 1e-10);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Tension to emax, then compression. With X = x_xx - x_yy (= 1.5 x_xx in uniaxial stress) reverse
   yielding starts at sigma_xx = X - R(p_max), i.e. after an elastic unloading at
   exx_rev = emax + (X - R(p_max) - sigma_max) / E; in compression eps_p,xx = 2 p_max - p so
   X = H (2 p_max - p) and the stress stays at X - R(p). */
static PetscErrorCode TestCycle(const char *name, const IndPlasticParams *m)
{
  IndPlasticState top, st, probe;
  const PetscReal emax = 0.01, E = Young(m), delta = 1e-9;
  const int       nsteps = 40;
  PetscReal       lat = 0.0, lat_top, sigma[6], sigma_top, dp, X, pred, exx_rev, worst = 0.0, worst_onset = 0.0,
    prev_exx, prev_sigma = 0.0;
  PetscBool       reversed = PETSC_FALSE;
  char            label[128];

  PetscFunctionBeginUser;
  memset(&top, 0, sizeof(top));
  for (int k = 1; k <= nsteps; ++k) PetscCall(UniaxialStep(m, emax * k / nsteps, &lat, &top, &top, sigma, &dp));
  sigma_top = sigma[0];
  lat_top   = lat;
  X         = top.x[0] - top.x[1];
  pred      = X - IndPlasticR(m, top.p);
  exx_rev   = emax + (pred - sigma_top) / E;
  worst     = PetscAbsReal(X - 1.5 * top.x[0]) / PetscAbsReal(X);

  /* Sharp onset: single steps from the top state just before, at and just past exx_rev. */
  lat = lat_top;
  PetscCall(UniaxialStep(m, exx_rev + delta, &lat, &top, &probe, sigma, &dp));
  PetscCheck(dp == 0.0, PETSC_COMM_SELF, PETSC_ERR_PLIB,
    "%s: yielded in compression before the predicted onset (exx_rev + %g)", name, (double)delta);
  lat = lat_top;
  PetscCall(UniaxialStep(m, exx_rev, &lat, &top, &probe, sigma, &dp));
  worst_onset = PetscAbsReal(sigma[0] - pred) / PetscAbsReal(pred);
  lat         = lat_top;
  PetscCall(UniaxialStep(m, exx_rev - delta, &lat, &top, &probe, sigma, &dp));
  PetscCheck(dp > 0.0, PETSC_COMM_SELF, PETSC_ERR_PLIB,
    "%s: no reverse yielding just past the predicted onset (exx_rev - %g)", name, (double)delta);

  /* The cycle itself: the first plastic compression step must bracket exx_rev, every plastic one
     must sit on sigma_xx = H (2 p_max - p) - R(p). */
  st       = top;
  lat      = lat_top;
  prev_exx = emax;
  for (int k = 1; k <= 2 * nsteps; ++k) {
    const PetscReal exx = emax - 2.0 * emax * k / nsteps;

    PetscCall(UniaxialStep(m, exx, &lat, &st, &st, sigma, &dp));
    if (dp > 0) {
      const PetscReal Xn = st.x[0] - st.x[1], closed = m->H * (2.0 * top.p - st.p) - IndPlasticR(m, st.p);

      if (!reversed) {
        PetscCheck(prev_exx > exx_rev && exx < exx_rev, PETSC_COMM_SELF, PETSC_ERR_PLIB,
          "%s: first reverse plastic step at exx = %g, previous %g, predicted onset %g", name, (double)exx,
          (double)prev_exx, (double)exx_rev);
        PetscCheck(prev_sigma >= pred, PETSC_COMM_SELF, PETSC_ERR_PLIB,
          "%s: elastic unloading reached %g below the reverse yield stress %g", name, (double)prev_sigma, (double)pred);
        reversed = PETSC_TRUE;
      }
      worst = PetscMax(worst, PetscAbsReal(sigma[0] - (Xn - IndPlasticR(m, st.p))) / PetscAbsReal(sigma[0]));
      worst = PetscMax(worst, PetscAbsReal(sigma[0] - closed) / PetscAbsReal(sigma[0]));
    } else {
      PetscCheck(!reversed, PETSC_COMM_SELF, PETSC_ERR_PLIB,
        "%s: elastic step during monotonic compression at exx = %g", name, (double)exx);
      /* elastic unloading from the top state */
      worst = PetscMax(worst, PetscAbsReal(sigma[0] - (sigma_top + E * (exx - emax))) / PetscAbsReal(sigma_top));
    }
    prev_exx   = exx;
    prev_sigma = sigma[0];
  }
  PetscCheck(reversed, PETSC_COMM_SELF, PETSC_ERR_PLIB, "%s: never yielded in compression", name);
  PetscCall(PetscPrintf(PETSC_COMM_SELF,
    "  cycle %s: sigma_max %.6f, X %.6f, reverse yield at X - R(p) = %.6f GPa (exx %.6f)\n", name, (double)sigma_top,
    (double)X, (double)pred, (double)exx_rev));
  PetscCall(PetscSNPrintf(label, sizeof(label), "cycle %s: stress at the predicted onset", name));
  CHECK_TOL(label, worst_onset, 1e-10);
  PetscCall(PetscSNPrintf(label, sizeof(label), "cycle %s: unloading and sigma = X - R(p)", name));
  CHECK_TOL(label, worst, 1e-10);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Isochoric simple shear eps = gamma e_xy: stress stays pure shear, and with n_xy = 1/sqrt(2),
   deps_p,xy (tensor) = sqrt(3/2) dp / sqrt(2) gives gamma_p = sqrt(3) p, x_xy = H p / sqrt(3) and the
   yield condition sqrt(3) |tau - x_xy| = R(p) gives tau = (R(p) + H p) / sqrt(3) = mu (gamma - gamma_p). */
static PetscErrorCode TestShear(const char *name, const IndPlasticParams *m)
{
  IndPlasticState st;
  PetscReal       sigma[6], dp, worst = 0.0, worst_p = 0.0, worst_other = 0.0;
  const int       nsteps = 50;
  char            label[128];

  PetscFunctionBeginUser;
  memset(&st, 0, sizeof(st));
  for (int k = 1; k <= nsteps; ++k) {
    const PetscReal g = 0.05 * k / nsteps, eps[6] = {0, 0, 0, g, 0, 0};
    PetscReal       tau;

    PetscCall(Update(m, eps, &st, &st, sigma, NULL, &dp));
    tau         = st.p > 0 ? (IndPlasticR(m, st.p) + m->H * st.p) / PetscSqrtReal(3.0) : m->mu * g;
    worst       = PetscMax(worst, PetscAbsReal(sigma[3] - tau) / tau);
    worst       = PetscMax(worst, PetscAbsReal(sigma[3] - m->mu * (g - st.eps_p[3])) / tau);
    worst_other = PetscMax(worst_other, PetscMax(PetscMax(PetscAbsReal(sigma[0]), PetscAbsReal(sigma[1])),
      PetscMax(PetscAbsReal(sigma[2]), PetscMax(PetscAbsReal(sigma[4]), PetscAbsReal(sigma[5])))) / tau);
    if (st.p > 0) worst_p = PetscMax(worst_p, PetscAbsReal(st.p - st.eps_p[3] / PetscSqrtReal(3.0)) / st.p);
  }
  PetscCheck(st.p > 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "%s: shear test never yielded", name);
  PetscCall(PetscSNPrintf(label, sizeof(label), "shear %s: tau = (R(p) + H p)/sqrt(3)", name));
  CHECK_TOL(label, worst, 1e-10);
  PetscCall(PetscSNPrintf(label, sizeof(label), "shear %s: p = gamma_p/sqrt(3)", name));
  CHECK_TOL(label, worst_p, 1e-10);
  PetscCall(PetscSNPrintf(label, sizeof(label), "shear %s: other stress components / tau", name));
  CHECK_TOL(label, worst_other, 1e-13);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A random history and a total strain whose trial von Mises stress is factor * R(p_n). */
static void RandomState(const IndPlasticParams *m, unsigned long long *s, PetscReal factor, IndPlasticState *old,
  PetscReal eps[6])
{
  PetscReal ep[6], d[6], nd, q, vol = 1e-3 * Normal(s);

  RandomDeviator(s, 2e-3, ep);
  if (m->H > 0) RandomDeviator(s, 0.05, old->x);
  else memset(old->x, 0, sizeof(old->x)); /* x stays 0 without kinematic hardening */
  old->p = PetscAbsReal(Normal(s)) * 5e-3;
  q      = factor * IndPlasticR(m, old->p);
  RandomDeviator(s, 1.0, d);
  nd = TensorNorm(d);
  for (int i = 0; i < 6; ++i) {
    /* eta_E = 2 mu (e - eps_p) - x = q / sqrt(3/2) d / |d| */
    const PetscReal e = ep[i] + (q / PetscSqrtReal(1.5) * d[i] / nd + old->x[i]) / (2.0 * m->mu);

    old->eps_p[i] = (i < 3 ? 1.0 : 2.0) * ep[i];
    eps[i]        = i < 3 ? e + vol / 3.0 : 2.0 * e;
  }
}

/* Consistent tangent against central differences, and the returned state on the yield surface. */
static PetscErrorCode TestTangent(const char *name, const IndPlasticParams *m, int nsamples, unsigned long long *seed,
  PetscReal *worst_fd, PetscReal *worst_ys, int *used, int *skipped, int *plastic)
{
  PetscFunctionBeginUser;
  for (int k = 0; k < nsamples; ++k) {
    IndPlasticState old, st;
    PetscReal       eps[6], sigma[6], D[36], Dfd[36], dp, factor, h, emax = 0.0, dmax = 0.0, diff = 0.0;
    PetscBool       kink = PETSC_FALSE;

    switch (k % 4) { /* elastic, near the surface on either side, moderate and large plastic steps */
    case 0:
      factor = 0.98 * Uniform(seed);
      break;
    case 1:
      factor = 1.0 + (Uniform(seed) < 0.5 ? -1.0 : 1.0) * PetscPowReal(10.0, -10.0 + 8.0 * Uniform(seed));
      break;
    case 2:
      factor = 1.0 + PetscPowReal(10.0, -2.0 + 2.0 * Uniform(seed));
      break;
    default:
      factor = 2.0 + 48.0 * Uniform(seed);
    }
    RandomState(m, seed, factor, &old, eps);
    PetscCall(Update(m, eps, &old, &st, sigma, D, &dp));
    if (dp > 0) {
      ++*plastic;
      *worst_ys = PetscMax(*worst_ys,
        PetscAbsReal(Equivalent(sigma, st.x) - IndPlasticR(m, st.p)) / IndPlasticR(m, st.p));
    }
    for (int i = 0; i < 6; ++i) emax = PetscMax(emax, PetscAbsReal(eps[i]));
    h = 1e-7 * PetscMax(emax, m->R0 / (2.0 * m->mu));
    PetscCall(CentralDifferenceTangent(IndPlasticUpdate, m, &old, eps, h, (PetscBool)(dp > 0), Dfd, &kink));
    if (kink) {
      ++*skipped;
      continue;
    }
    for (int i = 0; i < 36; ++i) {
      dmax = PetscMax(dmax, PetscAbsReal(D[i]));
      diff = PetscMax(diff, PetscAbsReal(D[i] - Dfd[i]));
    }
    PetscCheck(diff / dmax <= 1e-6, PETSC_COMM_SELF, PETSC_ERR_PLIB,
      "%s: tangent differs from finite differences by %g (relative) at sample %d, factor %g, dp %g", name,
      (double)(diff / dmax), k, (double)factor, (double)dp);
    *worst_fd = PetscMax(*worst_fd, diff / dmax);
    ++*used;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Failure must be reported, never papered over with an invented state; and the safeguards must let
   hard cases converge. */
static PetscErrorCode TestRobustness(void)
{
  IndPlasticParams m = Law(VOCE, 0.3, 0.5, 20.0, 0.0, 1.0);
  IndPlasticState  old, st;
  PetscReal        eps[6], sigma[6], D[36], dp, worst = 0.0;
  unsigned long long seed = 7;
  IndPlasticStatus status;

  PetscFunctionBeginUser;
  /* One Newton step from dp = 0 cannot solve a Voce return exactly (r is strictly convex). */
  m.max_iterations = 1;
  RandomState(&m, &seed, 20.0, &old, eps);
  memset(&st, 0x5a, sizeof(st));
  status = IndPlasticUpdate(&m, eps, &old, &st, sigma, D, &dp);
  PetscCheck(status == IND_PLASTIC_NOT_CONVERGED, PETSC_COMM_SELF, PETSC_ERR_PLIB,
    "max_iterations = 1 on a large Voce increment should not converge");
  PetscCheck(!memcmp(&st, &old, sizeof(st)), PETSC_COMM_SELF, PETSC_ERR_PLIB,
    "new_state differs from old after a failed return");
  for (int i = 0; i < 6; ++i) PetscCheck(PetscIsNanReal(sigma[i]), PETSC_COMM_SELF, PETSC_ERR_PLIB,
    "sigma must be NaN after a failed return");
  for (int i = 0; i < 36; ++i) PetscCheck(PetscIsNanReal(D[i]), PETSC_COMM_SELF, PETSC_ERR_PLIB,
    "D must be NaN after a failed return");
  PetscCheck(PetscIsNanReal(dp), PETSC_COMM_SELF, PETSC_ERR_PLIB, "dp must be NaN after a failed return");
  st     = old; /* in place, as an assembly loop may call it */
  status = IndPlasticUpdate(&m, eps, &st, &st, sigma, NULL, NULL);
  PetscCheck(status == IND_PLASTIC_NOT_CONVERGED && !memcmp(&st, &old, sizeof(st)), PETSC_COMM_SELF, PETSC_ERR_PLIB,
    "in-place failed return changed the state");
  m.max_iterations = 0;
  PetscCall(Update(&m, eps, &old, &st, sigma, NULL, &dp));
  PetscCall(PetscPrintf(PETSC_COMM_SELF,
    "  failed return (max_iterations = 1): NOT_CONVERGED, state untouched, outputs NaN; default cap converges\n"));

  /* Pathological Voce: saturation within p ~ 1e-6. */
  m = Law(VOCE, 0.3, 0.5, 1e6, 0.0, 1.0);
  PetscCall(IndPlasticParamsCheck(&m, "film_", PETSC_COMM_SELF));
  for (int k = 0; k < 200; ++k) {
    RandomState(&m, &seed, 1.0 + PetscPowReal(10.0, -6.0 + 8.0 * Uniform(&seed)), &old, eps);
    PetscCall(Update(&m, eps, &old, &st, sigma, NULL, &dp));
    worst = PetscMax(worst, PetscAbsReal(Equivalent(sigma, st.x) - IndPlasticR(&m, st.p)) / IndPlasticR(&m, st.p));
  }
  CHECK_TOL("Voce gamma = 1e6: returned state on the yield surface", worst, 1e-12);

  /* Steep Voce softening: the first Newton step overshoots the bracket, so only bisection saves it. */
  m       = Law(VOCE, 0.5, 0.3, 0.0, 0.0, 0.5);
  IndHardeningSetVoce(&m, 0.3, 0.99 * (3.0 * m.mu + m.H) / (m.R0 - 0.3));
  PetscCall(IndPlasticParamsCheck(&m, "film_", PETSC_COMM_SELF));
  worst = 0.0;
  for (int k = 0; k < 200; ++k) {
    const PetscReal factor = 1.05 + 20.0 * Uniform(&seed), c = 3.0 * m.mu + m.H;
    PetscReal       qE, newton0;

    /* virgin material, where the softening slope is steepest; simple shear trial with
       qE = sqrt(3) mu gamma = factor R0 */
    memset(&old, 0, sizeof(old));
    for (int i = 0; i < 6; ++i) eps[i] = 0.0;
    qE      = factor * m.R0;
    eps[3]  = qE / (PetscSqrtReal(3.0) * m.mu);
    newton0 = (qE - m.R0) / (c + IndPlasticdR(&m, 0.0));
    PetscCheck(newton0 > qE / c, PETSC_COMM_SELF, PETSC_ERR_PLIB,
      "softening case does not exercise the bisection fallback");
    PetscCall(Update(&m, eps, &old, &st, sigma, NULL, &dp));
    worst = PetscMax(worst, PetscAbsReal(Equivalent(sigma, st.x) - IndPlasticR(&m, st.p)) / IndPlasticR(&m, st.p));
    worst = PetscMax(worst, PetscAbsReal(qE - c * dp - IndPlasticR(&m, dp)) / qE);
  }
  CHECK_TOL("steep softening (bisection fallback): on the yield surface", worst, 1e-12);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Each non-physical value must be rejected, naming its option. */
static PetscErrorCode TestParamsCheck(void)
{
  const char *option[] = {"-film_young", "-film_young", "-film_yield", "-film_yield", "-film_saturation",
    "-film_voce_rate", "-film_kinematic", "-film_hardening_slope", "-film_voce_rate", "-film_yield"};
  const int   ncases   = (int)(sizeof(option) / sizeof(option[0]));

  PetscFunctionBeginUser;
  for (int k = 0; k < ncases; ++k) {
    IndPlasticParams m = Law(VOCE, 0.3, 0.5, 20.0, 0.0, 1.0);
    PetscErrorCode   ierr;
    char            *msg = NULL;

    switch (k) {
    case 0: m.mu = 0.0; break;
    case 1: m.kappa = -1.0; break;
    case 2: m.R0 = 0.0; break;
    case 3: m.R0 = NAN; break;
    case 4: IndHardeningSetVoce(&m, -0.1, 20.0); break;
    case 5: IndHardeningSetVoce(&m, 0.5, -1.0); break;
    case 6: m.H = -1.0; break;
    case 7: IndHardeningSetLinear(&m, -1.0); break;
    case 8: IndHardeningSetVoce(&m, 0.1, (3.0 * m.mu + m.H) / (m.R0 - 0.1)); break; /* softening: a flat return */
    default: m.R0 = 9.0 * m.kappa * m.mu / (3.0 * m.kappa + m.mu); /* a yield strain of 1: a stress in MPa */
    }
    PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
    ierr = IndPlasticParamsCheck(&m, "film_", PETSC_COMM_SELF);
    PetscCall(PetscPopErrorHandler());
    PetscCheck(ierr != 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "IndPlasticParamsCheck accepted bad case %d (%s)", k,
      option[k]);
    PetscCall(PetscErrorMessage(ierr, NULL, &msg));
    PetscCheck(msg && strstr(msg, option[k]), PETSC_COMM_SELF, PETSC_ERR_PLIB,
      "Rejection of case %d does not name %s: '%s'", k, option[k], msg ? msg : "(none)");
  }
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "Parameter check: %d non-physical cases rejected, each naming its option\n",
    ncases));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The tabulated curve of the tests: (eps_p, stress in GPa). */
static const PetscReal TABLE[] = {0, 0.3, 0.01, 0.4, 0.05, 0.5, 0.2, 0.55};

/* p of a stress on the curve, from its closed form (the inverse of R), for each law of TestUniaxialClosed. */
static PetscReal InversePower(const IndPlasticParams *m, PetscReal s)
{
  return m->R0 / Young(m) * (PetscPowReal(s / m->R0, 1 / 0.2) - 1);
}

static PetscReal InverseSwift(const IndPlasticParams *m, PetscReal s)
{
  (void)m;
  return PetscPowReal(s / 0.8, 1 / 0.25) - 0.01;
}

static PetscReal InverseTable(const IndPlasticParams *m, PetscReal s)
{
  const PetscInt n = (PetscInt)(sizeof(TABLE) / sizeof(TABLE[0])) / 2;
  (void)m;
  for (PetscInt i = 0; i + 1 < n; ++i)
    if (s <= TABLE[2 * i + 3]) return TABLE[2 * i] + (s - TABLE[2 * i + 1]) * (TABLE[2 * i + 2] - TABLE[2 * i]) /
                                                     (TABLE[2 * i + 3] - TABLE[2 * i + 1]);
  return NAN;
}

/* Monotonic tension without kinematic hardening, against the law's closed form written independently of R:
   exx = sigma / E + p(sigma). */
static PetscErrorCode TestUniaxialClosed(const char *name, const IndPlasticParams *m,
                                         PetscReal (*inverse)(const IndPlasticParams *, PetscReal))
{
  IndPlasticState st;
  PetscReal       lat = 0.0, sigma[6], dp, worst = 0.0;
  const PetscReal emax = 0.1;
  const int       nsteps = 50;
  char            label[128];

  PetscFunctionBeginUser;
  memset(&st, 0, sizeof(st));
  for (int k = 1; k <= nsteps; ++k) {
    const PetscReal exx = emax * k / nsteps;
    PetscCall(UniaxialStep(m, exx, &lat, &st, &st, sigma, &dp));
    if (st.p > 0) worst = PetscMax(worst, PetscAbsReal(sigma[0] / Young(m) + inverse(m, sigma[0]) - exx) / exx);
  }
  PetscCheck(st.p > 0.05, PETSC_COMM_SELF, PETSC_ERR_PLIB, "%s: only p = %g at the end", name, (double)st.p);
  PetscCall(PetscSNPrintf(label, sizeof(label), "uniaxial %s: exx = sigma / E + p(sigma), closed form", name));
  CHECK_TOL(label, worst, 1e-10);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A bad input is refused with a message holding `expect`. */
static PetscErrorCode ExpectRefused(PetscErrorCode ierr, const char what[], const char expect[])
{
  char *msg = NULL;

  PetscFunctionBeginUser;
  PetscCheck(ierr != 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "%s was accepted", what);
  PetscCall(PetscErrorMessage(ierr, NULL, &msg));
  PetscCheck(msg && strstr(msg, expect), PETSC_COMM_SELF, PETSC_ERR_PLIB, "%s: the message '%s' does not say '%s'",
             what, msg ? msg : "(none)", expect);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Non-physical parameters of the power and Swift laws, and tables that are not curves. */
static PetscErrorCode TestNewLawsRefused(void)
{
  const struct {
    const char *text, *expect;
  } tables[] = {
    {"eps_p,stress\n0,0.3\n0.01,abc\n", "line 3: '0.01 abc' is not two numbers"},
    {"0,0.3\n", "holds 1 point; a curve needs at least 2"},
    {"0,0.3\n0.01,0.4\n0.02,0.35\n", "the stress falls from 0.4 to 0.35 GPa"},
    {"0.001,0.3\n0.01,0.4\n", "its first point must be at 0"},
    {"0,0.3\n0.01,0.4\n0.01,0.45\n", "the plastic strain does not increase"},
    {"0,0\n0.01,0.4\n", "must be > 0 GPa"},
  };
  IndPlasticParams m;
  PetscErrorCode   ierr;
  PetscInt         n;
  PetscReal       *pts = NULL;

  PetscFunctionBeginUser;
  PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
  m = Law(VOCE, 0.3, 0.5, 20.0, 0.0, 0.0);
  IndHardeningSetPower(&m, -0.1);
  ierr = IndPlasticParamsCheck(&m, "film_", PETSC_COMM_SELF);
  PetscCall(ExpectRefused(ierr, "power law n = -0.1", "-film_hardening_exponent must lie in [0, 1]"));
  IndHardeningSetSwift(&m, -1.0, 0.01, 0.2);
  ierr = IndPlasticParamsCheck(&m, "film_", PETSC_COMM_SELF);
  PetscCall(ExpectRefused(ierr, "Swift K = -1", "-film_swift_k must be > 0"));
  IndHardeningSetSwift(&m, 1.0, 0.0, 0.2);
  ierr = IndPlasticParamsCheck(&m, "film_", PETSC_COMM_SELF);
  PetscCall(ExpectRefused(ierr, "Swift eps0 = 0", "-film_swift_eps0 must be > 0"));
  for (size_t k = 0; k < sizeof(tables) / sizeof(tables[0]); ++k) {
    ierr = IndHardeningTableParse(PETSC_COMM_SELF, tables[k].text, "-film_hardening_file 't.csv'", &n, &pts);
    PetscCall(PetscFree(pts));
    PetscCall(ExpectRefused(ierr, tables[k].text, tables[k].expect));
  }
  PetscCall(PetscPopErrorHandler());
  /* a header, comments, blank lines and separators of every kind are a curve */
  PetscCall(IndHardeningTableParse(PETSC_COMM_SELF, "strain;stress\n# a comment\n\n0 0.3\n0.01\t0.4\r\n0.1,0.5",
                                   "t.csv", &n, &pts));
  PetscCheck(n == 3 && pts[4] == 0.1 && pts[5] == 0.5, PETSC_COMM_SELF, PETSC_ERR_PLIB, "table parsed to %" PetscInt_FMT
             " points", n);
  PetscCall(PetscFree(pts));
  /* as spreadsheets save it: a UTF-8 byte-order mark; semicolons or tabs with decimal commas (a European locale) */
  {
    const char *forms[] = {"\xef\xbb\xbf" "0,0.3\n0.01,0.4\n0.1,0.5\n", "0;0,3\r\n0,01;0,4\r\n0,1;0,5\r\n",
                           "\xef\xbb\xbf" "strain\tstress\n0\t0,3\n0,01\t0,4\n0,1\t0,5\n"};
    for (size_t k = 0; k < sizeof(forms) / sizeof(forms[0]); ++k) {
      PetscCall(IndHardeningTableParse(PETSC_COMM_SELF, forms[k], "t.csv", &n, &pts));
      PetscCheck(n == 3 && pts[0] == 0 && pts[1] == 0.3 && pts[2] == 0.01 && pts[3] == 0.4 && pts[4] == 0.1 &&
                 pts[5] == 0.5, PETSC_COMM_SELF, PETSC_ERR_PLIB, "spreadsheet form %d parsed to %" PetscInt_FMT
                 " points", (int)k, n);
      PetscCall(PetscFree(pts));
    }
  }
  /* a law added at run time is found by its name, and listed after the built-in ones */
  {
    const IndHardeningLaw *law;
    PetscCall(IndRegistryAdd(&IndHardeningRegistry, "linear_again", (IndRegistryFn)IndHardeningLinear));
    PetscCall(IndHardeningFind(PETSC_COMM_SELF, "-film_hardening", "linear_again", &law));
    PetscCheck(law == IndHardeningLinear() && !strcmp(IndHardeningRegistry.names[IndHardeningRegistry.n - 1],
               "linear_again") && !IndHardeningRegistry.names[IndHardeningRegistry.n], PETSC_COMM_SELF,
               PETSC_ERR_PLIB, "a law registered at run time is not found or not listed last");
  }
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "New laws: 3 bad parameters and %d bad tables refused, each saying why\n",
                        (int)(sizeof(tables) / sizeof(tables[0]))));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* R and R' of the new laws against their formulas and central differences (the table's beyond-rules too). */
static PetscErrorCode TestNewLawsValues(void)
{
  IndPlasticParams pw = Law(VOCE, 0.3, 0, 0, 0, 0), sw = pw, tf = pw, ts = pw;
  PetscReal        worst = 0, worst_d = 0;

  PetscFunctionBeginUser;
  IndHardeningSetPower(&pw, 0.2);
  IndHardeningSetSwift(&sw, 0.8, 0.01, 0.25);
  IndHardeningSetTable(&tf, 4, TABLE, PETSC_FALSE);
  IndHardeningSetTable(&ts, 4, TABLE, PETSC_TRUE);
  for (int k = 0; k <= 60; ++k) {
    const PetscReal p = 0.3 * k / 60 + 1e-4, h = 1e-7;
    const PetscReal expect[4] = {0.3 * PetscPowReal(1 + Young(&pw) * p / 0.3, 0.2), 0.8 * PetscPowReal(0.01 + p, 0.25),
                                 p < 0.2 ? NAN : 0.55, p < 0.2 ? NAN : 0.55 + (p - 0.2) * 0.05 / 0.15};
    const IndPlasticParams *ms[4] = {&pw, &sw, &tf, &ts};
    for (int l = 0; l < 4; ++l) {
      const PetscReal fd = (IndPlasticR(ms[l], p + h) - IndPlasticR(ms[l], p - h)) / (2 * h);
      if (!PetscIsNanReal(expect[l])) worst = PetscMax(worst, PetscAbsReal(IndPlasticR(ms[l], p) / expect[l] - 1));
      if (PetscAbsReal(p - 0.01) > 2 * h && PetscAbsReal(p - 0.05) > 2 * h && PetscAbsReal(p - 0.2) > 2 * h)
        worst_d = PetscMax(worst_d, PetscAbsReal(IndPlasticdR(ms[l], p) - fd) / PetscMax(1.0, PetscAbsReal(fd)));
    }
  }
  CHECK_TOL("power, Swift, table: R(p) against its formula", worst, 1e-14);
  CHECK_TOL("power, Swift, table: R'(p) against central differences", worst_d, 1e-6);
  CHECK_TOL("power: R(0) = R0, Swift: R(0) = K eps0^n = R0, table: R(0) = its first stress",
            PetscAbsReal(IndPlasticR(&pw, 0) - 0.3) + PetscAbsReal(IndPlasticR(&sw, 0) - sw.R0) +
              PetscAbsReal(IndPlasticR(&tf, 0) - 0.3), 1e-15);
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  const IndPlasticParams voce = Law(VOCE, 0.3, 0.5, 20.0, 0.0, 1.0);
  const IndPlasticParams linear = Law(LINEAR, 0.3, 0.0, 0.0, 2.0, 0.0);
  const IndPlasticParams linear_kin = Law(LINEAR, 0.3, 0.0, 0.0, 2.0, 5.0);
  IndPlasticParams       power = Law(VOCE, 0.3, 0, 0, 0, 0), power_kin = Law(VOCE, 0.3, 0, 0, 0, 2.0), swift = power;
  IndPlasticParams       table_flat = power, table_slope = power;
  struct {
    const char      *name;
    IndPlasticParams m;
  } laws[] = {
    {"Voce + Prager",        voce                                              },
    {"Voce isotropic",       Law(VOCE, 0.3, 0.8, 50.0, 0.0, 0.0) },
    {"linear isotropic",     linear                                            },
    {"linear + Prager",      linear_kin                                        },
    {"perfect (Rs = R0)",    Law(VOCE, 0.3, 0.3, 20.0, 0.0, 0.0) },
    {"perfect (linear h=0)", Law(LINEAR, 0.3, 0.0, 0.0, 0.0, 0.0)},
    {"mild Voce softening",  Law(VOCE, 0.5, 0.3, 50.0, 0.0, 0.0) },
    {"power (Dao)",          power                                             },
    {"power + Prager",       power_kin                                         },
    {"Swift",                swift                                             },
    {"table, flat beyond",   table_flat                                        },
    {"table, slope beyond",  table_slope                                       },
    {"elastic_only",         voce                                              },
  };
  const int          nlaws = (int)(sizeof(laws) / sizeof(laws[0]));
  unsigned long long seed  = 2024;
  PetscReal          worst_fd = 0.0, worst_ys = 0.0;
  int                used = 0, skipped = 0, plastic = 0;

  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  IndHardeningSetPower(&power, 0.2);
  IndHardeningSetPower(&power_kin, 0.2);
  IndHardeningSetSwift(&swift, 0.8, 0.01, 0.25);
  IndHardeningSetTable(&table_flat, 4, TABLE, PETSC_FALSE);
  IndHardeningSetTable(&table_slope, 4, TABLE, PETSC_TRUE);
  laws[7].m  = power;
  laws[8].m  = power_kin;
  laws[9].m  = swift;
  laws[10].m = table_flat;
  laws[11].m = table_slope;
  laws[nlaws - 1].m.elastic_only = PETSC_TRUE;
  for (int l = 0; l < nlaws; ++l) PetscCall(IndPlasticParamsCheck(&laws[l].m, "film_", PETSC_COMM_SELF));
  PetscCall(TestParamsCheck());

  PetscCall(PetscPrintf(PETSC_COMM_SELF, "Uniaxial monotonic tension (E = %g GPa, nu = %g)\n", (double)YOUNG,
    (double)POISSON));
  PetscCall(TestUniaxial("Voce + Prager", &voce));
  PetscCall(TestUniaxial("linear isotropic", &linear));
  PetscCall(TestUniaxial("linear + Prager", &linear_kin));
  PetscCall(TestUniaxial("power + Prager", &power_kin));
  PetscCall(TestUniaxial("Swift", &swift));
  PetscCall(TestUniaxial("table, slope beyond", &table_slope));
  PetscCall(TestUniaxialClosed("power (Dao)", &power, InversePower));
  PetscCall(TestUniaxialClosed("Swift", &swift, InverseSwift));
  PetscCall(TestUniaxialClosed("table", &table_flat, InverseTable));
  PetscCall(TestNewLawsValues());
  PetscCall(TestNewLawsRefused());
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "Tension-compression cycle (Bauschinger)\n"));
  PetscCall(TestCycle("Voce + Prager", &voce));
  PetscCall(TestCycle("linear + Prager", &linear_kin));
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "Simple shear\n"));
  PetscCall(TestShear("Voce + Prager", &voce));
  PetscCall(TestShear("linear + Prager", &linear_kin));
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "Consistent tangent vs central differences\n"));
  for (int l = 0; l < nlaws; ++l) {
    PetscReal w = 0.0;
    int       u = 0, s = 0, p = 0;

    PetscCall(TestTangent(laws[l].name, &laws[l].m, 300, &seed, &w, &worst_ys, &u, &s, &p));
    PetscCall(PetscPrintf(PETSC_COMM_SELF,
      "  %-22s %3d compared (%3d plastic), %2d skipped at the kink, worst %.2e\n", laws[l].name, u, p, s, (double)w));
    worst_fd = PetscMax(worst_fd, w);
    used += u;
    skipped += s;
    plastic += p;
  }
  PetscCheck(used >= 1000, PETSC_COMM_SELF, PETSC_ERR_PLIB, "Only %d finite-difference samples compared", used);
  PetscCall(PetscPrintf(PETSC_COMM_SELF,
    "  %d samples compared, %d skipped (stencil across the elastic/plastic kink)\n", used, skipped));
  CHECK_TOL("tangent vs FD: max|D - Dfd| / max|D|", worst_fd, 1e-6);
  CHECK_TOL("returned state on the yield surface (random plastic)", worst_ys, 1e-12);
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "Robustness\n"));
  PetscCall(TestRobustness());
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "All plasticity tests passed\n"));
  PetscCall(PetscFinalize());
  return 0;
}
