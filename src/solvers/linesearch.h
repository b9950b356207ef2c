#pragma once
/* The line search of depth control's Newton (src/solvers/linesearch.c): a step to near the critical point of the
   energy along the Newton direction, the full step when that is near it already.

   Elasto-plasticity with frictionless contact is the gradient of an incremental energy, and so very nearly with
   small friction; g(l) = F(X - l Y).Y is that energy's slope along the step, negated. Backtracking on |F|^2
   accepted full steps that overshot the energy's minimum along the line while points yielded and contact nodes
   entered: on the README's case its early loading steps took 10 to 12 Newton iterations, the elastic film's 5 to 6.

   The full step is taken when |g(1)| <= 0.1 g(0): then a quadratic model of the energy along the line says it
   gains 99% of the decrease at the critical point, and its residual, which is evaluated anyway, is the next
   iterate's. Otherwise secant (regula falsi) steps on g look for the critical point until |g| <= 0.9 g(0), the
   curvature condition of Wolfe's for Newton's method, which guards against the secant's overshoot where g
   flattens; after 10 of them the last stands. A step whose residual does not exist (an inverted cell, a failed
   return map) is halved first; only when 20 halvings find none does the search fail, and the load step is cut.

   A direction that does not descend the energy (g(0) <= 0: friction's unsymmetric rows, or a contact state the
   linear solve saw differently) tells nothing along the energy, but the Newton direction descends |F| for any
   linear solve with rtol < 1: the step is halved until |F| falls by Armijo's condition. Taking it whole, as before,
   raised the residual sixfold in a load step of the paper's case at h_tip 3, whose Newton then wandered through
   2,421 Krylov iterations to a cut; where |F| rises all along the direction the search fails at once. */
#include <petscsnes.h>
#include "ind_common.h"

/* The next trial step from two points on the line, pure: a < b with slopes ga > 0 and gb. With gb < 0 the
   critical point lies between them: the secant's root (regula falsi). With 0 < gb < ga it lies beyond b: the
   secant's root, at most b + (b - a) (no farther than the points reach). Anything else (gb >= ga: no positive
   curvature; or not a number): b. */
PetscReal IndSecantStep(PetscReal a, PetscReal ga, PetscReal b, PetscReal gb);

/* Makes ls that line search (a SNESLINESEARCHSHELL; -snes_linesearch_type bt and the others still apply). */
PetscErrorCode IndLineSearchSetCriticalPoint(SNESLineSearch ls);
