static const char help[] = "Uniaxial stress in an elasto-plastic cube (rollers on x = 0, y = 0, z = 0; top face of height 1\n"
                           "pulled to z = strain): after every accepted load step each cell's stress and accumulated\n"
                           "plastic strain must equal the closed form sigma = R(p) + H p, eps = sigma / E + p.\n"
                           "  -uni_strain e          axial strain at full load (must match -bc_displacement top:z=e)\n"
                           "  -uni_tol t             relative tolerance (default 1e-8)\n"
                           "  -uni_expect_cutbacks   fail unless the load stepping cut back at least once\n";

#include "ind_app.h"

typedef struct {
  PetscReal strain, tol;
  PetscInt  checked, plastic_steps;
  PetscReal worst_stress, worst_p;
  PetscReal *stress, *strain_avg, *p, *back, *yielding;
} Check;

/* Plastic strain p reached at total axial strain eps: the root of (R(p) + H p) / E + p = eps, which
   increases with p; bisection to the last bit, independent of the return-map code under test. */
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

static PetscErrorCode CheckStep(IndApp app, const IndStepResult *step, void *ctx)
{
  Check            *c   = (Check *)ctx;
  const IndMaterial *m  = &app->mats->mat[0];
  const PetscReal   eps = step->t * c->strain, p = ClosedFormP(m, eps);
  const PetscReal   sig = p > 0 ? IndPlasticR(&m->plastic, p) + m->plastic.H * p : m->young * eps;
  IndCellFields     f   = {c->stress, c->strain_avg, c->p, c->back, c->yielding};
  PetscReal         es = 0, ep = 0;

  PetscFunctionBeginUser;
  PetscCall(DMGlobalToLocal(app->disc->dm, app->U, INSERT_VALUES, app->solver->Uloc));
  PetscCall(IndAssemblyCellAverages(app->assembly, app->solver->Uloc, &f));
  for (PetscInt i = 0; i < app->disc->ncell; ++i) {
    for (int k = 0; k < 6; ++k) es = PetscMax(es, PetscAbsReal(c->stress[6 * i + k] - (k == 2 ? sig : 0.0)) / sig);
    ep = PetscMax(ep, PetscAbsReal(c->p[i] - p) / eps);
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &es, 1, MPIU_REAL, MPIU_MAX, app->comm));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &ep, 1, MPIU_REAL, MPIU_MAX, app->comm));
  PetscCall(PetscPrintf(app->comm, "  load %.6f: strain %.6e  closed form sigma %.10e GPa, p %.6e  max error: stress %.2e, p %.2e (relative)\n", (double)step->t, (double)eps, (double)sig, (double)p, (double)es, (double)ep));
  PetscCheck(es <= c->tol && ep <= c->tol, app->comm, PETSC_ERR_NOT_CONVERGED, "Uniaxial plasticity: error stress %.3e, p %.3e above %.1e at load %g", (double)es, (double)ep, (double)c->tol, (double)step->t);
  c->worst_stress = PetscMax(c->worst_stress, es);
  c->worst_p      = PetscMax(c->worst_p, ep);
  c->checked++;
  if (p > 0) c->plastic_steps++;
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  IndApp    app;
  Check     c = {0};
  PetscBool has_strain, expect_cutbacks = PETSC_FALSE;
  PetscInt  n;

  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  c.tol = 1e-8;
  PetscCall(PetscOptionsGetReal(NULL, NULL, "-uni_strain", &c.strain, &has_strain));
  PetscCall(PetscOptionsGetReal(NULL, NULL, "-uni_tol", &c.tol, NULL));
  PetscCall(PetscOptionsGetBool(NULL, NULL, "-uni_expect_cutbacks", &expect_cutbacks, NULL));
  PetscCheck(has_strain && c.strain > 0, PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "-uni_strain e > 0 is required");
  PetscCall(IndAppCreate(PETSC_COMM_WORLD, &app));
  PetscCheck(app->mats->n == 1 && app->mats->mat[0].model == IND_MODEL_PLASTIC, PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "Needs one elasto-plastic region");
  n = app->disc->ncell;
  PetscCall(PetscMalloc5(6 * n, &c.stress, 6 * n, &c.strain_avg, n, &c.p, n, &c.back, n, &c.yielding));
  PetscCall(IndAppSetStepMonitor(app, CheckStep, &c));
  PetscCall(IndAppRun(app));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "uniaxial plasticity: %" PetscInt_FMT " steps checked (%" PetscInt_FMT " plastic), %" PetscInt_FMT " cutbacks; worst relative error stress %.3e, p %.3e (tolerance %.1e)\n", c.checked, c.plastic_steps,
                        app->path.cutbacks, (double)c.worst_stress, (double)c.worst_p, (double)c.tol));
  PetscCheck(c.plastic_steps > 0, PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "The load never reached yield: the test checked nothing plastic");
  PetscCheck(!expect_cutbacks || app->path.cutbacks > 0, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "Expected the load stepping to cut back, it did not");
  PetscCall(PetscFree5(c.stress, c.strain_avg, c.p, c.back, c.yielding));
  PetscCall(IndAppDestroy(&app));
  PetscCall(PetscFinalize());
  return 0;
}
