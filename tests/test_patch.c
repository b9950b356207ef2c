static const char help[] = "Patch test: an affine displacement prescribed on the whole boundary is reproduced inside.\n";

#include "ind_app.h"

/* A generic affine field: no symmetry, no zero entries, so no term can cancel by accident. */
static const PetscReal A[3][3] = {{1.0e-3, 2.0e-3, -1.5e-3}, {-0.7e-3, 0.5e-3, 1.1e-3}, {0.3e-3, -1.2e-3, -0.9e-3}};
static const PetscReal b[3]    = {0.01, -0.02, 0.005};

static PetscErrorCode Affine(const PetscReal x[3], PetscReal u[3], void *ctx)
{
  (void)ctx;
  for (int i = 0; i < 3; ++i) u[i] = b[i] + A[i][0] * x[0] + A[i][1] * x[1] + A[i][2] * x[2];
  return PETSC_SUCCESS;
}

static PetscErrorCode AffineProject(PetscInt dim, PetscReal t, const PetscReal x[], PetscInt Nc, PetscScalar *u, void *ctx)
{
  PetscReal v[3];
  (void)dim;
  (void)t;
  (void)Nc;
  PetscCall(Affine(x, v, ctx));
  for (int i = 0; i < 3; ++i) u[i] = v[i];
  return PETSC_SUCCESS;
}

int main(int argc, char **argv)
{
  IndApp    app;
  Vec       exact;
  PetscReal err, norm, tol = 1e-10;
  PetscErrorCode (*funcs[1])(PetscInt, PetscReal, const PetscReal[], PetscInt, PetscScalar *, void *) = {AffineProject};

  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  PetscCall(PetscOptionsGetReal(NULL, NULL, "-patch_tol", &tol, NULL));
  PetscCall(IndAppCreate(PETSC_COMM_WORLD, &app));
  for (PetscInt r = 0; r < app->mesh->nregions; ++r)
    if (app->mesh->regions[r].dim == 2) PetscCall(IndAppAddBoundaryFunction(app, app->mesh->regions[r].name, 7, Affine, NULL));
  PetscCall(IndAppRun(app));

  PetscCall(VecDuplicate(app->U, &exact));
  PetscCall(DMProjectFunction(app->disc->dm, 0.0, funcs, NULL, INSERT_ALL_VALUES, exact));
  PetscCall(VecNorm(exact, NORM_INFINITY, &norm));
  PetscCall(VecAXPY(exact, -1.0, app->U));
  PetscCall(VecNorm(exact, NORM_INFINITY, &err));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "patch test: max nodal error %.3e, relative %.3e (tolerance %.1e)\n", (double)err, (double)(err / norm), (double)tol));
  PetscCheck(err / norm <= tol, PETSC_COMM_WORLD, PETSC_ERR_NOT_CONVERGED, "Patch test failed: relative nodal error %.3e > %.1e", (double)(err / norm), (double)tol);
  PetscCall(VecDestroy(&exact));
  PetscCall(IndAppDestroy(&app));
  PetscCall(PetscFinalize());
  return 0;
}
