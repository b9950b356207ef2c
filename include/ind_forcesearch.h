#pragma once
/* Load control: the indenter depth at which the computed load equals the prescribed one. The load is a
   nondecreasing function of the depth, so the search keeps a bracket [lo, hi] with P(lo) <= P* <= P(hi)
   and takes the secant of the bracket (regula falsi, Illinois variant, so that neither end sticks),
   which converges by construction once both ends are known; until then it extrapolates along the secant
   of its last two loads, or at first the last step's stiffness dP/dh (or takes the caller's guess),
   clamped to [0, the largest depth allowed].
   Pure: no PETSc objects. */
#include "ind_common.h"

typedef struct {
  PetscReal target, tol; /* P* and the accepted |P - P*| (uN) */
  PetscReal dmax;        /* the largest depth allowed (nm) */
  PetscReal lo, plo;     /* deepest depth known with P < P* (plo), or the lower limit 0 with plo = -1 */
  PetscReal hi, phi;     /* shallowest depth known with P > P*, or dmax with phi = -1 when none */
  int       side;        /* which end moved last (-1 lo, +1 hi), for the Illinois halving */
  PetscInt  its;         /* loads evaluated */
  PetscReal d[2], p[2];  /* the last two states evaluated (the start counts), newest last */
  PetscReal first;       /* the depth to evaluate first when the start's load is unknown (-1: none) */
} IndForceSearch;

/* A search for target from the accepted state (depth d0, load p0). p0 < 0: the load at d0 is not known
   (the step changes more than the depth: a scratch slides), and d0 is evaluated first. */
void      IndForceSearchStart(IndForceSearch *s, PetscReal target, PetscReal tol, PetscReal dmax, PetscReal d0,
                              PetscReal p0);
/* The next depth to evaluate; slope is the last accepted step's dP/dh (<= 0: unknown, then guess is
   tried while one end of the bracket is missing). */
PetscReal IndForceSearchNext(const IndForceSearch *s, PetscReal slope, PetscReal guess);
/* Records the load p at depth d; returns 1 when |p - P*| <= tol, -1 when P* is out of reach (p < P* at
   the largest depth allowed), 0 otherwise. */
int       IndForceSearchUpdate(IndForceSearch *s, PetscReal d, PetscReal p);
