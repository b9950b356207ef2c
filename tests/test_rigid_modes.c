static const char help[] = "The Jacobian's rigid-body modes (GAMG's near null space) are held while the\n"
                           "multigrid builds its interpolation: let go after its first set-up, given back when a\n"
                           "restored state resets it, and kept throughout when the interpolation is rebuilt\n"
                           "(-pc_gamg_reuse_interpolation 0).\n";

#include "ind_app.h"
#include "ind_solver.h"

/* The number of vectors of J's near null space (0: none). */
static PetscErrorCode RigidModes(IndApp app, PetscInt *n)
{
  MatNullSpace nsp;
  PetscBool    constant;
  const Vec   *vecs;

  PetscFunctionBeginUser;
  *n = 0;
  PetscCall(MatGetNearNullSpace(IndSolverGetJacobian(IndAppGetSolver(app)), &nsp));
  if (nsp) PetscCall(MatNullSpaceGetVecs(nsp, &constant, n, &vecs));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Expect(IndApp app, PetscInt want, const char *when, PetscInt *failures)
{
  PetscInt n;

  PetscFunctionBeginUser;
  PetscCall(RigidModes(app, &n));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "  %-52s %" PetscInt_FMT " rigid-body modes (want %" PetscInt_FMT ")%s\n",
                        when, n, want, n == want ? "" : "  FAIL"));
  if (n != want) (*failures)++;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Step(IndApp app)
{
  IndStepResult r;

  PetscFunctionBeginUser;
  PetscCall(IndAppStep(app, &r));
  PetscCheck(r.converged, PETSC_COMM_WORLD, PETSC_ERR_NOT_CONVERGED, "a step failed: %s", r.why);
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  IndApp    app;
  PetscInt  failures = 0, after;
  PetscBool reuse = PETSC_TRUE; /* GAMG's interpolation reused (the default): the modes let go after a set-up */
  char      path[PETSC_MAX_PATH_LEN] = "";

  PetscFunctionBeginUser;
  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  PetscCall(PetscOptionsGetString(NULL, NULL, "-rigid_checkpoint", path, sizeof(path), NULL));
  PetscCheck(path[0], PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT, "-rigid_checkpoint <file> is required");
  PetscCall(PetscOptionsGetBool(NULL, NULL, "-pc_gamg_reuse_interpolation", &reuse, NULL));
  after = reuse ? 0 : 6;
  PetscCall(IndAppCreate(PETSC_COMM_WORLD, &app));
  PetscCall(Expect(app, 6, "before the first solve", &failures));
  PetscCall(Step(app));
  PetscCall(Expect(app, after, "after the first step", &failures));
  PetscCall(IndAppCheckpoint(app, path, FILE_MODE_WRITE));
  PetscCall(IndAppCheckpoint(app, path, FILE_MODE_READ));
  PetscCall(Expect(app, 6, "after a state restored (the multigrid reset)", &failures));
  PetscCall(Step(app));
  PetscCall(Expect(app, after, "after the next step", &failures));
  PetscCall(IndAppDestroy(&app));
  PetscCall(PetscFinalize());
  return failures ? 1 : 0;
}
