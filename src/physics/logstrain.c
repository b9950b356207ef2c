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

/* Non-iterative, after Scherzinger & Dohrmann (CMAME 197 (2008) 4007): the eigenvalue farthest from
   the other two comes accurately from the invariants of the deviator (the cosine is taken where it
   is flat), its eigenvector as the largest cross product of two rows of B - eta I, and the other two
   from the 2x2 problem in the plane normal to it, by one exact rotation. No case is ill-conditioned:
   coincident eigenvalues only leave the rotation angle free. */
void IndSymEigen(const PetscReal S[6], PetscReal lambda[3], PetscReal V[9])
{
  const PetscReal m = (S[0] + S[1] + S[2]) / 3.0;
  const PetscReal B[9] = {S[0] - m, S[3], S[5], S[3], S[1] - m, S[4], S[5], S[4], S[2] - m};
  const PetscReal scale2 = S[0] * S[0] + S[1] * S[1] + S[2] * S[2] + 2.0 * (S[3] * S[3] + S[4] * S[4] + S[5] * S[5]);
  PetscReal       J2 = 0.5 * (B[0] * B[0] + B[4] * B[4] + B[8] * B[8]) + B[1] * B[1] + B[2] * B[2] + B[5] * B[5];
  PetscReal       v1[3] = {0, 0, 1}, u1[3], u2[3], eta1, best = -1;

  if (!(J2 > 1e-32 * scale2)) { /* isotropic to round-off */
    for (int i = 0; i < 9; ++i) V[i] = (i % 4 == 0) ? 1.0 : 0.0;
    for (int k = 0; k < 3; ++k) lambda[k] = S[k];
    return;
  }
  {
    const PetscReal J3 = B[0] * (B[4] * B[8] - B[5] * B[7]) - B[1] * (B[3] * B[8] - B[5] * B[6]) +
                         B[2] * (B[3] * B[7] - B[4] * B[6]);
    const PetscReal r  = 2.0 * PetscSqrtReal(J2 / 3.0);
    const PetscReal q  = 3.0 / J2;
    PetscReal       c  = 0.5 * J3 * q * PetscSqrtReal(q);
    PetscReal       alpha;
    c     = PetscMin(1.0, PetscMax(-1.0, c));
    alpha = PetscAcosReal(c) / 3.0;
    eta1  = alpha < PETSC_PI / 6.0 ? r * PetscCosReal(alpha) : r * PetscCosReal(alpha + 2.0 * PETSC_PI / 3.0);
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
    best = PetscSqrtReal(best);
    for (int d = 0; d < 3; ++d) v1[d] /= best;
  }
  /* an orthonormal pair spanning the plane normal to v1: start from the axis least aligned with it */
  {
    int       k    = 0;
    PetscReal e[3] = {0, 0, 0}, n;
    for (int d = 1; d < 3; ++d)
      if (PetscAbsReal(v1[d]) < PetscAbsReal(v1[k])) k = d;
    e[k] = 1.0;
    Cross(v1, e, u1);
    n = PetscSqrtReal(u1[0] * u1[0] + u1[1] * u1[1] + u1[2] * u1[2]);
    for (int d = 0; d < 3; ++d) u1[d] /= n;
    Cross(v1, u1, u2);
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
       t = s / c is the smaller root of t^2 + 2 theta t - 1 = 0 */
    if (b != 0) {
      const PetscReal theta = (d - a) / (2.0 * b);
      t = (theta >= 0 ? 1.0 : -1.0) / (PetscAbsReal(theta) + PetscSqrtReal(theta * theta + 1.0));
      c = 1.0 / PetscSqrtReal(t * t + 1.0);
      s = t * c;
    }
    for (int i = 0; i < 3; ++i) {
      w[i] = c * u1[i] - s * u2[i];
      x[i] = s * u1[i] + c * u2[i];
    }
    lambda[0] = m + eta1;
    lambda[1] = m + a - t * b;
    lambda[2] = m + d + t * b;
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
  const PetscReal d = a - b, x = d / (1.0 + b);
  if (PetscAbsReal(x) < 1e-2) {
    static const PetscReal inv[10] = {0, 1.0, 1.0 / 2, 1.0 / 3, 1.0 / 4, 1.0 / 5, 1.0 / 6, 1.0 / 7, 1.0 / 8, 1.0 / 9};
    PetscReal              s       = 0.1;
    for (int n = 9; n >= 1; --n) s = inv[n] - x * s;
    return 0.5 * s / (1.0 + b);
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
  const PetscReal  m  = 1.0 + (mu[hi] + mu[mid] + mu[lo]) / 3.0;

  if (mu[hi] - mu[lo] <= 2e-4 * m) {
    const PetscReal d0 = mu[hi] + 1.0 - m, d1 = mu[mid] + 1.0 - m, d2 = mu[lo] + 1.0 - m;
    const PetscReal h2 = d0 * d0 + d1 * d1 + d2 * d2 + d0 * d1 + d0 * d2 + d1 * d2;
    return -0.25 / (m * m) - h2 / (8.0 * m * m * m * m);
  }
  return (ls->f1[3 * hi + mid] - ls->f1[3 * mid + lo]) / (mu[hi] - mu[lo]);
}

/* f2[9 i + 3 j + k] for all index triples: the 10 distinct values, each computed once with its
   arguments in the order of the eigenvalues, copied to its permutations. */
static void F2Table(const IndLogStrain *ls, PetscReal f2[27])
{
  const PetscReal *mu = ls->lm1;
  int              o[3] = {0, 1, 2};

  for (int p = 0; p < 2; ++p)
    for (int q = 0; q < 2 - p; ++q)
      if (mu[o[q]] < mu[o[q + 1]]) {
        const int t = o[q];
        o[q]        = o[q + 1];
        o[q + 1]    = t;
      }
  for (int p = 0; p < 3; ++p)
    for (int q = p; q < 3; ++q)
      for (int r = q; r < 3; ++r) {
        const int       i = o[p], j = o[q], k = o[r];
        const PetscReal v = F2(ls, i, j, k);
        f2[9 * i + 3 * j + k] = f2[9 * i + 3 * k + j] = f2[9 * j + 3 * i + k] = v;
        f2[9 * j + 3 * k + i] = f2[9 * k + 3 * i + j] = f2[9 * k + 3 * j + i] = v;
      }
}

int IndLogStrainFromGradient(const PetscReal H[9], IndLogStrain *ls, PetscReal E[6])
{
  PetscReal Cm[9], Cv[6], Em[9] = {0}, F[9];

  for (int k = 0; k < 9; ++k) F[k] = H[k] + (k % 4 == 0 ? 1.0 : 0.0);
  ls->J = F[0] * (F[4] * F[8] - F[5] * F[7]) - F[1] * (F[3] * F[8] - F[5] * F[6]) + F[2] * (F[3] * F[7] - F[4] * F[6]);
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
    ls->L[k]  = Log1p(ls->lm1[k]);
    Em[4 * k] = 0.5 * ls->L[k];
  }
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j) ls->f1[3 * i + j] = ls->f1[3 * j + i] = F1(ls->lm1[i], ls->lm1[j], ls->L[i], ls->L[j]);
  {
    PetscReal Eg[9];
    OutOfBasis(ls->N, Em, Eg);
    ToVoigt(Eg, 2.0, E);
  }
  return 0;
}

void IndLogStrainStress(const IndLogStrain *ls, const PetscReal T[6], PetscReal S[6])
{
  PetscReal Tm[9], Tt[9], St[9], Sm[9];

  ToMatrix(T, Tm);
  IntoBasis(ls->N, Tm, Tt);
  for (int k = 0; k < 9; ++k) St[k] = 2.0 * ls->f1[k] * Tt[k];
  OutOfBasis(ls->N, St, Sm);
  ToVoigt(Sm, 1.0, S);
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

void IndLogStrainTangent(const IndLogStrain *ls, const PetscReal T[6], const PetscReal DT[36], PetscBool isotropic,
                         PetscReal DS[36])
{
  const PetscReal *N = ls->N, *f1 = ls->f1;
  PetscReal        R[36], ReT[36], Tt[9], DTt[36], M[36], f2[27];

  /* R rotates tensor-Voigt vectors into the eigenbasis (A~ = N^T A N); engineering strains rotate with
     Re = W R W^-1 = R^-T (W = diag(1,1,1,2,2,2): the contraction of a stress with a strain is
     invariant), so a tangent D (engineering to tensor) becomes R D R^T there and Re^T D~ Re back. */
  for (int v = 0; v < 6; ++v) {
    const int a = va[v], b = vb[v];
    for (int i = 0; i < 3; ++i) R[6 * v + i] = N[3 * i + a] * N[3 * i + b];
    for (int w = 3; w < 6; ++w) {
      const int i = va[w], j = vb[w];
      R[6 * v + w] = N[3 * i + a] * N[3 * j + b] + N[3 * j + a] * N[3 * i + b];
    }
  }
  {
    PetscReal Tm[9];
    ToMatrix(T, Tm);
    IntoBasis(N, Tm, Tt);
  }
  F2Table(ls, f2);
  /* an isotropic tangent (elastic) is the same in every basis */
  if (isotropic) PetscArraycpy(DTt, DT, 36);
  else SymSandwich(R, DT, DTt);
  /* In the eigenbasis, per unit engineering strain e_(cd): dE~ = 2 f1_cd e_(cd) (engineering) and
     dS~_ab = 2 f1_ab dT~_ab + 2 [d_ac f2_abd T~_db + d_ad f2_abc T~_cb + d_bd f2_abc T~_ac + d_bc f2_abd T~_ad],
     the bracket from T : d2E[dC, .] with dC~ = e_c e_d^T + e_d e_c^T; symmetric in (ab, cd) as the
     second derivative of a potential. */
  for (int v = 0; v < 6; ++v) {
    const int       a = va[v], b = vb[v];
    const PetscReal fab = 4.0 * f1[3 * a + b];
    for (int w = v; w < 6; ++w) {
      const int c = va[w], d = vb[w];
      PetscReal g = 0;
      if (a == c) g += f2[9 * a + 3 * b + d] * Tt[3 * d + b];
      if (a == d) g += f2[9 * a + 3 * b + c] * Tt[3 * c + b];
      if (b == d) g += f2[9 * a + 3 * b + c] * Tt[3 * a + c];
      if (b == c) g += f2[9 * a + 3 * b + d] * Tt[3 * a + d];
      M[6 * v + w] = M[6 * w + v] = fab * DTt[6 * v + w] * f1[3 * c + d] + 2.0 * g;
    }
  }
  /* DS = Re^T M Re, Re = W R W^-1 */
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
