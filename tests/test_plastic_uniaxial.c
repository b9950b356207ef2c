static const char help[] = "Uniaxial stress in an elasto-plastic cube (rollers on x = 0, y = 0, z = 0; top face of "
  "height 1\n"
                           "pulled to z = strain): after every accepted load step each cell's stress and accumulated\n"
                           "plastic strain must equal the closed form sigma = R(p) + H p, eps = sigma / E + p.\n"
                           "  -uni_strain e          axial strain at full load (must match -bc_displacement top:z=e)\n"
                           "  -uni_tol t             relative tolerance (default 1e-8)\n"
                           "  -uni_expect_cutbacks   fail unless the load stepping cut back at least once\n"
                           "  -uni_cycle e1,e2,...   instead of -bc_displacement, drive the top face through these "
                             "axial strains\n"
                           "                         (piecewise linear from 0, -uni_segment_steps steps each) and "
                             "compare with\n"
                           "                         a one-dimensional return map of the same law: reverse yielding "
                             "at X - R(p)\n";

#include "ind_app.h"

#define MAX_CYCLE 16

/* Uniaxial-stress state of the one-dimensional oracle: axial plastic strain, accumulated p, and the
   uniaxial back stress X = x_zz - (x_xx + x_yy) / 2 = H * ep. */
typedef struct {
  PetscReal ep, p, X;
} Uniaxial;

typedef struct {
  PetscReal strain, tol;
  PetscBool cyclic;
  PetscReal eps;      /* current axial strain of the cyclic path */
  Uniaxial  oracle;   /* committed state of the oracle */
  PetscInt  checked, plastic_steps, reverse_steps;
  PetscReal worst_stress, worst_p;
  PetscReal *stress, *strain_avg, *p, *back, *yielding;
} Check;

/* Plastic strain p reached at total axial strain eps: the root of (R(p) + H p) / E + p = eps, which
   increases with p; bisection to the last bit, independent of the return-map code under test. */
/* Cells of this rank. */
static PetscInt CellCount(IndApp app)
{
  const IndDiscLayout *L;
  (void)IndDiscGetLayout(IndAppGetDisc(app), &L);
  return L->ncell;
}

static PetscReal ClosedFormP(const IndMaterial *m, PetscReal eps)
{
  const IndPlasticParams *pp = &m->plastic;
  PetscReal               lo = 0, hi = eps;
  if (m->young * eps <= pp->R0) return 0.0;
  for (int it = 0; it < 200 && hi - lo > 0; ++it) {
    const PetscReal mid = 0.5 * (lo + hi);
    if (mid == lo || mid == hi) break;
    if ((IndPlasticR(pp, mid) + pp->H * mid) / m->young + mid > eps) hi = mid;
    else lo = mid;
  }
  return 0.5 * (lo + hi);
}

/* Backward-Euler return of the one-dimensional law sigma = E (eps - ep), |sigma - X| <= R(p),
   dep = s dp, dX = H dep: the root of |sigma_tr - X| - (E + H) dp - R(p + dp) = 0, by bisection. */
static PetscReal UniaxialUpdate(const IndMaterial *m, PetscReal eps, Uniaxial *st)
{
  const IndPlasticParams *pp = &m->plastic;
  const PetscReal         E = m->young, str = E * (eps - st->ep), q = PetscAbsReal(str - st->X),
    s = str >= st->X ? 1.0 : -1.0;
  PetscReal               lo = 0, hi, dp;

  if (q <= IndPlasticR(pp, st->p)) return str;
  hi = q / (E + pp->H);
  for (int it = 0; it < 200; ++it) {
    const PetscReal mid = 0.5 * (lo + hi);
    if (mid == lo || mid == hi) break;
    if (q - (E + pp->H) * mid - IndPlasticR(pp, st->p + mid) > 0) lo = mid;
    else hi = mid;
  }
  dp = 0.5 * (lo + hi);
  st->ep += s * dp;
  st->p += dp;
  st->X += s * pp->H * dp;
  return E * (eps - st->ep);
}

static PetscErrorCode CheckStep(IndApp app, const IndStepResult *step, void *ctx)
{
  Check             *c = (Check *)ctx;
  const IndMaterial *m = IndMaterialsGet(IndAppGetMaterials(app), 0);
  PetscReal          eps, p, sig, scale;
  IndCellFields      f  = {c->stress, c->strain_avg, c->p, c->back, c->yielding, NULL};
  PetscReal          es = 0, ep = 0;

  PetscFunctionBeginUser;
  if (c->cyclic) {
    const PetscReal ep_old = c->oracle.ep;
    eps   = c->eps;
    sig   = UniaxialUpdate(m, eps, &c->oracle);
    if (c->oracle.ep < ep_old) c->reverse_steps++;
    p     = c->oracle.p;
    scale = PetscMax(PetscAbsReal(sig), IndPlasticR(&m->plastic, 0));
  } else {
    eps   = step->t * c->strain;
    p     = ClosedFormP(m, eps);
    sig   = p > 0 ? IndPlasticR(&m->plastic, p) + m->plastic.H * p : m->young * eps;
    scale = sig;
  }
  {
    Vec Uloc;
    PetscCall(DMGetLocalVector(IndAppGetDM(app), &Uloc));
    PetscCall(DMGlobalToLocal(IndAppGetDM(app), IndAppGetSolution(app), INSERT_VALUES, Uloc));
    PetscCall(IndAssemblyCellAverages(IndAppGetAssembly(app), Uloc, &f));
    PetscCall(DMRestoreLocalVector(IndAppGetDM(app), &Uloc));
  }
  for (PetscInt i = 0; i < CellCount(app); ++i) {
    for (int k = 0; k < 6; ++k) es = PetscMax(es, PetscAbsReal(c->stress[6 * i + k] - (k == 2 ? sig : 0.0)) / scale);
    ep = PetscMax(ep, PetscAbsReal(c->p[i] - p) / PetscMax(PetscAbsReal(eps), c->strain));
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &es, 1, MPIU_REAL, MPIU_MAX, IndAppGetComm(app)));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &ep, 1, MPIU_REAL, MPIU_MAX, IndAppGetComm(app)));
  PetscCall(PetscPrintf(IndAppGetComm(app),
    "  step %2" PetscInt_FMT " (load %.6f): strain %+.6e  expected sigma %+.10e GPa, p %.6e  max error: stress %.2e, "
    "p %.2e (relative)\n", c->checked + 1, (double)step->t, (double)eps, (double)sig, (double)p, (double)es,
    (double)ep));
  PetscCheck(es <= c->tol && ep <= c->tol, IndAppGetComm(app), PETSC_ERR_NOT_CONVERGED,
    "Uniaxial plasticity: error stress %.3e, p %.3e above %.1e at load %g", (double)es, (double)ep, (double)c->tol,
    (double)step->t);
  c->worst_stress = PetscMax(c->worst_stress, es);
  c->worst_p      = PetscMax(c->worst_p, ep);
  c->checked++;
  if (p > 0) c->plastic_steps++;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Top(const PetscReal x[3], PetscReal u[3], void *ctx)
{
  const Check *c = (const Check *)ctx;
  u[0] = u[1] = 0.0;
  u[2] = c->eps * x[2];
  return PETSC_SUCCESS;
}

/* Drives the top face through the strain targets, -uni_segment_steps steps per segment, solving
   each step at load factor 1 with the displacement held in the boundary function. */
static PetscErrorCode RunCycle(IndApp app, Check *c, const PetscReal *targets, PetscInt ntargets, PetscInt nseg)
{
  PetscReal from = 0.0;

  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < ntargets; ++k) {
    for (PetscInt j = 1; j <= nseg; ++j) {
      IndStepResult r;
      c->eps = from + (targets[k] - from) * j / nseg;
      PetscCall(IndBCInvalidate(IndAppGetBC(app)));
      PetscCall(IndAppSolveStep(app, 1.0, &r));
      PetscCheck(r.converged, IndAppGetComm(app), PETSC_ERR_NOT_CONVERGED,
        "Cycle segment %" PetscInt_FMT " step %" PetscInt_FMT ": Newton failed (%s)", k, j,
        SNESConvergedReasons[r.reason]);
      PetscCall(CheckStep(app, &r, c));
    }
    from = targets[k];
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  PetscReal targets[MAX_CYCLE];
  PetscInt  ntargets = MAX_CYCLE, nseg = 4;
  IndApp    app;
  Check     c = {0};
  PetscBool has_strain, expect_cutbacks = PETSC_FALSE;
  PetscInt  n;

  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  c.tol = 1e-8;
  PetscCall(PetscOptionsGetReal(NULL, NULL, "-uni_strain", &c.strain, &has_strain));
  PetscCall(PetscOptionsGetReal(NULL, NULL, "-uni_tol", &c.tol, NULL));
  PetscCall(PetscOptionsGetBool(NULL, NULL, "-uni_expect_cutbacks", &expect_cutbacks, NULL));
  PetscCall(PetscOptionsGetRealArray(NULL, NULL, "-uni_cycle", targets, &ntargets, &c.cyclic));
  PetscCall(PetscOptionsGetInt(NULL, NULL, "-uni_segment_steps", &nseg, NULL));
  if (c.cyclic) {
    PetscCheck(ntargets > 0 && nseg > 0, PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG,
      "-uni_cycle needs strains and -uni_segment_steps > 0");
    for (PetscInt k = 0; k < ntargets; ++k) c.strain = PetscMax(c.strain, PetscAbsReal(targets[k]));
  } else PetscCheck(has_strain && c.strain > 0, PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "-uni_strain e > 0 is required");
  PetscCall(IndAppCreate(PETSC_COMM_WORLD, &app));
  PetscCheck(IndMaterialsGetCount(IndAppGetMaterials(app)) == 1 &&
               IndMaterialsGet(IndAppGetMaterials(app), 0)->model == IND_MODEL_PLASTIC,
             PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG,
    "Needs one elasto-plastic region");
  n = CellCount(app);
  PetscCall(PetscMalloc5(6 * n, &c.stress, 6 * n, &c.strain_avg, n, &c.p, n, &c.back, n, &c.yielding));
  if (c.cyclic) {
    PetscCall(IndAppAddBoundaryFunction(app, "top", 4, Top, &c));
    PetscCall(RunCycle(app, &c, targets, ntargets, nseg));
  } else {
    PetscCall(IndAppSetStepMonitor(app, CheckStep, &c));
    PetscCall(IndAppRun(app));
  }
  PetscCall(PetscPrintf(PETSC_COMM_WORLD,
    "uniaxial plasticity: %" PetscInt_FMT " steps checked (%" PetscInt_FMT " plastic, %" PetscInt_FMT " yielding in "
    "reverse), %" PetscInt_FMT " cutbacks; worst relative error stress %.3e, p %.3e (tolerance %.1e)\n", c.checked,
    c.plastic_steps, c.reverse_steps,
                        IndAppGetLoadPath(app)->cutbacks, (double)c.worst_stress, (double)c.worst_p, (double)c.tol));
  PetscCheck(c.plastic_steps > 0, PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG,
    "The load never reached yield: the test checked nothing plastic");
  PetscCheck(!c.cyclic || c.reverse_steps > 0, PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG,
    "The cycle never yielded in reverse: the Bauschinger branch went unchecked");
  PetscCheck(!expect_cutbacks || IndAppGetLoadPath(app)->cutbacks > 0, PETSC_COMM_WORLD, PETSC_ERR_PLIB,
    "Expected the load stepping to cut back, it did not");
  PetscCall(PetscFree5(c.stress, c.strain_avg, c.p, c.back, c.yielding));
  PetscCall(IndAppDestroy(&app));
  PetscCall(PetscFinalize());
  return 0;
}
