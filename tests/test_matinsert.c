static const char help[] = "The Jacobian assembled at cached positions equals the one assembled by MatSetValues.\n";

#include "ind_app.h"
#include "assembly_impl.h" /* a unit test of the physics group: it switches the cached insertion off */

int main(int argc, char **argv)
{
  IndApp       app;
  IndAssembly  a;
  IndMatInsert ins;
  Mat          J, Jref;
  Vec          Uloc;
  PetscReal    diff, norm;

  PetscFunctionBeginUser;
  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  PetscCall(IndAppCreate(PETSC_COMM_WORLD, &app));
  a = IndAppGetAssembly(app);
  J = a->J;
  PetscCheck(a->insert, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "No cached insertion for this matrix");
  /* a displacement that makes every entry distinct: a smooth field of position */
  PetscCall(DMGetLocalVector(IndAppGetDM(app), &Uloc));
  PetscCall(VecSetRandom(Uloc, NULL));
  PetscCall(VecScale(Uloc, 1e-3));
  PetscCall(IndAssemblyJacobian(a, Uloc, J));
  PetscCall(MatDuplicate(J, MAT_COPY_VALUES, &Jref));
  ins       = a->insert;
  a->insert = NULL;
  PetscCall(IndAssemblyJacobian(a, Uloc, Jref));
  a->insert = ins;
  PetscCall(MatNorm(Jref, NORM_FROBENIUS, &norm));
  PetscCall(MatAXPY(Jref, -1.0, J, SAME_NONZERO_PATTERN));
  PetscCall(MatNorm(Jref, NORM_FROBENIUS, &diff));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "|J_cached - J_MatSetValues| / |J| = %.3e\n", (double)(diff / norm)));
  PetscCall(DMRestoreLocalVector(IndAppGetDM(app), &Uloc));
  PetscCall(MatDestroy(&Jref));
  PetscCall(IndAppDestroy(&app));
  PetscCall(PetscFinalize());
  return diff <= 1e-14 * norm ? 0 : 1;
}
