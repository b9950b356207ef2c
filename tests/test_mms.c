static const char help[] = "Manufactured solution with body force on the unit cube: L2 error and its rate over "
  "refinements.\n"
                           "  -mms_levels n      number of meshes (each refines the previous once)\n"
                           "  -mms_meshes a,b,c  or a series of mesh files whose element size halves from one to the "
                             "next\n"
                           "  -mms_rate r        expected rate, -mms_rate_tol its tolerance\n";

#include "ind_app.h"

/* u_i = a_i phi, phi = sin(pi x) sin(pi y) sin(pi z): zero on the boundary, smooth, all couplings present. */
static const PetscReal a[3] = {1.0e-2, -2.0e-2, 1.5e-2};

typedef struct {
  PetscReal lambda, mu;
} Lame;

static PetscErrorCode Exact(const PetscReal x[3], PetscReal u[3], void *ctx)
{
  const PetscReal phi = PetscSinReal(PETSC_PI * x[0]) * PetscSinReal(PETSC_PI * x[1]) * PetscSinReal(PETSC_PI * x[2]);
  (void)ctx;
  for (int i = 0; i < 3; ++i) u[i] = a[i] * phi;
  return PETSC_SUCCESS;
}

static PetscErrorCode ExactProject(PetscInt dim, PetscReal t, const PetscReal x[], PetscInt Nc, PetscScalar *u,
  void *ctx)
{
  PetscReal v[3];
  (void)dim;
  (void)t;
  (void)Nc;
  PetscCall(Exact(x, v, ctx));
  for (int i = 0; i < 3; ++i) u[i] = v[i];
  return PETSC_SUCCESS;
}

/* f = -div sigma = -(mu lap u + (lambda + mu) grad div u). */
static PetscErrorCode BodyForce(const PetscReal x[3], PetscReal f[3], void *ctx)
{
  const Lame *m = (const Lame *)ctx;
  PetscReal   s[3], c[3], H[3][3], phi;
  for (int i = 0; i < 3; ++i) {
    s[i] = PetscSinReal(PETSC_PI * x[i]);
    c[i] = PetscCosReal(PETSC_PI * x[i]);
  }
  phi = s[0] * s[1] * s[2];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const int k = 3 - i - j;
      H[i][j]     = (i == j) ? -PETSC_PI * PETSC_PI * phi : PETSC_PI * PETSC_PI * c[i] * c[j] * s[k];
    }
  for (int i = 0; i < 3; ++i) {
    PetscReal graddiv = 0;
    for (int j = 0; j < 3; ++j) graddiv += a[j] * H[i][j];
    f[i] = -(m->mu * (-3.0 * PETSC_PI * PETSC_PI * a[i] * phi) + (m->lambda + m->mu) * graddiv);
  }
  return PETSC_SUCCESS;
}

int main(int argc, char **argv)
{
  PetscInt  levels = 3;
  PetscReal rate = 2.0, rate_tol = 0.1, err[16], h[16];
  char     *meshes[16];
  PetscInt  nmeshes = 16;
  PetscBool series;
  PetscErrorCode (*funcs[1])(PetscInt, PetscReal, const PetscReal[], PetscInt, PetscScalar *, void *) = {ExactProject};

  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  PetscCall(PetscOptionsGetInt(NULL, NULL, "-mms_levels", &levels, NULL));
  PetscCall(PetscOptionsGetReal(NULL, NULL, "-mms_rate", &rate, NULL));
  PetscCall(PetscOptionsGetReal(NULL, NULL, "-mms_rate_tol", &rate_tol, NULL));
  PetscCall(PetscOptionsGetStringArray(NULL, NULL, "-mms_meshes", meshes, &nmeshes, &series));
  if (series) levels = nmeshes;
  PetscCheck(levels >= 2 && levels <= 16, PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE,
    "-mms_levels must lie in [2, 16]");
  for (PetscInt l = 0; l < levels; ++l) {
    IndApp   app;
    Lame     lame;
    char     refine[16];
    PetscInt ndof;

    if (series) {
      PetscCall(PetscOptionsSetValue(NULL, "-mesh_file", meshes[l]));
      PetscCall(PetscFree(meshes[l]));
    } else {
      PetscCall(PetscSNPrintf(refine, sizeof(refine), "%" PetscInt_FMT, l));
      PetscCall(PetscOptionsSetValue(NULL, "-mesh_refine", refine));
    }
    PetscCall(IndAppCreate(PETSC_COMM_WORLD, &app));
    lame.mu     = IndMaterialsGet(IndAppGetMaterials(app), 0)->mu;
    lame.lambda = IndMaterialsGet(IndAppGetMaterials(app), 0)->kappa - 2.0 * lame.mu / 3.0;
    PetscCall(IndAppSetBodyForce(app, BodyForce, &lame));
    {
      PetscInt         nregions;
      const IndRegion *regions;
      PetscCall(IndMeshGetRegions(IndAppGetMesh(app), &nregions, &regions));
    for (PetscInt r = 0; r < nregions; ++r)
      if (regions[r].dim == 2) PetscCall(IndAppAddBoundaryFunction(app, regions[r].name, 7,
        Exact, NULL));
    }
    PetscCall(IndAppRun(app));
    PetscCall(DMComputeL2Diff(IndAppGetDM(app), 0.0, funcs, NULL, IndAppGetSolution(app), &err[l]));
    PetscCall(VecGetSize(IndAppGetSolution(app), &ndof));
    h[l] = PetscPowReal(0.5, (PetscReal)l);
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "level %" PetscInt_FMT ": %8" PetscInt_FMT " dofs  L2 error %.4e", l,
      ndof, (double)err[l]));
    if (l) PetscCall(PetscPrintf(PETSC_COMM_WORLD, "  rate %.3f",
      (double)(PetscLogReal(err[l - 1] / err[l]) / PetscLogReal(h[l - 1] / h[l]))));
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "\n"));
    PetscCall(IndAppDestroy(&app));
  }
  {
    /* The last pair is the closest to the asymptotic regime. */
    const PetscReal last = PetscLogReal(err[levels - 2] / err[levels - 1]) / PetscLogReal(h[levels - 2] / h[levels
      - 1]);
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "final rate %.3f, expected %.2f +- %.2f\n", (double)last, (double)rate,
      (double)rate_tol));
    PetscCheck(PetscAbsReal(last - rate) <= rate_tol, PETSC_COMM_WORLD, PETSC_ERR_NOT_CONVERGED,
      "L2 convergence rate %.3f is not %.2f +- %.2f", (double)last, (double)rate, (double)rate_tol);
  }
  PetscCall(PetscFinalize());
  return 0;
}
