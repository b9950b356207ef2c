#include "bordered.h"

struct _p_IndBordered {
  IndContact contact;
  PetscReal  depth_max;  /* nm */
  PetscReal  tol;        /* accepted |c|, nN of the modelled part */
  PetscReal  target;     /* P*, nN of the modelled part */
  PetscReal  c;          /* P(U) - P* at the last residual, nN of the modelled part */
  PetscBool  limited;    /* the last step put the indenter at depth_max with c < 0 */
  PetscInt   linear;     /* Krylov iterations of the bordering solves since the last reset */
  Vec        e, p, Fd, b;
};

PetscReal IndBorderedDepthIncrement(PetscReal c, PetscReal pY, PetscReal pb, PetscReal gap, PetscReal depth,
                                    PetscReal depth_max)
{
  PetscReal dd = 0;

  if (pb < 0) dd = (c - pY) / pb;
  /* The gap is measured from the nodes' current positions, so touching takes the gap; a millionth of
     the depth range more makes the nearest node active, and its stiffness takes over. */
  else if (c < 0) dd = PetscMax(gap, 0.0) + 1e-6 * depth_max;
  return PetscMin(PetscMax(depth + dd, 0.0), depth_max) - depth;
}

PetscErrorCode IndBorderedCreate(IndContact contact, Vec U, PetscReal depth_max, PetscReal load_tol, IndBordered *out)
{
  IndBordered b;

  PetscFunctionBeginUser;
  PetscCheck(contact && IndContactReactionsFromResidual(contact), PetscObjectComm((PetscObject)U), PETSC_ERR_ARG_INCOMP,
             "-load_force needs -contact_uzawa newton: load control makes the depth an unknown of the Newton "
             "iteration, and the fixed point freezes the reactions within it");
  PetscCall(PetscNew(&b));
  b->contact   = contact;
  b->depth_max = depth_max;
  b->tol       = load_tol / IndContactGetSymmetry(contact);
  PetscCall(VecDuplicate(U, &b->e));
  PetscCall(VecDuplicate(U, &b->p));
  PetscCall(VecDuplicate(U, &b->Fd));
  PetscCall(VecDuplicate(U, &b->b));
  PetscCall(IndContactLoadRows(contact, b->e));
  *out = b;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndBorderedDestroy(IndBordered *b)
{
  PetscFunctionBeginUser;
  if (!*b) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(VecDestroy(&(*b)->e));
  PetscCall(VecDestroy(&(*b)->p));
  PetscCall(VecDestroy(&(*b)->Fd));
  PetscCall(VecDestroy(&(*b)->b));
  PetscCall(PetscFree(*b));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndBorderedSetTarget(IndBordered b, PetscReal load)
{
  PetscFunctionBeginUser;
  b->target  = load / IndContactGetSymmetry(b->contact);
  b->limited = PETSC_FALSE;
  b->linear  = 0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndBorderedResidual(IndBordered b)
{
  PetscReal load;

  PetscFunctionBeginUser;
  PetscCall(IndContactModelLoad(b->contact, &load));
  b->c = load - b->target;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscReal IndBorderedLoadResidual(IndBordered b)
{
  return b->c;
}

PetscReal IndBorderedLoad(IndBordered b)
{
  return (b->target + b->c) * IndContactGetSymmetry(b->contact);
}

PetscBool IndBorderedLoadMet(IndBordered b)
{
  return PetscAbsReal(b->c) <= b->tol ? PETSC_TRUE : PETSC_FALSE;
}

PetscBool IndBorderedOutOfReach(IndBordered b)
{
  return b->limited;
}

PetscInt IndBorderedLinearIterations(IndBordered b)
{
  return b->linear;
}

PetscErrorCode IndBorderedBodyJacobian(IndBordered b, Mat K)
{
  PetscFunctionBeginUser;
  /* P = -e^T L(U), L the residual without contact: p = -K^T e */
  PetscCall(MatMultTranspose(K, b->e, b->p));
  PetscCall(VecScale(b->p, -1.0));
  PetscCall(VecZeroEntries(b->Fd));
  PetscFunctionReturn(PETSC_SUCCESS);
}

Vec IndBorderedDepthDerivative(IndBordered b)
{
  return b->Fd;
}

Vec IndBorderedLoadDerivative(IndBordered b)
{
  return b->p;
}

/* The line search of SNESLINESEARCHSHELL: extends SNES's step Y by the depth's (bordering), then
   backtracks on |F|^2 + c^2 with the depth moving along with U. */
PetscErrorCode IndBorderedLineSearch(SNESLineSearch ls, void *ctx)
{
  IndBordered        b = (IndBordered)ctx;
  SNES               snes;
  KSP                ksp;
  Vec                X, F, Y, W, G;
  KSPConvergedReason kr;
  PetscReal          xnorm, fnorm, ynorm, pY, pb, gap = 0, dd, d0, c0, phi0, lambda = 1;
  const PetscInt     halvings = 20;
  PetscInt           its;
  PetscBool          accepted = PETSC_FALSE, domain = PETSC_FALSE;

  PetscFunctionBeginUser;
  PetscCall(SNESLineSearchGetSNES(ls, &snes));
  PetscCall(SNESLineSearchGetVecs(ls, &X, &F, &Y, &W, &G));
  PetscCall(SNESLineSearchGetNorms(ls, &xnorm, &fnorm, &ynorm));
  PetscCall(SNESGetKSP(snes, &ksp));
  PetscCall(KSPSolve(ksp, b->Fd, b->b));
  PetscCall(KSPGetIterationNumber(ksp, &its));
  PetscCall(KSPGetConvergedReason(ksp, &kr));
  b->linear += its;
  if (kr < 0) {
    PetscCall(SNESLineSearchSetReason(ls, SNES_LINESEARCH_FAILED_REDUCT));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(VecDot(b->p, Y, &pY));
  PetscCall(VecDot(b->p, b->b, &pb));
  c0 = b->c;
  d0 = IndContactGetDepth(b->contact);
  if (!(pb < 0) && c0 < 0) PetscCall(IndContactSmallestGap(b->contact, X, &gap));
  dd = IndBorderedDepthIncrement(c0, pY, pb, gap, d0, b->depth_max);
  PetscCall(VecAXPY(Y, dd, b->b));
  phi0 = fnorm * fnorm + c0 * c0;
  /* Backtracking with Armijo's test on the merit, whose slope along an exact Newton step is -2 phi0 */
  for (PetscInt k = 0; k < halvings; ++k) {
    PetscReal phi;
    lambda = PetscPowReal(0.5, (PetscReal)k);
    PetscCall(VecWAXPY(W, -lambda, Y, X));
    PetscCall(IndContactSetDepth(b->contact, d0 + lambda * dd));
    PetscCall(SNESComputeFunction(snes, W, G));
    PetscCall(SNESGetFunctionDomainError(snes, &domain));
    if (domain) continue;
    PetscCall(VecNorm(G, NORM_2, &fnorm));
    phi      = fnorm * fnorm + b->c * b->c;
    accepted = phi <= (1 - 2e-4 * lambda) * phi0 ? PETSC_TRUE : PETSC_FALSE;
    if (accepted) break;
  }
  /* Nothing better in all halvings: the last trial stands, and SNES reports the failed search. */
  PetscCall(VecCopy(W, X));
  PetscCall(VecCopy(G, F));
  PetscCall(VecNorm(X, NORM_2, &xnorm));
  PetscCall(VecNorm(Y, NORM_2, &ynorm));
  ynorm = lambda * PetscSqrtReal(ynorm * ynorm + dd * dd);
  PetscCall(SNESLineSearchSetNorms(ls, xnorm, fnorm, ynorm));
  PetscCall(SNESLineSearchSetLambda(ls, lambda));
  b->limited = d0 + lambda * dd >= b->depth_max && b->c < 0 ? PETSC_TRUE : PETSC_FALSE;
  if (domain) PetscCall(SNESLineSearchSetReason(ls, SNES_LINESEARCH_FAILED_DOMAIN));
  else if (!accepted) PetscCall(SNESLineSearchSetReason(ls, SNES_LINESEARCH_FAILED_REDUCT));
  else PetscCall(SNESLineSearchSetReason(ls, SNES_LINESEARCH_SUCCEEDED));
  PetscFunctionReturn(PETSC_SUCCESS);
}
