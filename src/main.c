static const char help[] = "indent: finite-element nanoindentation of elasto-plastic films (PETSc).\n"
                           "With -help, lists every option the given inputs read (with their values) and exits without solving;\n"
                           "see doc/ for a guide.\n";

#include "ind_app.h"

int main(int argc, char **argv)
{
  IndApp    app;
  PetscBool listing;

  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  PetscCall(PetscOptionsHasHelp(NULL, &listing));
  PetscCall(IndAppCreate(PETSC_COMM_WORLD, &app));
  /* the set-up has read (and listed) every option; a user asking for the list does not want the run */
  if (!listing) PetscCall(IndAppRun(app));
  PetscCall(IndAppDestroy(&app));
  PetscCall(PetscFinalize());
  return 0;
}
