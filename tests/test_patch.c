static const char help[] = "Patch test: an affine displacement prescribed on the whole boundary is reproduced inside.\n"
                           "  -patch_uniaxial e  instead, take the boundary conditions from the options (symmetry or "
                             "roller\n"
                           "                     planes at x = y = z = 0, top pushed down by e at z = 1) and check "
                             "the\n"
                           "                     uniform uniaxial-stress field u = (nu e x, nu e y, -e z)\n";

#include "ind_app.h"

/* A generic affine field: no symmetry, no zero entries, so no term can cancel by accident. */
static const PetscReal A[3][3] = {{1.0e-3, 2.0e-3, -1.5e-3}, {-0.7e-3, 0.5e-3, 1.1e-3}, {0.3e-3, -1.2e-3, -0.9e-3}};
static const PetscReal b[3]    = {0.01, -0.02, 0.005};

typedef struct {
  PetscBool uniaxial;
  PetscReal strain, nu;
} Case;

static PetscErrorCode Affine(const PetscReal x[3], PetscReal u[3], void *ctx)
{
  const Case *c = (const Case *)ctx;
  if (c && c->uniaxial) {
    u[0] = c->nu * c->strain * x[0];
    u[1] = c->nu * c->strain * x[1];
    u[2] = -c->strain * x[2];
  } else
    for (int i = 0; i < 3; ++i) u[i] = b[i] + A[i][0] * x[0] + A[i][1] * x[1] + A[i][2] * x[2];
  return PETSC_SUCCESS;
}

static PetscErrorCode AffineProject(PetscInt dim, PetscReal t, const PetscReal x[], PetscInt Nc, PetscScalar *u,
  void *ctx)
{
  PetscReal v[3];
  (void)dim;
  (void)t;
  (void)Nc;
  PetscCall(Affine(x, v, ctx));
  for (int i = 0; i < 3; ++i) u[i] = v[i];
  return PETSC_SUCCESS;
}

static PetscErrorCode Position(PetscInt dim, PetscReal t, const PetscReal x[], PetscInt Nc, PetscScalar *u, void *ctx)
{
  (void)dim;
  (void)t;
  (void)Nc;
  (void)ctx;
  for (int i = 0; i < 3; ++i) u[i] = x[i];
  return PETSC_SUCCESS;
}

int main(int argc, char **argv)
{
  IndApp    app;
  Vec       exact;
  PetscReal err, norm, tol = 1e-10;
  Case      c = {PETSC_FALSE, 0, 0};
  void     *ctxs[1] = {&c};
  PetscErrorCode (*funcs[1])(PetscInt, PetscReal, const PetscReal[], PetscInt, PetscScalar *, void *) = {AffineProject};

  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  PetscCall(PetscOptionsGetReal(NULL, NULL, "-patch_tol", &tol, NULL));
  PetscCall(PetscOptionsGetReal(NULL, NULL, "-patch_uniaxial", &c.strain, &c.uniaxial));
  PetscCall(IndAppCreate(PETSC_COMM_WORLD, &app));
  c.nu = IndMaterialsGet(IndAppGetMaterials(app), 0)->poisson;
  if (!c.uniaxial)
    {
      PetscInt         nregions;
      const IndRegion *regions;
      PetscCall(IndMeshGetRegions(IndAppGetMesh(app), &nregions, &regions));
    for (PetscInt r = 0; r < nregions; ++r)
      if (regions[r].dim == 2) PetscCall(IndAppAddBoundaryFunction(app, regions[r].name, 7,
        Affine, &c));
    }
  PetscCall(IndAppRun(app));

  PetscCall(VecDuplicate(IndAppGetSolution(app), &exact));
  PetscCall(DMProjectFunction(IndAppGetDM(app), 0.0, funcs, ctxs, INSERT_ALL_VALUES, exact));
  PetscCall(VecNorm(exact, NORM_INFINITY, &norm));
  PetscCall(VecAXPY(exact, -1.0, IndAppGetSolution(app)));
  PetscCall(VecNorm(exact, NORM_INFINITY, &err));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "patch test: max nodal error %.3e, relative %.3e (tolerance %.1e)\n",
    (double)err, (double)(err / norm), (double)tol));
  PetscCheck(err / norm <= tol, PETSC_COMM_WORLD, PETSC_ERR_NOT_CONVERGED,
    "Patch test failed: relative nodal error %.3e > %.1e", (double)(err / norm), (double)tol);
  PetscCall(VecDestroy(&exact));

  { /* The node positions behind the rigid-body modes agree with PETSc's projection of x. */
    Vec       nodes, x;
    PetscReal nerr, nnorm;
    PetscErrorCode (*ident[1])(PetscInt, PetscReal, const PetscReal[], PetscInt, PetscScalar *, void *) = {Position};
    PetscCall(IndDiscNodeCoordinates(IndAppGetDisc(app), &nodes));
    PetscCall(VecDuplicate(nodes, &x));
    PetscCall(DMProjectFunction(IndAppGetDM(app), 0.0, ident, NULL, INSERT_ALL_VALUES, x));
    PetscCall(VecNorm(x, NORM_INFINITY, &nnorm));
    PetscCall(VecAXPY(x, -1.0, nodes));
    PetscCall(VecNorm(x, NORM_INFINITY, &nerr));
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "node coordinates: max error %.3e relative\n", (double)(nerr / nnorm)));
    PetscCheck(nerr <= 1e-12 * nnorm, PETSC_COMM_WORLD, PETSC_ERR_PLIB,
      "Node coordinates differ from the projection of x by %.3e", (double)nerr);
    PetscCall(VecDestroy(&x));
    PetscCall(VecDestroy(&nodes));
  }
  PetscCall(IndAppDestroy(&app));
  PetscCall(PetscFinalize());
  return 0;
}
