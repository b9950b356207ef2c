static const char help[] = "Unit tests of the rigid indenters (gap, normal, area) and the bi-potential projection.\n";

#include "ind_indenter.h"
#include "ind_bipotential.h"

#include "unit_report.h"

static PetscReal Gap(const IndIndenter *ind, const PetscReal x[3])
{
  PetscReal g, n[3];
  IndIndenterGap(ind, x, &g, n);
  return g;
}

static void MakeIndenter(IndIndenterType type, PetscReal radius, IndIndenter *ind)
{
  PetscMemzero(ind, sizeof(*ind));
  ind->type     = type;
  ind->radius   = radius;
  ind->rotation = 0.3;
  ind->axis[0]  = 7.0;
  ind->axis[1]  = -3.0;
  ind->surface  = 2.0;
  ind->depth    = 40.0;
  if (IndIndenterSetUp(ind)) failures++;
}

/* The normal is the unit gradient of the gap (central differences), outside the core where the
   distance is smooth, and the gap is 1-Lipschitz along any segment (no jump anywhere, in particular
   where the tip sphere meets faces and edges). */
static void CheckGradient(const char *name, const IndIndenter *ind, PetscReal scale)
{
  unsigned long long seed = 12345;
  PetscReal          worst_n = 0, worst_unit = 0, worst_lip = 0;
  char               what[128];

  for (int k = 0; k < 4000; ++k) {
    PetscReal x[3], g, n[3], fd[3], h = 1e-6 * scale, y[3];
    x[0] = ind->axis[0] + scale * (2 * Rand(&seed) - 1);
    x[1] = ind->axis[1] + scale * (2 * Rand(&seed) - 1);
    x[2] = ind->surface - ind->depth + scale * (2 * Rand(&seed) - 0.5);
    IndIndenterGap(ind, x, &g, n);
    worst_unit = PetscMax(worst_unit, PetscAbsReal(n[0] * n[0] + n[1] * n[1] + n[2] * n[2] - 1));
    for (int c = 0; c < 3; ++c) y[c] = x[c] + 0.01 * scale * (2 * Rand(&seed) - 1);
    worst_lip = PetscMax(worst_lip, PetscAbsReal(Gap(ind,
      y) - g) / PetscSqrtReal(PetscSqr(y[0] - x[0]) + PetscSqr(y[1] - x[1]) + PetscSqr(y[2] - x[2])) - 1);
    if (g < -ind->radius + 1e-3 * scale && ind->type != IND_INDENTER_FLAT) continue; /* inside the core */
    if (ind->type == IND_INDENTER_FLAT && g < 1e-3 * scale) continue;
    for (int c = 0; c < 3; ++c) {
      PetscReal xp[3] = {x[0], x[1], x[2]}, xm[3] = {x[0], x[1], x[2]};
      xp[c] += h;
      xm[c] -= h;
      fd[c] = (Gap(ind, xp) - Gap(ind, xm)) / (2 * h);
    }
    for (int c = 0; c < 3; ++c) worst_n = PetscMax(worst_n, PetscAbsReal(fd[c] - n[c]));
  }
  snprintf(what, sizeof(what), "%s: |n| = 1", name);
  Report(what, worst_unit, 1e-14);
  snprintf(what, sizeof(what), "%s: n = gradient of the gap (central differences)", name);
  Report(what, worst_n, 1e-6);
  snprintf(what, sizeof(what), "%s: gap 1-Lipschitz (continuous everywhere)", name);
  Report(what, PetscMax(worst_lip, 0.0), 1e-9);
}

/* Unit direction, pointing up, of the edge shared by faces i and j of a pyramid. */
static void EdgeUp(const IndIndenter *b, PetscInt i, PetscInt j, PetscReal e[3])
{
  PetscReal l;
  e[0] = b->m[i][1] * b->m[j][2] - b->m[i][2] * b->m[j][1];
  e[1] = b->m[i][2] * b->m[j][0] - b->m[i][0] * b->m[j][2];
  e[2] = b->m[i][0] * b->m[j][1] - b->m[i][1] * b->m[j][0];
  l    = PetscSqrtReal(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
  for (int k = 0; k < 3; ++k) e[k] /= (e[2] < 0 ? -l : l);
}

static void CheckExactDistances(void)
{
  IndIndenter s, c, b;
  PetscReal   worst = 0, x[3], g, n[3];
  const PetscReal lowest_s = 2.0 - 40.0;

  /* Sphere: |x - centre| - R. */
  MakeIndenter(IND_INDENTER_SPHERE, 100.0, &s);
  for (int k = 0; k < 50; ++k) {
    const PetscReal th = 0.1 * k, d = 3.0 * k - 20;
    x[0] = 7.0 + (100 + d) * PetscSinReal(th);
    x[1] = -3.0;
    x[2] = lowest_s + 100 - (100 + d) * PetscCosReal(th);
    IndIndenterGap(&s, x, &g, n);
    worst = PetscMax(worst, PetscAbsReal(g - d));
  }
  Report("sphere: gap = |x - centre| - R", worst, 1e-12);

  /* Sharp cone 70.3 deg: a point offset by d along the mantle normal from a mantle point. */
  MakeIndenter(IND_INDENTER_CONE, 0.0, &c);
  worst = 0;
  for (int k = 0; k < 50; ++k) {
    const PetscReal a = c.angle, t = 5.0 * (k + 1), phi = 0.37 * k, d = 0.5 * k - 5;
    const PetscReal q[3] = {7.0 + t * PetscSinReal(a) * PetscCosReal(phi),
      -3.0 + t * PetscSinReal(a) * PetscSinReal(phi), lowest_s + t * PetscCosReal(a)};
    const PetscReal m[3] = {PetscCosReal(a) * PetscCosReal(phi), PetscCosReal(a) * PetscSinReal(phi), -PetscSinReal(a)};
    if (d < 0 && -d > t * PetscSinReal(a)) continue; /* would reach the axis */
    for (int i = 0; i < 3; ++i) x[i] = q[i] + d * m[i];
    IndIndenterGap(&c, x, &g, n);
    worst = PetscMax(worst, PetscAbsReal(g - d));
  }
  x[0] = 7.0, x[1] = -3.0, x[2] = lowest_s - 4.0;
  IndIndenterGap(&c, x, &g, n);
  worst = PetscMax(worst, PetscAbsReal(g - 4.0) + PetscAbsReal(n[2] + 1));
  Report("cone: distances to the mantle and below the apex", worst, 1e-12);

  /* Berkovich with a 50 nm tip: faces offset by R, edges and tip rounded with radius R. */
  MakeIndenter(IND_INDENTER_BERKOVICH, 50.0, &b);
  worst = 0;
  {
    const PetscReal apex[3] = {7.0, -3.0, lowest_s + 50.0};
    for (PetscInt i = 0; i < 3; ++i) {
      PetscReal e[3], e2[3], w[3], lw, f[3];
      EdgeUp(&b, i, (i + 1) % 3, e);  /* the edge between faces i and i+1 */
      EdgeUp(&b, (i + 2) % 3, i, e2); /* face i's other edge */
      for (int k = 0; k < 3; ++k) w[k] = b.m[i][k] + b.m[(i + 1) % 3][k];
      lw = PetscSqrtReal(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
      for (int k = 0; k < 3; ++k) w[k] /= lw;
      for (PetscReal d = -10; d <= 10; d += 2.5) {
        /* on the edge, 200 nm up, then out along the bisector of the faces: distance R + d from the core */
        for (int k = 0; k < 3; ++k) x[k] = apex[k] + 200 * e[k] + (50 + d) * w[k];
        IndIndenterGap(&b, x, &g, n);
        worst = PetscMax(worst, PetscAbsReal(g - d));
        /* on face i, midway between its edges at the same height, then out along its normal */
        for (int k = 0; k < 3; ++k) f[k] = apex[k] + 100 * (e[k] + e2[k]) + (50 + d) * b.m[i][k];
        IndIndenterGap(&b, f, &g, n);
        worst = PetscMax(worst,
          PetscAbsReal(g - d) + PetscAbsReal(n[0] - b.m[i][0]) + PetscAbsReal(n[1] - b.m[i][1]) + PetscAbsReal(n[2]
            - b.m[i][2]));
      }
    }
    /* below the tip: the lowest point is at depth 40 */
    for (PetscReal d = 0; d <= 20; d += 5) {
      x[0] = 7.0, x[1] = -3.0, x[2] = lowest_s - d;
      IndIndenterGap(&b, x, &g, n);
      worst = PetscMax(worst, PetscAbsReal(g - d) + PetscAbsReal(n[2] + 1));
    }
  }
  Report("berkovich R = 50: distances to faces, rounded edges and tip", worst, 1e-10);
}

static void CheckAreas(void)
{
  IndIndenter s, c, b, bs, v, f;
  PetscReal   worst;

  MakeIndenter(IND_INDENTER_SPHERE, 100.0, &s);
  Report("sphere: A(h) = pi (2 R h - h^2)", PetscAbsReal(IndIndenterArea(&s,
    10) - PETSC_PI * (2000 - 100)) / (PETSC_PI * 1900), 1e-15);

  /* Sharp Berkovich: 3 sqrt(3) tan^2(65.27 deg) h^2 = 24.5 h^2 (to the 3 digits of the angle). */
  MakeIndenter(IND_INDENTER_BERKOVICH, 0.0, &bs);
  Report("berkovich sharp: A / h^2 = 24.5 (3 digits)", PetscAbsReal(IndIndenterArea(&bs, 100) / 1e4 - 24.5) / 24.5,
    3e-3);
  MakeIndenter(IND_INDENTER_VICKERS, 0.0, &v);
  Report("vickers sharp: A / h^2 = 24.5 (3 digits)", PetscAbsReal(IndIndenterArea(&v, 100) / 1e4 - 24.5) / 24.5, 3e-3);

  /* Rounded Berkovich by the ray integration: a sphere cap while only the tip is cut, and a tiny tip
     radius gives the sharp closed form. */
  MakeIndenter(IND_INDENTER_BERKOVICH, 50.0, &b);
  worst = PetscAbsReal(IndIndenterArea(&b, 1.0) - PETSC_PI * (100.0 - 1.0)) / (PETSC_PI * 99.0);
  Report("berkovich R = 50, h = 1: sphere cap", worst, 1e-12);
  MakeIndenter(IND_INDENTER_BERKOVICH, 1e-9, &b);
  Report("berkovich R = 1e-9: sharp closed form", PetscAbsReal(IndIndenterArea(&b, 100) - IndIndenterArea(&bs,
    100)) / IndIndenterArea(&bs, 100), 1e-9);
  /* Deep in, against an independent estimate: the fraction of a fine grid over the section that
     lies inside the indenter (error about the perimeter times the grid spacing, over the area). */
  MakeIndenter(IND_INDENTER_BERKOVICH, 50.0, &b);
  {
    const PetscReal h = 400, z = b.surface - b.depth + h,
      L = 1.2 * (h + 50) * PetscTanReal(b.angle) / PetscCosReal(PETSC_PI / 3) + 60;
    const PetscInt  N = 1500;
    PetscInt        inside = 0;
    for (PetscInt i = 0; i < N; ++i)
      for (PetscInt j = 0; j < N; ++j) {
        const PetscReal x[3] = {b.axis[0] - L + 2 * L * (i + 0.5) / N, b.axis[1] - L + 2 * L * (j + 0.5) / N, z};
        if (Gap(&b, x) <= 0) inside++;
      }
    Report("berkovich R = 50, h = 400: area vs counting a 1500^2 grid", PetscAbsReal(IndIndenterArea(&b,
      h) - inside * 4 * L * L / (N * N)) / IndIndenterArea(&b, h), 1e-3);
  }
  MakeIndenter(IND_INDENTER_CONE, 50.0, &c);
  {
    const PetscReal ht = 50 * (1 - PetscSinReal(c.angle));
    Report("cone R = 50: A continuous where the tip meets the mantle", PetscAbsReal(IndIndenterArea(&c,
      ht * (1 + 1e-12)) - IndIndenterArea(&c, ht * (1 - 1e-12))) / IndIndenterArea(&c, ht), 1e-9);
  }
  MakeIndenter(IND_INDENTER_FLAT, 300.0, &f);
  Report("flat punch: A = pi a^2", PetscAbsReal(IndIndenterArea(&f, 5) - PETSC_PI * 9e4) / (PETSC_PI * 9e4), 1e-15);
}

static void CheckProjection(void)
{
  unsigned long long seed = 99;
  PetscReal          worst_cone = 0, worst_idem = 0, worst_vi = 0, worst_D = 0, worst_mu0 = 0;
  PetscInt           count[3] = {0, 0, 0};

  for (int k = 0; k < 20000; ++k) {
    const PetscReal  mu = (k % 4 == 0) ? 0.0 : 1.0 * Rand(&seed);
    PetscReal        tau[3], r[3], rr[3], D[9];
    IndContactStatus st;
    for (int c = 0; c < 3; ++c) tau[c] = 2 * Rand(&seed) - 1;
    st = IndBipotentialProject(mu, tau, r, D);
    count[st]++;
    /* in the cone */
    worst_cone = PetscMax(worst_cone, PetscMax(PetscSqrtReal(r[1] * r[1] + r[2] * r[2]) - mu * r[0], -r[0]));
    /* idempotent */
    IndBipotentialProject(mu, r, rr, NULL);
    for (int c = 0; c < 3; ++c) worst_idem = PetscMax(worst_idem, PetscAbsReal(rr[c] - r[c]));
    /* variational inequality (tau - r).(r' - r) <= 0 for r' in the cone */
    for (int j = 0; j < 20; ++j) {
      const PetscReal rn = 2 * Rand(&seed), ang = 2 * PETSC_PI * Rand(&seed), rt = mu * rn * Rand(&seed);
      const PetscReal rp[3] = {rn, rt * PetscCosReal(ang), rt * PetscSinReal(ang)};
      PetscReal       vi = 0;
      for (int c = 0; c < 3; ++c) vi += (tau[c] - r[c]) * (rp[c] - r[c]);
      worst_vi = PetscMax(worst_vi, vi);
    }
    /* dr/dtau by central differences, away from the case boundaries */
    {
      const PetscReal h = 1e-7;
      PetscBool       smooth = PETSC_TRUE;
      PetscReal       rp[3], rm[3], Dfd[9];
      for (int c = 0; c < 3 && smooth; ++c) {
        PetscReal tp[3] = {tau[0], tau[1], tau[2]}, tm[3] = {tau[0], tau[1], tau[2]};
        tp[c] += h;
        tm[c] -= h;
        if (IndBipotentialProject(mu, tp, rp, NULL) != st || IndBipotentialProject(mu, tm, rm,
          NULL) != st) smooth = PETSC_FALSE;
        for (int i = 0; i < 3; ++i) Dfd[3 * i + c] = (rp[i] - rm[i]) / (2 * h);
      }
      if (smooth)
        for (int i = 0; i < 9; ++i) worst_D = PetscMax(worst_D, PetscAbsReal(Dfd[i] - D[i]));
    }
    if (mu == 0) worst_mu0 = PetscMax(worst_mu0, PetscAbsReal(r[0] - PetscMax(tau[0],
      0.0)) + PetscAbsReal(r[1]) + PetscAbsReal(r[2]));
  }
  Report("projection: r in the Coulomb cone", PetscMax(worst_cone, 0.0), 1e-15);
  Report("projection: idempotent", worst_idem, 1e-15);
  Report("projection: (tau - r).(r' - r) <= 0 for r' in the cone", PetscMax(worst_vi, 0.0), 1e-14);
  Report("projection: dr/dtau vs central differences", worst_D, 1e-7);
  Report("projection: mu = 0 is frictionless, r = (max(tau_n, 0), 0, 0)", worst_mu0, 1e-15);
  printf("  cases reached: open %d, stick %d, slip %d\n", (int)count[0], (int)count[1], (int)count[2]);
  if (!count[0] || !count[1] || !count[2]) failures++;
  {
    /* Predictor: penetration raises the normal pressure, slip lowers the tangential reaction. */
    const PetscReal r[3] = {1, 0.1, 0}, dut[2] = {0.5, 0}, mu = 0.3, rho = 2;
    PetscReal       tau[3];
    IndBipotentialPredictor(mu, rho, r, -0.25, dut, tau);
    Report("predictor: tau = r - rho (du_t + (g + mu |du_t|) n)",
      PetscAbsReal(tau[0] - (1 - 2 * (-0.25 + 0.15))) + PetscAbsReal(tau[1] - (0.1 - 1)) + PetscAbsReal(tau[2]), 1e-15);
  }
}

/* The edge the load steps follow (IndIndenterEdgeRadius): where the indenter at depth h meets the undeformed
   surface, pi a^2 = A(h) for the axisymmetric shapes and the sharp pyramids; its inverse returns the depth. */
static void CheckEdgeRadius(void)
{
  const IndIndenterType types[4] = {IND_INDENTER_SPHERE, IND_INDENTER_CONE, IND_INDENTER_BERKOVICH,
                                    IND_INDENTER_CUBE_CORNER};
  const PetscReal       radii[4] = {100.0, 50.0, 0.0, 0.0};
  const PetscReal       depths[6] = {0.5, 2.0, 3.0, 10.0, 60.0, 90.0};
  PetscReal             area = 0, trip = 0;
  IndIndenter           ind;

  for (int k = 0; k < 4; ++k) {
    MakeIndenter(types[k], radii[k], &ind);
    for (int j = 0; j < 6; ++j) {
      const PetscReal h = depths[j], a = IndIndenterEdgeRadius(&ind, h), A = IndIndenterArea(&ind, h);
      area = PetscMax(area, PetscAbsReal(PETSC_PI * a * a - A) / A);
      trip = PetscMax(trip, PetscAbsReal(IndIndenterEdgeDepth(&ind, a) - h) / h);
    }
  }
  Report("edge radius: pi a(h)^2 = A(h) (sphere, rounded cone, sharp pyramids)", area, 1e-13);
  Report("edge radius: its inverse returns the depth", trip, 1e-12);
  MakeIndenter(IND_INDENTER_SPHERE, 100.0, &ind);
  Report("edge radius: a sphere's edge never passes its radius", IndIndenterEdgeDepth(&ind, 100.0) == PETSC_MAX_REAL
    && IndIndenterEdgeRadius(&ind, 150.0) == 100.0 ? 0.0 : 1.0, 0.0);
  MakeIndenter(IND_INDENTER_FLAT, 100.0, &ind);
  Report("edge radius: a flat punch's is its radius at every depth", PetscAbsReal(IndIndenterEdgeRadius(&ind,
    5.0) - 100.0) + (IndIndenterEdgeDepth(&ind, 101.0) == PETSC_MAX_REAL ? 0.0 : 1.0), 0.0);
  /* A rounded pyramid's is the equal-area cone's with the same tip: its radius tracks the ray integration's. */
  MakeIndenter(IND_INDENTER_BERKOVICH, 50.0, &ind);
  area = 0;
  for (int j = 0; j < 6; ++j) {
    const PetscReal h = depths[j], a = IndIndenterEdgeRadius(&ind, h), A = IndIndenterArea(&ind, h);
    area = PetscMax(area, PetscAbsReal(a / PetscSqrtReal(A / PETSC_PI) - 1));
  }
  Report("edge radius: rounded berkovich R = 50, a within 8% of sqrt(A(h) / pi)", area, 0.08);
}

/* A table (-indenter_type table) sampled from the rounded cone and from the sphere gives their gaps and normals
   to the chords' error, their area functions and edge radii. */
static void CheckTable(void)
{
  enum { NCAP = 400 };
  static PetscReal   cone[2 * (NCAP + 2)], sphere[2 * (NCAP + 1)];
  IndIndenter        c, t, s, ts;
  const PetscReal    R = 50, th = 70.3 * PETSC_PI / 180, rt = R * PetscCosReal(th), Rs = 100;
  unsigned long long seed = 777;
  PetscReal          worst_g = 0, worst_n = 0, worst_a = 0, worst_s = 0;

  for (int i = 0; i <= NCAP; ++i) {
    const PetscReal r = rt * i / NCAP, phi = 0.49 * PETSC_PI * i / NCAP;
    cone[2 * i]       = r;
    cone[2 * i + 1]   = R - PetscSqrtReal(R * R - r * r);
    sphere[2 * i]     = Rs * PetscSinReal(phi);
    sphere[2 * i + 1] = Rs * (1 - PetscCosReal(phi));
  }
  cone[2 * NCAP + 2] = rt + 5000 * PetscTanReal(th);
  cone[2 * NCAP + 3] = R * (1 - PetscSinReal(th)) + 5000;
  MakeIndenter(IND_INDENTER_CONE, R, &c);
  MakeIndenter(IND_INDENTER_SPHERE, Rs, &s);
  PetscMemzero(&t, sizeof(t));
  t.type = IND_INDENTER_TABLE, t.profile = cone, t.nprofile = NCAP + 2;
  t.axis[0] = c.axis[0], t.axis[1] = c.axis[1], t.surface = c.surface, t.depth = c.depth;
  ts = t, ts.profile = sphere, ts.nprofile = NCAP + 1;
  if (IndIndenterSetUp(&t) || IndIndenterSetUp(&ts)) failures++;
  for (int k = 0; k < 1000; ++k) {
    PetscReal x[3], g0, g1, n0[3], n1[3];
    x[0] = c.axis[0] + 150 * (2 * Rand(&seed) - 1);
    x[1] = c.axis[1] + 150 * (2 * Rand(&seed) - 1);
    x[2] = c.surface - c.depth + 60 * (2 * Rand(&seed) - 1.2);
    IndIndenterGap(&c, x, &g0, n0);
    IndIndenterGap(&t, x, &g1, n1);
    worst_g = PetscMax(worst_g, PetscAbsReal(g1 - g0));
    if (g0 > 0.5) worst_n = PetscMax(worst_n, PetscAbsReal(n1[0] - n0[0]) + PetscAbsReal(n1[1] - n0[1]) +
                                     PetscAbsReal(n1[2] - n0[2]));
    if (PetscSqrtReal(PetscSqr(x[0] - s.axis[0]) + PetscSqr(x[1] - s.axis[1])) < 0.9 * Rs) {
      IndIndenterGap(&s, x, &g0, n0);
      IndIndenterGap(&ts, x, &g1, n1);
      worst_s = PetscMax(worst_s, PetscAbsReal(g1 - g0));
    }
  }
  for (int j = 1; j <= 50; ++j) {
    const PetscReal h = 2.0 * j;
    worst_a = PetscMax(worst_a, PetscAbsReal(IndIndenterArea(&t, h) / IndIndenterArea(&c, h) - 1));
    worst_a = PetscMax(worst_a, PetscAbsReal(IndIndenterEdgeRadius(&t, h) / IndIndenterEdgeRadius(&c, h) - 1));
    worst_a = PetscMax(worst_a, PetscAbsReal(IndIndenterEdgeDepth(&t, IndIndenterEdgeRadius(&t, h)) / h - 1));
  }
  /* chords of 0.049 pi / 400 rad on a sphere of radius 100 nm sag by R (1 - cos(dphi / 2)) = 1.9e-4 nm */
  Report("table of the rounded cone (400 chords on the cap): gap", worst_g, 1e-4);
  Report("table of the rounded cone: normal (smoothed across corners), 0.5 nm and more outside", worst_n, 1e-3);
  Report("table of the rounded cone: A(h), edge radius and its inverse", worst_a, 1e-4);
  Report("table of a sphere (400 chords): gap within 0.9 R of the axis, to the chords' sag", worst_s, 2e-4);
  {
    PetscReal bad[6] = {0, 0, 10, 1, 20, 1}; /* a flat last segment */
    IndIndenter b = t;
    b.profile = bad, b.nprofile = 3;
    Report("table: a flat last segment is refused", IndIndenterSetUp(&b) ? 0.0 : 1.0, 0.0);
    bad[4] = 5, bad[5] = 2; /* r falling */
    Report("table: a falling r is refused", IndIndenterSetUp(&b) ? 0.0 : 1.0, 0.0);
  }
}

int main(int argc, char **argv)
{
  IndIndenter ind;

  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  printf("Indenter geometry\n");
  CheckExactDistances();
  MakeIndenter(IND_INDENTER_SPHERE, 100.0, &ind);
  CheckGradient("sphere R = 100", &ind, 150);
  MakeIndenter(IND_INDENTER_CONE, 50.0, &ind);
  CheckGradient("cone 70.3 deg, R = 50", &ind, 200);
  MakeIndenter(IND_INDENTER_BERKOVICH, 50.0, &ind);
  CheckGradient("berkovich R = 50", &ind, 200);
  MakeIndenter(IND_INDENTER_BERKOVICH, 0.0, &ind);
  CheckGradient("berkovich sharp", &ind, 200);
  MakeIndenter(IND_INDENTER_VICKERS, 20.0, &ind);
  CheckGradient("vickers R = 20", &ind, 200);
  MakeIndenter(IND_INDENTER_CUBE_CORNER, 20.0, &ind);
  CheckGradient("cube corner R = 20", &ind, 200);
  MakeIndenter(IND_INDENTER_FLAT, 100.0, &ind);
  CheckGradient("flat punch a = 100", &ind, 200);
  printf("Area functions\n");
  CheckAreas();
  CheckEdgeRadius();
  CheckTable();
  printf("Bi-potential projection\n");
  CheckProjection();
  {
    IndIndenter bad;
    PetscMemzero(&bad, sizeof(bad));
    bad.type = IND_INDENTER_SPHERE;
    if (!IndIndenterSetUp(&bad)) failures++; /* a sphere needs a radius */
  }
  printf("%s: %d failure(s)\n", failures ? "FAIL" : "ok", (int)failures);
  PetscCall(PetscFinalize());
  return failures ? 1 : 0;
}
