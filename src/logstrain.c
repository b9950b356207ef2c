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
    for (int j = 0; j < 3; ++j) A[3 * i + j] = NA[3 * i] * N[3 * j] + NA[3 * i + 1] * N[3 * j + 1] + NA[3 * i + 2] * N[3 * j + 2];
}

void IndSymEigen(const PetscReal S[6], PetscReal lambda[3], PetscReal V[9])
{
  PetscReal A[9];
  PetscReal scale = 0;

  ToMatrix(S, A);
  for (int i = 0; i < 9; ++i) {
    V[i] = (i % 4 == 0) ? 1.0 : 0.0;
    scale += A[i] * A[i];
  }
  for (int sweep = 0; sweep < 50; ++sweep) {
    const PetscReal off = A[1] * A[1] + A[2] * A[2] + A[5] * A[5];
    if (off <= 1e-34 * scale || off == 0) break;
    for (int p = 0; p < 2; ++p)
      for (int q = p + 1; q < 3; ++q) {
        const PetscReal apq = A[3 * p + q];
        PetscReal       theta, t, c, s;
        if (apq == 0) continue;
        theta = (A[3 * q + q] - A[3 * p + p]) / (2.0 * apq);
        t     = (theta >= 0 ? 1.0 : -1.0) / (PetscAbsReal(theta) + PetscSqrtReal(theta * theta + 1.0));
        c     = 1.0 / PetscSqrtReal(t * t + 1.0);
        s     = t * c;
        /* A <- J^T A J and V <- V J, J the rotation in the (p, q) plane that zeroes A_pq */
        for (int k = 0; k < 3; ++k) {
          const PetscReal akp = A[3 * k + p], akq = A[3 * k + q], vkp = V[3 * k + p], vkq = V[3 * k + q];
          A[3 * k + p] = c * akp - s * akq;
          A[3 * k + q] = s * akp + c * akq;
          V[3 * k + p] = c * vkp - s * vkq;
          V[3 * k + q] = s * vkp + c * vkq;
        }
        for (int k = 0; k < 3; ++k) {
          const PetscReal apk = A[3 * p + k], aqk = A[3 * q + k];
          A[3 * p + k] = c * apk - s * aqk;
          A[3 * q + k] = s * apk + c * aqk;
        }
        A[3 * p + q] = A[3 * q + p] = 0.0;
      }
  }
  for (int k = 0; k < 3; ++k) lambda[k] = A[4 * k];
}

/* First divided difference of f = (1/2) ln at 1 + a and 1 + b, from a and b (exact as a -> b). */
static inline PetscReal F1(PetscReal a, PetscReal b)
{
  const PetscReal d = a - b;
  if (d == 0) return 0.5 / (1.0 + b);
  return 0.5 * Log1p(d / (1.0 + b)) / d;
}

/* Second divided difference, symmetric in its arguments. The difference quotient over the widest
   pair loses eps / spread to cancellation; below a relative spread of 2e-4 the Taylor series about the
   mean, f''/2 + f''''/24 h2 (h2 the complete symmetric quadratic of the offsets), is used instead: both
   are good to about 1e-12 relative there. */
static inline PetscReal F2(PetscReal a, PetscReal b, PetscReal c)
{
  PetscReal       hi = PetscMax(a, PetscMax(b, c)), lo = PetscMin(a, PetscMin(b, c)), mid = a + b + c - hi - lo;
  const PetscReal m  = 1.0 + (a + b + c) / 3.0;

  if (hi - lo <= 2e-4 * m) {
    const PetscReal d0 = a + 1.0 - m, d1 = b + 1.0 - m, d2 = c + 1.0 - m;
    const PetscReal h2 = d0 * d0 + d1 * d1 + d2 * d2 + d0 * d1 + d0 * d2 + d1 * d2;
    return -0.25 / (m * m) - h2 / (8.0 * m * m * m * m);
  }
  return (F1(hi, mid) - F1(mid, lo)) / (hi - lo);
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
    Em[4 * k] = 0.5 * Log1p(ls->lm1[k]);
  }
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      ls->f1[3 * i + j] = F1(ls->lm1[i], ls->lm1[j]);
      for (int k = 0; k < 3; ++k) ls->f2[9 * i + 3 * j + k] = F2(ls->lm1[i], ls->lm1[j], ls->lm1[k]);
    }
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

void IndLogStrainTangent(const IndLogStrain *ls, const PetscReal T[6], const PetscReal DT[36], PetscReal DS[36])
{
  PetscReal Tm[9], Tt[9];

  ToMatrix(T, Tm);
  IntoBasis(ls->N, Tm, Tt);
  for (int col = 0; col < 6; ++col) {
    PetscReal dEg[6] = {0, 0, 0, 0, 0, 0}, dEgm[9], dCt[9], dEt[9], dEm[9], dEv[6], dTv[6], dTm[9], dTt[9], dSt[9], dSm[9], dS[6];

    dEg[col] = col < 3 ? 1.0 : 0.5; /* a unit engineering strain, as tensor components */
    ToMatrix(dEg, dEgm);
    IntoBasis(ls->N, dEgm, dCt);
    for (int k = 0; k < 9; ++k) {
      dCt[k] *= 2.0; /* dC = 2 dE_GL */
      dEt[k] = ls->f1[k] * dCt[k];
    }
    OutOfBasis(ls->N, dEt, dEm);
    ToVoigt(dEm, 2.0, dEv);
    for (int r = 0; r < 6; ++r) {
      dTv[r] = 0;
      for (int s = 0; s < 6; ++s) dTv[r] += DT[6 * r + s] * dEv[s];
    }
    ToMatrix(dTv, dTm);
    IntoBasis(ls->N, dTm, dTt);
    /* dS~_ab = 2 f1_ab dT~_ab + 2 sum_m f2_abm (dC~_am T~_mb + T~_am dC~_mb) */
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) {
        PetscReal v = 2.0 * ls->f1[3 * a + b] * dTt[3 * a + b];
        for (int m = 0; m < 3; ++m) v += 2.0 * ls->f2[9 * a + 3 * b + m] * (dCt[3 * a + m] * Tt[3 * m + b] + Tt[3 * a + m] * dCt[3 * m + b]);
        dSt[3 * a + b] = v;
      }
    OutOfBasis(ls->N, dSt, dSm);
    ToVoigt(dSm, 1.0, dS);
    for (int r = 0; r < 6; ++r) DS[6 * r + col] = dS[r];
  }
}

void IndLogStrainCauchy(const PetscReal F[9], PetscReal J, const PetscReal S[6], PetscReal sigma[6])
{
  PetscReal Sm[9], FS[9], s[9];

  ToMatrix(S, Sm);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) FS[3 * i + j] = F[3 * i] * Sm[j] + F[3 * i + 1] * Sm[3 + j] + F[3 * i + 2] * Sm[6 + j];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) s[3 * i + j] = (FS[3 * i] * F[3 * j] + FS[3 * i + 1] * F[3 * j + 1] + FS[3 * i + 2] * F[3 * j + 2]) / J;
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
