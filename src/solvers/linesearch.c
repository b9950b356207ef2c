#include "linesearch.h"

/* |g| <= 0.1 g(0) at the full step: it gains 99% of the critical point's decrease under a quadratic model */
static const PetscReal full_step_slope = 0.1;
/* Wolfe's curvature condition, with the constant usual for Newton's method */
static const PetscReal curvature = 0.9;
static const PetscInt  halvings = 20, secants = 10;
/* Armijo's sufficient decrease of |F| where the energy gives no direction, with its usual constant */
static const PetscReal armijo = 1e-4;

PetscReal IndSecantStep(PetscReal a, PetscReal ga, PetscReal b, PetscReal gb)
{
  if (!(ga > 0) || !(gb < ga)) return b;
  return PetscMin(b + (b - a) * gb / (ga - gb), 2 * b - a);
}

/* The residual at W = X - lambda Y into G; whether it exists (no inverted cell, no failed return map). */
static PetscErrorCode TryStep(SNES snes, Vec X, Vec Y, PetscReal lambda, Vec W, Vec G, PetscBool *exists)
{
  PetscBool domain;

  PetscFunctionBeginUser;
  PetscCall(VecWAXPY(W, -lambda, Y, X));
  PetscCall(SNESComputeFunction(snes, W, G));
  PetscCall(SNESGetFunctionDomainError(snes, &domain));
  *exists = domain ? PETSC_FALSE : PETSC_TRUE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode CriticalPointApply(SNESLineSearch ls, void *ctx)
{
  SNES        snes;
  Vec         X, F, Y, W, G;
  PetscViewer monitor;
  PetscReal   g0, gf = 0, lambda_f = 1, lambda, held;
  PetscInt    trials = 0;
  PetscBool   exists = PETSC_FALSE, accepted = PETSC_TRUE, changed_y, changed_w;

  PetscFunctionBeginUser;
  (void)ctx;
  PetscCall(SNESLineSearchGetSNES(ls, &snes));
  PetscCall(SNESLineSearchGetVecs(ls, &X, &F, &Y, &W, &G));
  PetscCall(SNESLineSearchGetDefaultMonitor(ls, &monitor));
  PetscCall(SNESLineSearchPreCheck(ls, X, Y, &changed_y));
  PetscCall(VecDot(F, Y, &g0));
  for (PetscInt k = 0; k < halvings && !exists; ++k) {
    lambda_f = PetscPowReal(0.5, (PetscReal)k);
    PetscCall(TryStep(snes, X, Y, lambda_f, W, G, &exists));
  }
  if (!exists) { /* SNES sees the infinite residual and reports the domain error: the load step is cut */
    PetscCall(VecCopy(W, X));
    PetscCall(VecCopy(G, F));
    PetscCall(SNESLineSearchComputeNorms(ls));
    PetscCall(SNESLineSearchSetLambda(ls, lambda_f));
    PetscCall(SNESLineSearchSetReason(ls, SNES_LINESEARCH_FAILED_DOMAIN));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(VecDot(G, Y, &gf));
  lambda = held = lambda_f;
  /* Not a descent direction (friction's unsymmetric rows can make it one), or near the critical point already */
  if (g0 > 0 && !(PetscAbsReal(gf) <= full_step_slope * g0)) {
    PetscReal a = 0, ga = g0, b = lambda_f, gb = gf;
    accepted = PETSC_FALSE;
    for (trials = 0; trials < secants && !accepted; ++trials) {
      const PetscReal trial = IndSecantStep(a, ga, b, gb);
      PetscReal       g;
      if (trial == b) break; /* no critical point ahead: b stands */
      PetscCall(TryStep(snes, X, Y, trial, W, G, &exists));
      if (!exists) break;
      PetscCall(VecDot(G, Y, &g));
      held = trial;
      accepted = PetscAbsReal(g) <= curvature * g0 ? PETSC_TRUE : PETSC_FALSE;
      if (trial > b) a = b, ga = gb, b = trial, gb = g;
      else if (g > 0) a = trial, ga = g;
      else b = trial, gb = g;
    }
    /* Short of the curvature condition: after every secant step the last one, closer to the critical point than
       the start; otherwise b, where the secant has no root ahead or its point does not exist */
    lambda = accepted || trials == secants ? held : b;
  } else if (!(g0 > 0)) {
    /* Not a descent direction of the energy (friction's unsymmetric rows can make one): it says nothing along
       the step, but |F| does, which the Newton direction descends for any linear solve with rtol < 1. Halve the
       step until |F| falls (Armijo's condition); a direction along which it never falls is of no use, and the
       search fails at once rather than leave Newton to wander from a worse point. */
    PetscReal f0, f;
    PetscCall(VecNorm(F, NORM_2, &f0));
    PetscCall(VecNorm(G, NORM_2, &f));
    accepted = f <= (1 - armijo * lambda) * f0 ? PETSC_TRUE : PETSC_FALSE;
    for (PetscInt k = 0; k < halvings && !accepted; ++k) {
      lambda *= 0.5;
      PetscCall(TryStep(snes, X, Y, lambda, W, G, &exists));
      if (!exists) continue;
      PetscCall(VecNorm(G, NORM_2, &f));
      accepted = f <= (1 - armijo * lambda) * f0 ? PETSC_TRUE : PETSC_FALSE;
    }
    held = lambda;
    if (!accepted) {
      if (monitor) PetscCall(PetscViewerASCIIPrintf(monitor, "    Line search: slope %g at 0: |F| %g rises along "
                                                    "the step\n", (double)g0, (double)f0));
      PetscCall(SNESLineSearchSetReason(ls, SNES_LINESEARCH_FAILED_REDUCT));
      PetscFunctionReturn(PETSC_SUCCESS);
    }
  }
  if (monitor) {
    PetscInt tab;
    PetscCall(PetscObjectGetTabLevel((PetscObject)ls, &tab));
    PetscCall(PetscViewerASCIIAddTab(monitor, tab));
    PetscCall(PetscViewerASCIIPrintf(monitor, "    Line search: slope %g at 0, %g at %g; %" PetscInt_FMT
                                     " secant steps: %g%s\n", (double)g0, (double)gf, (double)lambda_f, trials,
                                     (double)lambda, accepted ? "" : " (short of the curvature condition)"));
    PetscCall(PetscViewerASCIISubtractTab(monitor, tab));
  }
  if (lambda != held) PetscCall(TryStep(snes, X, Y, lambda, W, G, &exists));
  PetscCall(SNESLineSearchPostCheck(ls, X, Y, W, &changed_y, &changed_w));
  if (changed_y) PetscCall(VecWAXPY(W, -lambda, Y, X));
  if (changed_y || changed_w) PetscCall(SNESComputeFunction(snes, W, G));
  PetscCall(VecCopy(W, X));
  PetscCall(VecCopy(G, F));
  PetscCall(SNESLineSearchComputeNorms(ls));
  PetscCall(SNESLineSearchSetLambda(ls, lambda));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndLineSearchSetCriticalPoint(SNESLineSearch ls)
{
  PetscFunctionBeginUser;
  PetscCall(SNESLineSearchSetType(ls, SNESLINESEARCHSHELL));
  PetscCall(SNESLineSearchShellSetUserFunc(ls, CriticalPointApply, NULL));
  PetscFunctionReturn(PETSC_SUCCESS);
}
