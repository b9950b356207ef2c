#include "heldlu.h"

typedef struct {
  IndBC       bc;
  PetscInt    nheld, *held; /* the held rows of the last set-up (owned, global, sorted) */
  PetscScalar *dinv;        /* 1 / their diagonal */
  IS          free;
  Mat         Aff;
  KSP         inner;
  VecScatter  scatter;
  Vec         bf, xf, diag; /* the free block's right-hand side and solution; the whole matrix's diagonal */
} HeldLU;

static const char *const HeldLUName = "held rows apart, the free block factored";

/* The rows held now, sorted, against those of the last set-up: a change (a condition moved) rebuilds the
   free block's index set and everything made from it. */
static PetscErrorCode UpdateFreeRows(HeldLU *h, Mat P)
{
  const PetscInt *rows;
  PetscInt        n, rstart, rend, *sorted, *freerows, nfree = 0;
  PetscBool       same;

  PetscFunctionBeginUser;
  PetscCall(IndBCGetRows(h->bc, &n, &rows, NULL));
  PetscCall(PetscMalloc1(n, &sorted));
  PetscCall(PetscArraycpy(sorted, rows, n));
  PetscCall(PetscSortInt(n, sorted));
  same = (h->free && n == h->nheld) ? PETSC_TRUE : PETSC_FALSE;
  if (same) PetscCall(PetscArraycmp(sorted, h->held, n, &same));
  {
    PetscMPIInt all = same ? 1 : 0;
    PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &all, 1, MPI_INT, MPI_MIN, PetscObjectComm((PetscObject)P)));
    same = all ? PETSC_TRUE : PETSC_FALSE;
  }
  if (same) {
    PetscCall(PetscFree(sorted));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(PetscFree(h->held));
  PetscCall(PetscFree(h->dinv));
  h->held  = sorted;
  h->nheld = n;
  PetscCall(PetscMalloc1(n, &h->dinv));
  if (h->free) PetscCall(KSPReset(h->inner)); /* the free block's size changes */
  PetscCall(ISDestroy(&h->free));
  PetscCall(MatDestroy(&h->Aff));
  PetscCall(VecScatterDestroy(&h->scatter));
  PetscCall(VecDestroy(&h->bf));
  PetscCall(VecDestroy(&h->xf));
  PetscCall(VecDestroy(&h->diag));
  PetscCall(MatGetOwnershipRange(P, &rstart, &rend));
  PetscCall(PetscMalloc1(rend - rstart - n, &freerows));
  for (PetscInt r = rstart, k = 0; r < rend; ++r) {
    while (k < n && sorted[k] < r) ++k;
    if (k < n && sorted[k] == r) continue;
    freerows[nfree++] = r;
  }
  PetscCall(ISCreateGeneral(PetscObjectComm((PetscObject)P), nfree, freerows, PETSC_OWN_POINTER, &h->free));
  PetscCall(MatCreateVecs(P, &h->diag, NULL));
  PetscCall(VecCreateMPI(PetscObjectComm((PetscObject)P), nfree, PETSC_DETERMINE, &h->bf));
  PetscCall(VecDuplicate(h->bf, &h->xf));
  PetscCall(VecScatterCreate(h->diag, h->free, h->bf, NULL, &h->scatter));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode SetUp(PC pc)
{
  HeldLU            *h;
  Mat                P;
  const PetscScalar *dv;
  PetscInt           rstart;

  PetscFunctionBeginUser;
  PetscCall(PCShellGetContext(pc, &h));
  PetscCall(PCGetOperators(pc, NULL, &P));
  PetscCall(UpdateFreeRows(h, P));
  PetscCall(MatCreateSubMatrix(P, h->free, h->free, h->Aff ? MAT_REUSE_MATRIX : MAT_INITIAL_MATRIX, &h->Aff));
  PetscCall(KSPSetOperators(h->inner, h->Aff, h->Aff));
  PetscCall(KSPSetUp(h->inner));
  PetscCall(MatGetDiagonal(P, h->diag));
  PetscCall(MatGetOwnershipRange(P, &rstart, NULL));
  PetscCall(VecGetArrayRead(h->diag, &dv));
  for (PetscInt k = 0; k < h->nheld; ++k) h->dinv[k] = 1.0 / dv[h->held[k] - rstart];
  PetscCall(VecRestoreArrayRead(h->diag, &dv));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Apply(PC pc, Vec x, Vec y)
{
  HeldLU            *h;
  const PetscScalar *xv;
  PetscScalar       *yv;
  PetscInt           rstart;

  PetscFunctionBeginUser;
  PetscCall(PCShellGetContext(pc, &h));
  PetscCall(VecScatterBegin(h->scatter, x, h->bf, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(h->scatter, x, h->bf, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(KSPSolve(h->inner, h->bf, h->xf));
  PetscCall(KSPCheckSolve(h->inner, pc, h->xf));
  PetscCall(VecScatterBegin(h->scatter, h->xf, y, INSERT_VALUES, SCATTER_REVERSE));
  PetscCall(VecScatterEnd(h->scatter, h->xf, y, INSERT_VALUES, SCATTER_REVERSE));
  PetscCall(VecGetOwnershipRange(y, &rstart, NULL));
  PetscCall(VecGetArrayRead(x, &xv));
  PetscCall(VecGetArray(y, &yv));
  for (PetscInt k = 0; k < h->nheld; ++k) yv[h->held[k] - rstart] = h->dinv[k] * xv[h->held[k] - rstart];
  PetscCall(VecRestoreArray(y, &yv));
  PetscCall(VecRestoreArrayRead(x, &xv));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode View(PC pc, PetscViewer viewer)
{
  HeldLU   *h;
  PetscBool ascii;
  PetscInt  nheld;

  PetscFunctionBeginUser;
  PetscCall(PCShellGetContext(pc, &h));
  PetscCall(PetscObjectTypeCompare((PetscObject)viewer, PETSCVIEWERASCII, &ascii));
  if (!ascii) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCallMPI(MPI_Allreduce(&h->nheld, &nheld, 1, MPIU_INT, MPI_SUM, PetscObjectComm((PetscObject)pc)));
  PetscCall(PetscViewerASCIIPrintf(viewer, "%s: %" PetscInt_FMT " held rows\n", HeldLUName, nheld));
  PetscCall(PetscViewerASCIIPushTab(viewer));
  PetscCall(KSPView(h->inner, viewer));
  PetscCall(PetscViewerASCIIPopTab(viewer));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Destroy(PC pc)
{
  HeldLU *h;

  PetscFunctionBeginUser;
  PetscCall(PCShellGetContext(pc, &h));
  PetscCall(PetscFree(h->held));
  PetscCall(PetscFree(h->dinv));
  PetscCall(ISDestroy(&h->free));
  PetscCall(MatDestroy(&h->Aff));
  PetscCall(KSPDestroy(&h->inner));
  PetscCall(VecScatterDestroy(&h->scatter));
  PetscCall(VecDestroy(&h->bf));
  PetscCall(VecDestroy(&h->xf));
  PetscCall(VecDestroy(&h->diag));
  PetscCall(PetscFree(h));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndHeldLUSetUp(PC pc, IndBC bc)
{
  HeldLU   *h;
  PC        ipc;
  PetscBool mumps;

  PetscFunctionBeginUser;
  PetscCall(PetscNew(&h));
  h->bc = bc;
  PetscCall(KSPCreate(PetscObjectComm((PetscObject)pc), &h->inner));
  PetscCall(KSPSetOptionsPrefix(h->inner, "free_"));
  PetscCall(KSPSetType(h->inner, KSPPREONLY));
  PetscCall(KSPGetPC(h->inner, &ipc));
  PetscCall(PCSetType(ipc, PCLU));
  PetscCall(PetscHasExternalPackage("mumps", &mumps));
  if (mumps) PetscCall(PCFactorSetMatSolverType(ipc, MATSOLVERMUMPS));
  PetscCall(KSPSetFromOptions(h->inner));
  PetscCall(PCSetType(pc, PCSHELL));
  PetscCall(PCShellSetContext(pc, h));
  PetscCall(PCShellSetName(pc, HeldLUName));
  PetscCall(PCShellSetSetUp(pc, SetUp));
  PetscCall(PCShellSetApply(pc, Apply));
  PetscCall(PCShellSetView(pc, View));
  PetscCall(PCShellSetDestroy(pc, Destroy));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndHeldLUGetFreeKSP(PC pc, KSP *free)
{
  PetscBool   shell, ours = PETSC_FALSE;
  const char *name = NULL;

  PetscFunctionBeginUser;
  *free = NULL;
  PetscCall(PetscObjectTypeCompare((PetscObject)pc, PCSHELL, &shell));
  if (shell) PetscCall(PCShellGetName(pc, &name));
  if (name) PetscCall(PetscStrcmp(name, HeldLUName, &ours));
  if (ours) {
    HeldLU *h;
    PetscCall(PCShellGetContext(pc, &h));
    *free = h->inner;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}
