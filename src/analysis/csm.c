#include <stdio.h>
#include "ind_csm.h"
#include "ind_stepcsv.h"

PetscErrorCode IndCSMStiffness(IndSolver solver, IndBC bc, IndContact c, const IndOPParams *op, Vec U, PetscReal h,
                               PetscReal P, PetscReal area_true, IndCSMPoint *pt)
{
  MPI_Comm        comm = PetscObjectComm((PetscObject)U);
  Mat             K, K0;
  Vec             X, B, F;
  KSP             ksp;
  PetscInt        n = 0, nbc, *rows;
  const PetscInt *bcrows;
  PetscReal       Fz = 0, sqrtpi = PetscSqrtReal(PETSC_PI);

  PetscFunctionBeginUser;
  /* Unloading is elastic: the elastic tangent at the current state. */
  PetscCall(IndSolverElasticStiffness(solver, U, &K));
  PetscCall(MatDuplicate(K, MAT_COPY_VALUES, &K0));

  /* The increment: the contact nodes rise by 1 nm with the indenter, 0 on the boundary conditions. */
  PetscCall(MatCreateVecs(K, &X, &B));
  PetscCall(VecDuplicate(X, &F));
  PetscCall(VecZeroEntries(X));
  PetscCall(VecZeroEntries(B));
  PetscCall(IndBCGetRows(bc, &nbc, &bcrows, NULL));
  PetscCall(PetscMalloc1(nbc + 3 * IndContactGetSize(c) + 1, &rows));
  for (PetscInt i = 0; i < nbc; ++i) rows[n++] = bcrows[i];
  PetscCall(IndContactUnloadingRows(c, X, &n, rows));
  PetscCall(MatZeroRowsColumns(K, n, rows, 1.0, X, B));
  PetscCall(PetscFree(rows));

  PetscCall(KSPCreate(comm, &ksp));
  PetscCall(KSPSetOptionsPrefix(ksp, "csm_"));
  PetscCall(KSPSetType(ksp, KSPCG));
  PetscCall(KSPSetTolerances(ksp, 1e-10, PETSC_DEFAULT, PETSC_DEFAULT, 10000));
  {
    PC pc;
    PetscCall(KSPGetPC(ksp, &pc));
    PetscCall(PCSetType(pc, PCGAMG));
  }
  PetscCall(KSPSetOperators(ksp, K, K));
  PetscCall(KSPSetFromOptions(ksp));
  PetscCall(KSPSetInitialGuessNonzero(ksp, PETSC_TRUE));
  PetscCall(KSPSolve(ksp, B, X));
  {
    KSPConvergedReason reason;
    PetscCall(KSPGetConvergedReason(ksp, &reason));
    PetscCheck(reason > 0, comm, PETSC_ERR_NOT_CONVERGED,
      "-csm_every: the unloading stiffness's linear solve failed (%s)",
               KSPConvergedReasons[reason]);
  }
  /* The force on the body at the contact nodes: the load falls by S per nm the indenter rises. */
  PetscCall(MatMult(K0, X, F));
  PetscCall(IndContactActiveForce(c, F, &Fz));
  pt->S   = Fz * 1e-3; /* nN/nm to uN/nm */
  pt->h_c = pt->S > 0 ? h - op->epsilon * P / pt->S : 0;
  pt->A   = IndIndenterArea(IndContactGetIndenter(c), pt->h_c); /* 0 below the tip, but a punch's face */
  pt->H   = pt->A > 0 ? 1e3 * P / pt->A : 0;
  pt->E_r = pt->A > 0 ? 1e3 * sqrtpi / (2 * op->beta) * pt->S / PetscSqrtReal(pt->A) : 0;
  pt->a   = PetscSqrtReal(area_true / PETSC_PI);
  PetscCall(KSPDestroy(&ksp));
  PetscCall(VecDestroy(&X));
  PetscCall(VecDestroy(&B));
  PetscCall(VecDestroy(&F));
  PetscCall(MatDestroy(&K));
  PetscCall(MatDestroy(&K0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

#define CSM_HEADER "step,depth_nm,load_uN,S_uN_per_nm,h_c_nm,A_nm2,H_GPa,E_r_GPa,contact_radius_nm"

PetscErrorCode IndCSMWrite(MPI_Comm comm, const char dir[], PetscInt step, PetscReal h, PetscReal P,
  const IndCSMPoint *pt)
{
  char line[512], H[32] = "", Er[32] = "";

  PetscFunctionBeginUser;
  /* withheld values (NaN) are empty cells, which spreadsheets and numpy read as missing */
  if (!PetscIsInfOrNanReal(pt->H)) PetscCall(PetscSNPrintf(H, sizeof(H), "%.10g", (double)pt->H));
  if (!PetscIsInfOrNanReal(pt->E_r)) PetscCall(PetscSNPrintf(Er, sizeof(Er), "%.10g", (double)pt->E_r));
  PetscCall(PetscSNPrintf(line, sizeof(line), "%" PetscInt_FMT ",%.12g,%.12g,%.10g,%.10g,%.10g,%s,%s,%.10g", step,
                          (double)h, (double)P, (double)pt->S, (double)pt->h_c, (double)pt->A, H, Er, (double)pt->a));
  PetscCall(IndStepCSVAppend(comm, dir, IND_CSM_FILE, CSM_HEADER, line));
  PetscFunctionReturn(PETSC_SUCCESS);
}
