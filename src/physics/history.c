#include "history_impl.h"
#include "ind_history.h"

#if defined(PETSC_USE_COMPLEX)
  #error "indent stores quadrature-point history as real numbers: build against a real PETSc"
#endif
_Static_assert(sizeof(IndPlasticState) == IND_HISTORY_DP * sizeof(PetscReal),
  "IndPlasticState must be IND_HISTORY_DP packed reals");

PetscErrorCode IndHistoryCreate(IndDisc space, PetscBool back_stress, IndHistory *out)
{
  IndHistory           h;
  PetscSection         s, gs;
  PetscInt             pStart, pEnd, n;
  DM                   dm;
  const IndDiscLayout *disc;

  PetscFunctionBeginUser;
  PetscCall(IndDiscGetLayout(space, &disc));
  PetscCall(IndDiscGetDM(space, &dm));
  PetscCall(PetscCalloc1(1, &h));
  h->nq     = disc->nq;
  h->nval   = back_stress ? IND_HISTORY_NVAL : IND_HISTORY_NVAL_NO_BACK_STRESS;
  h->stride = disc->nq * h->nval;
  PetscCall(DMClone(dm, &h->dm));
  /* a chart of the cells only: its section and the global one hold two integers a point of the chart, and the
     mesh's faces, edges and vertices are 7 of 8 of its points (34 MB on the plastic cube at 824k dofs) */
  pStart = disc->cStart;
  pEnd   = disc->cStart + disc->ncell;
  PetscCall(PetscSectionCreate(PetscObjectComm((PetscObject)dm), &s));
  PetscCall(PetscSectionSetChart(s, pStart, pEnd));
  for (PetscInt i = 0; i < disc->ncell; ++i) PetscCall(PetscSectionSetDof(s, disc->cStart + i, h->stride));
  PetscCall(PetscSectionSetUp(s));
  PetscCall(DMSetLocalSection(h->dm, s));
  PetscCall(PetscSectionDestroy(&s));
  PetscCall(DMCreateGlobalVector(h->dm, &h->committed));
  PetscCall(PetscObjectSetName((PetscObject)h->committed, "history"));
  PetscCall(VecZeroEntries(h->committed));

  /* The cell loop indexes the history as i * stride: with no cell overlap every cell is owned, so the
     owned part of the global vector is exactly that; check it rather than assume it. */
  PetscCall(VecGetLocalSize(h->committed, &n));
  PetscCheck(n == disc->ncell * h->stride, PETSC_COMM_SELF, PETSC_ERR_PLIB,
    "History holds %" PetscInt_FMT " values for %" PetscInt_FMT " local cells of %" PetscInt_FMT, n, disc->ncell,
    h->stride);
  PetscCall(DMGetGlobalSection(h->dm, &gs));
  {
    PetscInt rstart, off;
    PetscCall(VecGetOwnershipRange(h->committed, &rstart, NULL));
    for (PetscInt i = 0; i < disc->ncell; ++i) {
      PetscCall(PetscSectionGetOffset(gs, disc->cStart + i, &off));
      PetscCheck(off - rstart == i * h->stride, PETSC_COMM_SELF, PETSC_ERR_PLIB,
        "History of cell %" PetscInt_FMT " is not at i * stride", disc->cStart + i);
    }
  }
  *out = h;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndHistoryDestroy(IndHistory *h)
{
  PetscFunctionBeginUser;
  if (!*h) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(VecDestroy(&(*h)->committed));
  PetscCall(DMDestroy(&(*h)->dm));
  PetscCall(PetscFree(*h));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndHistoryState(void *obj, IndStateFile f)
{
  IndHistory   h      = (IndHistory)obj;
  PetscReal    stride = (PetscReal)h->stride;
  PetscScalar *a;

  PetscFunctionBeginUser;
  PetscCall(IndStateReals(f, "stride", 1, &stride));
  PetscCheck((PetscInt)stride == h->stride, PetscObjectComm((PetscObject)h->committed), PETSC_ERR_ARG_INCOMP,
    "-restart: the checkpoint holds %" PetscInt_FMT " history values per cell, this run %" PetscInt_FMT " (another "
    "element or quadrature, or kinematic hardening on one side only: it stores a back stress)", (PetscInt)stride,
    h->stride);
  PetscCall(VecGetArray(h->committed, &a));
  PetscCall(IndStateCells(f, "committed", h->stride, (PetscReal *)a));
  PetscCall(VecRestoreArray(h->committed, &a));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndHistoryGetCommitted(IndHistory h, Vec *committed, PetscInt *stride)
{
  PetscFunctionBeginUser;
  if (committed) *committed = h->committed;
  if (stride) *stride = h->stride;
  PetscFunctionReturn(PETSC_SUCCESS);
}
