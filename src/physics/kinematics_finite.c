/* The "finite" kinematics (-formulation finite): total Lagrangian finite strain at a quadrature point, the
   residual's integrand G_a . P with P = F S, and its exact derivative B^T (dS/dE_GL) B + (G_a . S G_b) I, the
   second term being the geometric (initial stress) stiffness. The cell loops (assembly.c), reference gradients,
   weights and history layout are the small-strain ones; only the kinematics and the material point differ. */
#include "assembly_impl.h"
#include "ind_logstrain.h"

/* The material point: the small-strain response at the Hencky strain, mapped to S (and DS). An
   inverted point (det F <= 0) fails like a return map that does not converge: the step is cut. */
static inline IndPlasticStatus FinitePoint(const IndMaterial *m, IndTangent tangent, const PetscReal H[9],
                                           const PetscReal *old, PetscReal *trial, PetscReal S[6], PetscReal *DS,
                                           PetscReal *dp)
{
  IndLogStrain     ls;
  IndPlasticStatus status;
  PetscReal        E[6], T[6], D[36];

  *dp = 0.0;
  if (IndLogStrainFromGradient(H, &ls, E)) return IND_PLASTIC_NOT_CONVERGED;
  status = MaterialResponse(m, tangent, E, old, trial, T, DS ? D : NULL, dp);
  if (status != IND_PLASTIC_OK) return status;
  IndLogStrainStress(&ls, T, S);
  /* a point that did not yield has the elastic, isotropic tangent (so has every point under
     -tangent elastic) */
  if (DS) IndLogStrainTangent(&ls, T, D, (PetscBool)(*dp == 0.0 || tangent == IND_TANGENT_ELASTIC), DS);
  return status;
}

static IndPlasticStatus Stress(const IndMaterial *m, IndTangent tangent, PetscInt nb, const PetscReal *G,
                               const PetscReal *hoop, const PetscReal *ue, const PetscReal *old, PetscReal *trial,
                               PetscReal P[9], PetscReal *dp)
{
  PetscReal        H[9], F[9], S[6];
  IndPlasticStatus status;

  IndDeformationGradient(nb, G, hoop, ue, H, F);
  status = FinitePoint(m, tangent, H, old, trial, S, NULL, dp);
  if (status != IND_PLASTIC_OK) return status;
  /* P = F S = S + H S, summed so that small strains keep their digits */
  for (int r = 0; r < 3; ++r) {
    const PetscReal H0 = H[3 * r], H1 = H[3 * r + 1], H2 = H[3 * r + 2];
    P[3 * r + 0] = H0 * S[0] + H1 * S[3] + H2 * S[5];
    P[3 * r + 1] = H0 * S[3] + H1 * S[1] + H2 * S[4];
    P[3 * r + 2] = H0 * S[5] + H1 * S[4] + H2 * S[2];
  }
  P[0] += S[0], P[1] += S[3], P[2] += S[5];
  P[3] += S[3], P[4] += S[1], P[5] += S[4];
  P[6] += S[5], P[7] += S[4], P[8] += S[2];
  return status;
}

/* Ke += w (B^T DS B + geometric) on and above the diagonal, B the 6 x nd derivative of the
   Green-Lagrange strain (engineering shears): column 3a+i of B is sym(F^T dH), dH = e_i (x) G_a (plus
   hoop_a e_y (x) e_y for i = x on an axisymmetric section). B and DS B are stored by columns (Bt[6 k + r] =
   B[r][k]) so that each entry of Ke is one contiguous dot product. */
static inline void AddFiniteStiffness(PetscInt nb, const PetscReal *G, const PetscReal *hoop, const PetscReal F[9],
                                      const PetscReal S[6], const PetscReal DS[36], PetscReal w, PetscReal *Bt,
                                      PetscReal *DBt, PetscReal *Ke)
{
  const PetscInt nd = 3 * nb;

  for (PetscInt a = 0; a < nb; ++a) {
    const PetscReal gx = G[3 * a], gy = G[3 * a + 1], gz = G[3 * a + 2];
    for (int i = 0; i < 3; ++i) {
      const PetscReal F0 = F[3 * i], F1 = F[3 * i + 1], F2 = F[3 * i + 2];
      PetscReal      *b = Bt + 6 * (3 * a + i), *db = DBt + 6 * (3 * a + i);
      b[0] = F0 * gx;
      b[1] = F1 * gy;
      b[2] = F2 * gz;
      b[3] = F0 * gy + F1 * gx;
      b[4] = F1 * gz + F2 * gy;
      b[5] = F0 * gz + F2 * gx;
      if (hoop && i == 0) { /* sym(F^T (e_y (x) e_y)) hoop_a: column y of F^T, in row and column y */
        b[1] += F[4] * hoop[a];
        b[3] += F[3] * hoop[a];
        b[4] += F[5] * hoop[a];
      }
      for (int r = 0; r < 6; ++r) {
        const PetscReal *Dr = DS + 6 * r;
        db[r] = w * (Dr[0] * b[0] + Dr[1] * b[1] + Dr[2] * b[2] + Dr[3] * b[3] + Dr[4] * b[4] + Dr[5] * b[5]);
      }
    }
  }
  /* the upper triangle only: the cell loop mirrors it */
  for (PetscInt j = 0; j < nd; ++j) {
    const PetscReal *b  = Bt + 6 * j;
    PetscReal       *Kj = Ke + j * nd;
    for (PetscInt k = j; k < nd; ++k) {
      const PetscReal *db = DBt + 6 * k;
      Kj[k] += b[0] * db[0] + b[1] * db[1] + b[2] * db[2] + b[3] * db[3] + b[4] * db[4] + b[5] * db[5];
    }
  }
  for (PetscInt a = 0; a < nb; ++a) {
    const PetscReal ga[3] = {G[3 * a], G[3 * a + 1], G[3 * a + 2]};
    const PetscReal Sg[3] = {S[0] * ga[0] + S[3] * ga[1] + S[5] * ga[2], S[3] * ga[0] + S[1] * ga[1] + S[4] * ga[2],
                             S[5] * ga[0] + S[4] * ga[1] + S[2] * ga[2]};
    for (PetscInt b = a; b < nb; ++b) {
      const PetscReal g = w * (Sg[0] * G[3 * b] + Sg[1] * G[3 * b + 1] + Sg[2] * G[3 * b + 2]);
      for (int i = 0; i < 3; ++i) Ke[(3 * a + i) * nd + 3 * b + i] += g;
      if (hoop) {
        /* S : sym(dH_ai^T dH_bj) with the hoop parts of dH: the (x, x), (y, x) and (x, y) pairs */
        const PetscReal Sgb_y = S[3] * G[3 * b] + S[1] * G[3 * b + 1] + S[4] * G[3 * b + 2];
        Ke[(3 * a) * nd + 3 * b] += w * hoop[a] * hoop[b] * S[1];
        Ke[(3 * a) * nd + 3 * b + 1] += w * hoop[a] * Sgb_y;
        if (b > a) Ke[(3 * a + 1) * nd + 3 * b] += w * hoop[b] * Sg[1];
      }
    }
  }
}

static IndPlasticStatus Stiffness(const IndMaterial *m, IndTangent tangent, PetscInt nb, const PetscReal *G,
                                  const PetscReal *hoop, const PetscReal *ue, const PetscReal *old, PetscReal w,
                                  PetscReal *B, PetscReal *DB, PetscReal *Ke)
{
  PetscReal        H[9], F[9], S[6], DS[36], dp;
  IndPlasticStatus status;

  IndDeformationGradient(nb, G, hoop, ue, H, F);
  status = FinitePoint(m, tangent, H, old, NULL, S, DS, &dp);
  if (status == IND_PLASTIC_OK) AddFiniteStiffness(nb, G, hoop, F, S, DS, w, B, DB, Ke);
  return status;
}

/* Cauchy stress and spatial Hencky strain of a committed point; w becomes the weight of the current volume. */
static void Fields(const IndMaterial *m, PetscInt nb, const PetscReal *G, const PetscReal *hoop, const PetscReal *ue,
                   const PetscReal *h, PetscReal sigma[6], PetscReal e[6], PetscReal *w)
{
  const IndPlasticState *st = (const IndPlasticState *)h;
  IndLogStrain           ls;
  PetscReal              H[9], F[9], E[6], ee[6], T[6], S[6];

  IndDeformationGradient(nb, G, hoop, ue, H, F);
  if (IndLogStrainFromGradient(H, &ls, E)) { /* a committed state is never inverted; report it, not hide it */
    for (int k = 0; k < 6; ++k) sigma[k] = e[k] = NAN;
    return;
  }
  /* the committed state is converged: T is elastic in E - eps_p, with no return map to repeat */
  for (int k = 0; k < 6; ++k) ee[k] = E[k] - st->eps_p[k];
  IndElasticStress(m->kappa, m->mu, ee, T);
  IndLogStrainStress(&ls, T, S);
  IndLogStrainCauchy(F, ls.J, S, sigma);
  IndLogStrainSpatial(F, &ls, e);
  *w *= ls.J;
}

const IndKinematics *IndKinematicsFinite(void)
{
  static const IndKinematics kin = {"finite", Stress, Stiffness, Fields, PETSC_TRUE};
  return &kin;
}
