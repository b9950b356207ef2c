#include "ind_forcesearch.h"

void IndForceSearchStart(IndForceSearch *s, PetscReal target, PetscReal tol, PetscReal dmax, PetscReal d0, PetscReal p0)
{
  s->target = target;
  s->tol    = tol;
  s->dmax   = dmax;
  s->its    = 0;
  s->side   = 0;
  s->d[0] = s->d[1] = d0;
  s->p[0] = s->p[1] = p0;
  s->lo = 0, s->plo = -1;
  s->hi = dmax, s->phi = -1;
  s->first = -1;
  if (p0 < 0) s->first = d0;
  else if (p0 <= target) s->lo = d0, s->plo = p0;
  else s->hi = d0, s->phi = p0;
}

PetscReal IndForceSearchNext(const IndForceSearch *s, PetscReal slope, PetscReal guess)
{
  const PetscReal width = s->hi - s->lo;
  PetscReal       d;

  if (s->its == 0 && s->first >= 0) return s->first;

  if (s->plo >= 0 && s->phi >= 0) {
    /* both ends known: the secant, kept off the ends (else bisection) */
    d = s->lo + (s->target - s->plo) / (s->phi - s->plo) * width;
    if (!(d > s->lo && d < s->hi)) d = s->lo + 0.5 * width;
    return d;
  }
  /* one end missing: the secant through the last two loads evaluated once there are two */
  if (s->its > 0 && s->d[1] != s->d[0]) {
    const PetscReal secant = (s->p[1] - s->p[0]) / (s->d[1] - s->d[0]);
    if (secant > 0) slope = secant;
  }
  if (s->plo >= 0) { /* loading: no depth known yet with a larger load */
    d = slope > 0 ? s->lo + (s->target - s->plo) / slope : guess;
    if (!(d > s->lo)) d = s->lo + 0.5 * width;
    return PetscMin(d, s->dmax);
  }
  /* unloading to zero: any depth where the indenter has left will do, and near that depth the load
     vanishes like a power > 1 of the distance, where secants crawl; depth 0 has left the imprint */
  if (s->target <= s->tol) return 0.0;
  d = slope > 0 ? s->hi - (s->phi - s->target) / slope : guess; /* unloading: none with a smaller load */
  if (!(d < s->hi)) d = 0.5 * s->hi;
  return PetscMax(d, 0.0);
}

int IndForceSearchUpdate(IndForceSearch *s, PetscReal d, PetscReal p)
{
  s->its++;
  s->d[0] = s->d[1], s->p[0] = s->p[1];
  s->d[1] = d, s->p[1] = p;
  if (PetscAbsReal(p - s->target) <= s->tol) return 1;
  if (p < s->target) {
    if (d >= s->dmax) return -1;
    s->lo = d, s->plo = p;
    /* Illinois: the other end, fixed twice in a row, counts half, so regula falsi does not stall */
    if (s->side == -1 && s->phi >= 0) s->phi = s->target + 0.5 * (s->phi - s->target);
    s->side = -1;
  } else {
    s->hi = d, s->phi = p;
    if (s->side == 1 && s->plo >= 0) s->plo = s->target - 0.5 * (s->target - s->plo);
    s->side = 1;
  }
  return 0;
}
