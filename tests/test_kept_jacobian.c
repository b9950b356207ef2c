static const char help[] =
  "The Jacobian that reuses what the residual's points kept at its displacement equals, to round-off, the one that\n"
  "computes everything; a residual at another displacement is not reused. -test_min_kept_pieces n: the residual\n"
  "kept its values in at least n pieces on every rank (a mesh large enough for the pieces' indexing to be tested).\n";

#include "ind_app.h"
#include "assembly_impl.h" /* a unit test of the physics group: both Jacobians into the matrix and its insertion */

/* |A - B|_F, A and B of one nonzero pattern; B is overwritten. */
static PetscErrorCode Difference(Mat A, Mat B, PetscReal *diff)
{
  PetscFunctionBeginUser;
  PetscCall(MatAXPY(B, -1.0, A, SAME_NONZERO_PATTERN));
  PetscCall(MatNorm(B, NORM_FROBENIUS, diff));
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  IndApp      app;
  IndAssembly a;
  DM          dm;
  Mat         J, Jfresh;
  Vec         U, V, F;
  PetscReal   diff, norm;
  PetscInt    uses0, uses1, uses2, total[2], local[2], pieces, min_pieces = 0;
  PetscBool   finite;

  PetscFunctionBeginUser;
  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  PetscCall(PetscOptionsGetInt(NULL, NULL, "-test_min_kept_pieces", &min_pieces, NULL));
  PetscCall(IndAppCreate(PETSC_COMM_WORLD, &app));
  a      = IndAppGetAssembly(app);
  dm     = IndAppGetDM(app);
  finite = IndAssemblyIsFiniteStrain(a);
  J      = a->J;
  PetscCall(DMGetLocalVector(dm, &U));
  PetscCall(DMGetLocalVector(dm, &V));
  PetscCall(DMGetLocalVector(dm, &F));
  /* random displacements of a strain of some 1e-3 (the mesh spans about 1) */
  PetscCall(VecSetRandom(U, NULL));
  PetscCall(VecScale(U, 1e-3));
  PetscCall(VecCopy(U, V));
  PetscCall(VecShift(V, 1e-4));
  PetscCall(VecScale(V, 0.5));

  uses0 = IndAssemblyGetKeptUses(a);
  PetscCall(IndAssemblyResidual(a, V, F)); /* another displacement: nothing to reuse */
  PetscCall(IndAssemblyJacobian(a, U, J));
  PetscCall(MatDuplicate(J, MAT_COPY_VALUES, &Jfresh));
  uses1 = IndAssemblyGetKeptUses(a);
  PetscCall(IndAssemblyResidual(a, U, F));
  pieces = a->kept_pieces;
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &pieces, 1, MPIU_INT, MPI_MIN, PETSC_COMM_WORLD));
  PetscCall(IndAssemblyJacobian(a, U, J));
  uses2 = IndAssemblyGetKeptUses(a);
  local[0] = uses1 - uses0, local[1] = uses2 - uses1;
  PetscCall(MPIU_Allreduce(local, total, 2, MPIU_INT, MPI_SUM, PETSC_COMM_WORLD));
  PetscCall(MatNorm(J, NORM_FROBENIUS, &norm));
  PetscCall(Difference(J, Jfresh, &diff));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD,
                        "%s strain: reused after another displacement's residual on %" PetscInt_FMT " ranks, after "
                        "its own on %" PetscInt_FMT "; |J_kept - J| / |J| = %.3e; kept in %" PetscInt_FMT
                        " pieces or more a rank\n",
                        finite ? "finite" : "small", total[0], total[1], (double)(diff / norm), pieces));
  PetscCall(DMRestoreLocalVector(dm, &F));
  PetscCall(DMRestoreLocalVector(dm, &V));
  PetscCall(DMRestoreLocalVector(dm, &U));
  PetscCall(MatDestroy(&Jfresh));
  {
    PetscMPIInt size;
    PetscBool   ok;
    PetscCallMPI(MPI_Comm_size(PETSC_COMM_WORLD, &size));
    /* finite strain keeps the decomposition of C on every rank; small strain has nothing to keep */
    ok = (PetscBool)(diff <= 1e-13 * norm && total[0] == 0 && total[1] == (finite ? size : 0) &&
                     pieces >= min_pieces);
    PetscCall(IndAppDestroy(&app));
    PetscCall(PetscFinalize());
    return ok ? 0 : 1;
  }
}
