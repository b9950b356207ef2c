static const char help[] = "Depth control's line search (src/solvers/linesearch.c): the step's decisions against the\n"
                           "quadratic model, and Newton with it on small gradient systems, with a domain the\n"
                           "residual is refused outside of.\n";

#include "linesearch.h"
#include "unit_report.h"

static PetscMPIInt rank;

/* Report on rank 0; every rank counts the failure (all compute the same figures). */
static void Check(const char *what, PetscReal worst, PetscReal tol)
{
  if (!rank) Report(what, worst, tol);
  else if (!(worst <= tol)) failures++;
}

/* |IndSecantStep - want| */
static PetscReal StepError(PetscReal a, PetscReal ga, PetscReal b, PetscReal gb, PetscReal want)
{
  return PetscAbsReal(IndSecantStep(a, ga, b, gb) - want);
}

typedef struct {
  PetscReal shift;  /* F_i = atan(x_i - shift): the energy is convex, and full Newton steps diverge beyond 1.39 */
  PetscReal domain; /* the residual exists for x_i > domain only */
  PetscReal linear; /* not 0: F_i = linear (x_i - shift) instead, a quadratic energy (concave for linear < 0) */
  PetscReal flip;   /* -1: the Jacobian given to Newton has the wrong sign, its direction raises |F| */
} Problem;

static PetscErrorCode Residual(SNES snes, Vec X, Vec F, void *ctx)
{
  Problem           *p = (Problem *)ctx;
  const PetscScalar *x;
  PetscScalar       *f;
  PetscInt           n, outside = 0;

  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(X, &n));
  PetscCall(VecGetArrayRead(X, &x));
  PetscCall(VecGetArray(F, &f));
  for (PetscInt i = 0; i < n; ++i) {
    f[i] = p->linear != 0 ? p->linear * (x[i] - p->shift) : PetscAtanReal(x[i] - p->shift);
    if (x[i] <= p->domain) outside++;
  }
  PetscCall(VecRestoreArrayRead(X, &x));
  PetscCall(VecRestoreArray(F, &f));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &outside, 1, MPIU_INT, MPI_SUM, PetscObjectComm((PetscObject)X)));
  if (outside) PetscCall(SNESSetFunctionDomainError(snes));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Jacobian(SNES snes, Vec X, Mat J, Mat P, void *ctx)
{
  Problem           *p = (Problem *)ctx;
  const PetscScalar *x;
  PetscInt           lo, hi;

  PetscFunctionBeginUser;
  (void)snes;
  PetscCall(VecGetOwnershipRange(X, &lo, &hi));
  PetscCall(VecGetArrayRead(X, &x));
  for (PetscInt i = lo; i < hi; ++i) {
    const PetscReal d = x[i - lo] - p->shift, v = p->linear != 0 ? p->linear : 1 / (1 + d * d);
    PetscCall(MatSetValue(P, i, i, (p->flip < 0 ? -1 : 1) * v, INSERT_VALUES));
  }
  PetscCall(VecRestoreArrayRead(X, &x));
  PetscCall(MatAssemblyBegin(P, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(P, MAT_FINAL_ASSEMBLY));
  if (J != P) {
    PetscCall(MatAssemblyBegin(J, MAT_FINAL_ASSEMBLY));
    PetscCall(MatAssemblyEnd(J, MAT_FINAL_ASSEMBLY));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Newton with the line search from x_i = start (4 unknowns a rank); its error, iterations and residuals */
static PetscErrorCode Solve(Problem *p, PetscReal start, PetscReal *error, PetscInt *its, PetscInt *evals,
                            SNESConvergedReason *reason)
{
  SNES           snes;
  SNESLineSearch ls;
  KSP            ksp;
  PC             pc;
  Vec            X, R;
  Mat            J;

  PetscFunctionBeginUser;
  PetscCall(VecCreateMPI(PETSC_COMM_WORLD, 4, PETSC_DETERMINE, &X));
  PetscCall(VecDuplicate(X, &R));
  PetscCall(MatCreateAIJ(PETSC_COMM_WORLD, 4, 4, PETSC_DETERMINE, PETSC_DETERMINE, 1, NULL, 0, NULL, &J));
  PetscCall(SNESCreate(PETSC_COMM_WORLD, &snes));
  PetscCall(SNESSetFunction(snes, R, Residual, p));
  PetscCall(SNESSetJacobian(snes, J, J, Jacobian, p));
  PetscCall(SNESGetKSP(snes, &ksp));
  PetscCall(KSPSetType(ksp, KSPPREONLY));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PCSetType(pc, PCJACOBI));
  PetscCall(SNESSetTolerances(snes, 1e-12, 1e-12, 0, 100, 10000));
  PetscCall(SNESGetLineSearch(snes, &ls));
  PetscCall(IndLineSearchSetCriticalPoint(ls));
  PetscCall(VecSet(X, start));
  PetscCall(SNESSolve(snes, NULL, X));
  PetscCall(SNESGetConvergedReason(snes, reason));
  PetscCall(SNESGetIterationNumber(snes, its));
  PetscCall(SNESGetNumberFunctionEvals(snes, evals));
  PetscCall(VecShift(X, -p->shift));
  PetscCall(VecNorm(X, NORM_INFINITY, error));
  PetscCall(SNESDestroy(&snes));
  PetscCall(MatDestroy(&J));
  PetscCall(VecDestroy(&R));
  PetscCall(VecDestroy(&X));
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  PetscCallMPI(MPI_Comm_rank(PETSC_COMM_WORLD, &rank));

  /* the next trial: the root of the slope's secant, inside the points or at most as far beyond them again */
  Check("slopes 1 at 0 and -1 at 1: the root 0.5", StepError(0, 1, 1, -1, 0.5), 1e-15);
  Check("slopes 0.2 at 0.5 and -0.2 at 1: the root 0.75", StepError(0.5, 0.2, 1, -0.2, 0.75), 1e-15);
  Check("slopes 1 at 0 and 0.25 at 1: the root ahead, 4/3", StepError(0, 1, 1, 0.25, 4.0 / 3), 1e-15);
  Check("slopes 1 at 0 and 0.9 at 1: the root at 10, cut to 2", StepError(0, 1, 1, 0.9, 2), 0);
  Check("slopes 1 at 0.5 and 0.9 at 1: cut to 1.5", StepError(0.5, 1, 1, 0.9, 1.5), 0);
  Check("not a descent direction (slope -1 at 0): b", StepError(0, -1, 1, -3, 1), 0);
  Check("no positive curvature (slope 2 at 1 after 1 at 0): b", StepError(0, 1, 1, 2, 1), 0);
  Check("a slope that is not a number: b", StepError(0, 1, 1, NAN, 1), 0);

  {
    Problem             quad = {2.0, -PETSC_MAX_REAL, 5.0, 1}, atan = {0.5, -PETSC_MAX_REAL, 0, 1};
    Problem             fence = {0.5, -2.5, 0, 1}, concave = {2.0, -PETSC_MAX_REAL, -5.0, 1};
    Problem             wrong = {2.0, -PETSC_MAX_REAL, 5.0, -1};
    PetscReal           err;
    PetscInt            its, evals;
    SNESConvergedReason reason;

    /* a quadratic energy: the Newton step is exact, its slope 0 at the full step, taken without a second residual */
    PetscCall(Solve(&quad, -7, &err, &its, &evals, &reason));
    if (!rank) printf("quadratic energy: %d Newton iteration(s), %d residuals\n", (int)its, (int)evals);
    Check("quadratic energy: error after Newton", err, 1e-12);
    Check("quadratic energy: one iteration, two residuals (start and full step)",
          (PetscReal)(PetscAbsInt(its - 1) + PetscAbsInt(evals - 2)), 0);

    /* atan from 3.5 off its root: full Newton steps diverge (beyond 1.39), and so does one secant step (it
       overshoots where the slope flattens); with the curvature condition Newton converges, and its last iterations
       take full steps with one residual each */
    PetscCall(Solve(&atan, 4.0, &err, &its, &evals, &reason));
    if (!rank) printf("atan from 3.5 off: %d Newton iterations, %d residuals, %s\n", (int)its, (int)evals,
                      SNESConvergedReasons[reason]);
    Check("atan: converged", reason > 0 ? 0 : 1, 0);
    Check("atan: error after Newton", err, 1e-12);
    Check("atan: iterations beyond 10", (PetscReal)PetscMax(its - 10, 0), 0);

    /* the same with the residual refused at x <= -2.5 (the full step lands at -9): halved into the domain */
    PetscCall(Solve(&fence, 4.0, &err, &its, &evals, &reason));
    if (!rank) printf("atan, refused below -2.5: %d Newton iterations, %d residuals, %s\n", (int)its, (int)evals,
                      SNESConvergedReasons[reason]);
    Check("atan with a domain: converged", reason > 0 ? 0 : 1, 0);
    Check("atan with a domain: error after Newton", err, 1e-12);

    /* not a descent direction of the energy (slope < 0 at 0), but the full step zeroes F: taken, as before */
    PetscCall(Solve(&concave, -7, &err, &its, &evals, &reason));
    if (!rank) printf("concave energy: %d Newton iteration(s), %d residuals\n", (int)its, (int)evals);
    Check("concave energy: error after Newton", err, 1e-12);
    Check("concave energy: one iteration, two residuals", (PetscReal)(PetscAbsInt(its - 1) + PetscAbsInt(evals - 2)),
          0);

    /* a direction along which |F| rises at every step (the wrong Jacobian): the search fails at once, 20 halvings
       after the full step, and Newton stops there instead of taking steps away from the root */
    PetscCall(Solve(&wrong, -7, &err, &its, &evals, &reason));
    if (!rank) printf("a direction that raises |F|: %d Newton iterations, %d residuals, %s\n", (int)its, (int)evals,
                      SNESConvergedReasons[reason]);
    Check("a direction that raises |F|: the line search fails", reason == SNES_DIVERGED_LINE_SEARCH ? 0 : 1, 0);
    Check("a direction that raises |F|: no iteration taken", (PetscReal)its, 0);
    Check("a direction that raises |F|: residuals beyond 22", (PetscReal)PetscMax(evals - 22, 0), 0);
    Check("a direction that raises |F|: the start kept", PetscAbsReal(err - 9), 1e-12);
  }
  PetscCall(PetscFinalize());
  return failures ? 1 : 0;
}
