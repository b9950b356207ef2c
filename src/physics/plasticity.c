#include <math.h>
#include "ind_plasticity.h"

PetscReal IndPlasticR(const IndPlasticParams *m, PetscReal p)
{
  return m->law->R(m, p);
}

PetscReal IndPlasticdR(const IndPlasticParams *m, PetscReal p)
{
  return m->law->dR(m, p);
}

PetscErrorCode IndPlasticCommonCheck(const IndPlasticParams *m, const char prefix[], MPI_Comm comm)
{
  const char *pre = prefix ? prefix : "";

  PetscFunctionBeginUser;
  PetscCheck(m->mu > 0 && m->kappa > 0, comm, PETSC_ERR_ARG_OUTOFRANGE,
    "Elastic moduli must be > 0, got mu = %g, kappa = %g GPa: check -%syoung and -%spoisson", (double)m->mu,
    (double)m->kappa, pre, pre);
  if (m->elastic_only) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCheck(m->max_iterations >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE,
    "-%sreturn_max_it must be >= 0 (0: the default, 100), got %" PetscInt_FMT, pre, m->max_iterations);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndPlasticParamsCheck(const IndPlasticParams *m, const char prefix[], MPI_Comm comm)
{
  const char *pre = prefix ? prefix : "";

  PetscFunctionBeginUser;
  PetscCall(IndPlasticCommonCheck(m, prefix, comm));
  if (m->elastic_only) PetscFunctionReturn(PETSC_SUCCESS);

  PetscCheck(m->H >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-%skinematic must be >= 0 (GPa), got %g", pre, (double)m->H);
  PetscCheck(m->law, comm, PETSC_ERR_ARG_WRONGSTATE, "No hardening law for region prefix '%s'", pre);
  PetscCall(IndPlasticYieldCheckModulus(m, pre, comm)); /* first: a stress in MPa fails the law's checks obscurely */
  PetscCall(m->law->check(m, pre, comm));
  /* a law that derives R0 from its own parameters has checked them: this names -yield for the others */
  PetscCheck(m->R0 > 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-%syield must be > 0 (GPa), got %g", pre, (double)m->R0);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* No solid yields at a strain of 1: an initial yield stress at or above E is a stress given in MPa (or a region
   meant to stay elastic), and would silently make the region elastic. */
PetscErrorCode IndPlasticYieldCheckModulus(const IndPlasticParams *m, const char pre[], MPI_Comm comm)
{
  const PetscReal E    = IndPlasticYoung(m);
  const char     *name = m->law ? m->law->name : NULL;
  char            opt[256];
  PetscBool       swift = PETSC_FALSE, table = PETSC_FALSE;

  PetscFunctionBeginUser;
  if (name) PetscCall(PetscStrcmp(name, "swift", &swift));
  if (name) PetscCall(PetscStrcmp(name, "table", &table));
  if (swift) PetscCall(PetscSNPrintf(opt, sizeof(opt), "-%sswift_k and -%sswift_eps0", pre, pre));
  else if (table) PetscCall(PetscSNPrintf(opt, sizeof(opt), "the first stress of -%shardening_file", pre));
  else PetscCall(PetscSNPrintf(opt, sizeof(opt), "-%syield", pre));
  PetscCheck(m->R0 < E, comm, PETSC_ERR_ARG_OUTOFRANGE,
    "The initial yield stress %g GPa (%s) is not below the region's Young's modulus %g GPa: no solid yields at a "
    "strain of 1. Stresses are in GPa (300 MPa is 0.3); a region that never yields is -%smodel elastic",
    (double)m->R0, opt, (double)E, pre);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Solves r(dp) = qE - (3 mu + H) dp - R(p + dp) = 0 for dp > 0, given r(0) > 0.
   r(qE / (3 mu + H)) = -R < 0 since R > 0, so [0, qE / (3 mu + H)] brackets the root for any law
   IndPlasticParamsCheck accepts. Newton from 0 converges monotonically for hardening; bisection
   takes over whenever a Newton step would leave the bracket (steep softening). */
static IndPlasticStatus SolveReturn(const IndPlasticParams *m, PetscReal qE, PetscReal p, PetscReal *dp_out)
{
  const PetscInt  maxit = m->max_iterations > 0 ? m->max_iterations : 100;
  const PetscReal c = 3.0 * m->mu + m->H, tol = 1e-15 * qE;
  /* r is evaluated with an absolute round-off of a few ulps of qE, so dp cannot be known better than
     a few ulps of its bound qE / c; a step below that ends the iteration even when |r| > tol. */
  const PetscReal ddp_min = 4.0 * PETSC_MACHINE_EPSILON * qE / c;
  PetscReal       lo = 0.0, hi = qE / c, dp = 0.0, r = qE - IndPlasticR(m, p);

  for (PetscInt it = 0; it < maxit; ++it) {
    PetscReal next = dp + r / (c + IndPlasticdR(m, p + dp));
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi); /* also catches a NaN step */
    const PetscBool stalled = PetscAbsReal(next - dp) <= ddp_min ? PETSC_TRUE : PETSC_FALSE;
    dp = next;
    r  = qE - c * dp - IndPlasticR(m, p + dp);
    if (PetscAbsReal(r) <= tol || stalled) {
      *dp_out = dp;
      return IND_PLASTIC_OK;
    }
    if (r > 0) lo = dp;
    else hi = dp;
  }
  return IND_PLASTIC_NOT_CONVERGED;
}

void IndPlasticTangentElastic(PetscReal kappa, PetscReal mu, IndPlasticTangent *t)
{
  t->kappa    = kappa;
  t->mu       = mu;
  t->theta    = 1.0;
  t->thetabar = 0.0;
  for (int i = 0; i < 6; ++i) t->n[i] = 0.0;
}

void IndPlasticTangentMatrix(const IndPlasticTangent *t, const PetscReal n[6], PetscReal D[36])
{
  const PetscReal mu = t->mu, theta = t->theta, thetabar = t->thetabar;

  /* I = diag(1,1,1,1/2,1/2,1/2) because the tangent acts on engineering shears */
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) {
      PetscReal v = -2.0 * mu * thetabar * n[i] * n[j];
      if (i < 3 && j < 3) v += t->kappa - 2.0 * mu * theta / 3.0;
      if (i == j) v += 2.0 * mu * theta * (i < 3 ? 1.0 : 0.5);
      D[6 * i + j] = v;
    }
}

IndPlasticStatus IndPlasticUpdate(const IndPlasticParams *m, const PetscReal eps[6], const IndPlasticState *old,
  IndPlasticState *new_state, PetscReal sigma[6], PetscReal D[36], PetscReal *dp_out)
{
  IndPlasticTangent      t;
  const IndPlasticStatus status = IndPlasticUpdateParts(m, eps, old, new_state, sigma, D ? &t : NULL, dp_out);

  if (D) IndPlasticTangentMatrix(&t, t.n, D);
  return status;
}

IndPlasticStatus IndPlasticUpdateParts(const IndPlasticParams *m, const PetscReal eps[6], const IndPlasticState *old,
  IndPlasticState *new_state, PetscReal sigma[6], IndPlasticTangent *t, PetscReal *dp_out)
{
  const IndPlasticState o  = *old; /* new_state may alias old */
  const PetscReal       mu = m->mu, H = m->H, tr = eps[0] + eps[1] + eps[2], s32 = PetscSqrtReal(1.5);
  PetscReal             ee[6], eta[6], n[6] = {0, 0, 0, 0, 0, 0}, nrm2 = 0.0, qE, dp = 0.0, theta = 1.0, thetabar = 0.0;

  /* ee: elastic strain deviator, tensor components (halve the engineering shears). */
  for (int i = 0; i < 3; ++i) ee[i] = eps[i] - tr / 3.0 - o.eps_p[i];
  for (int i = 3; i < 6; ++i) ee[i] = 0.5 * (eps[i] - o.eps_p[i]);
  for (int i = 0; i < 6; ++i) {
    eta[i] = 2.0 * mu * ee[i] - o.x[i];
    nrm2 += (i < 3 ? 1.0 : 2.0) * eta[i] * eta[i]; /* off-diagonal terms appear twice in the tensor */
  }
  qE         = s32 * PetscSqrtReal(nrm2);
  *new_state = o;

  if (!m->elastic_only && qE - IndPlasticR(m, o.p) > 1e-12 * m->R0) {
    const PetscReal nrm = PetscSqrtReal(nrm2);

    if (SolveReturn(m, qE, o.p, &dp) != IND_PLASTIC_OK) {
      for (int i = 0; i < 6; ++i) sigma[i] = NAN;
      if (t) {
        t->kappa = t->mu = t->theta = t->thetabar = NAN;
        for (int i = 0; i < 6; ++i) t->n[i] = NAN;
      }
      if (dp_out) *dp_out = NAN;
      return IND_PLASTIC_NOT_CONVERGED;
    }
    for (int i = 0; i < 6; ++i) {
      const PetscReal deps_p = s32 * dp * eta[i] / nrm; /* tensor component */

      n[i] = eta[i] / nrm;
      ee[i] -= deps_p;
      new_state->eps_p[i] += (i < 3 ? 1.0 : 2.0) * deps_p;
      new_state->x[i] += 2.0 / 3.0 * H * deps_p;
    }
    new_state->p += dp;
    theta    = 1.0 - 3.0 * mu * dp / qE;
    thetabar = 3.0 * mu / (3.0 * mu + H + IndPlasticdR(m, new_state->p)) - 3.0 * mu * dp / qE;
  }
  for (int i = 0; i < 6; ++i) sigma[i] = (i < 3 ? m->kappa * tr : 0.0) + 2.0 * mu * ee[i];
  if (t) {
    t->kappa    = m->kappa;
    t->mu       = mu;
    t->theta    = theta;
    t->thetabar = thetabar;
    for (int i = 0; i < 6; ++i) t->n[i] = n[i];
  }
  if (dp_out) *dp_out = dp;
  return IND_PLASTIC_OK;
}
