/* Unit test of the densifying plasticity kernel (src/physics/densification.c) against closed forms: hydrostatic
   compaction with and without densification hardening, pure shear (J2's), the J2 limit of a far cap, points
   returned onto the ellipse, the consistent tangent against central differences and its symmetry without
   densification hardening (the assembly mirrors element matrices), and the checks of bad parameters. Exits
   non-zero, naming the check, on the first failure. */
#include <math.h>
#include <string.h>
#include "ind_densification.h"
#include "ind_hardening.h"
#include "ind_elasticity.h"
#include "kernel_tests.h"

/* fused silica's elastic constants; sigma_s and p_c of the order the fits give */
static IndPlasticParams Params(PetscReal sy, PetscReal pc, PetscReal Hv)
{
  IndPlasticParams m;
  memset(&m, 0, sizeof(m));
  IndElasticModuli(72.0, 0.17, &m.kappa, &m.mu);
  m.R0                    = sy;
  m.yield_pressure        = pc;
  m.densification_modulus = Hv;
  return m;
}

static PetscErrorCode Update(const IndPlasticParams *m, const PetscReal eps[6], const IndPlasticState *old,
  IndPlasticState *st, PetscReal sigma[6], PetscReal D[36], PetscReal *dp)
{
  PetscFunctionBeginUser;
  PetscCheck(IndDensifyingUpdate(m, eps, old, st, sigma, D, dp) == IND_PLASTIC_OK, PETSC_COMM_SELF, PETSC_ERR_PLIB,
    "return map did not converge");
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscReal Pressure(const PetscReal s[6])
{
  return -(s[0] + s[1] + s[2]) / 3.0;
}

/* Hydrostatic compression in steps: p = p_c0 + H_v c and p = kappa (-tr eps - c) give
   c = (kappa (-tr eps) - p_c0) / (kappa + H_v) once past yield; the stress stays hydrostatic. */
static PetscErrorCode TestHydrostatic(PetscReal Hv)
{
  IndPlasticParams m = Params(6.0, 10.0, Hv);
  IndPlasticState  st;
  PetscReal        worst_p = 0, worst_c = 0, worst_dev = 0;
  char             label[96];

  PetscFunctionBeginUser;
  memset(&st, 0, sizeof(st));
  for (int k = 1; k <= 20; ++k) {
    const PetscReal e = -0.01 * k, eps[6] = {e, e, e, 0, 0, 0}; /* tr eps = -0.6 at the end: p_tr 21.8 GPa */
    const PetscReal ptr = -m.kappa * 3.0 * e;
    PetscReal       sigma[6], dp, c_exact, p_exact;

    PetscCall(Update(&m, eps, &st, &st, sigma, NULL, &dp));
    c_exact = ptr > m.yield_pressure ? (ptr - m.yield_pressure) / (m.kappa + Hv) : 0.0;
    p_exact = ptr - m.kappa * c_exact;
    worst_p = PetscMax(worst_p, PetscAbsReal(Pressure(sigma) - p_exact) / p_exact);
    worst_c = PetscMax(worst_c, PetscAbsReal(-(st.eps_p[0] + st.eps_p[1] + st.eps_p[2]) - c_exact));
    worst_dev =
      PetscMax(worst_dev, PetscAbsReal(sigma[0] - sigma[1]) + PetscAbsReal(sigma[3]) + PetscAbsReal(sigma[5]));
  }
  PetscCall(PetscSNPrintf(label, sizeof(label), "hydrostatic, H_v %g: pressure (relative)", (double)Hv));
  CHECK_TOL(label, worst_p, 1e-12);
  PetscCall(PetscSNPrintf(label, sizeof(label), "hydrostatic, H_v %g: compaction", (double)Hv));
  CHECK_TOL(label, worst_c, 1e-13);
  PetscCall(PetscSNPrintf(label, sizeof(label), "hydrostatic, H_v %g: deviatoric stress (GPa)", (double)Hv));
  CHECK_TOL(label, worst_dev, 1e-12);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Simple shear has no pressure: the ellipse is von Mises' circle there, tau = sigma_s / sqrt(3) past yield, and
   no compaction. */
static PetscErrorCode TestShear(void)
{
  IndPlasticParams m = Params(6.0, 10.0, 30.0);
  IndPlasticState  st;
  PetscReal        worst_tau = 0, worst_c = 0;

  PetscFunctionBeginUser;
  memset(&st, 0, sizeof(st));
  for (int k = 1; k <= 10; ++k) {
    const PetscReal gamma = 0.02 * k, eps[6] = {0, 0, 0, gamma, 0, 0};
    const PetscReal tau   = PetscMin(m.mu * gamma, m.R0 / PetscSqrtReal(3.0));
    PetscReal       sigma[6], dp;

    PetscCall(Update(&m, eps, &st, &st, sigma, NULL, &dp));
    worst_tau = PetscMax(worst_tau, PetscAbsReal(sigma[3] - tau) / tau);
    worst_c   = PetscMax(worst_c, PetscAbsReal(st.eps_p[0] + st.eps_p[1] + st.eps_p[2]));
  }
  CHECK_TOL("simple shear: tau = sigma_s / sqrt(3) (relative)", worst_tau, 1e-13);
  CHECK_TOL("simple shear: no compaction", worst_c, 1e-15);
  PetscFunctionReturn(PETSC_SUCCESS);
}

static unsigned long long Next(unsigned long long *s)
{
  *s = *s * 6364136223846793005ULL + 1442695040888963407ULL;
  return *s >> 11;
}

static PetscReal Uniform(unsigned long long *s)
{
  return (PetscReal)Next(s) / 9007199254740992.0;
}

/* A random history (compaction c0 >= 0, some deviatoric plastic strain) and a strain whose trial state lies at
   factor times the ellipse, in a random direction of (q, p) with p mostly compressive. */
static void RandomState(const IndPlasticParams *m, unsigned long long *s, PetscReal factor, IndPlasticState *old,
                        PetscReal eps[6])
{
  PetscReal c0 = 0.05 * Uniform(s), d[6], nd = 0, angle = -0.3 + 1.8 * Uniform(s), pc, q, p, tr;

  memset(old, 0, sizeof(*old));
  for (int i = 0; i < 6; ++i) old->eps_p[i] = 2e-3 * (Uniform(s) - 0.5);
  tr = old->eps_p[0] + old->eps_p[1] + old->eps_p[2];
  for (int i = 0; i < 3; ++i) old->eps_p[i] += (-c0 - tr) / 3.0;
  old->p = 0.01 * Uniform(s);
  pc     = IndDensifyingYieldPressure(m, c0);
  q      = factor * m->R0 * PetscCosReal(angle);
  p      = factor * pc * PetscSinReal(angle);
  for (int i = 0; i < 6; ++i) d[i] = Uniform(s) - 0.5;
  tr = d[0] + d[1] + d[2];
  for (int i = 0; i < 3; ++i) d[i] -= tr / 3.0;
  for (int i = 0; i < 6; ++i) nd += (i < 3 ? 1.0 : 2.0) * d[i] * d[i];
  nd = PetscSqrtReal(nd);
  for (int i = 0; i < 6; ++i) {
    /* s_tr = 2 mu e_dev = q / sqrt(3/2) d / |d|; tr(eps - eps_p) = -p / kappa */
    const PetscReal e = q / PetscSqrtReal(1.5) * d[i] / nd / (2.0 * m->mu);
    eps[i] = old->eps_p[i] + (i < 3 ? e - p / (3.0 * m->kappa) : 2.0 * e);
  }
}

static PetscErrorCode TestTangent(const char *name, const IndPlasticParams *m, int nsamples, unsigned long long *seed)
{
  PetscReal worst_fd = 0, worst_sym = 0, worst_ys = 0;
  int       used = 0, plastic = 0;
  char      label[96];

  PetscFunctionBeginUser;
  for (int k = 0; k < nsamples; ++k) {
    IndPlasticState old, st;
    PetscReal       eps[6], sigma[6], D[36], Dfd[36], dp, factor, h, emax = 0, dmax = 0, diff = 0, asym = 0;
    PetscBool       kink = PETSC_FALSE;

    factor = k % 3 == 0 ? 0.95 * Uniform(seed) : (k % 3 == 1 ? 1.0 + 0.1 * Uniform(seed) : 1.5 + 8.0 * Uniform(seed));
    RandomState(m, seed, factor, &old, eps);
    PetscCall(Update(m, eps, &old, &st, sigma, D, &dp));
    if (dp > 0) {
      const PetscReal pc = IndDensifyingYieldPressure(m, -(st.eps_p[0] + st.eps_p[1] + st.eps_p[2]));
      const PetscReal p = Pressure(sigma), q = IndVonMises(sigma);
      ++plastic;
      worst_ys = PetscMax(worst_ys, PetscAbsReal(PetscSqrtReal(q * q + PetscSqr(m->R0 * p / pc)) - m->R0) / m->R0);
    }
    for (int i = 0; i < 6; ++i) emax = PetscMax(emax, PetscAbsReal(eps[i]));
    h = 1e-7 * emax;
    PetscCall(CentralDifferenceTangent(IndDensifyingUpdate, m, &old, eps, h, (PetscBool)(dp > 0), Dfd, &kink));
    for (int i = 0; i < 36; ++i) dmax = PetscMax(dmax, PetscAbsReal(D[i]));
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j) asym = PetscMax(asym, PetscAbsReal(D[6 * i + j] - D[6 * j + i]) / dmax);
    worst_sym = PetscMax(worst_sym, asym);
    if (kink) continue;
    for (int i = 0; i < 36; ++i) diff = PetscMax(diff, PetscAbsReal(D[i] - Dfd[i]));
    worst_fd = PetscMax(worst_fd, diff / dmax);
    ++used;
  }
  PetscCheck(plastic >= nsamples / 2 && used >= nsamples - 5, PETSC_COMM_SELF, PETSC_ERR_PLIB,
    "%s: too few samples tested (%d plastic, %d away from the kink, of %d)", name, plastic, used, nsamples);
  PetscCall(PetscSNPrintf(label, sizeof(label), "%s: tangent vs central differences", name));
  CHECK_TOL(label, worst_fd, 1e-6);
  /* associated flow with a cap fixed in place gives a symmetric tangent; a cap that moves with the compaction
     does not (the assembly then takes its symmetric part, ind_densification.h) */
  if (m->densification_modulus == 0) {
    PetscCall(PetscSNPrintf(label, sizeof(label), "%s: tangent symmetric", name));
    CHECK_TOL(label, worst_sym, 1e-12);
  } else PetscCall(PetscPrintf(PETSC_COMM_SELF, "  %-58s %.2e\n", "largest asymmetry (relative)", (double)worst_sym));
  PetscCall(PetscSNPrintf(label, sizeof(label), "%s: returned onto the ellipse", name));
  CHECK_TOL(label, worst_ys, 1e-12);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A cap far away (p_c0 = 1e8 sigma_s) leaves J2 perfect plasticity: the same stress and tangent as
   IndPlasticUpdate with a linear law of zero slope. */
static PetscErrorCode TestJ2Limit(unsigned long long *seed)
{
  IndPlasticParams cap = Params(6.0, 6e8, 0.0), j2 = Params(6.0, 0, 0), gen = Params(6.0, 10.0, 0.0);
  PetscReal        worst_s = 0, worst_d = 0;

  PetscFunctionBeginUser;
  PetscCall(IndHardeningFind(PETSC_COMM_SELF, "-domain_hardening", "linear", &j2.law));
  for (int k = 0; k < 50; ++k) {
    IndPlasticState old, a, b;
    PetscReal       eps[6], sa[6], sb[6], Da[36], Db[36], dpa, dpb, tr;

    RandomState(&gen, seed, 0.5 + 3.0 * Uniform(seed), &old, eps); /* pressures of the order of 10 GPa */
    tr = old.eps_p[0] + old.eps_p[1] + old.eps_p[2]; /* J2's plastic strain is deviatoric */
    for (int i = 0; i < 3; ++i) old.eps_p[i] -= tr / 3.0, eps[i] -= tr / 3.0;
    PetscCall(Update(&cap, eps, &old, &a, sa, Da, &dpa));
    PetscCheck(IndPlasticUpdate(&j2, eps, &old, &b, sb, Db, &dpb) == IND_PLASTIC_OK, PETSC_COMM_SELF, PETSC_ERR_PLIB,
      "J2 return failed");
    for (int i = 0; i < 6; ++i) worst_s = PetscMax(worst_s, PetscAbsReal(sa[i] - sb[i]) / cap.R0);
    for (int i = 0; i < 36; ++i) worst_d = PetscMax(worst_d, PetscAbsReal(Da[i] - Db[i]) / (2.0 * cap.mu + cap.kappa));
  }
  CHECK_TOL("far cap: stress as J2's (relative to sigma_s)", worst_s, 1e-8);
  CHECK_TOL("far cap: tangent as J2's (relative to the moduli)", worst_d, 1e-7);
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode ExpectRejected(IndPlasticParams m, const char *what)
{
  PetscErrorCode ierr;

  PetscFunctionBeginUser;
  PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
  ierr = IndDensifyingParamsCheck(&m, "film_", PETSC_COMM_SELF);
  PetscCall(PetscPopErrorHandler());
  PetscCheck(ierr != PETSC_SUCCESS, PETSC_COMM_SELF, PETSC_ERR_PLIB, "%s was accepted", what);
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "  rejected: %s\n", what));
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  unsigned long long seed = 20261127ULL;

  PetscFunctionBeginUser;
  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  PetscCall(TestHydrostatic(0.0));
  PetscCall(TestHydrostatic(40.0));
  PetscCall(TestShear());
  {
    IndPlasticParams perfect = Params(6.0, 10.0, 0.0), hard = Params(6.0, 10.0, 40.0), near = Params(6.0, 8.0, 5.0);
    PetscCall(TestTangent("no densification hardening", &perfect, 300, &seed));
    PetscCall(TestTangent("H_v 40 GPa", &hard, 300, &seed));
    PetscCall(TestTangent("H_v 5 GPa, p_c0 8 GPa", &near, 300, &seed));
  }
  PetscCall(TestJ2Limit(&seed));
  PetscCall(IndDensifyingParamsCheck(&(IndPlasticParams){.kappa = 1, .mu = 1, .R0 = 1, .yield_pressure = 1}, "film_",
    PETSC_COMM_SELF));
  PetscCall(ExpectRejected(Params(0.0, 10.0, 0.0), "-film_yield 0"));
  PetscCall(ExpectRejected(Params(6.0, -1.0, 0.0), "-film_yield_pressure -1"));
  PetscCall(ExpectRejected(Params(6.0, 10.0, -2.0), "-film_densification_modulus -2"));
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "densification kernel: all checks passed\n"));
  PetscCall(PetscFinalize());
  return 0;
}
