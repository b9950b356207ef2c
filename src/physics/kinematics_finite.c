/* The "finite" kinematics (-formulation finite): total Lagrangian finite strain at a quadrature point, the
   residual's integrand G_a . P with P = F S, and its exact derivative B^T (dS/dE_GL) B + (G_a . S G_b) I, the
   second term being the geometric (initial stress) stiffness. The cell loops (assembly.c), reference gradients,
   weights and history layout are the small-strain ones; only the kinematics and the material point differ. */
#include "assembly_impl.h"
#include "ind_logstrain.h"

/* A committed state without plastic strain, back stress or accumulated plastic strain: the point's response is then
   an isotropic function of E alone, which the material gives in E's own eigenbasis as well as in any other. */
static inline PetscBool Virgin(const PetscReal *old)
{
  const IndPlasticState *o = (const IndPlasticState *)old;
  PetscBool              v = (PetscBool)(o->p == 0.0);
  for (int k = 0; k < 6; ++k) v = (PetscBool)(v && o->eps_p[k] == 0.0 && o->x[k] == 0.0);
  return v;
}

/* The material point: the small-strain response at the Hencky strain, mapped to S. An inverted point (det F <= 0)
   fails like a return map that does not converge: the step is cut. A virgin point's material is evaluated in the
   eigenbasis of C (as by the stiffness), but for the commit, whose history update is in the global frame. */
static inline IndPlasticStatus FinitePoint(const IndMaterial *m, IndTangent tangent, const PetscReal H[9],
                                           const PetscReal *old, PetscReal *trial, PetscReal S[6], PetscReal *dp,
                                           PetscReal *keep)
{
  const PetscBool  eigen = (PetscBool)(!trial && Virgin(old));
  IndLogStrain     ls;
  IndPlasticStatus status;
  PetscReal        E[6], T[6];

  *dp = 0.0;
  if (IndLogStrainFromGradient(H, &ls, eigen ? NULL : E)) return IND_PLASTIC_NOT_CONVERGED;
  if (keep) IndLogStrainKeep(&ls, keep);
  if (eigen) E[0] = 0.5 * ls.L[0], E[1] = 0.5 * ls.L[1], E[2] = 0.5 * ls.L[2], E[3] = E[4] = E[5] = 0.0;
  status = MaterialResponse(m, tangent, E, old, trial, T, NULL, dp);
  if (status != IND_PLASTIC_OK) return status;
  if (eigen) {
    const PetscReal Tt[9] = {T[0], 0, 0, 0, T[1], 0, 0, 0, T[2]};
    IndLogStrainStressFromBasis(&ls, Tt, S);
  } else IndLogStrainStress(&ls, T, S);
  return status;
}

static IndPlasticStatus Stress(const IndMaterial *m, IndTangent tangent, PetscInt nb, const PetscReal *G,
                               const PetscReal *hoop, const PetscReal *ue, const PetscReal *old, PetscReal *trial,
                               PetscReal P[9], PetscReal *dp, PetscReal *keep)
{
  PetscReal        H[9], F[9], S[6];
  IndPlasticStatus status;

  IndDeformationGradient(nb, G, hoop, ue, H, F);
  status = FinitePoint(m, tangent, H, old, trial, S, dp, keep);
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

/* Ke += w (B^T DS B + geometric) on and above the diagonal, in the rows and columns of the first nt nodes. B is the
   6 x nd derivative of the Green-Lagrange strain (engineering shears), taken in the eigenbasis N of C where the
   tangent M is formed (DS = Re^T M Re): column 3a+i of B~ is sym(F~^T dH~) = sym(f~_i (x) g~_a), f~_i row i of
   F~ = F N and g~_a = N^T G_a (plus hoop_a sym(f~_y (x) n_y) for i = x on an axisymmetric section, n_y = N^T e_y).
   Rotating F and the gradients (27 + 9 nt products) costs less than rotating the 6 x 6 tangent back. B~ and
   w M B~ are stored by rows (Bt[r nd + k] = B~[r][k]), so that the loops over columns are contiguous. */
static inline void AddFiniteStiffness(PetscInt nb, PetscInt nt, const PetscReal *G, const PetscReal *hoop,
                                      const PetscReal F[9], const PetscReal N[9], const PetscReal S[6],
                                      const PetscReal M[36], PetscBool coaxial, PetscReal w, PetscReal *Bt,
                                      PetscReal *DBt, PetscReal *Ke)
{
  const PetscInt nd = 3 * nb, ne = 3 * nt;
  PetscReal      Ft[9];

  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) Ft[3 * i + k] = F[3 * i] * N[k] + F[3 * i + 1] * N[3 + k] + F[3 * i + 2] * N[6 + k];
  for (PetscInt a = 0; a < nt; ++a) {
    const PetscReal *g  = G + 3 * a;
    const PetscReal  gx = g[0] * N[0] + g[1] * N[3] + g[2] * N[6], gy = g[0] * N[1] + g[1] * N[4] + g[2] * N[7],
                     gz = g[0] * N[2] + g[1] * N[5] + g[2] * N[8];
    for (int i = 0; i < 3; ++i) {
      const PetscReal F0 = Ft[3 * i], F1 = Ft[3 * i + 1], F2 = Ft[3 * i + 2];
      const PetscInt  k = 3 * a + i;
      Bt[0 * nd + k] = F0 * gx;
      Bt[1 * nd + k] = F1 * gy;
      Bt[2 * nd + k] = F2 * gz;
      Bt[3 * nd + k] = F0 * gy + F1 * gx;
      Bt[4 * nd + k] = F1 * gz + F2 * gy;
      Bt[5 * nd + k] = F0 * gz + F2 * gx;
    }
    if (hoop) { /* hoop_a sym(f~_y (x) n_y) in column x, f~_y row y of F~ */
      const PetscReal h = hoop[a], n0 = h * N[3], n1 = h * N[4], n2 = h * N[5];
      const PetscInt  k = 3 * a;
      Bt[0 * nd + k] += Ft[3] * n0;
      Bt[1 * nd + k] += Ft[4] * n1;
      Bt[2 * nd + k] += Ft[5] * n2;
      Bt[3 * nd + k] += Ft[3] * n1 + Ft[4] * n0;
      Bt[4 * nd + k] += Ft[4] * n2 + Ft[5] * n1;
      Bt[5 * nd + k] += Ft[3] * n2 + Ft[5] * n0;
    }
  }
  /* w M B~, row by row: the loops over the columns k are independent and contiguous, so they vectorise. A coaxial
     M (IndLogStrainTangentCoaxial) has a 3 x 3 block and a diagonal: a third of the products. */
  if (coaxial) {
    for (int r = 0; r < 3; ++r) {
      const PetscReal m0 = w * M[6 * r], m1 = w * M[6 * r + 1], m2 = w * M[6 * r + 2];
      PetscReal      *db = DBt + r * nd;
      for (PetscInt k = 0; k < ne; ++k) db[k] = m0 * Bt[k] + m1 * Bt[nd + k] + m2 * Bt[2 * nd + k];
    }
    for (int r = 3; r < 6; ++r) {
      const PetscReal m = w * M[7 * r];
      for (PetscInt k = 0; k < ne; ++k) DBt[r * nd + k] = m * Bt[r * nd + k];
    }
  } else {
    for (int r = 0; r < 6; ++r) {
      const PetscReal *Mr = M + 6 * r;
      const PetscReal  m0 = w * Mr[0], m1 = w * Mr[1], m2 = w * Mr[2], m3 = w * Mr[3], m4 = w * Mr[4], m5 = w * Mr[5];
      PetscReal       *db = DBt + r * nd;
      for (PetscInt k = 0; k < ne; ++k)
        db[k] = m0 * Bt[k] + m1 * Bt[nd + k] + m2 * Bt[2 * nd + k] + m3 * Bt[3 * nd + k] + m4 * Bt[4 * nd + k] +
                m5 * Bt[5 * nd + k];
    }
  }
  /* the upper triangle only: the cell loop mirrors it */
  for (PetscInt j = 0; j < ne; ++j) {
    const PetscReal b0 = Bt[j], b1 = Bt[nd + j], b2 = Bt[2 * nd + j], b3 = Bt[3 * nd + j], b4 = Bt[4 * nd + j],
                    b5 = Bt[5 * nd + j];
    PetscReal      *Kj = Ke + j * nd;
    for (PetscInt k = j; k < ne; ++k)
      Kj[k] += b0 * DBt[k] + b1 * DBt[nd + k] + b2 * DBt[2 * nd + k] + b3 * DBt[3 * nd + k] + b4 * DBt[4 * nd + k] +
               b5 * DBt[5 * nd + k];
  }
  for (PetscInt a = 0; a < nt; ++a) {
    const PetscReal ga[3] = {G[3 * a], G[3 * a + 1], G[3 * a + 2]};
    const PetscReal Sg[3] = {S[0] * ga[0] + S[3] * ga[1] + S[5] * ga[2], S[3] * ga[0] + S[1] * ga[1] + S[4] * ga[2],
                             S[5] * ga[0] + S[4] * ga[1] + S[2] * ga[2]};
    for (PetscInt b = a; b < nt; ++b) {
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

static IndPlasticStatus Stiffness(const IndMaterial *m, IndTangent tangent, PetscInt nb, PetscInt nt,
                                  const PetscReal *G, const PetscReal *hoop, const PetscReal *ue, const PetscReal *old,
                                  PetscReal w, PetscReal *B, PetscReal *DB, PetscReal *Ke, const PetscReal *kept)
{
  const PetscBool   virgin = Virgin(old);
  IndLogStrain      ls;
  IndPlasticTangent parts;
  PetscReal         H[9], F[9], E[6], T[6], Tt[9], S[6], D[36], M[36], dp;
  PetscBool         by_parts, coaxial = PETSC_FALSE;
  IndPlasticStatus  status;

  IndDeformationGradient(nb, G, hoop, ue, H, F);
  if (kept) IndLogStrainFromKept(H, kept, &ls, virgin ? NULL : E);
  else if (IndLogStrainFromGradient(H, &ls, virgin ? NULL : E)) return IND_PLASTIC_NOT_CONVERGED;
  /* A virgin point's material is evaluated in the eigenbasis of C, at E~ = diag(L) / 2: its stress T~ is diagonal
     (E~ has no shears) and its tangent comes in that basis, E, T and the flow direction are not rotated. */
  if (virgin) E[0] = 0.5 * ls.L[0], E[1] = 0.5 * ls.L[1], E[2] = 0.5 * ls.L[2], E[3] = E[4] = E[5] = 0.0;
  status = MaterialResponseParts(m, tangent, E, old, T, &parts, &by_parts, D, &dp);
  if (status != IND_PLASTIC_OK) return status;
  if (virgin) {
    for (int k = 0; k < 9; ++k) Tt[k] = 0.0;
    Tt[0] = T[0], Tt[4] = T[1], Tt[8] = T[2];
    if (by_parts) IndPlasticTangentMatrix(&parts, parts.n, D);
    /* a tangent by its parts with a flow direction free of shears: normal and shear parts uncoupled, the shear
       part diagonal. The densifying model's whole tangent is in the eigenbasis already: not rotated. */
    coaxial = by_parts;
    if (!coaxial) IndLogStrainTangentEigen(&ls, Tt, D, PETSC_TRUE, M);
  } else {
    IndLogStrainIntoBasis(&ls, T, Tt);
    /* The tangent in the eigenbasis of C: its isotropic part is the same in every basis, its rank-one part turns
       with the flow direction alone (a 3 x 3 rotation where the whole 6 x 6 would cost 12 times as many products) */
    if (by_parts) {
      PetscReal n[6] = {0, 0, 0, 0, 0, 0};
      if (parts.thetabar != 0.0) {
        PetscReal nt[9];
        IndLogStrainIntoBasis(&ls, parts.n, nt);
        n[0] = nt[0], n[1] = nt[4], n[2] = nt[8], n[3] = nt[1], n[4] = nt[5], n[5] = nt[2];
      }
      IndPlasticTangentMatrix(&parts, n, D);
    }
    IndLogStrainTangentEigen(&ls, Tt, D, (PetscBool)(by_parts || dp == 0.0 || tangent == IND_TANGENT_ELASTIC), M);
  }
  if (coaxial) IndLogStrainTangentCoaxial(&ls, Tt, D, M);
  IndLogStrainStressFromBasis(&ls, Tt, S);
  /* the linear tetrahedron and hexahedron by constant sizes: their loops are unrolled */
  if (nb == 4 && nt == 4) {
    if (coaxial) AddFiniteStiffness(4, 4, G, hoop, F, ls.N, S, M, PETSC_TRUE, w, B, DB, Ke);
    else AddFiniteStiffness(4, 4, G, hoop, F, ls.N, S, M, PETSC_FALSE, w, B, DB, Ke);
  } else if (nb == 8 && nt == 7) {
    if (coaxial) AddFiniteStiffness(8, 7, G, hoop, F, ls.N, S, M, PETSC_TRUE, w, B, DB, Ke);
    else AddFiniteStiffness(8, 7, G, hoop, F, ls.N, S, M, PETSC_FALSE, w, B, DB, Ke);
  } else AddFiniteStiffness(nb, nt, G, hoop, F, ls.N, S, M, coaxial, w, B, DB, Ke);
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
  static const IndKinematics kin = {"finite", Stress, Stiffness, Fields, PETSC_TRUE, IND_LOGSTRAIN_NKEEP};
  return &kin;
}
