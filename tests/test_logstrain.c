/* Unit test of the finite-strain kinematics (src/physics/logstrain.c) around the small-strain kernel:
   eigen-decomposition, Hencky strain, stress and tangent against finite differences (plastic states,
   coincident eigenvalues), objectivity, uniaxial tension to 100% logarithmic strain against the
   closed form, elastic simple shear against the Hencky closed form and perfectly plastic simple shear
   against an independent integration of the continuum flow. Expected values are computed here. */
#include <math.h>
#include <string.h>
#include "ind_logstrain.h"
#include "ind_plasticity.h"
#include "ind_hardening.h"
#include "ind_elasticity.h"
#include "unit_report.h"

static const PetscReal YOUNG = 70.0, POISSON = 0.3;

typedef enum { VOCE, LINEAR } Kind;

static IndPlasticParams Law(Kind law, PetscReal R0, PetscReal h, PetscReal H, PetscBool elastic)
{
  IndPlasticParams m;
  memset(&m, 0, sizeof(m));
  IndElasticModuli(YOUNG, POISSON, &m.kappa, &m.mu);
  m.R0 = R0;
  m.H  = H;
  if (law == LINEAR) IndHardeningSetLinear(&m, h);
  else IndHardeningSetVoce(&m, 2.0 * R0, 20.0);
  m.elastic_only = elastic;
  return m;
}

/* The kernel takes H = F - I. */
static int FromF(const PetscReal F[9], IndLogStrain *ls, PetscReal E[6])
{
  PetscReal H[9];
  for (int k = 0; k < 9; ++k) H[k] = F[k] - (k % 4 == 0 ? 1.0 : 0.0);
  return IndLogStrainFromGradient(H, ls, E);
}

/* One finite-strain material point: S (and DS when not NULL) at F from the history old. */
static int Point(const IndPlasticParams *m, const PetscReal F[9], const IndPlasticState *old, IndPlasticState *st,
                 PetscReal S[6], PetscReal DS[36], PetscReal T[6])
{
  IndLogStrain ls;
  PetscReal    E[6], D[36], dp, Tl[6];
  if (FromF(F, &ls, E)) return 1;
  if (IndPlasticUpdate(m, E, old, st, T ? T : Tl, D, &dp) != IND_PLASTIC_OK) return 1;
  IndLogStrainStress(&ls, T ? T : Tl, S);
  if (DS) IndLogStrainTangent(&ls, T ? T : Tl, D, (PetscBool)(dp == 0.0), DS);
  return 0;
}

static void MatMul(const PetscReal A[9], const PetscReal B[9], PetscReal C[9])
{
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) C[3 * i + j] = A[3 * i] * B[j] + A[3 * i + 1] * B[3 + j] + A[3 * i + 2] * B[6 + j];
}

/* Rotation by angle t about the unit axis a (Rodrigues). */
static void Rotation(const PetscReal a[3], PetscReal t, PetscReal R[9])
{
  const PetscReal c = PetscCosReal(t), s = PetscSinReal(t);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) R[3 * i + j] = (i == j ? c : 0.0) + (1 - c) * a[i] * a[j];
  R[1] -= s * a[2], R[2] += s * a[1], R[3] += s * a[2], R[5] -= s * a[0], R[6] -= s * a[1], R[7] += s * a[0];
}

static void RandomRotation(unsigned long long *seed, PetscReal R[9])
{
  PetscReal a[3], n = 0;
  for (int i = 0; i < 3; ++i) {
    a[i] = 2 * Rand(seed) - 1;
    n += a[i] * a[i];
  }
  for (int i = 0; i < 3; ++i) a[i] /= PetscSqrtReal(n);
  Rotation(a, 2 * PETSC_PI * Rand(seed), R);
}

/* F = R Q diag(s) Q^T: stretches s along the axes Q, then the rotation R. */
static void Deformation(const PetscReal R[9], const PetscReal Q[9], const PetscReal s[3], PetscReal F[9])
{
  PetscReal U[9];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      U[3 * i + j] = Q[3 * i] * s[0] * Q[3 * j] + Q[3 * i + 1] * s[1] * Q[3 * j + 1] +
                     Q[3 * i + 2] * s[2] * Q[3 * j + 2];
  MatMul(R, U, F);
}

static PetscReal MaxAbs(const PetscReal *a, int n)
{
  PetscReal m = 0;
  for (int i = 0; i < n; ++i) m = PetscMax(m, PetscAbsReal(a[i]));
  return m;
}

static const PetscReal identity[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};

static void Sort3(PetscReal v[3])
{
  for (int p = 0; p < 2; ++p)
    for (int q = 0; q < 2 - p; ++q)
      if (v[q] > v[q + 1]) {
        const PetscReal t = v[q];
        v[q]              = v[q + 1];
        v[q + 1]          = t;
      }
}

static void TestEigen(unsigned long long *seed)
{
  PetscReal worst = 0, worst_o = 0, worst_l = 0;
  for (int t = 0; t < 300; ++t) {
    PetscReal Q[9], lam[3], V[9], s[3] = {2 * Rand(seed), 2 * Rand(seed), 2 * Rand(seed)}, A[6], Am[9];
    if (t % 3 == 1) s[1] = s[0];                 /* a double eigenvalue */
    if (t % 3 == 2) s[1] = s[2] = s[0] * (1 + 1e-9); /* nearly triple */
    RandomRotation(seed, Q);
    Deformation(identity, Q, s, Am);
    A[0] = Am[0], A[1] = Am[4], A[2] = Am[8], A[3] = Am[1], A[4] = Am[5], A[5] = Am[2];
    IndSymEigen(A, lam, V);
    {
      PetscReal l[3] = {lam[0], lam[1], lam[2]}, e[3] = {s[0], s[1], s[2]};
      Sort3(l);
      Sort3(e);
      for (int k = 0; k < 3; ++k) worst_l = PetscMax(worst_l, PetscAbsReal(l[k] - e[k]) / e[2]);
    }
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        PetscReal r = 0, o = 0;
        for (int k = 0; k < 3; ++k) {
          r += V[3 * i + k] * lam[k] * V[3 * j + k];
          o += V[3 * k + i] * V[3 * k + j];
        }
        worst   = PetscMax(worst, PetscAbsReal(r - Am[3 * i + j]) / 2.0);
        worst_o = PetscMax(worst_o, PetscAbsReal(o - (i == j)));
      }
  }
  Report("eigen: V diag(l) V^T = A (random, double, near-triple), relative", worst, 1e-14);
  Report("eigen: V^T V = I", worst_o, 1e-14);
  Report("eigen: the eigenvalues, relative to the largest", worst_l, 1e-14);
}

/* Small strains: C - I of size 1e-6 with a random orientation, its eigenvalues (double, triple-ish, distinct),
   relative to the largest: the decomposition of C - I keeps the digits that F = I + H would round away. */
static void TestEigenSmall(unsigned long long *seed)
{
  PetscReal worst = 0;
  for (int t = 0; t < 300; ++t) {
    PetscReal Q[9], lam[3], V[9], A[6], Am[9], e[3];
    PetscReal s[3] = {1e-6 * (2 * Rand(seed) - 1), 1e-6 * (2 * Rand(seed) - 1), 1e-6 * (2 * Rand(seed) - 1)};
    if (t % 3 == 1) s[1] = s[0];
    if (t % 3 == 2) s[1] = s[2] = s[0] * (1 + 1e-9);
    RandomRotation(seed, Q);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        Am[3 * i + j] = 0;
        for (int k = 0; k < 3; ++k) Am[3 * i + j] += Q[3 * i + k] * s[k] * Q[3 * j + k];
      }
    A[0] = Am[0], A[1] = Am[4], A[2] = Am[8], A[3] = Am[1], A[4] = Am[5], A[5] = Am[2];
    IndSymEigen(A, lam, V);
    Sort3(lam);
    for (int k = 0; k < 3; ++k) e[k] = s[k];
    Sort3(e);
    for (int k = 0; k < 3; ++k)
      worst = PetscMax(worst, PetscAbsReal(lam[k] - e[k]) / PetscMax(PetscAbsReal(e[0]), PetscAbsReal(e[2])));
  }
  Report("eigen: eigenvalues of a C - I of 1e-6, relative to the largest", worst, 1e-14);
}

/* E of F = R Q diag(s) Q^T is Q diag(ln s) Q^T; the spatial one is R E R^T. */
static void TestHencky(unsigned long long *seed)
{
  PetscReal worst = 0, worst_sp = 0, worst_small = 0;
  for (int t = 0; t < 200; ++t) {
    PetscReal    R[9], Q[9], F[9], E[6], e[6], s[3], RQ[9];
    IndLogStrain ls;
    for (int k = 0; k < 3; ++k) s[k] = PetscExpReal(2 * Rand(seed) - 1);
    if (t % 2) s[2] = s[1];
    RandomRotation(seed, R);
    RandomRotation(seed, Q);
    Deformation(R, Q, s, F);
    (void)FromF(F, &ls, E);
    IndLogStrainSpatial(F, &ls, e);
    MatMul(R, Q, RQ);
    for (int i = 0; i < 3; ++i)
      for (int j = i; j < 3; ++j) {
        const int       v  = i == j ? i : (j == i + 1 ? 3 + i : 5);
        const PetscReal sh = i == j ? 1.0 : 2.0;
        PetscReal       x = 0, y = 0;
        for (int k = 0; k < 3; ++k) {
          x += Q[3 * i + k] * PetscLogReal(s[k]) * Q[3 * j + k];
          y += RQ[3 * i + k] * PetscLogReal(s[k]) * RQ[3 * j + k];
        }
        worst    = PetscMax(worst, PetscAbsReal(E[v] - sh * x));
        worst_sp = PetscMax(worst_sp, PetscAbsReal(e[v] - sh * y));
      }
  }
  /* small strains keep their digits: H of 1e-9 gives E = sym H to its second-order terms */
  for (int t = 0; t < 50; ++t) {
    PetscReal    H[9], E[6];
    IndLogStrain ls;
    for (int k = 0; k < 9; ++k) H[k] = 1e-9 * (2 * Rand(seed) - 1);
    (void)IndLogStrainFromGradient(H, &ls, E);
    /* E = sym H - (H^T H)/2-like terms of order |H|^2: relative 1e-9, with no round-off of 1 + H */
    worst_small = PetscMax(worst_small, PetscMax(PetscAbsReal(E[0] - H[0]), PetscAbsReal(E[3] - (H[1] + H[3]))) / 1e-9);
  }
  Report("Hencky strain E = Q ln(s) Q^T (random, double stretch)", worst, 1e-13);
  Report("spatial Hencky strain e = R E R^T", worst_sp, 1e-13);
  Report("H ~ 1e-9: E = sym H to O(|H|^2), relative to |H|", worst_small, 3e-9);
}

/* S and DS against central differences: T : dE = S : dE_GL along random dF, and dS = DS dE_GL, at
   plastic states and where eigenvalues of C coincide (pure rotation, equal stretches, I + tiny). */
static void TestDerivatives(unsigned long long *seed)
{
  const IndPlasticParams law = Law(VOCE, 0.3, 0, 2.0, PETSC_FALSE);
  PetscReal              worst_s = 0, worst_t = 0;
  int                    plastic = 0;
  for (int t = 0; t < 150; ++t) {
    PetscReal       R[9], Q[9], F[9], s[3], dF[9], S[6], DS[36], T[6], dEg[6], h = 1e-6;
    IndPlasticState old, st;
    memset(&old, 0, sizeof(old));
    for (int k = 0; k < 3; ++k) s[k] = PetscExpReal(0.6 * Rand(seed) - 0.3);
    if (t % 5 == 1) s[1] = s[0];
    if (t % 5 == 2) s[0] = s[1] = s[2];
    if (t % 5 == 3) s[0] = s[1] = s[2] = 1.0 + 1e-7 * Rand(seed);
    if (t % 5 == 4) { /* close but distinct: both sides of the series and Taylor switches */
      s[1] = s[0] * (1 + 1e-4 * Rand(seed));
      s[2] = s[0] * (1 + 2e-2 * Rand(seed));
    }
    RandomRotation(seed, R);
    RandomRotation(seed, Q);
    Deformation(R, Q, s, F);
    /* a plastic history: a random deviatoric plastic strain and back stress */
    for (int k = 0; k < 6; ++k) {
      old.eps_p[k] = 0.05 * (2 * Rand(seed) - 1);
      old.x[k]     = 0.05 * (2 * Rand(seed) - 1);
    }
    {
      const PetscReal m = (old.eps_p[0] + old.eps_p[1] + old.eps_p[2]) / 3, mx = (old.x[0] + old.x[1] + old.x[2]) / 3;
      for (int k = 0; k < 3; ++k) old.eps_p[k] -= m, old.x[k] -= mx;
    }
    old.p = 0.1 * Rand(seed);
    for (int k = 0; k < 9; ++k) dF[k] = 2 * Rand(seed) - 1;
    (void)Point(&law, F, &old, &st, S, DS, T);
    plastic += st.p > old.p;
    /* dE_GL = sym(F^T dF), engineering shears */
    {
      PetscReal FtdF[9];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) FtdF[3 * i + j] = F[i] * dF[j] + F[3 + i] * dF[3 + j] + F[6 + i] * dF[6 + j];
      dEg[0] = FtdF[0], dEg[1] = FtdF[4], dEg[2] = FtdF[8];
      dEg[3] = FtdF[1] + FtdF[3], dEg[4] = FtdF[5] + FtdF[7], dEg[5] = FtdF[2] + FtdF[6];
    }
    {
      PetscReal    Fp[9], Fm[9], Ep[6], Em[6], Sp[6], Sm[6], work, dW = 0, dS[6], dSfd[6];
      IndLogStrain lsp, lsm;
      IndPlasticState tmp;
      for (int k = 0; k < 9; ++k) Fp[k] = F[k] + h * dF[k], Fm[k] = F[k] - h * dF[k];
      (void)FromF(Fp, &lsp, Ep);
      (void)FromF(Fm, &lsm, Em);
      /* T : dE (engineering E against tensor T) = S : dE_GL */
      work = 0;
      for (int k = 0; k < 6; ++k) {
        work += T[k] * (Ep[k] - Em[k]) / (2 * h);
        dW += S[k] * dEg[k];
      }
      worst_s = PetscMax(worst_s, PetscAbsReal(work - dW) / (MaxAbs(S, 6) * MaxAbs(dEg, 6)));
      (void)Point(&law, Fp, &old, &tmp, Sp, NULL, NULL);
      (void)Point(&law, Fm, &old, &tmp, Sm, NULL, NULL);
      for (int r = 0; r < 6; ++r) {
        dS[r]   = 0;
        dSfd[r] = (Sp[r] - Sm[r]) / (2 * h);
        for (int c = 0; c < 6; ++c) dS[r] += DS[6 * r + c] * dEg[c];
        dSfd[r] -= dS[r];
      }
      worst_t = PetscMax(worst_t, MaxAbs(dSfd, 6) / (MaxAbs(dS, 6) + 1e-30));
    }
  }
  PetscCheckAbort(plastic > 40, PETSC_COMM_SELF, PETSC_ERR_PLIB, "too few plastic states (%d)", plastic);
  Report("S = T : 2 dE/dC against differences of E (T : dE = S : dE_GL)", worst_s, 1e-8);
  Report("DS = dS/dE_GL against central differences (plastic, coincident)", worst_t, 1e-6);
}

/* A random deformation with distinct stretches, two equal (t % 3 == 1) or three equal (t % 3 == 2). */
static void RandomStretch(unsigned long long *seed, int t, PetscReal F[9])
{
  PetscReal R[9], Q[9], s[3];
  for (int k = 0; k < 3; ++k) s[k] = PetscExpReal(0.6 * Rand(seed) - 0.3);
  if (t % 3 == 1) s[1] = s[0];
  if (t % 3 == 2) s[0] = s[1] = s[2];
  RandomRotation(seed, R);
  RandomRotation(seed, Q);
  Deformation(R, Q, s, F);
}

/* The decomposition kept in 7 values (eigenvalues, eigenvectors as a quaternion) and rebuilt gives the one computed
   from H: eigenvalues and logarithms in every bit, eigenvectors, f1 and E to round-off; at distinct and coincident
   eigenvalues, small strains and the identity, with eigenbases that take each of the quaternion's four branches. */
static void TestKept(unsigned long long *seed)
{
  PetscReal worst_n = 0, worst_e = 0, worst_bits = 0;
  int       branch[4] = {0, 0, 0, 0};

  for (int t = 0; t < 400; ++t) {
    IndLogStrain a, b;
    PetscReal    F[9], H[9], Ea[6], Eb[6], kept[IND_LOGSTRAIN_NKEEP], tr;
    if (t == 0)
      for (int k = 0; k < 9; ++k) F[k] = identity[k];
    else RandomStretch(seed, t, F);
    for (int k = 0; k < 9; ++k) H[k] = F[k] - identity[k];
    if (t % 4 == 3)
      for (int k = 0; k < 9; ++k) H[k] *= 1e-5; /* a small strain */
    (void)IndLogStrainFromGradient(H, &a, Ea);
    IndLogStrainKeep(&a, kept);
    IndLogStrainFromKept(H, kept, &b, Eb);
    tr = a.N[0] + a.N[4] + a.N[8];
    if (tr >= a.N[0] && tr >= a.N[4] && tr >= a.N[8]) branch[0]++;
    else if (a.N[0] >= a.N[4] && a.N[0] >= a.N[8]) branch[1]++;
    else branch[a.N[4] >= a.N[8] ? 2 : 3]++;
    for (int k = 0; k < 3; ++k)
      worst_bits = PetscMax(worst_bits, (a.lm1[k] != b.lm1[k] || a.L[k] != b.L[k]) ? 1.0 : 0.0);
    worst_bits = PetscMax(worst_bits, a.J != b.J ? 1.0 : 0.0);
    for (int k = 0; k < 9; ++k) worst_n = PetscMax(worst_n, PetscAbsReal(a.N[k] - b.N[k]));
    for (int k = 0; k < 9; ++k) worst_e = PetscMax(worst_e, PetscAbsReal(a.f1[k] - b.f1[k]) / MaxAbs(a.f1, 9));
    for (int k = 0; k < 6; ++k)
      worst_e = PetscMax(worst_e, PetscAbsReal(Ea[k] - Eb[k]) / PetscMax(MaxAbs(Ea, 6), 1e-300));
  }
  Report("kept decomposition: eigenvalues, logarithms and det F rebuilt bit for bit (1: not)", worst_bits, 0.5);
  Report("kept decomposition: eigenvectors from the quaternion", worst_n, 4e-15);
  Report("kept decomposition: f1 and E, relative", worst_e, 1e-14);
  Report("kept decomposition: each of the quaternion's branches taken (1 / fewest)",
         1.0 / PetscMax(1, PetscMin(PetscMin(branch[0], branch[1]), PetscMin(branch[2], branch[3]))), 0.5);
}

/* An elastic (isotropic) tangent taken as the same in every basis gives the DS of its full rotation into
   the eigenbasis of C, at distinct and coincident eigenvalues. */
static void TestIsotropicTangent(unsigned long long *seed)
{
  const IndPlasticParams law = Law(VOCE, 0.3, 0, 2.0, PETSC_TRUE);
  PetscReal              worst = 0;
  for (int t = 0; t < 60; ++t) {
    PetscReal       F[9], E[6], T[6], D[36], DSr[36], DSi[36], d[36], dp;
    IndLogStrain    ls;
    IndPlasticState old, st;
    memset(&old, 0, sizeof(old));
    RandomStretch(seed, t, F);
    (void)FromF(F, &ls, E);
    (void)IndPlasticUpdate(&law, E, &old, &st, T, D, &dp);
    IndLogStrainTangent(&ls, T, D, PETSC_FALSE, DSr);
    IndLogStrainTangent(&ls, T, D, PETSC_TRUE, DSi);
    for (int k = 0; k < 36; ++k) d[k] = DSi[k] - DSr[k];
    worst = PetscMax(worst, MaxAbs(d, 36) / MaxAbs(DSr, 36));
  }
  Report("DS of an elastic tangent without its rotation = with it", worst, 1e-13);
}

/* A point that never yielded: its stress is coaxial with C and the tangent in the eigenbasis by its 3 x 3 block and
   diagonal (IndLogStrainTangentCoaxial) is the full one, at distinct and coincident eigenvalues. A plastic strain in
   the history turns T away from C's axes, and the two must then differ: the comparison can fail. */
static void TestCoaxialTangent(unsigned long long *seed)
{
  const IndPlasticParams law = Law(VOCE, 0.3, 0, 2.0, PETSC_TRUE);
  PetscReal              worst = 0, control = PETSC_MAX_REAL;
  for (int t = 0; t < 120; ++t) {
    const PetscBool history = (PetscBool)(t >= 60);
    PetscReal       F[9], E[6], T[6], Tt[9], D[36], Mc[36], Mg[36], d[36], dp;
    IndLogStrain    ls;
    IndPlasticState old, st;
    memset(&old, 0, sizeof(old));
    if (history)
      for (int k = 0; k < 6; ++k) old.eps_p[k] = 0.02 * Rand(seed);
    RandomStretch(seed, t, F);
    (void)FromF(F, &ls, E);
    (void)IndPlasticUpdate(&law, E, &old, &st, T, D, &dp);
    IndLogStrainIntoBasis(&ls, T, Tt);
    IndLogStrainTangentEigen(&ls, Tt, D, PETSC_TRUE, Mg);
    IndLogStrainTangentCoaxial(&ls, Tt, D, Mc);
    for (int k = 0; k < 36; ++k) d[k] = Mc[k] - Mg[k];
    if (history) control = PetscMin(control, MaxAbs(d, 36) / MaxAbs(Mg, 36));
    else worst = PetscMax(worst, MaxAbs(d, 36) / MaxAbs(Mg, 36));
  }
  Report("M of a point that never yielded by its block and diagonal = the full M", worst, 1e-13);
  Report("control: with a plastic history the two differ (1e-5 / smallest difference)", 1e-5 / control, 1.0);
}

/* A plastic point's tangent turned into the eigenbasis by its parts (the isotropic part as it is, the flow direction
   rotated as a tensor) is the 6 x 6 D turned whole, at distinct and coincident eigenvalues, from a virgin and from a
   plastic history. Leaving n unrotated must differ: the comparison can fail. */
static void TestTangentByParts(unsigned long long *seed)
{
  const IndPlasticParams law = Law(VOCE, 0.3, 0, 2.0, PETSC_FALSE);
  PetscReal              worst = 0, control = PETSC_MAX_REAL;
  PetscInt               plastic = 0;
  for (int t = 0; t < 120; ++t) {
    PetscReal         F[9], E[6], T[6], Tt[9], D[36], Dt[36], Du[36], Mw[36], Mp[36], Mu[36], d[36];
    PetscReal         n[6], nt[9], dp;
    IndLogStrain      ls;
    IndPlasticState   old, st;
    IndPlasticTangent parts;
    memset(&old, 0, sizeof(old));
    if (t % 2)
      for (int k = 0; k < 6; ++k) old.eps_p[k] = 0.02 * Rand(seed);
    RandomStretch(seed, t, F);
    (void)FromF(F, &ls, E);
    (void)IndPlasticUpdate(&law, E, &old, &st, T, D, &dp);
    (void)IndPlasticUpdateParts(&law, E, &old, &st, T, &parts, &dp);
    if (dp > 0) plastic++;
    IndLogStrainIntoBasis(&ls, T, Tt);
    IndLogStrainIntoBasis(&ls, parts.n, nt);
    n[0] = nt[0], n[1] = nt[4], n[2] = nt[8], n[3] = nt[1], n[4] = nt[5], n[5] = nt[2];
    IndPlasticTangentMatrix(&parts, n, Dt);
    IndPlasticTangentMatrix(&parts, parts.n, Du);
    IndLogStrainTangentEigen(&ls, Tt, D, PETSC_FALSE, Mw);
    IndLogStrainTangentEigen(&ls, Tt, Dt, PETSC_TRUE, Mp);
    IndLogStrainTangentEigen(&ls, Tt, Du, PETSC_TRUE, Mu);
    for (int k = 0; k < 36; ++k) d[k] = Mp[k] - Mw[k];
    worst = PetscMax(worst, MaxAbs(d, 36) / MaxAbs(Mw, 36));
    if (dp > 0 && t % 3 == 0) {
      for (int k = 0; k < 36; ++k) d[k] = Mu[k] - Mw[k];
      control = PetscMin(control, MaxAbs(d, 36) / MaxAbs(Mw, 36));
    }
  }
  Report("M from the tangent's parts, n rotated = from D rotated whole", worst, 1e-13);
  Report("... of which plastic points (1 / count)", 1.0 / PetscMax(plastic, 1), 1.0 / 60);
  Report("control: n left unrotated differs (1e-6 / smallest difference)", 1e-6 / control, 1.0);
}

/* A rotation Q applied after F leaves E, T and the history unchanged and rotates the Cauchy stress. */
static void TestObjectivity(unsigned long long *seed)
{
  const IndPlasticParams law = Law(VOCE, 0.3, 0, 2.0, PETSC_FALSE);
  PetscReal              worst_sig = 0, worst_h = 0;
  for (int t = 0; t < 100; ++t) {
    PetscReal       R[9], Q[9], W[9], F[9], WF[9], s[3], S1[6], S2[6], sig1[6], sig2[6], s1[9], Rs[9];
    IndPlasticState old, st1, st2;
    IndLogStrain    ls1, ls2;
    PetscReal       E1[6], E2[6];
    memset(&old, 0, sizeof(old));
    for (int k = 0; k < 3; ++k) s[k] = PetscExpReal(0.4 * Rand(seed) - 0.2);
    RandomRotation(seed, R);
    RandomRotation(seed, Q);
    RandomRotation(seed, W);
    Deformation(R, Q, s, F);
    MatMul(W, F, WF);
    (void)Point(&law, F, &old, &st1, S1, NULL, NULL);
    (void)Point(&law, WF, &old, &st2, S2, NULL, NULL);
    (void)FromF(F, &ls1, E1);
    (void)FromF(WF, &ls2, E2);
    IndLogStrainCauchy(F, ls1.J, S1, sig1);
    IndLogStrainCauchy(WF, ls2.J, S2, sig2);
    for (int k = 0; k < 13; ++k)
      worst_h = PetscMax(worst_h, PetscAbsReal(((PetscReal *)&st1)[k] - ((PetscReal *)&st2)[k]));
    /* W sigma1 W^T */
    {
      const int v[3][3] = {{0, 3, 5}, {3, 1, 4}, {5, 4, 2}};
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) s1[3 * i + j] = sig1[v[i][j]];
      MatMul(W, s1, Rs);
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          PetscReal x = 0;
          for (int k = 0; k < 3; ++k) x += Rs[3 * i + k] * W[3 * j + k];
          worst_sig = PetscMax(worst_sig, PetscAbsReal(x - sig2[v[i][j]]) / MaxAbs(sig1, 6));
        }
    }
    PetscCheckAbort(st1.p > 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "objectivity state %d is elastic", t);
  }
  Report("objectivity: Cauchy stress of W F = W sigma W^T (plastic step)", worst_sig, 1e-10);
  Report("objectivity: history after W F = after F", worst_h, 1e-10);
}

/* Uniaxial stress to 100% logarithmic strain (stretch e): with linear hardening h and kinematic H,
   the log-strain kernel gives T_xx = (R0 + (h + H) ln l) / (1 + (h + H) / E) once yielded, lateral
   log strain -nu T/E - p/2, Cauchy T_xx / J. */
static void TestUniaxial(void)
{
  const IndPlasticParams law = Law(LINEAR, 0.3, 1.5, 1.0, PETSC_FALSE);
  IndPlasticState        st;
  PetscReal              lat = 0, worst = 0, worst_lat = 0, worst_c = 0;
  const int              n   = 25;
  memset(&st, 0, sizeof(st));
  for (int k = 1; k <= n; ++k) {
    const PetscReal eps = 1.0 * k / n; /* ln(stretch) */
    PetscReal       S[6], DS[36], T[6], sig[6], expected, hH = IndPlasticdR(&law, 0) + law.H;
    IndPlasticState trial;
    for (int it = 0;; ++it) {
      const PetscReal F[9] = {PetscExpReal(eps), 0, 0, 0, PetscExpReal(lat), 0, 0, 0, PetscExpReal(lat)};
      (void)Point(&law, F, &st, &trial, S, DS, T);
      if (PetscAbsReal(T[1]) <= 1e-13 * PetscAbsReal(T[0]) || it > 50) {
        IndLogStrain ls;
        PetscReal    E[6];
        (void)FromF(F, &ls, E);
        IndLogStrainCauchy(F, ls.J, S, sig);
        worst_c = PetscMax(worst_c, PetscAbsReal(sig[0] - T[0] / ls.J) / T[0] + PetscAbsReal(sig[1]) / T[0]);
        break;
      }
      /* dS_yy / d lat: dE_GL,yy = l^2 d ln l, over both lateral directions */
      lat -= S[1] / ((DS[6 + 1] + DS[6 + 2]) * PetscExpReal(2 * lat));
    }
    st       = trial;
    expected = eps > law.R0 / YOUNG ? (law.R0 + hH * eps) / (1.0 + hH / YOUNG) : YOUNG * eps;
    worst    = PetscMax(worst, PetscAbsReal(T[0] - expected) / expected);
    worst_lat = PetscMax(worst_lat, PetscAbsReal(lat - (-POISSON * T[0] / YOUNG - 0.5 * st.p)));
  }
  Report("uniaxial to ln(l) = 1: T_xx against the closed form in log strain", worst, 1e-10);
  Report("uniaxial: lateral log strain -nu T/E - p/2", worst_lat, 1e-10);
  Report("uniaxial: Cauchy = (T_xx / J, 0)", worst_c, 1e-10);
}

/* Lagrangian Hencky strain of simple shear g (in the x-y plane), from the 2x2 closed form:
   (exx, eyy, exy) tensor components. */
static void ShearHencky(PetscReal g, PetscReal e[3])
{
  const PetscReal c11 = 1, c22 = 1 + g * g, c12 = g, m = 0.5 * (c11 + c22);
  const PetscReal d = PetscSqrtReal(0.25 * (c11 - c22) * (c11 - c22) + c12 * c12);
  const PetscReal l1 = m + d, l2 = m - d, k = 0.25 * PetscLogReal(l1 / l2) / d; /* (f(l1) - f(l2)) / (l1 - l2) */
  /* E = a I + k (C - m I) with a = (f(l1) + f(l2)) / 2 = 0 since l1 l2 = 1 */
  e[0] = k * (c11 - m), e[1] = k * (c22 - m), e[2] = k * c12;
}

/* Simple shear, F = I + g e_x e_y. Elastic: the Hencky closed form, Cauchy shear
   2 mu asinh(g/2) / sqrt(1 + g^2/4) and normal 2 mu asinh(g/2) g / sqrt(4 + g^2) (Xiao, Bruhns &
   Meyers 1997). Perfectly plastic: against the continuum flow dEe = dE - (dE . n) n on the circle
   |Ee| = R0 / (sqrt(6) mu), integrated here by RK4 from the 2x2 closed-form E(g). */
static void TestSimpleShear(void)
{
  const IndPlasticParams el = Law(LINEAR, 0.3, 0, 0, PETSC_TRUE);
  const IndPlasticParams pp = Law(LINEAR, 0.3, 0, 0, PETSC_FALSE);
  const PetscReal        mu = el.mu, gmax = 2.0;
  PetscReal              worst = 0, err[2] = {0, 0};
  for (int k = 1; k <= 8; ++k) {
    const PetscReal g = 0.25 * k, F[9] = {1, g, 0, 0, 1, 0, 0, 0, 1};
    PetscReal       S[6], sig[6], E[6];
    IndPlasticState st, old;
    IndLogStrain    ls;
    memset(&old, 0, sizeof(old));
    (void)Point(&el, F, &old, &st, S, NULL, NULL);
    (void)FromF(F, &ls, E);
    IndLogStrainCauchy(F, ls.J, S, sig);
    worst = PetscMax(worst, PetscAbsReal(sig[3] - 2 * mu * asinh(g / 2) / PetscSqrtReal(1 + g * g / 4)) / mu);
    worst = PetscMax(worst, PetscAbsReal(sig[0] - 2 * mu * asinh(g / 2) * g / PetscSqrtReal(4 + g * g)) / mu);
    worst = PetscMax(worst, PetscAbsReal(sig[0] + sig[1]) / mu + PetscAbsReal(sig[2]) / mu);
  }
  Report("elastic simple shear: Cauchy against the Hencky closed form (/mu)", worst, 1e-12);

  /* the continuum reference: y = Ee in (xx, xy) components (yy = -xx), |Ee|^2 = 2 y0^2 + 2 y1^2 */
  {
    const PetscReal r0 = pp.R0 / (PetscSqrtReal(6.0) * mu);
    const int       nref = 400000;
    PetscReal       y[2] = {0, 0}, hstep = gmax / nref;
    for (int i = 0; i < nref; ++i) {
      PetscReal kk[4][2], g0 = i * hstep;
      for (int s = 0; s < 4; ++s) {
        const PetscReal gs = g0 + (s == 0 ? 0 : s == 3 ? hstep : 0.5 * hstep), c = s == 0 ? 0 : s == 3 ? 1 : 0.5;
        PetscReal       ys[2] = {y[0] + (s ? c * hstep * kk[s - 1][0] : 0), y[1] + (s ? c * hstep * kk[s - 1][1] : 0)};
        PetscReal       ea[3], eb[3], dE[2], nrm;
        ShearHencky(gs + 1e-6, ea);
        ShearHencky(gs - 1e-6, eb);
        dE[0] = (ea[0] - eb[0]) / 2e-6, dE[1] = (ea[2] - eb[2]) / 2e-6;
        nrm   = PetscSqrtReal(2 * ys[0] * ys[0] + 2 * ys[1] * ys[1]);
        kk[s][0] = dE[0], kk[s][1] = dE[1];
        if (nrm >= r0 * (1 - 1e-12)) {
          const PetscReal dot = (2 * dE[0] * ys[0] + 2 * dE[1] * ys[1]) / nrm;
          if (dot > 0) kk[s][0] -= dot * ys[0] / nrm, kk[s][1] -= dot * ys[1] / nrm;
        }
      }
      for (int d = 0; d < 2; ++d) y[d] += hstep / 6 * (kk[0][d] + 2 * kk[1][d] + 2 * kk[2][d] + kk[3][d]);
      /* stay on the circle against the integrator's drift */
      {
        const PetscReal nrm = PetscSqrtReal(2 * y[0] * y[0] + 2 * y[1] * y[1]);
        if (nrm > r0) y[0] *= r0 / nrm, y[1] *= r0 / nrm;
      }
    }
    for (int run = 0; run < 2; ++run) {
      const int       n = run ? 4000 : 1000;
      IndPlasticState st;
      PetscReal       T[6], S[6];
      memset(&st, 0, sizeof(st));
      for (int k = 1; k <= n; ++k) {
        const PetscReal g = gmax * k / n, F[9] = {1, g, 0, 0, 1, 0, 0, 0, 1};
        (void)Point(&pp, F, &st, &st, S, NULL, T);
      }
      /* T = 2 mu Ee in the Lagrangian frame */
      err[run] = PetscMax(PetscAbsReal(T[0] - 2 * mu * y[0]), PetscAbsReal(T[3] - 2 * mu * y[1])) / pp.R0;
    }
    Report("perfectly plastic simple shear to g = 2: T against the continuum flow, 4000 steps (/R0)", err[1], 2e-3);
    Report("  ... and first order in the step: error(1000) / error(4000) - 4", PetscAbsReal(err[0] / err[1] - 4.0),
           0.5);
  }
}

int main(int argc, char **argv)
{
  unsigned long long seed = 12345;
  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  TestEigen(&seed);
  TestEigenSmall(&seed);
  TestHencky(&seed);
  TestDerivatives(&seed);
  TestIsotropicTangent(&seed);
  TestCoaxialTangent(&seed);
  TestKept(&seed);
  TestTangentByParts(&seed);
  TestObjectivity(&seed);
  TestUniaxial();
  TestSimpleShear();
  printf("%s: %" PetscInt_FMT " failed\n", failures ? "FAILED" : "passed", failures);
  PetscCall(PetscFinalize());
  return failures ? 1 : 0;
}
