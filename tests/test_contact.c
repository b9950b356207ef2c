static const char help[] = "Contact verification against closed forms, after every accepted step of an indentation "
  "run:\n"
                           "  -expect_hertz           P = 4/3 E* sqrt(R) h^1.5 (sphere; E, nu of region 'domain')\n"
                           "  -expect_sphere          the rigid sphere itself, not Hertz's paraboloid (Segedin 1957):\n"
                           "                          h = a/2 ln((R+a)/(R-a)),\n"
                           "                          P = E*/2 ((a^2+R^2) ln((R+a)/(R-a)) - 2aR)\n"
                           "  -expect_sneddon         P = 2/pi E* tan(alpha) h^2 (cone of half-angle alpha)\n"
                           "  -expect_tol t           relative tolerance of those (default 0.03)\n"
                           "  -expect_from h          check only steps with depth >= h (nm) while loading\n"
                           "  -expect_patch           flat punch over the whole top of a block of height H: every "
                             "contact node's\n"
                           "                          reaction over its tributary area equals -E depth / H (relative "
                             "1e-8)\n"
                           "  -expect_stick_inside    with friction: every sticking node lies nearer the axis than "
                             "every slipping one\n"
                           "  -expect_unload          the run ends with zero load and a displacement below 1e-6 of "
                             "the depth\n";

#include "ind_app.h"

typedef struct {
  PetscBool hertz, sphere, sneddon, patch, stick_inside, unload;
  PetscReal tol, from, worst, height;
  PetscInt  checked;
} Expect;

/* The load of a rigid sphere of radius R pressed h into an elastic half-space (Segedin 1957): the contact radius a
   solves h = a/2 ln((R+a)/(R-a)), by bisection on (0, R). */
static PetscReal SphereLoad(PetscReal Es, PetscReal R, PetscReal h)
{
  PetscReal lo = 0, hi = R, a = 0, L = 0;
  for (int k = 0; k < 200; ++k) {
    a = 0.5 * (lo + hi);
    L = PetscLogReal((R + a) / (R - a));
    if (0.5 * a * L < h) lo = a;
    else hi = a;
  }
  return 0.5 * Es * ((a * a + R * R) * L - 2 * a * R);
}

static PetscErrorCode CheckStep(IndApp app, const IndStepResult *r, void *ctx)
{
  Expect            *e  = (Expect *)ctx;
  const IndMaterial *m  = IndMaterialsGet(IndAppGetMaterials(app), 0);
  IndContactNodes    cn;
  const IndIndenter *in = IndContactGetIndenter(IndAppGetContact(app));
  const PetscReal    Es = m->young / (1 - m->poisson * m->poisson), h = r->depth;

  PetscFunctionBeginUser;
  PetscCall(IndContactGetNodes(IndAppGetContact(app), &cn));
  if ((e->hertz || e->sphere || e->sneddon) && !IndLoadPathUnloading(IndAppGetLoadPath(app), r->t) && h >= e->from &&
      h > 0) {
    const PetscReal P = e->hertz    ? 4.0 / 3.0 * Es * PetscSqrtReal(in->radius) * PetscPowReal(h, 1.5)
                      : e->sphere ? SphereLoad(Es, in->radius, h)
                                  : 2.0 / PETSC_PI * Es * PetscTanReal(in->angle) * h * h;
    const PetscReal err = r->contact.load / P - 1;
    PetscCall(PetscPrintf(IndAppGetComm(app), "  depth %8.3f nm: P %.6e nN, %s %.6e nN, error %+.3f%%\n", (double)h,
      (double)r->contact.load, e->hertz ? "Hertz" : e->sphere ? "sphere" : "Sneddon", (double)P, (double)(100 * err)));
    e->worst = PetscMax(e->worst, PetscAbsReal(err));
    e->checked++;
  }
  if (e->patch) {
    const PetscReal sigma = -m->young * h / e->height;
    PetscReal       worst = 0;
    PetscInt        n     = cn.n, touching = 0;
    for (PetscInt i = 0; i < n; ++i) {
      /* a node without area (a P2 section's corner on the axis, whose ring has zero consistent force) must carry
         no force; measured against the mean node's share */
      const PetscReal share = PetscAbsReal(r->contact.area) / cn.n, A = cn.A[i] > 1e-9 * share ? cn.A[i] : 1e-2 * share;
      worst = PetscMax(worst, PetscAbsReal(cn.R[3 * i + 2] / A - (A == cn.A[i] ? sigma : 0)) / PetscAbsReal(sigma));
      worst = PetscMax(worst, (PetscAbsReal(cn.R[3 * i]) + PetscAbsReal(cn.R[3 * i + 1])) / (PetscAbsReal(sigma) * A));
      touching += cn.status[i] != IND_CONTACT_OPEN || A != cn.A[i];
    }
    PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &worst, 1, MPIU_REAL, MPIU_MAX, IndAppGetComm(app)));
    PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &n, 1, MPIU_INT, MPI_SUM, IndAppGetComm(app)));
    PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &touching, 1, MPIU_INT, MPI_SUM, IndAppGetComm(app)));
    PetscCall(PetscPrintf(IndAppGetComm(app),
      "  depth %8.4f nm: sigma_zz %.10e GPa; %" PetscInt_FMT " of %" PetscInt_FMT " nodes in contact; worst |R / A - "
      "sigma| / |sigma| = %.3e\n", (double)h, (double)sigma, touching, n, (double)worst));
    PetscCheck(touching == n, IndAppGetComm(app), PETSC_ERR_PLIB,
      "Only %" PetscInt_FMT " of %" PetscInt_FMT " top nodes touch the punch", touching, n);
    e->worst = PetscMax(e->worst, worst);
    e->checked++;
  }
  if (e->stick_inside && r->contact.stick > 0 && r->contact.slip > 0) {
    PetscReal rstick = 0, rslip = PETSC_MAX_REAL;
    for (PetscInt i = 0; i < cn.n; ++i) {
      const PetscReal *X = cn.X + 3 * i,
        rad = PetscSqrtReal(PetscSqr(X[0] - in->axis[0]) + PetscSqr(X[1] - in->axis[1]));
      if (cn.status[i] == IND_CONTACT_STICK) rstick = PetscMax(rstick, rad);
      if (cn.status[i] == IND_CONTACT_SLIP) rslip = PetscMin(rslip, rad);
    }
    PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &rstick, 1, MPIU_REAL, MPIU_MAX, IndAppGetComm(app)));
    PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &rslip, 1, MPIU_REAL, MPIU_MIN, IndAppGetComm(app)));
    PetscCall(PetscPrintf(IndAppGetComm(app),
      "  depth %8.3f nm: %" PetscInt_FMT " stick out to r = %.2f nm, %" PetscInt_FMT " slip from r = %.2f nm\n",
      (double)h, r->contact.stick, (double)rstick, r->contact.slip, (double)rslip));
    PetscCheck(rstick <= rslip, IndAppGetComm(app), PETSC_ERR_PLIB,
      "A sticking node (r = %g) lies outside a slipping one (r = %g)", (double)rstick, (double)rslip);
    e->checked++;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  IndApp app;
  Expect e = {0};

  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  e.tol = 0.03;
  PetscCall(PetscOptionsGetBool(NULL, NULL, "-expect_hertz", &e.hertz, NULL));
  PetscCall(PetscOptionsGetBool(NULL, NULL, "-expect_sphere", &e.sphere, NULL));
  PetscCall(PetscOptionsGetBool(NULL, NULL, "-expect_sneddon", &e.sneddon, NULL));
  PetscCall(PetscOptionsGetBool(NULL, NULL, "-expect_patch", &e.patch, NULL));
  PetscCall(PetscOptionsGetBool(NULL, NULL, "-expect_stick_inside", &e.stick_inside, NULL));
  PetscCall(PetscOptionsGetBool(NULL, NULL, "-expect_unload", &e.unload, NULL));
  PetscCall(PetscOptionsGetReal(NULL, NULL, "-expect_tol", &e.tol, NULL));
  PetscCall(PetscOptionsGetReal(NULL, NULL, "-expect_from", &e.from, NULL));
  if (e.patch) e.tol = 1e-8;
  PetscCall(IndAppCreate(PETSC_COMM_WORLD, &app));
  PetscCheck(IndAppGetContact(app), PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "Needs an indenter (-indenter_type)");
  if (e.patch) {
    PetscReal zmin = PETSC_MAX_REAL;
    Vec       nodes;
    PetscCall(IndDiscNodeCoordinates(IndAppGetDisc(app), &nodes));
    PetscCall(VecStrideMin(nodes, 2, NULL, &zmin));
    PetscCall(VecDestroy(&nodes));
    e.height = IndContactGetIndenter(IndAppGetContact(app))->surface - zmin;
  }
  PetscCall(IndAppSetStepMonitor(app, CheckStep, &e));
  PetscCall(IndAppRun(app));
  if (e.unload) {
    PetscReal umax;
    PetscCall(VecNorm(IndAppGetSolution(app), NORM_INFINITY, &umax));
    PetscCall(PetscPrintf(PETSC_COMM_WORLD,
      "after unloading: depth %.4f nm, max |u| %.3e nm (%.2e of the largest depth)\n",
      (double)IndContactGetIndenter(IndAppGetContact(app))->depth, (double)umax,
      (double)(umax / IndAppGetLoadPath(app)->depth_max)));
    PetscCheck(umax <= 1e-6 * IndAppGetLoadPath(app)->depth_max, PETSC_COMM_WORLD, PETSC_ERR_PLIB,
      "An elastic body keeps a displacement of %g nm after unloading", (double)umax);
  }
  PetscCall(PetscPrintf(PETSC_COMM_WORLD,
    "contact checks: %" PetscInt_FMT " steps checked, worst relative error %.3e (tolerance %.1e)\n", e.checked,
    (double)e.worst, (double)e.tol));
  PetscCheck(e.checked > 0 || e.unload, PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "Nothing was checked");
  PetscCheck(e.worst <= e.tol, PETSC_COMM_WORLD, PETSC_ERR_NOT_CONVERGED, "Worst relative error %.3e above %.1e",
    (double)e.worst, (double)e.tol);
  PetscCall(IndAppDestroy(&app));
  PetscCall(PetscFinalize());
  return 0;
}
