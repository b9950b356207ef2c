static const char help[] = "indent: finite-element nanoindentation of elasto-plastic films (PETSc).\n"
                           "Run with -help for every option; see doc/ for a guide.\n";

#include "ind_app.h"

int main(int argc, char **argv)
{
  IndApp app;

  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  PetscCall(IndAppCreate(PETSC_COMM_WORLD, &app));
  PetscCall(IndAppRun(app));
  PetscCall(IndAppDestroy(&app));
  PetscCall(PetscFinalize());
  return 0;
}
