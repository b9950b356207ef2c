#include <math.h>
#include "ind_indenter.h"

const char *const IndIndenterTypes[] = {"sphere", "cone", "berkovich", "vickers", "cube_corner", "flat", "table",
  "IndIndenterType", "IND_INDENTER_", NULL};

static const PetscReal deg = PETSC_PI / 180.0;

void IndIndenterOPConstants(IndIndenterType type, PetscReal *epsilon, PetscReal *beta)
{
  *epsilon = type == IND_INDENTER_CONE ? 0.72 : type == IND_INDENTER_FLAT ? 1.0 : 0.75;
  *beta    = type == IND_INDENTER_BERKOVICH || type == IND_INDENTER_CUBE_CORNER ? 1.034
             : type == IND_INDENTER_VICKERS                                       ? 1.012
                                                                                 : 1.0;
}

int IndIndenterSetUp(IndIndenter *ind)
{
  PetscReal standard = 0;

  ind->nfaces = 0;
  switch (ind->type) {
  case IND_INDENTER_BERKOVICH:
    ind->nfaces = 3;
    standard    = 65.27 * deg;
    break;
  case IND_INDENTER_VICKERS:
    ind->nfaces = 4;
    standard    = 68.0 * deg;
    break;
  case IND_INDENTER_CUBE_CORNER:
    ind->nfaces = 3;
    standard    = 35.26 * deg;
    break;
  case IND_INDENTER_CONE:
    standard = 70.3 * deg;
    break;
  default:
    break;
  }
  if (ind->type == IND_INDENTER_TABLE) {
    const PetscReal *p = ind->profile;
    const PetscInt   n = ind->nprofile;
    if (!p || n < 2 || p[0] != 0 || p[1] != 0) return 1;
    for (PetscInt i = 1; i < n; ++i)
      if (!(p[2 * i] > p[2 * i - 2]) || !(p[2 * i + 1] >= p[2 * i - 1])) return 1;
    return p[2 * n - 1] > p[2 * n - 3] ? 0 : 1;
  }
  if (ind->angle == 0) ind->angle = standard;
  if (ind->radius < 0) return 1;
  if ((ind->type == IND_INDENTER_SPHERE || ind->type == IND_INDENTER_FLAT) && !(ind->radius > 0)) return 1;
  if (ind->type != IND_INDENTER_SPHERE && ind->type != IND_INDENTER_FLAT && !(ind->angle > 0 && ind->angle < 0.5
    * PETSC_PI)) return 1;
  for (PetscInt i = 0; i < ind->nfaces; ++i) {
    const PetscReal phi = ind->rotation + 2.0 * PETSC_PI * i / ind->nfaces;
    ind->m[i][0]        = PetscCosReal(ind->angle) * PetscCosReal(phi);
    ind->m[i][1]        = PetscCosReal(ind->angle) * PetscSinReal(phi);
    ind->m[i][2]        = -PetscSinReal(ind->angle);
  }
  return 0;
}

static inline PetscReal Dot(const PetscReal a[3], const PetscReal b[3])
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static inline void Normalize(PetscReal v[3])
{
  const PetscReal l = PetscSqrtReal(Dot(v, v));
  for (int k = 0; k < 3; ++k) v[k] /= l;
}

/* Distance from the point y (relative to the apex) to a sharp cone opening upwards, half-angle a. */
static void ConeCore(PetscReal a, const PetscReal y[3], PetscReal *d, PetscReal n[3])
{
  const PetscReal r = PetscSqrtReal(y[0] * y[0] + y[1] * y[1]), h = y[2];
  const PetscReal er[2] = {r > 0 ? y[0] / r : 1.0, r > 0 ? y[1] / r : 0.0};

  if (r * PetscSinReal(a) + h * PetscCosReal(a) >= 0) { /* closest point on the mantle */
    *d   = r * PetscCosReal(a) - h * PetscSinReal(a);
    n[0] = PetscCosReal(a) * er[0];
    n[1] = PetscCosReal(a) * er[1];
    n[2] = -PetscSinReal(a);
  } else { /* below the apex's normal cone: the apex is closest */
    *d = PetscSqrtReal(Dot(y, y));
    for (int k = 0; k < 3; ++k) n[k] = y[k] / *d;
  }
}

/* Signed distance from y (relative to the apex) to the sharp pyramid {y : y.m_i <= 0}: inside, the
   nearest face plane; outside, the nearest of the feasible projections on faces, edges and apex. */
static void PyramidCore(const IndIndenter *ind, const PetscReal y[3], PetscReal *d, PetscReal n[3])
{
  const PetscInt nf = ind->nfaces;
  PetscReal      s[IND_INDENTER_MAX_FACES], smax = -PETSC_MAX_REAL, best = PETSC_MAX_REAL, p[3];
  PetscInt       imax = 0;

  for (PetscInt i = 0; i < nf; ++i) {
    s[i] = Dot(y, ind->m[i]);
    if (s[i] > smax) {
      smax = s[i];
      imax = i;
    }
  }
  if (smax <= 0) {
    *d = smax;
    for (int k = 0; k < 3; ++k) n[k] = ind->m[imax][k];
    return;
  }
  /* The apex is always feasible. */
  best = PetscSqrtReal(Dot(y, y));
  for (int k = 0; k < 3; ++k) p[k] = 0.0;
  for (PetscInt i = 0; i < nf; ++i) {
    const PetscInt j = (i + 1) % nf;
    PetscReal      q[3], e[3], t, dist;
    PetscBool      feasible = PETSC_TRUE;

    if (s[i] > 0) { /* foot of the perpendicular on face i's plane */
      for (int k = 0; k < 3; ++k) q[k] = y[k] - s[i] * ind->m[i][k];
      for (PetscInt l = 0; l < nf && feasible; ++l)
        if (l != i && Dot(q, ind->m[l]) > 1e-14 * (PetscAbsReal(s[i]) + PetscSqrtReal(Dot(y,
          y)))) feasible = PETSC_FALSE;
      if (feasible && s[i] < best) {
        best = s[i];
        for (int k = 0; k < 3; ++k) p[k] = q[k];
      }
    }
    /* The edge between faces i and j, a ray from the apex upwards. */
    e[0] = ind->m[i][1] * ind->m[j][2] - ind->m[i][2] * ind->m[j][1];
    e[1] = ind->m[i][2] * ind->m[j][0] - ind->m[i][0] * ind->m[j][2];
    e[2] = ind->m[i][0] * ind->m[j][1] - ind->m[i][1] * ind->m[j][0];
    Normalize(e);
    if (e[2] < 0)
      for (int k = 0; k < 3; ++k) e[k] = -e[k];
    t = Dot(y, e);
    if (t > 0) {
      for (int k = 0; k < 3; ++k) q[k] = t * e[k];
      dist = PetscSqrtReal(PetscSqr(y[0] - q[0]) + PetscSqr(y[1] - q[1]) + PetscSqr(y[2] - q[2]));
      if (dist < best) {
        best = dist;
        for (int k = 0; k < 3; ++k) p[k] = q[k];
      }
    }
  }
  *d = best;
  for (int k = 0; k < 3; ++k) n[k] = y[k] - p[k];
  Normalize(n);
}

static void FlatPunch(const IndIndenter *ind, const PetscReal y[3], PetscReal *d, PetscReal n[3])
{
  const PetscReal a = ind->radius, r = PetscSqrtReal(y[0] * y[0] + y[1] * y[1]), h = y[2];
  const PetscReal er[2] = {r > 0 ? y[0] / r : 1.0, r > 0 ? y[1] / r : 0.0};

  n[0] = n[1] = n[2] = 0.0;
  if (r <= a && h >= 0) { /* inside: the nearer of face and mantle */
    if (h <= a - r) {
      *d   = -h;
      n[2] = -1.0;
    } else {
      *d   = r - a;
      n[0] = er[0];
      n[1] = er[1];
    }
  } else if (r <= a) {
    *d   = -h;
    n[2] = -1.0;
  } else if (h >= 0) {
    *d   = r - a;
    n[0] = er[0];
    n[1] = er[1];
  } else {
    *d   = PetscSqrtReal(PetscSqr(r - a) + h * h);
    n[0] = (r - a) * er[0] / *d;
    n[1] = (r - a) * er[1] / *d;
    n[2] = h / *d;
  }
}

/* The table's height at radius r: straight between its points, along the last segment past them. */
static PetscReal ProfileHeight(const IndIndenter *ind, PetscReal r)
{
  const PetscReal *p = ind->profile;
  const PetscInt   n = ind->nprofile;
  PetscInt         i = 0;

  while (i < n - 2 && r > p[2 * i + 2]) ++i;
  return p[2 * i + 1] + (r - p[2 * i]) * (p[2 * i + 3] - p[2 * i + 1]) / (p[2 * i + 2] - p[2 * i]);
}

/* The largest radius where the table's height is at most h: the edge of its cross-section at height h. */
static PetscReal ProfileRadius(const IndIndenter *ind, PetscReal h)
{
  const PetscReal *p = ind->profile;
  const PetscInt   n = ind->nprofile;

  for (PetscInt i = 0; i < n - 1; ++i)
    if (p[2 * i + 3] > h) {
      if (i == n - 2 || p[2 * i + 1] <= h) /* rising through h here (or past the end, along the last segment) */
        return p[2 * i] + (h - p[2 * i + 1]) * (p[2 * i + 2] - p[2 * i]) / (p[2 * i + 3] - p[2 * i + 1]);
    }
  {
    const PetscReal *a = p + 2 * (n - 2);
    return a[2] + (h - a[3]) * (a[2] - a[0]) / (a[3] - a[1]);
  }
}

/* Unit normal of segment i (pointing down and out of the indenter), in (r, z); i = -1 is segment 0's mirror
   image across the axis. */
static void SegmentNormal(const PetscReal *p, PetscInt i, PetscReal n[2])
{
  const PetscInt  k  = i < 0 ? 0 : i;
  const PetscReal dr = p[2 * k + 2] - p[2 * k], dh = p[2 * k + 3] - p[2 * k + 1], L = PetscSqrtReal(dr * dr + dh * dh);
  n[0] = (i < 0 ? -dh : dh) / L;
  n[1] = -dr / L;
}

/* Signed distance from y (relative to the lowest point) to the table's surface of revolution, in the
   half-plane (rho, z) through y and the axis: to the nearest point q of the polyline or of its continuation.
   The normal is the segments' turned smoothly across each corner: at a corner the mean of its two segments'
   normals, the segment's own from half the shorter segment away (from `rounding` away at the tip, as a sharp
   cone's is rounded). A polyline's own normal would jump at every corner, and Newton would stall on the
   nodes sliding across them. */
static void ProfileCore(const IndIndenter *ind, const PetscReal y[3], PetscReal *d, PetscReal n[3])
{
  const PetscReal *p = ind->profile;
  const PetscInt   ns = ind->nprofile - 1;
  const PetscReal  rho = PetscSqrtReal(y[0] * y[0] + y[1] * y[1]);
  const PetscReal  er[2] = {rho > 0 ? y[0] / rho : 1.0, rho > 0 ? y[1] / rho : 0.0};
  PetscReal        best = PETSC_MAX_REAL, tq = 0, g[2], m[2], w[2], L[3];
  PetscInt         iq = 0;

  for (PetscInt i = 0; i < ns; ++i) {
    const PetscReal dr = p[2 * i + 2] - p[2 * i], dh = p[2 * i + 3] - p[2 * i + 1], L2 = dr * dr + dh * dh;
    PetscReal       t = ((rho - p[2 * i]) * dr + (y[2] - p[2 * i + 1]) * dh) / L2, d2;
    t = PetscMax(t, 0.0);
    if (i < ns - 1) t = PetscMin(t, 1.0); /* the last segment goes on */
    d2 = PetscSqr(rho - p[2 * i] - t * dr) + PetscSqr(y[2] - p[2 * i + 1] - t * dh);
    if (d2 < best) best = d2, iq = i, tq = t;
  }
  *d = PetscSqrtReal(best);
  if (y[2] > ProfileHeight(ind, rho)) *d = -*d;
  /* the smoothed normal at q: blend with the neighbour's over w from each corner */
  for (int k = 0; k < 3; ++k) {
    const PetscInt j = iq - 1 + k;
    L[k] = j < 0 || j >= ns ? PETSC_MAX_REAL
                            : PetscSqrtReal(PetscSqr(p[2 * j + 2] - p[2 * j]) + PetscSqr(p[2 * j + 3] - p[2 * j + 1]));
  }
  L[0] = iq == 0 ? L[1] : L[0];
  w[0] = iq == 0 ? PetscMin(0.5 * L[1], ind->rounding) : 0.5 * PetscMin(L[0], L[1]);
  w[1] = iq == ns - 1 ? 0.0 : 0.5 * PetscMin(L[1], L[2]);
  SegmentNormal(p, iq, g);
  {
    const PetscReal s = tq * L[1]; /* distance along the segment from its first corner */
    if (w[0] > 0 && s < w[0]) {
      const PetscReal f = 0.5 * (1 - s / w[0]);
      SegmentNormal(p, iq - 1, m);
      g[0] += f * (m[0] - g[0]), g[1] += f * (m[1] - g[1]);
    } else if (w[1] > 0 && L[1] - s < w[1]) {
      const PetscReal f = 0.5 * (1 - (L[1] - s) / w[1]);
      SegmentNormal(p, iq + 1, m);
      g[0] += f * (m[0] - g[0]), g[1] += f * (m[1] - g[1]);
    }
  }
  {
    const PetscReal gn = PetscSqrtReal(g[0] * g[0] + g[1] * g[1]);
    n[0] = g[0] / gn * er[0];
    n[1] = g[0] / gn * er[1];
    n[2] = g[1] / gn;
  }
}

void IndIndenterGap(const IndIndenter *ind, const PetscReal x[3], PetscReal *gap, PetscReal n[3])
{
  const PetscReal lowest = ind->surface - ind->depth;
  /* A sharp shape's contact sees it rounded by `rounding` (see the header) */
  const PetscReal radius = ind->radius > 0 ? ind->radius : ind->rounding;
  PetscReal       y[3], d;

  if (ind->type == IND_INDENTER_FLAT || ind->type == IND_INDENTER_TABLE) {
    y[0] = x[0] - ind->axis[0];
    y[1] = x[1] - ind->axis[1];
    y[2] = x[2] - lowest;
    if (ind->type == IND_INDENTER_FLAT) FlatPunch(ind, y, gap, n);
    else ProfileCore(ind, y, gap, n);
    return;
  }
  /* Relative to the core's apex, tip_radius above the lowest point. */
  y[0] = x[0] - ind->axis[0];
  y[1] = x[1] - ind->axis[1];
  y[2] = x[2] - (lowest + radius);
  switch (ind->type) {
  case IND_INDENTER_SPHERE:
    d = PetscSqrtReal(Dot(y, y));
    if (d > 0)
      for (int k = 0; k < 3; ++k) n[k] = y[k] / d;
    else n[0] = n[1] = 0, n[2] = -1;
    break;
  case IND_INDENTER_CONE:
    ConeCore(ind->angle, y, &d, n);
    break;
  default:
    PyramidCore(ind, y, &d, n);
  }
  *gap = d - radius;
}

void IndIndenterTangents(const PetscReal n[3], PetscReal t1[3], PetscReal t2[3])
{
  /* t1 along the projection of x on the tangent plane, or of z when n is nearly along x. */
  const PetscReal e[3] = {PetscAbsReal(n[0]) < 0.9 ? 1.0 : 0.0, 0.0, PetscAbsReal(n[0]) < 0.9 ? 0.0 : 1.0};
  const PetscReal en   = Dot(e, n);
  for (int k = 0; k < 3; ++k) t1[k] = e[k] - en * n[k];
  Normalize(t1);
  t2[0] = n[1] * t1[2] - n[2] * t1[1];
  t2[1] = n[2] * t1[0] - n[0] * t1[2];
  t2[2] = n[0] * t1[1] - n[1] * t1[0];
}

/* Distance from the axis to the section's boundary along azimuth phi at height z (absolute). */
static PetscReal SectionRadius(const IndIndenter *ind, PetscReal phi, PetscReal z)
{
  PetscReal lo = 0, hi = ind->radius + 1.0, g, n[3], x[3];

  x[2] = z;
  for (int it = 0; it < 200; ++it) { /* grow until outside */
    x[0] = ind->axis[0] + hi * PetscCosReal(phi);
    x[1] = ind->axis[1] + hi * PetscSinReal(phi);
    IndIndenterGap(ind, x, &g, n);
    if (g > 0) break;
    lo = hi;
    hi *= 2;
  }
  for (int it = 0; it < 200 && hi - lo > 1e-15 * hi; ++it) {
    const PetscReal mid = 0.5 * (lo + hi);
    x[0]                = ind->axis[0] + mid * PetscCosReal(phi);
    x[1]                = ind->axis[1] + mid * PetscSinReal(phi);
    IndIndenterGap(ind, x, &g, n);
    if (g > 0) hi = mid;
    else lo = mid;
  }
  return 0.5 * (lo + hi);
}

PetscReal IndIndenterArea(const IndIndenter *ind, PetscReal hc)
{
  const PetscReal R = ind->radius, a = ind->angle;

  /* a loaded punch touches with its whole face: its contact depth (0 by Oliver and Pharr's epsilon = 1, or a
     round-off below) does not change its area */
  if (ind->type == IND_INDENTER_FLAT) return PETSC_PI * R * R;
  if (hc <= 0) return 0.0;
  switch (ind->type) {
  case IND_INDENTER_TABLE:
    return PETSC_PI * PetscSqr(ProfileRadius(ind, hc));
  case IND_INDENTER_SPHERE:
    return hc >= R ? PETSC_PI * R * R : PETSC_PI * (2 * R * hc - hc * hc);
  case IND_INDENTER_CONE: {
    const PetscReal ht = R * (1 - PetscSinReal(a)); /* where the tip sphere meets the mantle */
    if (hc <= ht) return PETSC_PI * (2 * R * hc - hc * hc);
    return PETSC_PI * PetscSqr(R * PetscCosReal(a) + (hc - ht) * PetscTanReal(a));
  }
  default:
    break;
  }
  if (R == 0) return ind->nfaces * PetscTanReal(PETSC_PI / ind->nfaces) * PetscSqr(hc * PetscTanReal(a));
  {
    /* A = 1/2 int r(phi)^2 dphi over the convex section, by 5-point Gauss-Legendre on sub-intervals of
       the 2 nfaces sectors between face and edge azimuths, where r(phi) is smooth piecewise. */
    const PetscReal xg[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831, 0.9061798459386640};
    const PetscReal wg[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665,
      0.2369268850561891};
    const PetscInt  nsub = 64, nsec = 2 * ind->nfaces;
    const PetscReal z = ind->surface - ind->depth + hc, width = 2 * PETSC_PI / nsec;
    PetscReal       A = 0;
    for (PetscInt s = 0; s < nsec; ++s)
      for (PetscInt k = 0; k < nsub; ++k) {
        const PetscReal p0 = ind->rotation + s * width + k * width / nsub, hw = 0.5 * width / nsub;
        for (int q = 0; q < 5; ++q) A += hw * wg[q] * 0.5 * PetscSqr(SectionRadius(ind, p0 + hw * (1 + xg[q]), z));
      }
    return A;
  }
}

/* A pyramid's edge advances along its faces and corners at different rates; this follows their mean, the
   edge of the cone of equal cross-section areas with the same tip radius (its areas are those of a rounded
   pyramid to within 15%, its radii to within 8%: close enough to size a load step). */
static PetscReal EdgeAngle(const IndIndenter *ind)
{
  if (ind->type == IND_INDENTER_CONE || ind->nfaces == 0) return ind->angle;
  return PetscAtanReal(PetscTanReal(ind->angle) * PetscSqrtReal(ind->nfaces * PetscTanReal(PETSC_PI / ind->nfaces) /
                                                                 PETSC_PI));
}

PetscReal IndIndenterEdgeRadius(const IndIndenter *ind, PetscReal h)
{
  const PetscReal R = ind->radius;

  if (ind->type == IND_INDENTER_FLAT) return R;
  if (h <= 0) return 0.0;
  if (ind->type == IND_INDENTER_TABLE) return ProfileRadius(ind, h);
  if (ind->type == IND_INDENTER_SPHERE) return h >= R ? R : PetscSqrtReal(2 * R * h - h * h);
  {
    const PetscReal a = EdgeAngle(ind), ht = R * (1 - PetscSinReal(a)); /* where the tip sphere meets the mantle */
    if (h <= ht) return PetscSqrtReal(2 * R * h - h * h);
    return R * PetscCosReal(a) + (h - ht) * PetscTanReal(a);
  }
}

PetscReal IndIndenterEdgeDepth(const IndIndenter *ind, PetscReal r)
{
  const PetscReal R = ind->radius;

  if (r <= 0) return 0.0;
  if (ind->type == IND_INDENTER_FLAT) return PETSC_MAX_REAL;
  if (ind->type == IND_INDENTER_TABLE) return ProfileHeight(ind, r);
  if (ind->type == IND_INDENTER_SPHERE) return r >= R ? PETSC_MAX_REAL : R - PetscSqrtReal(R * R - r * r);
  {
    const PetscReal a = EdgeAngle(ind), rt = R * PetscCosReal(a);
    if (r <= rt) return R - PetscSqrtReal(R * R - r * r);
    return R * (1 - PetscSinReal(a)) + (r - rt) / PetscTanReal(a);
  }
}
