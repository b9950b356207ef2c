static const char help[] = "Newton on a non-proportional plastic path: a cube clamped at z = 0 has its top face "
  "pulled up\n"
                           "(tension), then slid sideways (shear) with the tension held. Records the residual history\n"
                           "of every step and asserts the order of convergence in the plastic steps; at the last step\n"
                           "it compares the assembled Jacobian with central differences of the residual.\n"
                           "  -newton_tension a, -newton_shear b      top displacement at the end of each phase\n"
                           "  -newton_steps n1,n2                      steps per phase (n2 = 0: tension alone)\n"
                           "  -newton_expect quadratic|linear          the convergence to assert (linear: "
                             "-plastic_tangent elastic)\n"
                           "  -newton_order q                          least order accepted for quadratic (default "
                             "1.8)\n"
                           "  -newton_fd_tol t                         largest relative Frobenius error of the "
                             "Jacobian (default 1e-6; < 0 skips)\n"
                           "  -newton_fd_h h                           difference step relative to max |U| (default "
                             "1e-8: small enough that\n"
                           "                                           few quadrature points lie within it of the "
                             "yield surface's kink)\n";

#include "ind_app.h"

#define MAX_ITS 512

typedef struct {
  PetscReal tension, shear; /* current top displacement */
  PetscReal norms[MAX_ITS];
  PetscInt  n;
} Path;

static PetscErrorCode Top(const PetscReal x[3], PetscReal u[3], void *ctx)
{
  const Path *p = (const Path *)ctx;
  (void)x;
  u[0] = p->shear;
  u[1] = 0.0;
  u[2] = p->tension;
  return PETSC_SUCCESS;
}

static PetscErrorCode Record(SNES snes, PetscInt it, PetscReal fnorm, void *ctx)
{
  Path *p = (Path *)ctx;
  (void)snes;
  if (it < MAX_ITS) {
    p->norms[it] = fnorm;
    p->n         = it + 1;
  }
  return PETSC_SUCCESS;
}

/* Order estimates q_k = log(r_{k+1} / r_k) / log(r_k / r_{k-1}) over the iterates in the asymptotic
   range (r_k below 1e-2 r_0) and above round-off (r_{k+1} above 1e-14 r_0); returns the largest, or
   0 if there is none. Newton with a consistent tangent reaches about 2, an inconsistent one stays
   near 1 however far it goes. */
static PetscReal ConvergenceOrder(const Path *p)
{
  PetscReal q = 0;
  for (PetscInt k = 1; k + 1 < p->n; ++k) {
    const PetscReal r0 = p->norms[0];
    if (p->norms[k] > 1e-2 * r0 || p->norms[k + 1] < 1e-14 * r0) continue;
    q = PetscMax(q, PetscLogReal(p->norms[k + 1] / p->norms[k]) / PetscLogReal(p->norms[k] / p->norms[k - 1]));
  }
  return q;
}

/* || J - J_fd ||_F / || J ||_F with J_fd by central differences of the residual, column by column. */
static PetscErrorCode JacobianError(IndApp app, PetscReal fd_h, PetscReal *rel)
{
  SNES      snes = IndSolverGetSNES(IndAppGetSolver(app));
  Mat       J    = IndSolverGetJacobian(IndAppGetSolver(app));
  Vec       U = IndAppGetSolution(app), Up, Fp, Fm, e, Jc;
  PetscInt  N, lo, hi;
  PetscReal umax, h, d2 = 0, j2 = 0, nd, nj;

  PetscFunctionBeginUser;
  PetscCall(SNESComputeJacobian(snes, U, J, J));
  PetscCall(VecNorm(U, NORM_INFINITY, &umax));
  h = umax * fd_h;
  PetscCall(VecDuplicate(U, &Up));
  PetscCall(VecDuplicate(U, &Fp));
  PetscCall(VecDuplicate(U, &Fm));
  PetscCall(VecDuplicate(U, &e));
  PetscCall(VecDuplicate(U, &Jc));
  PetscCall(VecGetSize(U, &N));
  PetscCall(VecGetOwnershipRange(U, &lo, &hi));
  for (PetscInt j = 0; j < N; ++j) {
    PetscCall(VecCopy(U, Up));
    if (j >= lo && j < hi) PetscCall(VecSetValue(Up, j, h, ADD_VALUES));
    PetscCall(VecAssemblyBegin(Up));
    PetscCall(VecAssemblyEnd(Up));
    PetscCall(SNESComputeFunction(snes, Up, Fp));
    if (j >= lo && j < hi) PetscCall(VecSetValue(Up, j, -2 * h, ADD_VALUES));
    PetscCall(VecAssemblyBegin(Up));
    PetscCall(VecAssemblyEnd(Up));
    PetscCall(SNESComputeFunction(snes, Up, Fm));
    PetscCall(VecAXPY(Fp, -1.0, Fm));
    PetscCall(VecScale(Fp, 0.5 / h));
    PetscCall(VecZeroEntries(e));
    if (j >= lo && j < hi) PetscCall(VecSetValue(e, j, 1.0, INSERT_VALUES));
    PetscCall(VecAssemblyBegin(e));
    PetscCall(VecAssemblyEnd(e));
    PetscCall(MatMult(J, e, Jc));
    PetscCall(VecAXPY(Fp, -1.0, Jc));
    PetscCall(VecNorm(Fp, NORM_2, &nd));
    PetscCall(VecNorm(Jc, NORM_2, &nj));
    d2 += nd * nd;
    j2 += nj * nj;
  }
  /* Leave the trial history at U, as the solver left it. */
  PetscCall(SNESComputeFunction(snes, U, Fp));
  *rel = PetscSqrtReal(d2 / j2);
  PetscCall(VecDestroy(&Up));
  PetscCall(VecDestroy(&Fp));
  PetscCall(VecDestroy(&Fm));
  PetscCall(VecDestroy(&e));
  PetscCall(VecDestroy(&Jc));
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  IndApp    app;
  Path      path = {0};
  PetscReal tension = 0.01, shear = 0.02, min_order = 1.8, fd_tol = 1e-6, fd_h = 1e-8, worst_order = PETSC_MAX_REAL;
  PetscInt  steps[2] = {4, 4}, nsteps = 2, plastic_steps = 0, total_its = 0;
  char      expect[32] = "quadratic";
  PetscBool quadratic;

  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  PetscCall(PetscOptionsGetReal(NULL, NULL, "-newton_tension", &tension, NULL));
  PetscCall(PetscOptionsGetReal(NULL, NULL, "-newton_shear", &shear, NULL));
  PetscCall(PetscOptionsGetReal(NULL, NULL, "-newton_order", &min_order, NULL));
  PetscCall(PetscOptionsGetReal(NULL, NULL, "-newton_fd_tol", &fd_tol, NULL));
  PetscCall(PetscOptionsGetReal(NULL, NULL, "-newton_fd_h", &fd_h, NULL));
  PetscCall(PetscOptionsGetIntArray(NULL, NULL, "-newton_steps", steps, &nsteps, NULL));
  PetscCall(PetscOptionsGetString(NULL, NULL, "-newton_expect", expect, sizeof(expect), NULL));
  PetscCall(PetscStrcmp(expect, "quadratic", &quadratic));
  PetscCall(IndAppCreate(PETSC_COMM_WORLD, &app));
  PetscCall(IndAppAddBoundaryFunction(app, "top", 7, Top, &path));
  PetscCall(SNESMonitorSet(IndSolverGetSNES(IndAppGetSolver(app)), Record, &path, NULL));

  for (PetscInt phase = 0; phase < 2; ++phase)
    for (PetscInt k = 1; k <= steps[phase]; ++k) {
      /* with no shear phase (-newton_steps n,0: an axisymmetric section, whose top cannot slide radially at
         the axis) the last tension step is the one checked */
      const PetscBool last = k == steps[phase] && (phase == 1 || steps[1] == 0) ? PETSC_TRUE : PETSC_FALSE;
      IndStepResult   r;
      PetscReal       q;

      if (phase == 0) path.tension = tension * k / steps[0];
      else path.shear = shear * k / steps[1];
      PetscCall(IndBCInvalidate(IndAppGetBC(app)));
      /* The path lives in the boundary function, so every step solves at load factor 1. The last
         step is not committed: its Jacobian is checked against the residual, which must still start
         from the previous step's history (after a commit every plastic point sits on the kink of
         the yield surface, where no finite difference is meaningful). */
      if (last && fd_tol >= 0) {
        IndSolveResult sr;
        PetscCall(PetscMemzero(&r, sizeof(r)));
        PetscCall(IndSolverSolve(IndAppGetSolver(app), 1.0, IndAppGetSolution(app), &sr));
        PetscCall(IndSolverEvaluate(IndAppGetSolver(app), IndAppGetSolution(app)));
        r.reason    = sr.reason;
        r.newton    = sr.newton;
        r.converged = sr.converged;
        r.plastic   = IndSolverPlasticPoints(IndAppGetSolver(app));
      } else PetscCall(IndAppSolveStep(app, 1.0, &r));
      PetscCheck(r.converged, PETSC_COMM_WORLD, PETSC_ERR_NOT_CONVERGED,
        "%s step %" PetscInt_FMT ": Newton failed (%s)", phase ? "shear" : "tension", k,
        SNESConvergedReasons[r.reason]);
      q = ConvergenceOrder(&path);
      total_its += r.newton;
      PetscCall(PetscPrintf(PETSC_COMM_WORLD,
        "%s step %" PetscInt_FMT ": %" PetscInt_FMT " Newton iterations, %" PetscInt_FMT " plastic points, order "
        "%.2f; residual/initial:", phase ? "shear" : "tension", k, r.newton, r.plastic, (double)q));
      for (PetscInt i = 0; i < path.n; ++i) PetscCall(PetscPrintf(PETSC_COMM_WORLD, " %.1e",
        (double)(path.norms[i] / path.norms[0])));
      PetscCall(PetscPrintf(PETSC_COMM_WORLD, "\n"));
      if (r.plastic > 0 && q > 0) {
        plastic_steps++;
        worst_order = PetscMin(worst_order, q);
        if (quadratic) PetscCheck(q >= min_order, PETSC_COMM_WORLD, PETSC_ERR_NOT_CONVERGED,
          "Newton order %.2f < %.2f in a plastic step: the tangent is not consistent", (double)q, (double)min_order);
        else PetscCheck(q < 1.3, PETSC_COMM_WORLD, PETSC_ERR_NOT_CONVERGED,
          "Newton order %.2f: expected linear convergence with this tangent", (double)q);
      }
      if (last && fd_tol >= 0) {
        PetscReal err;
        PetscCall(JacobianError(app, fd_h, &err));
        PetscCall(PetscPrintf(PETSC_COMM_WORLD,
          "Jacobian vs central differences of the residual: ||J - J_fd||_F / ||J||_F = %.3e (tolerance %.1e)\n",
          (double)err, (double)fd_tol));
        PetscCheck(err <= fd_tol, PETSC_COMM_WORLD, PETSC_ERR_NOT_CONVERGED,
          "Jacobian differs from the residual's derivative by %.3e relative", (double)err);
      }
    }
  PetscCall(PetscPrintf(PETSC_COMM_WORLD,
    "non-proportional path: %" PetscInt_FMT " Newton iterations in all, %" PetscInt_FMT " plastic steps checked, "
    "lowest order %.2f (expected %s)\n", total_its, plastic_steps, (double)worst_order, expect));
  PetscCheck(plastic_steps >= 2, PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG,
    "Only %" PetscInt_FMT " plastic steps with enough iterations to measure an order", plastic_steps);
  PetscCall(IndAppDestroy(&app));
  PetscCall(PetscFinalize());
  return 0;
}
