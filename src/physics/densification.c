#include <math.h>
#include "ind_densification.h"

PetscReal IndDensifyingYieldPressure(const IndPlasticParams *m, PetscReal c)
{
  return m->yield_pressure + m->densification_modulus * PetscMax(c, 0.0);
}

PetscErrorCode IndDensifyingParamsCheck(const IndPlasticParams *m, const char prefix[], MPI_Comm comm)
{
  const char *pre = prefix ? prefix : "";

  PetscFunctionBeginUser;
  PetscCall(IndPlasticCommonCheck(m, prefix, comm));
  PetscCheck(m->R0 > 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-%syield must be > 0 (GPa), got %g", pre, (double)m->R0);
  PetscCheck(m->yield_pressure > 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-%syield_pressure must be > 0 (GPa), got %g", pre,
    (double)m->yield_pressure);
  PetscCheck(m->densification_modulus >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE,
    "-%sdensification_modulus must be >= 0 (GPa), got %g", pre, (double)m->densification_modulus);
  PetscCall(IndPlasticYieldCheckModulus(m, pre, comm));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The return in invariants. With g = dlambda / sigma_s the associated flow scales the trial invariants,
   q = a q_tr and p = b p_tr with a = 1 / (1 + 3 mu g) and b = 1 / (1 + kappa beta^2 g), beta = sigma_s / p_c(c).
   At the solution x = (g, c)
     r1 = (a q_tr)^2 + (beta b p_tr)^2 - sigma_s^2 = 0   (on the ellipse)
     r2 = c - c_old - g beta^2 b p_tr = 0               (the compaction the flow made)
   Partials holds the factors at x and the derivatives of r with respect to x and to y = (q_tr, p_tr), from which
   the consistent tangent follows (implicit differentiation; r2 does not depend on q_tr). */
typedef struct {
  PetscReal a, b, da, db_g, db_c;
  PetscReal r1_g, r1_c, r2_g, r2_c, r1_q, r1_p, r2_p;
} Partials;

static void EvaluatePartials(const IndPlasticParams *m, PetscReal q, PetscReal p, PetscReal g, PetscReal c,
                             Partials *r)
{
  const PetscReal K = m->kappa, G = m->mu, pc = IndDensifyingYieldPressure(m, c), beta = m->R0 / pc;
  const PetscReal dbeta = c > 0 ? -beta * m->densification_modulus / pc : 0.0; /* d beta / dc */

  r->a    = 1.0 / (1.0 + 3.0 * G * g);
  r->da   = -3.0 * G * r->a * r->a;
  r->b    = 1.0 / (1.0 + K * beta * beta * g);
  r->db_g = -K * beta * beta * r->b * r->b;
  r->db_c = -2.0 * K * g * beta * dbeta * r->b * r->b;
  r->r1_g = 2.0 * r->a * r->da * q * q + 2.0 * beta * beta * r->b * r->db_g * p * p;
  r->r1_c = 2.0 * beta * dbeta * r->b * r->b * p * p + 2.0 * beta * beta * r->b * r->db_c * p * p;
  r->r2_g = -beta * beta * p * (r->b + g * r->db_g);
  r->r2_c = 1.0 - g * p * (2.0 * beta * dbeta * r->b + beta * beta * r->db_c);
  r->r1_q = 2.0 * r->a * r->a * q;
  r->r1_p = 2.0 * beta * beta * r->b * r->b * p;
  r->r2_p = -g * beta * beta * r->b;
}

/* The return as one equation in the pressure's relative drop d = (p_tr - p) / p_tr, which fixes everything else:
   the compaction c = c_old + p_tr d / kappa (hence p_c and beta), the multiplier g = d / ((1 - d) kappa beta^2) and
   q = q_tr / (1 + 3 mu g). h(d) = q^2 + (beta p)^2 - sigma_s^2 is positive at d = 0 (the trial state lies outside)
   and tends to -sigma_s^2 as d -> 1 (g grows without bound, q and beta p vanish), so [0, 1) brackets a root.
   Newton from 0, with bisection whenever a step would leave the bracket: converges by construction. d rather than
   p keeps its digits when the cap is far (d ~ kappa beta^2 g is then tiny), and p_tr = 0 needs no special case. */
static void DropResidual(const IndPlasticParams *m, PetscReal q_tr, PetscReal p_tr, PetscReal c_old, PetscReal d,
                         PetscReal *h, PetscReal *dh, PetscReal *g_out, PetscReal *c_out)
{
  const PetscReal K = m->kappa, G = m->mu, sy = m->R0, c = c_old + p_tr * d / K;
  const PetscReal pc = IndDensifyingYieldPressure(m, c), beta = sy / pc, p = p_tr * (1.0 - d);
  const PetscReal dbeta = c > 0 ? -beta * m->densification_modulus / pc * p_tr / K : 0.0; /* d beta / dd */
  const PetscReal g = d / ((1.0 - d) * K * beta * beta);
  const PetscReal dg = 1.0 / ((1.0 - d) * (1.0 - d) * K * beta * beta) - 2.0 * g * dbeta / beta;
  const PetscReal den = 1.0 + 3.0 * G * g, q = q_tr / den, dq = -q_tr * 3.0 * G * dg / (den * den);

  *h  = q * q + beta * beta * p * p - sy * sy;
  *dh = 2.0 * q * dq + 2.0 * beta * dbeta * p * p - 2.0 * beta * beta * p * p_tr;
  if (g_out) *g_out = g;
  if (c_out) *c_out = c;
}

static IndPlasticStatus SolveReturn(const IndPlasticParams *m, PetscReal q_tr, PetscReal p_tr, PetscReal c_old,
                                    PetscReal *g_out, PetscReal *c_out)
{
  const PetscInt  maxit = m->max_iterations > 0 ? m->max_iterations : 100;
  const PetscReal tol   = 1e-14 * m->R0 * m->R0;
  PetscReal       lo = 0.0, hi = 1.0, d = 0.0, h, dh;

  for (PetscInt it = 0; it < maxit; ++it) {
    PetscReal next;
    DropResidual(m, q_tr, p_tr, c_old, d, &h, &dh, NULL, NULL);
    if (it > 0 && PetscAbsReal(h) <= tol) break;
    if (h > 0) lo = d;
    else hi = d;
    next = d - h / dh;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi); /* also catches a NaN step */
    if (PetscAbsReal(next - d) <= 4.0 * PETSC_MACHINE_EPSILON * d) {
      d = next;
      break;
    }
    d = next;
    if (it == maxit - 1) return IND_PLASTIC_NOT_CONVERGED;
  }
  DropResidual(m, q_tr, p_tr, c_old, d, &h, &dh, g_out, c_out);
  return IND_PLASTIC_OK;
}

void IndDensifyingSymmetrize(PetscReal D[36])
{
  for (int i = 0; i < 6; ++i)
    for (int j = i + 1; j < 6; ++j) D[6 * i + j] = D[6 * j + i] = 0.5 * (D[6 * i + j] + D[6 * j + i]);
}

static void Fail(PetscReal sigma[6], PetscReal D[36], PetscReal *dp_out)
{
  for (int i = 0; i < 6; ++i) sigma[i] = NAN;
  if (D)
    for (int i = 0; i < 36; ++i) D[i] = NAN;
  if (dp_out) *dp_out = NAN;
}

IndPlasticStatus IndDensifyingUpdate(const IndPlasticParams *m, const PetscReal eps[6], const IndPlasticState *old,
  IndPlasticState *new_state, PetscReal sigma[6], PetscReal D[36], PetscReal *dp_out)
{
  const IndPlasticState o = *old; /* new_state may alias old */
  const PetscReal       K = m->kappa, G = m->mu;
  const PetscReal       c_old = -(o.eps_p[0] + o.eps_p[1] + o.eps_p[2]);
  PetscReal             ee[6], s[6], tr, p_tr, nrm2 = 0.0, q_tr, a = 1.0, b = 1.0, aq = 0, ap = 0, bq = 0, bp = 0;
  PetscReal             dp = 0.0;
  Partials              r;

  for (int i = 0; i < 6; ++i) ee[i] = eps[i] - o.eps_p[i];
  tr   = ee[0] + ee[1] + ee[2];
  p_tr = -K * tr;
  for (int i = 0; i < 6; ++i) {
    s[i] = i < 3 ? 2.0 * G * (ee[i] - tr / 3.0) : G * ee[i]; /* tensor components of the trial deviator */
    nrm2 += (i < 3 ? 1.0 : 2.0) * s[i] * s[i];
  }
  q_tr       = PetscSqrtReal(1.5 * nrm2);
  *new_state = o;
  {
    const PetscReal beta0 = m->R0 / IndDensifyingYieldPressure(m, c_old);
    const PetscReal f_tr  = PetscSqrtReal(q_tr * q_tr + PetscSqr(beta0 * p_tr)) - m->R0;

    if (f_tr > 1e-12 * m->R0) {
      PetscReal g, c, det, gq, gp, cq, cp, dtr, dev2 = 0.0;

      if (SolveReturn(m, q_tr, p_tr, c_old, &g, &c) != IND_PLASTIC_OK) {
        Fail(sigma, D, dp_out);
        return IND_PLASTIC_NOT_CONVERGED;
      }
      if (D) { /* the tangent's derivatives, d(g, c) / d(q_tr, p_tr) = -(dr/dx)^-1 dr/dy with r2_q = 0 */
        EvaluatePartials(m, q_tr, p_tr, g, c, &r);
        det = r.r1_g * r.r2_c - r.r1_c * r.r2_g;
        gq  = -r.r2_c * r.r1_q / det;
        gp  = -(r.r2_c * r.r1_p - r.r1_c * r.r2_p) / det;
        cq  = r.r2_g * r.r1_q / det;
        cp  = -(-r.r2_g * r.r1_p + r.r1_g * r.r2_p) / det;
        aq  = r.da * gq;
        ap  = r.da * gp;
        bq  = r.db_g * gq + r.db_c * cq;
        bp  = r.db_g * gp + r.db_c * cp;
      }
      {
        const PetscReal beta = m->R0 / IndDensifyingYieldPressure(m, c);
        a = 1.0 / (1.0 + 3.0 * G * g);
        b = 1.0 / (1.0 + K * beta * beta * g);
      }
      /* the plastic strain increment: (1 - a) s_tr / 2 mu deviatoric, and its trace (p - p_tr) / kappa */
      dtr = (b - 1.0) * p_tr / K;
      for (int i = 0; i < 6; ++i) {
        const PetscReal de = (1.0 - a) * s[i] / (2.0 * G); /* tensor component */
        new_state->eps_p[i] += i < 3 ? de + dtr / 3.0 : 2.0 * de;
        dev2 += (i < 3 ? 1.0 : 2.0) * de * de;
      }
      dp = PetscSqrtReal(2.0 / 3.0 * (dev2 + dtr * dtr / 3.0));
      new_state->p += dp;
    }
  }
  for (int i = 0; i < 6; ++i) sigma[i] = a * s[i] + (i < 3 ? -b * p_tr : 0.0);
  if (D) {
    /* dsigma = a dev(ds_tr) + s_tr (a_q dq_tr + a_p dp_tr) - I (b dp_tr + p_tr (b_q dq_tr + b_p dp_tr)), with
       dq_tr = 3 mu s_tr : deps / q_tr and dp_tr = -kappa tr(deps); engineering shears on the right. */
    PetscReal gqv[6], gpv[6];
    for (int k = 0; k < 6; ++k) {
      gqv[k] = q_tr > 0 ? 3.0 * G * s[k] / q_tr : 0.0;
      gpv[k] = k < 3 ? -K : 0.0;
    }
    for (int i = 0; i < 6; ++i)
      for (int k = 0; k < 6; ++k) {
        PetscReal v = s[i] * (aq * gqv[k] + ap * gpv[k]);
        if (i == k) v += 2.0 * G * a * (k < 3 ? 1.0 : 0.5);
        if (i < 3 && k < 3) v -= 2.0 * G * a / 3.0;
        if (i < 3) v -= b * gpv[k] + p_tr * (bq * gqv[k] + bp * gpv[k]);
        D[6 * i + k] = v;
      }
  }
  if (dp_out) *dp_out = dp;
  return IND_PLASTIC_OK;
}
