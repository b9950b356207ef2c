#include <stdio.h>
#include "ind_csm.h"
#include "ind_stepcsv.h"

PetscErrorCode IndCSMStiffness(IndApp app, PetscReal h, PetscReal P, PetscReal area_true, IndCSMPoint *pt)
{
  IndAssembly        a = app->assembly;
  IndContact         c = app->contact;
  IndBC              bc = app->bc;
  const IndTangent   tangent = a->tangent;
  IndMatInsert       insert  = a->insert;
  Mat                K, K0;
  Vec                Uloc, X, B, F;
  KSP                ksp;
  PetscInt           n = 0, *rows, rstart;
  const PetscScalar *f;
  PetscScalar       *x;
  PetscReal          Fz = 0, sqrtpi = PetscSqrtReal(PETSC_PI);
  MatNullSpace       nsp;

  PetscFunctionBeginUser;
  PetscCall(MatDuplicate(app->solver->J, MAT_DO_NOT_COPY_VALUES, &K));
  PetscCall(MatGetNearNullSpace(app->solver->J, &nsp));
  if (nsp) PetscCall(MatSetNearNullSpace(K, nsp));
  /* Unloading is elastic: the elastic tangent at the current state; MatSetValues into the copy, whose
     entries are not where the cached insertion of the solver's matrix points. */
  a->tangent = IND_TANGENT_ELASTIC;
  a->insert  = NULL;
  PetscCall(DMGetLocalVector(app->disc->dm, &Uloc));
  PetscCall(DMGlobalToLocal(app->disc->dm, app->U, INSERT_VALUES, Uloc));
  PetscCall(IndAssemblyJacobian(a, Uloc, K));
  PetscCall(DMRestoreLocalVector(app->disc->dm, &Uloc));
  a->tangent = tangent;
  a->insert  = insert;
  PetscCall(MatDuplicate(K, MAT_COPY_VALUES, &K0));

  /* The increment: the contact nodes rise by 1 nm with the indenter, 0 on the boundary conditions. */
  PetscCall(MatCreateVecs(K, &X, &B));
  PetscCall(VecDuplicate(X, &F));
  PetscCall(VecZeroEntries(X));
  PetscCall(VecZeroEntries(B));
  PetscCall(VecGetOwnershipRange(X, &rstart, NULL));
  PetscCall(PetscMalloc1(bc->nrows + 3 * c->n + 1, &rows));
  for (PetscInt i = 0; i < bc->nrows; ++i) rows[n++] = bc->rows[i];
  PetscCall(VecGetArray(X, &x));
  for (PetscInt i = 0; i < c->n; ++i) {
    if (c->status[i] == IND_CONTACT_OPEN) continue;
    for (int d = 0; d < 3; ++d) {
      /* a sticking node moves with the indenter; a slipping one (every node without friction) only
         follows it vertically */
      if (c->fixed[i] & (1 << d) || (d < 2 && c->status[i] == IND_CONTACT_SLIP)) continue;
      rows[n++] = c->grow[i] + d;
      x[c->row[i] + d] = d == 2 ? 1.0 : 0.0;
    }
  }
  PetscCall(VecRestoreArray(X, &x));
  PetscCall(MatZeroRowsColumns(K, n, rows, 1.0, X, B));
  PetscCall(PetscFree(rows));

  PetscCall(KSPCreate(app->comm, &ksp));
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
    PetscCheck(reason > 0, app->comm, PETSC_ERR_NOT_CONVERGED,
      "-csm_every: the unloading stiffness's linear solve failed (%s)",
               KSPConvergedReasons[reason]);
  }
  /* The force on the body at the contact nodes: the load falls by S per nm the indenter rises. */
  PetscCall(MatMult(K0, X, F));
  PetscCall(VecGetArrayRead(F, &f));
  for (PetscInt i = 0; i < c->n; ++i)
    if (c->status[i] != IND_CONTACT_OPEN) Fz += PetscRealPart(f[c->row[i] + 2]);
  PetscCall(VecRestoreArrayRead(F, &f));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &Fz, 1, MPIU_REAL, MPIU_SUM, app->comm));
  pt->S   = c->symmetry * Fz * 1e-3; /* nN/nm to uN/nm */
  pt->h_c = pt->S > 0 ? h - app->summary->op.epsilon * P / pt->S : 0;
  pt->A   = pt->h_c > 0 ? IndIndenterArea(&c->indenter, pt->h_c) : 0;
  pt->H   = pt->A > 0 ? 1e3 * P / pt->A : 0;
  pt->E_r = pt->A > 0 ? 1e3 * sqrtpi / (2 * app->summary->op.beta) * pt->S / PetscSqrtReal(pt->A) : 0;
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
  char line[512];

  PetscFunctionBeginUser;
  PetscCall(PetscSNPrintf(line, sizeof(line), "%" PetscInt_FMT ",%.12g,%.12g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g", step,
                          (double)h, (double)P, (double)pt->S, (double)pt->h_c, (double)pt->A, (double)pt->H,
                          (double)pt->E_r, (double)pt->a));
  PetscCall(IndStepCSVAppend(comm, dir, IND_CSM_FILE, CSM_HEADER, line));
  PetscFunctionReturn(PETSC_SUCCESS);
}
