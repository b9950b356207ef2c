static const char help[] = "The Jacobian's pattern from the cells (IndPatternFromCells) against PETSc's own for the\n"
                           "same mesh and field (DMCreateMatrix): every local row has the same columns, on any rank\n"
                           "count (the couplings other ranks' cells give a rank's nodes included).\n";

#include "ind_app.h"
#include "ind_pattern.h"

int main(int argc, char **argv)
{
  IndApp   app;
  DM       dm;
  Mat      A, J;
  PetscInt m, M, rstart, rend, bad = 0, entries = 0;

  PetscFunctionBeginUser;
  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  PetscCall(IndAppCreate(PETSC_COMM_WORLD, &app));
  dm = IndAppGetDM(app);
  PetscCall(DMSetMatType(dm, MATAIJ));
  PetscCall(DMCreateMatrix(dm, &A));
  PetscCall(MatGetLocalSize(A, &m, NULL));
  PetscCall(MatGetSize(A, &M, NULL));
  PetscCall(MatCreate(PETSC_COMM_WORLD, &J));
  PetscCall(MatSetSizes(J, m, m, M, M));
  PetscCall(MatSetType(J, MATAIJ));
  PetscCall(MatSetBlockSize(J, 3));
  PetscCall(IndPatternFromCells(IndAppGetDisc(app), J));
  PetscCall(MatGetOwnershipRange(A, &rstart, &rend));
  for (PetscInt r = rstart; r < rend; ++r) {
    const PetscInt *ca, *cj;
    PetscInt        na, nj;
    PetscCall(MatGetRow(A, r, &na, &ca, NULL));
    PetscCall(MatGetRow(J, r, &nj, &cj, NULL));
    if (na != nj) ++bad;
    else
      for (PetscInt k = 0; k < na; ++k) bad += ca[k] != cj[k];
    entries += nj;
    PetscCall(MatRestoreRow(J, r, &nj, &cj, NULL));
    PetscCall(MatRestoreRow(A, r, &na, &ca, NULL));
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &bad, 1, MPIU_INT, MPI_SUM, PETSC_COMM_WORLD));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &entries, 1, MPIU_INT, MPI_SUM, PETSC_COMM_WORLD));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%" PetscInt_FMT " rows, %" PetscInt_FMT " entries; %" PetscInt_FMT
    " rows or columns differ from PETSc's pattern\n", M, entries, bad));
  PetscCall(MatDestroy(&J));
  PetscCall(MatDestroy(&A));
  PetscCall(IndAppDestroy(&app));
  PetscCall(PetscFinalize());
  return bad ? 1 : 0;
}
