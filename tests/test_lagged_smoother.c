static const char help[] =
  "A multigrid preconditioner reused after its matrix changed in place stays a preconditioner of the\n"
                           "new matrix once its finest smoother is refreshed (IndSolverRefreshFineSmoother).\n";

#include "solver_test.h"

/* A shear u_x = a z^2 exp(-(x^2 + y^2) / 0.05) near the top corner at the origin of the unit block: with a
   plastic material the points there yield and their tangent softens, as under an indenter, while
   the rest stays elastic. The coarse levels barely see a change so local; a Jacobi smoother must. */
static PetscErrorCode CornerShear(IndApp app, PetscReal a, Vec Uloc)
{
  Vec                nodes, U;
  const PetscScalar *x;
  PetscScalar       *u;
  PetscInt           n;

  PetscFunctionBeginUser;
  PetscCall(IndDiscNodeCoordinates(IndAppGetDisc(app), &nodes));
  PetscCall(DMGetGlobalVector(IndAppGetDM(app), &U));
  PetscCall(VecGetLocalSize(U, &n));
  PetscCall(VecGetArrayRead(nodes, &x));
  PetscCall(VecGetArray(U, &u));
  for (PetscInt k = 0; k < n; k += 3) {
    const PetscReal px = PetscRealPart(x[k]), py = PetscRealPart(x[k + 1]), pz = PetscRealPart(x[k + 2]);
    u[k]     = a * pz * pz * PetscExpReal(-(px * px + py * py) / 0.05);
    u[k + 1] = u[k + 2] = 0;
  }
  PetscCall(VecRestoreArray(U, &u));
  PetscCall(VecRestoreArrayRead(nodes, &x));
  PetscCall(DMGlobalToLocal(IndAppGetDM(app), U, INSERT_VALUES, Uloc));
  PetscCall(DMRestoreGlobalVector(IndAppGetDM(app), &U));
  PetscCall(VecDestroy(&nodes));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The tangent at the displacement Uloc, with the boundary conditions' rows and columns. */
static PetscErrorCode Tangent(IndApp app, Vec Uloc, Mat J)
{
  PetscFunctionBeginUser;
  PetscCall(IndAssemblyJacobian(IndAppGetAssembly(app), Uloc, J));
  PetscCall(IndBCApplyJacobian(IndAppGetBC(app), J));
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  IndApp   app;
  KSP      ksp = NULL;
  Mat      J   = NULL;
  Vec      b, x, U0, U1;
  PetscInt fresh, stale, refreshed, nplastic;

  PetscFunctionBeginUser;
  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  PetscCall(SolverTestCreate(1e-8, &app, &J, &ksp));
  PetscCall(MatCreateVecs(J, &x, &b));
  PetscCall(VecSet(b, 1.0));
  PetscCall(IndBCSetUp(IndAppGetBC(app)));

  PetscCall(DMGetLocalVector(IndAppGetDM(app), &U0));
  PetscCall(DMGetLocalVector(IndAppGetDM(app), &U1));
  PetscCall(VecZeroEntries(U0));
  PetscCall(CornerShear(app, 0.1, U1));

  /* the reference: a fresh preconditioner of the softened tangent */
  PetscCall(Tangent(app, U1, J));
  PetscCall(KSPSetOperators(ksp, J, J));
  PetscCall(KSPSetReusePreconditioner(ksp, PETSC_FALSE));
  PetscCall(SolveCounted(ksp, b, x, &fresh));
  {
    Vec      Floc;
    PetscInt mine;
    PetscCall(DMGetLocalVector(IndAppGetDM(app), &Floc));
    PetscCall(IndAssemblyResidual(IndAppGetAssembly(app), U1, Floc));
    PetscCall(DMRestoreLocalVector(IndAppGetDM(app), &Floc));
    IndAssemblyGetPointCounts(IndAppGetAssembly(app), NULL, &mine);
    PetscCall(MPIU_Allreduce(&mine, &nplastic, 1, MPIU_INT, MPI_SUM, PETSC_COMM_WORLD));
  }

  /* set up on the elastic tangent, then reused on the softened one: without and with the refresh */
  for (int refresh = 0; refresh < 2; ++refresh) {
    PetscCall(KSPSetReusePreconditioner(ksp, PETSC_FALSE));
    PetscCall(Tangent(app, U0, J));
    PetscCall(SolveCounted(ksp, b, x, refresh ? &refreshed : &stale));
    PetscCall(Tangent(app, U1, J));
    PetscCall(KSPSetReusePreconditioner(ksp, PETSC_TRUE));
    if (refresh) PetscCall(IndSolverRefreshFineSmoother(ksp));
    PetscCall(SolveCounted(ksp, b, x, refresh ? &refreshed : &stale));
  }
  PetscCall(DMRestoreLocalVector(IndAppGetDM(app), &U0));
  PetscCall(DMRestoreLocalVector(IndAppGetDM(app), &U1));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD,
    "Krylov iterations on the changed matrix: fresh preconditioner %" PetscInt_FMT ", reused %" PetscInt_FMT
    ", reused with its finest smoother refreshed %" PetscInt_FMT " (-1: no convergence); %" PetscInt_FMT
    " yielding points\n", fresh, stale, refreshed, nplastic));
  PetscCall(VecDestroy(&x));
  PetscCall(VecDestroy(&b));
  PetscCall(IndAppDestroy(&app));
  PetscCall(PetscFinalize());
  /* the coarse levels are the unchanged matrix's: a few more iterations than a fresh setup, never a failure */
  return fresh > 0 && refreshed > 0 && refreshed <= 2 * fresh ? 0 : 1;
}
