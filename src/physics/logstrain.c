#include <math.h>
#include "ind_logstrain.h"

/* PETSc 3.18 has no log1p wrapper; the project builds with double precision. */
static inline PetscReal Log1p(PetscReal x)
{
  return (PetscReal)log1p((double)x);
}

/* Voigt index of the tensor component (i, j). */
static const int voigt[3][3] = {{0, 3, 5}, {3, 1, 4}, {5, 4, 2}};

static inline void ToMatrix(const PetscReal v[6], PetscReal A[9])
{
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) A[3 * i + j] = v[voigt[i][j]];
}

/* Voigt from a symmetric matrix; shear_factor 1 for tensor components, 2 for engineering shears. */
static inline void ToVoigt(const PetscReal A[9], PetscReal shear_factor, PetscReal v[6])
{
  v[0] = A[0], v[1] = A[4], v[2] = A[8];
  v[3] = shear_factor * A[1], v[4] = shear_factor * A[5], v[5] = shear_factor * A[2];
}

/* At = N^T A N (into the eigenbasis). */
static inline void IntoBasis(const PetscReal N[9], const PetscReal A[9], PetscReal At[9])
{
  PetscReal AN[9];
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) AN[3 * i + k] = A[3 * i] * N[k] + A[3 * i + 1] * N[3 + k] + A[3 * i + 2] * N[6 + k];
  for (int k = 0; k < 3; ++k)
    for (int l = 0; l < 3; ++l) At[3 * k + l] = N[k] * AN[l] + N[3 + k] * AN[3 + l] + N[6 + k] * AN[6 + l];
}

/* A = N At N^T (out of the eigenbasis). */
static inline void OutOfBasis(const PetscReal N[9], const PetscReal At[9], PetscReal A[9])
{
  PetscReal NA[9];
  for (int i = 0; i < 3; ++i)
    for (int l = 0; l < 3; ++l) NA[3 * i + l] = N[3 * i] * At[l] + N[3 * i + 1] * At[3 + l] + N[3 * i + 2] * At[6 + l];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      A[3 * i + j] = NA[3 * i] * N[3 * j] + NA[3 * i + 1] * N[3 * j + 1] + NA[3 * i + 2] * N[3 * j + 2];
}

static inline void Cross(const PetscReal a[3], const PetscReal b[3], PetscReal c[3])
{
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
}

/* cos(acos(c) / 3) for c in [0, 1]: the largest root x of 4 x^3 - 3 x = c, in [sqrt(3) / 2, 1], where the cubic
   rises with a slope of at least 6 and is convex. A quintic in c starts within 1.3e-6 of it, and two Newton steps
   (quadratic there: the error becomes at most 1.8 e^2) end at round-off: a third of the time of acos and cos, and
   well-conditioned at c = 1 (two equal eigenvalues), where acos is not. */
static inline PetscReal CosThirdAcos(PetscReal c)
{
  PetscReal x = 0.8660266884420421 +
                c * (0.16660954054207355 +
                     c * (-0.04749187647419726 +
                          c * (0.02186569882389157 + c * (-0.008972271775816294 + c * 0.0019631785314175258))));
  for (int it = 0; it < 2; ++it) x -= (x * (4.0 * x * x - 3.0) - c) / (12.0 * x * x - 3.0);
  return x;
}

/* A fixed sequence of operations, no loop to convergence, after Scherzinger & Dohrmann (CMAME 197 (2008) 4007):
   the eigenvalue farthest from the other two comes accurately from the invariants of the deviator (as the root of
   the triple-angle cubic, CosThirdAcos), its eigenvector as the largest cross product of two rows of B - eta I, and
   the other two
   from the 2x2 problem in the plane normal to it, by one exact rotation. No case is ill-conditioned:
   coincident eigenvalues only leave the rotation angle free. */
void IndSymEigen(const PetscReal S[6], PetscReal lambda[3], PetscReal V[9])
{
  const PetscReal m = (S[0] + S[1] + S[2]) / 3.0;
  const PetscReal B[9] = {S[0] - m, S[3], S[5], S[3], S[1] - m, S[4], S[5], S[4], S[2] - m};
  const PetscReal scale2 = S[0] * S[0] + S[1] * S[1] + S[2] * S[2] + 2.0 * (S[3] * S[3] + S[4] * S[4] + S[5] * S[5]);
  PetscReal       J2 = 0.5 * (B[0] * B[0] + B[4] * B[4] + B[8] * B[8]) + B[1] * B[1] + B[2] * B[2] + B[5] * B[5];
  PetscReal       v1[3] = {0, 0, 1}, u1[3], u2[3], eta1, best = -1, irho;

  if (!(J2 > 1e-32 * scale2)) { /* isotropic to round-off */
    for (int i = 0; i < 9; ++i) V[i] = (i % 4 == 0) ? 1.0 : 0.0;
    for (int k = 0; k < 3; ++k) lambda[k] = S[k];
    return;
  }
  {
    const PetscReal J3 = B[0] * (B[4] * B[8] - B[5] * B[7]) - B[1] * (B[3] * B[8] - B[5] * B[6]) +
                         B[2] * (B[3] * B[7] - B[4] * B[6]);
    /* r = 2 sqrt(J2 / 3), c = (J3 / 2) (3 / J2)^(3/2): one square root and one division */
    const PetscReal sJ = PetscSqrtReal(J2);
    const PetscReal r  = sJ * 1.1547005383792515;
    PetscReal       c  = 2.598076211353316 * J3 / (J2 * sJ);
    c    = PetscMin(1.0, PetscMax(-1.0, c));
    /* the largest eigenvalue of the deviator for c > 0, the smallest otherwise: r cos(acos(c) / 3) and
       r cos(acos(c) / 3 + 2 pi / 3) = -r cos(acos(-c) / 3) */
    eta1 = c > 0 ? r * CosThirdAcos(c) : -r * CosThirdAcos(-c);
  }
  {
    const PetscReal rows[3][3] = {{B[0] - eta1, B[1], B[2]}, {B[3], B[4] - eta1, B[5]}, {B[6], B[7], B[8] - eta1}};
    const int       pr[3][2]   = {{0, 1}, {0, 2}, {1, 2}};
    for (int k = 0; k < 3; ++k) {
      PetscReal c[3], n2;
      Cross(rows[pr[k][0]], rows[pr[k][1]], c);
      n2 = c[0] * c[0] + c[1] * c[1] + c[2] * c[2];
      if (n2 > best) {
        best = n2;
        for (int d = 0; d < 3; ++d) v1[d] = c[d];
      }
    }
    best = 1.0 / PetscSqrtReal(best);
    for (int d = 0; d < 3; ++d) v1[d] *= best;
  }
  /* an orthonormal pair spanning the plane normal to v1: start from the axis least aligned with it */
  {
    int       k    = 0;
    PetscReal e[3] = {0, 0, 0};
    for (int d = 1; d < 3; ++d)
      if (PetscAbsReal(v1[d]) < PetscAbsReal(v1[k])) k = d;
    e[k] = 1.0;
    Cross(v1, e, u1);
    Cross(v1, u1, u2);
    /* u1 and u2 have the same norm rho; the 2x2 problem below is solved in them unnormalised (its rotation
       does not depend on the scale), so that 1 / rho comes in parallel with it */
    irho = 1.0 / PetscSqrtReal(u1[0] * u1[0] + u1[1] * u1[1] + u1[2] * u1[2]);
  }
  {
    PetscReal Bu1[3], Bu2[3], a, b, d, t = 0, c = 1, s = 0, w[3], x[3];
    for (int i = 0; i < 3; ++i) {
      Bu1[i] = B[3 * i] * u1[0] + B[3 * i + 1] * u1[1] + B[3 * i + 2] * u1[2];
      Bu2[i] = B[3 * i] * u2[0] + B[3 * i + 1] * u2[1] + B[3 * i + 2] * u2[2];
    }
    a = u1[0] * Bu1[0] + u1[1] * Bu1[1] + u1[2] * Bu1[2];
    b = u1[0] * Bu2[0] + u1[1] * Bu2[1] + u1[2] * Bu2[2];
    d = u2[0] * Bu2[0] + u2[1] * Bu2[1] + u2[2] * Bu2[2];
    /* one Jacobi rotation (c, s) = (cos, sin) in the (u1, u2) plane diagonalises [[a, b], [b, d]];
       t = s / c is the smaller root of t^2 + 2 theta t - 1 = 0, theta = tau / beta, tau = d - a, beta = 2 b:
       t = sign(theta) |beta| / (|tau| + sqrt(tau^2 + beta^2)), c = 1 / sqrt(1 + t^2), scaled free of divisions */
    if (b != 0) {
      const PetscReal tau = d - a, beta = 2.0 * b, sgn = tau * beta >= 0 ? 1.0 : -1.0;
      const PetscReal den = PetscAbsReal(tau) + PetscSqrtReal(tau * tau + beta * beta), ab = sgn * PetscAbsReal(beta);
      const PetscReal ir = 1.0 / PetscSqrtReal(den * den + beta * beta);
      t = ab / den;
      c = den * ir;
      s = ab * ir;
    }
    c *= irho;
    s *= irho;
    for (int i = 0; i < 3; ++i) {
      w[i] = c * u1[i] - s * u2[i];
      x[i] = s * u1[i] + c * u2[i];
    }
    lambda[0] = m + eta1;
    lambda[1] = m + (a - t * b) * (irho * irho);
    lambda[2] = m + (d + t * b) * (irho * irho);
    for (int i = 0; i < 3; ++i) {
      V[3 * i + 0] = v1[i];
      V[3 * i + 1] = w[i];
      V[3 * i + 2] = x[i];
    }
  }
}

/* First divided difference of f = (1/2) ln at 1 + a and 1 + b, from a, b and La = ln(1 + a),
   Lb = ln(1 + b). Close arguments use the series of log1p(x) / x in x = (a - b) / (1 + b) (truncation
   below 1e-19 for |x| < 1e-2), the others the difference of the logarithms the strain needed anyway:
   no logarithm is evaluated here. */
static inline PetscReal F1(PetscReal a, PetscReal b, PetscReal La, PetscReal Lb)
{
  const PetscReal d = a - b, ib = 1.0 / (1.0 + b), x = d * ib;
  if (PetscAbsReal(x) < 1e-2) {
    static const PetscReal inv[10] = {0, 1.0, 1.0 / 2, 1.0 / 3, 1.0 / 4, 1.0 / 5, 1.0 / 6, 1.0 / 7, 1.0 / 8, 1.0 / 9};
    PetscReal              s       = 0.1;
    for (int n = 9; n >= 1; --n) s = inv[n] - x * s;
    return 0.5 * s * ib;
  }
  return 0.5 * (La - Lb) / d;
}

/* Second divided difference f2(l_hi, l_mid, l_lo), symmetric in its arguments, from the table of f1;
   the arguments come ordered by eigenvalue, hi >= mid >= lo. The difference quotient over the widest
   pair loses eps / spread to cancellation; below a relative spread of 2e-4 the Taylor series about the
   mean, f''/2 + f''''/24 h2 (h2 the complete symmetric quadratic of the offsets), is used instead: both
   are good to about 1e-12 relative there. */
static inline PetscReal F2(const IndLogStrain *ls, int hi, int mid, int lo)
{
  const PetscReal *mu = ls->lm1;
  const PetscReal  m  = 1.0 + (mu[hi] + mu[mid] + mu[lo]) * (1.0 / 3.0);

  if (mu[hi] - mu[lo] <= 2e-4 * m) {
    const PetscReal d0 = mu[hi] + 1.0 - m, d1 = mu[mid] + 1.0 - m, d2 = mu[lo] + 1.0 - m;
    const PetscReal h2 = d0 * d0 + d1 * d1 + d2 * d2 + d0 * d1 + d0 * d2 + d1 * d2, im2 = 1.0 / (m * m);
    return -im2 * (0.25 + 0.125 * h2 * im2);
  }
  return (ls->f1[3 * hi + mid] - ls->f1[3 * mid + lo]) / (mu[hi] - mu[lo]);
}

/* f2 of any three eigenvalues, its arguments put in their order first. */
static inline PetscReal F2Any(const IndLogStrain *ls, int i, int j, int k)
{
  const PetscReal *mu = ls->lm1;
  int              t;

  if (mu[i] < mu[j]) t = i, i = j, j = t;
  if (mu[j] < mu[k]) t = j, j = k, k = t;
  if (mu[i] < mu[j]) t = i, i = j, j = t;
  return F2(ls, i, j, k);
}

/* What follows from lm1, L and N: f1, and E (engineering shears) unless E is NULL. */
static void CompleteDecomposition(IndLogStrain *ls, PetscReal E[6])
{
  for (int i = 0; i < 3; ++i) {
    ls->f1[4 * i] = 0.5 / (1.0 + ls->lm1[i]); /* f'(l) = 1 / (2 l) */
    for (int j = i + 1; j < 3; ++j)
      ls->f1[3 * i + j] = ls->f1[3 * j + i] = F1(ls->lm1[i], ls->lm1[j], ls->L[i], ls->L[j]);
  }
  if (E) {
    PetscReal Em[9] = {0}, Eg[9];
    for (int k = 0; k < 3; ++k) Em[4 * k] = 0.5 * ls->L[k];
    OutOfBasis(ls->N, Em, Eg);
    ToVoigt(Eg, 2.0, E);
  }
}

static inline PetscReal DetF(const PetscReal H[9])
{
  PetscReal F[9];

  for (int k = 0; k < 9; ++k) F[k] = H[k] + (k % 4 == 0 ? 1.0 : 0.0);
  return F[0] * (F[4] * F[8] - F[5] * F[7]) - F[1] * (F[3] * F[8] - F[5] * F[6]) + F[2] * (F[3] * F[7] - F[4] * F[6]);
}

int IndLogStrainFromGradient(const PetscReal H[9], IndLogStrain *ls, PetscReal E[6])
{
  PetscReal Cm[9], Cv[6];

  ls->J = DetF(H);
  if (!(ls->J > 0)) return 1;
  /* C - I = H + H^T + H^T H from H itself: F = I + H rounds H's digits below 1e-16 away */
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      PetscReal v = H[3 * i + j] + H[3 * j + i];
      for (int k = 0; k < 3; ++k) v += H[3 * k + i] * H[3 * k + j];
      Cm[3 * i + j] = v;
    }
  ToVoigt(Cm, 1.0, Cv);
  IndSymEigen(Cv, ls->lm1, ls->N);
  for (int k = 0; k < 3; ++k) {
    if (!(ls->lm1[k] > -1.0)) return 1;
    ls->L[k] = Log1p(ls->lm1[k]);
  }
  CompleteDecomposition(ls, E);
  return 0;
}

/* The rotation N (right-handed: IndSymEigen's column 3 is column 1 x column 2) as a unit quaternion (w, x, y, z), by
   Shepperd's choice of the largest of 1 + trace and 1 + 2 N_kk - trace, whose square root is then far from 0. */
static void QuaternionFromRotation(const PetscReal N[9], PetscReal q[4])
{
  const PetscReal t = N[0] + N[4] + N[8];
  PetscReal       r;

  if (t >= N[0] && t >= N[4] && t >= N[8]) {
    r    = PetscSqrtReal(1.0 + t);
    q[0] = 0.5 * r, r = 0.5 / r;
    q[1] = (N[7] - N[5]) * r, q[2] = (N[2] - N[6]) * r, q[3] = (N[3] - N[1]) * r;
  } else if (N[0] >= N[4] && N[0] >= N[8]) {
    r    = PetscSqrtReal(1.0 + N[0] - N[4] - N[8]);
    q[1] = 0.5 * r, r = 0.5 / r;
    q[0] = (N[7] - N[5]) * r, q[2] = (N[1] + N[3]) * r, q[3] = (N[2] + N[6]) * r;
  } else if (N[4] >= N[8]) {
    r    = PetscSqrtReal(1.0 - N[0] + N[4] - N[8]);
    q[2] = 0.5 * r, r = 0.5 / r;
    q[0] = (N[2] - N[6]) * r, q[1] = (N[1] + N[3]) * r, q[3] = (N[5] + N[7]) * r;
  } else {
    r    = PetscSqrtReal(1.0 - N[0] - N[4] + N[8]);
    q[3] = 0.5 * r, r = 0.5 / r;
    q[0] = (N[3] - N[1]) * r, q[1] = (N[2] + N[6]) * r, q[2] = (N[5] + N[7]) * r;
  }
}

/* The rotation of a quaternion, normalised on the way (2 / |q|^2 for 2). */
static void RotationFromQuaternion(const PetscReal q[4], PetscReal N[9])
{
  const PetscReal s = 2.0 / (q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  const PetscReal w = q[0], x = q[1], y = q[2], z = q[3];

  N[0] = 1.0 - s * (y * y + z * z), N[1] = s * (x * y - z * w), N[2] = s * (x * z + y * w);
  N[3] = s * (x * y + z * w), N[4] = 1.0 - s * (x * x + z * z), N[5] = s * (y * z - x * w);
  N[6] = s * (x * z - y * w), N[7] = s * (y * z + x * w), N[8] = 1.0 - s * (x * x + y * y);
}

void IndLogStrainKeep(const IndLogStrain *ls, PetscReal kept[IND_LOGSTRAIN_NKEEP])
{
  for (int k = 0; k < 3; ++k) kept[k] = ls->lm1[k];
  QuaternionFromRotation(ls->N, kept + 3);
}

void IndLogStrainFromKept(const PetscReal H[9], const PetscReal kept[IND_LOGSTRAIN_NKEEP], IndLogStrain *ls,
                          PetscReal E[6])
{
  ls->J = DetF(H);
  for (int k = 0; k < 3; ++k) {
    ls->lm1[k] = kept[k];
    ls->L[k]   = Log1p(kept[k]);
  }
  RotationFromQuaternion(kept + 3, ls->N);
  CompleteDecomposition(ls, E);
}

void IndLogStrainStressFromBasis(const IndLogStrain *ls, const PetscReal Tt[9], PetscReal S[6])
{
  PetscReal St[9], Sm[9];

  for (int k = 0; k < 9; ++k) St[k] = 2.0 * ls->f1[k] * Tt[k];
  OutOfBasis(ls->N, St, Sm);
  ToVoigt(Sm, 1.0, S);
}

void IndLogStrainStress(const IndLogStrain *ls, const PetscReal T[6], PetscReal S[6])
{
  PetscReal Tm[9], Tt[9];

  ToMatrix(T, Tm);
  IntoBasis(ls->N, Tm, Tt);
  IndLogStrainStressFromBasis(ls, Tt, S);
}

/* Voigt pairs: entry v of a Voigt vector is the tensor component (va[v], vb[v]). */
static const int va[6] = {0, 1, 2, 0, 1, 0}, vb[6] = {0, 1, 2, 1, 2, 2};

/* out = L A L^T for 6x6 matrices (row-major), A and so out symmetric: the upper triangle is computed
   and mirrored. */
static void SymSandwich(const PetscReal L[36], const PetscReal A[36], PetscReal out[36])
{
  PetscReal W[36];
  for (int v = 0; v < 6; ++v)
    for (int w = 0; w < 6; ++w) {
      PetscReal x = 0;
      for (int u = 0; u < 6; ++u) x += A[6 * v + u] * L[6 * w + u];
      W[6 * v + w] = x;
    }
  for (int v = 0; v < 6; ++v)
    for (int w = v; w < 6; ++w) {
      PetscReal x = 0;
      for (int u = 0; u < 6; ++u) x += L[6 * v + u] * W[6 * u + w];
      out[6 * v + w] = out[6 * w + v] = x;
    }
}

/* R rotates tensor-Voigt vectors into the eigenbasis (A~ = N^T A N). */
static void VoigtRotation(const PetscReal N[9], PetscReal R[36])
{
  for (int v = 0; v < 6; ++v) {
    const int a = va[v], b = vb[v];
    for (int i = 0; i < 3; ++i) R[6 * v + i] = N[3 * i + a] * N[3 * i + b];
    for (int w = 3; w < 6; ++w) {
      const int i = va[w], j = vb[w];
      R[6 * v + w] = N[3 * i + a] * N[3 * j + b] + N[3 * j + a] * N[3 * i + b];
    }
  }
}

void IndLogStrainIntoBasis(const IndLogStrain *ls, const PetscReal A[6], PetscReal At[9])
{
  PetscReal Am[9];

  ToMatrix(A, Am);
  IntoBasis(ls->N, Am, At);
}

void IndLogStrainTangentEigen(const IndLogStrain *ls, const PetscReal Tt[9], const PetscReal DT[36],
                              PetscBool isotropic, PetscReal M[36])
{
  const PetscReal *f1 = ls->f1, *D = DT;
  PetscReal        DTt[36], fv[6], f2p[3], f2pq[9], f2x;

  /* an isotropic tangent (elastic) is the same in every basis; another is rotated there as R DT R^T
     (engineering strains rotate with R^-T, so that the contraction with a stress is invariant) */
  if (!isotropic) {
    PetscReal R[36];
    VoigtRotation(ls->N, R);
    SymSandwich(R, DT, DTt);
    D = DTt;
  }
  /* f1 by Voigt pair, and the 10 distinct second divided differences: f2(p, p, p), f2(p, p, q), f2(0, 1, 2) */
  for (int v = 0; v < 6; ++v) fv[v] = f1[3 * va[v] + vb[v]];
  for (int p = 0; p < 3; ++p) {
    f2p[p] = F2(ls, p, p, p);
    for (int q = 0; q < 3; ++q)
      if (q != p) f2pq[3 * p + q] = F2Any(ls, p, p, q);
  }
  f2x = F2Any(ls, 0, 1, 2);
  /* In the eigenbasis, per unit engineering strain e_(cd): dE~ = 2 f1_cd e_(cd) (engineering) and
     dS~_ab = 2 f1_ab dT~_ab + 2 [d_ac f2_abd T~_db + d_ad f2_abc T~_cb + d_bd f2_abc T~_ac + d_bc f2_abd T~_ad],
     the bracket from T : d2E[dC, .] with dC~ = e_c e_d^T + e_d e_c^T; symmetric in (ab, cd) as the
     second derivative of a potential. The bracket, by the kinds of the pairs (ab) and (cd): */
  for (int v = 0; v < 6; ++v)
    for (int w = v; w < 6; ++w) {
      const int a = va[v], b = vb[v], c = va[w], d = vb[w];
      PetscReal g;
      if (w < 3) g = v == w ? 4.0 * f2p[a] * Tt[4 * a] : 0.0; /* (pp, rr) */
      else if (v < 3) /* (pp, cd): f2(p, p, q) T~_pq, q the other index of (cd) when p is one of them */
        g = a == c ? 2.0 * f2pq[3 * a + d] * Tt[3 * a + d] : a == d ? 2.0 * f2pq[3 * a + c] * Tt[3 * a + c] : 0.0;
      else if (v == w) g = f2pq[3 * b + a] * Tt[4 * b] + f2pq[3 * a + b] * Tt[4 * a]; /* (ab, ab) */
      else { /* two shear pairs share one index: f2(0, 1, 2) T~_xy, x and y their other indices */
        const int x = (a == c || a == d) ? b : a, y = (c == a || c == b) ? d : c;
        g = f2x * Tt[3 * x + y];
      }
      M[6 * v + w] = M[6 * w + v] = 4.0 * fv[v] * D[6 * v + w] * fv[w] + 2.0 * g;
    }
}

void IndLogStrainTangentCoaxial(const IndLogStrain *ls, const PetscReal Tt[9], const PetscReal DT[36], PetscReal M[36])
{
  const PetscReal *f1 = ls->f1;

  /* IndLogStrainTangentEigen's entries with T~ diagonal and DT isotropic: its brackets in T~'s off-diagonal vanish,
     and so do DT's normal-shear and shear-shear couplings */
  for (int v = 0; v < 36; ++v) M[v] = 0.0;
  for (int p = 0; p < 3; ++p) {
    for (int q = p; q < 3; ++q) M[6 * p + q] = M[6 * q + p] = 4.0 * f1[4 * p] * DT[6 * p + q] * f1[4 * q];
    M[7 * p] += 8.0 * F2(ls, p, p, p) * Tt[4 * p];
  }
  for (int v = 3; v < 6; ++v) {
    const int       a = va[v], b = vb[v];
    const PetscReal f = f1[3 * a + b];
    M[7 * v] = 4.0 * f * DT[7 * v] * f + 2.0 * (F2Any(ls, b, b, a) * Tt[4 * b] + F2Any(ls, a, a, b) * Tt[4 * a]);
  }
}

void IndLogStrainTangent(const IndLogStrain *ls, const PetscReal T[6], const PetscReal DT[36], PetscBool isotropic,
                         PetscReal DS[36])
{
  PetscReal R[36], ReT[36], Tt[9], M[36];

  IndLogStrainIntoBasis(ls, T, Tt);
  IndLogStrainTangentEigen(ls, Tt, DT, isotropic, M);
  /* DS = Re^T M Re, Re = W R W^-1 (W = diag(1,1,1,2,2,2)) the rotation of engineering strains */
  VoigtRotation(ls->N, R);
  for (int v = 0; v < 6; ++v)
    for (int w = 0; w < 6; ++w) ReT[6 * v + w] = R[6 * w + v] * (w < 3 ? 1.0 : 2.0) / (v < 3 ? 1.0 : 2.0);
  SymSandwich(ReT, M, DS);
}

void IndLogStrainCauchy(const PetscReal F[9], PetscReal J, const PetscReal S[6], PetscReal sigma[6])
{
  PetscReal Sm[9], FS[9], s[9];

  ToMatrix(S, Sm);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) FS[3 * i + j] = F[3 * i] * Sm[j] + F[3 * i + 1] * Sm[3 + j] + F[3 * i + 2] * Sm[6 + j];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      s[3 * i + j] = (FS[3 * i] * F[3 * j] + FS[3 * i + 1] * F[3 * j + 1] + FS[3 * i + 2] * F[3 * j + 2]) / J;
  ToVoigt(s, 1.0, sigma);
}

void IndLogStrainSpatial(const PetscReal F[9], const IndLogStrain *ls, PetscReal e[6])
{
  PetscReal em[9] = {0};

  for (int k = 0; k < 3; ++k) {
    const PetscReal lam = 1.0 + ls->lm1[k], w = 0.5 * Log1p(ls->lm1[k]) / lam;
    PetscReal       n[3];
    /* n_k = F N_k / sqrt(lambda_k); the 1 / lambda_k of n n^T is folded into w */
    for (int i = 0; i < 3; ++i) n[i] = F[3 * i] * ls->N[k] + F[3 * i + 1] * ls->N[3 + k] + F[3 * i + 2] * ls->N[6 + k];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) em[3 * i + j] += w * n[i] * n[j];
  }
  ToVoigt(em, 2.0, e);
}
