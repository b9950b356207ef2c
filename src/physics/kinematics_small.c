/* The "small" kinematics (-formulation small, the paper's model): infinitesimal strain, the stress itself
   integrated against the gradients, and the material tangent B^T D B. */
#include "assembly_impl.h"

/* Engineering strain from the gradients G (nb x 3) and the cell displacements u (nb x 3); on an axisymmetric
   section the hoop strain u_x / r in the yy slot. */
static inline void Strain(PetscInt nb, const PetscReal *G, const PetscReal *hoop, const PetscReal *u, PetscReal eps[6])
{
  for (int k = 0; k < 6; ++k) eps[k] = 0.0;
  for (PetscInt a = 0; a < nb; ++a) {
    const PetscReal gx = G[3 * a], gy = G[3 * a + 1], gz = G[3 * a + 2], ux = u[3 * a], uy = u[3 * a + 1],
      uz = u[3 * a + 2];
    eps[0] += gx * ux;
    eps[1] += gy * uy;
    eps[2] += gz * uz;
    eps[3] += gy * ux + gx * uy;
    eps[4] += gz * uy + gy * uz;
    eps[5] += gz * ux + gx * uz;
  }
  if (hoop)
    for (PetscInt a = 0; a < nb; ++a) eps[1] += hoop[a] * u[3 * a];
}

/* Ke += w B^T D B on and above the diagonal, in the rows and columns of the first nt nodes, using the sparsity of B:
   column 3b+c of B holds the gradient of N_b (and for c = x on an axisymmetric section hoop_b in the yy row). D is
   symmetric (elastic and consistent plastic tangents alike), so is Ke. */
static inline void AddBtDB(PetscInt nb, PetscInt nt, const PetscReal *G, const PetscReal *hoop, const PetscReal D[36],
                           PetscReal w, PetscReal *DB, PetscReal *Ke)
{
  const PetscInt nd = 3 * nb, ne = 3 * nt;
  for (PetscInt b = 0; b < nt; ++b) {
    const PetscReal gx = G[3 * b], gy = G[3 * b + 1], gz = G[3 * b + 2], hb = hoop ? hoop[b] : 0.0;
    for (int r = 0; r < 6; ++r) {
      const PetscReal *Dr = D + r * 6;
      DB[r * nd + 3 * b + 0] = Dr[0] * gx + Dr[3] * gy + Dr[5] * gz + Dr[1] * hb;
      DB[r * nd + 3 * b + 1] = Dr[1] * gy + Dr[3] * gx + Dr[4] * gz;
      DB[r * nd + 3 * b + 2] = Dr[2] * gz + Dr[4] * gy + Dr[5] * gx;
    }
  }
  /* the upper triangle only: the cell loop mirrors it */
  for (PetscInt a = 0; a < nt; ++a) {
    const PetscReal gx = w * G[3 * a], gy = w * G[3 * a + 1], gz = w * G[3 * a + 2], ha = hoop ? w * hoop[a] : 0.0;
    PetscReal      *K0 = Ke + (3 * a) * nd, *K1 = K0 + nd, *K2 = K1 + nd;
    for (PetscInt k = 3 * a; k < ne; ++k)
      K0[k] += gx * DB[0 * nd + k] + gy * DB[3 * nd + k] + gz * DB[5 * nd + k] + ha * DB[1 * nd + k];
    for (PetscInt k = 3 * a + 1; k < ne; ++k) K1[k] += gy * DB[1 * nd + k] + gx * DB[3 * nd + k] + gz * DB[4 * nd + k];
    for (PetscInt k = 3 * a + 2; k < ne; ++k) K2[k] += gz * DB[2 * nd + k] + gy * DB[4 * nd + k] + gx * DB[5 * nd + k];
  }
}

static IndPlasticStatus Stress(const IndMaterial *m, IndTangent tangent, PetscInt nb, const PetscReal *G,
                               const PetscReal *hoop, const PetscReal *ue, const PetscReal *old, PetscReal *trial,
                               PetscReal P[9], PetscReal *dp, PetscReal *keep)
{
  PetscReal        eps[6], s[6];
  IndPlasticStatus status;

  (void)keep;
  Strain(nb, G, hoop, ue, eps);
  status = MaterialResponse(m, tangent, eps, old, trial, s, NULL, dp);
  P[0] = s[0], P[1] = s[3], P[2] = s[5];
  P[3] = s[3], P[4] = s[1], P[5] = s[4];
  P[6] = s[5], P[7] = s[4], P[8] = s[2];
  return status;
}

static IndPlasticStatus Stiffness(const IndMaterial *m, IndTangent tangent, PetscInt nb, PetscInt nt,
                                  const PetscReal *G, const PetscReal *hoop, const PetscReal *ue, const PetscReal *old,
                                  PetscReal w, PetscReal *B, PetscReal *DB, PetscReal *Ke, const PetscReal *kept)
{
  PetscReal        eps[6], s[6], D[36], dp;
  IndPlasticStatus status;

  (void)B, (void)kept;
  Strain(nb, G, hoop, ue, eps);
  status = MaterialResponse(m, tangent, eps, old, NULL, s, D, &dp);
  AddBtDB(nb, nt, G, hoop, D, w, DB, Ke);
  return status;
}

/* The committed state is the converged one: its stress is elastic in eps - eps_p (with its trace, if any), with no
   return map to repeat. */
static void Fields(const IndMaterial *m, PetscInt nb, const PetscReal *G, const PetscReal *hoop, const PetscReal *ue,
                   const PetscReal *h, PetscReal sigma[6], PetscReal e[6], PetscReal *w)
{
  const IndPlasticState *st = (const IndPlasticState *)h;
  PetscReal              ee[6];

  (void)w;
  Strain(nb, G, hoop, ue, e);
  for (int k = 0; k < 6; ++k) ee[k] = e[k] - st->eps_p[k];
  IndElasticStress(m->kappa, m->mu, ee, sigma);
}

const IndKinematics *IndKinematicsSmall(void)
{
  static const IndKinematics kin = {"small", Stress, Stiffness, Fields, PETSC_FALSE, 0};
  return &kin;
}
