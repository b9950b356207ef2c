static const char help[] = "The displacement's layout against PETSc's own: the section charted over the points\n"
                           "that carry dofs numbers every dof (local and global) as DMPlexCreateSection's\n"
                           "section over the whole mesh does, and the cells' node numbers give the closure\n"
                           "indices of that section.\n";

#include "ind_app.h"

/* The section DMPlexCreateSection makes for the field of dm, over every point, and its global section: on a clone
   whose section is made anew (the clone shares the mesh and the field). */
static PetscErrorCode FullSections(DM dm, DM *clone, PetscSection *full, PetscSection *gfull)
{
  PetscFunctionBeginUser;
  PetscCall(DMClone(dm, clone));
  PetscCall(DMCopyDisc(dm, *clone));
  PetscCall(DMSetLocalSection(*clone, NULL));
  PetscCall(DMGetLocalSection(*clone, full));
  PetscCall(DMGetGlobalSection(*clone, gfull));
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  IndApp                 app;
  DM                     dm, clone;
  PetscSection           s, gs, full, gfull;
  ISLocalToGlobalMapping ltog;
  const IndDiscLayout   *L;
  PetscInt               pStart, pEnd, fStart, fEnd, bad = 0, points = 0, charted = 0, *dofs, *gdofs;

  PetscFunctionBeginUser;
  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  PetscCall(IndAppCreate(PETSC_COMM_WORLD, &app));
  dm = IndAppGetDM(app);
  PetscCall(IndDiscGetLayout(IndAppGetDisc(app), &L));
  PetscCall(DMGetLocalSection(dm, &s));
  PetscCall(DMGetGlobalSection(dm, &gs));
  PetscCall(FullSections(dm, &clone, &full, &gfull));
  PetscCall(PetscSectionGetChart(s, &pStart, &pEnd));
  PetscCall(PetscSectionGetChart(full, &fStart, &fEnd));
  /* every point of the whole chart: the same dofs, the same local and global offsets where there are dofs, and no
     point with dofs outside the short chart */
  for (PetscInt p = fStart; p < fEnd; ++p) {
    PetscInt dof, fdof, off, foff, goff, gfoff;
    PetscCall(IndDiscPointDof(s, p, &dof));
    PetscCall(PetscSectionGetDof(full, p, &fdof));
    if (dof != fdof) ++bad;
    if (!fdof) continue;
    PetscCall(PetscSectionGetOffset(s, p, &off));
    PetscCall(PetscSectionGetOffset(full, p, &foff));
    PetscCall(PetscSectionGetOffset(gs, p, &goff));
    PetscCall(PetscSectionGetOffset(gfull, p, &gfoff));
    if (off != foff || goff != gfoff) ++bad;
  }
  /* the short chart spans only the points that carry dofs: its first and last carry some; P1 and Q1 the vertices */
  if (pEnd > pStart) {
    PetscInt first, last, vStart, vEnd;
    PetscCall(PetscSectionGetDof(s, pStart, &first));
    PetscCall(PetscSectionGetDof(s, pEnd - 1, &last));
    PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
    if (!first || !last || (L->degree == 1 && (pStart != vStart || pEnd != vEnd))) ++bad;
  }
  /* the cells' node numbers against the closure indices of the whole section */
  PetscCall(DMGetLocalToGlobalMapping(clone, &ltog));
  PetscCall(PetscMalloc2(L->ndof, &dofs, L->ndof, &gdofs));
  for (PetscInt i = 0; i < L->ncell; ++i) {
    PetscInt n, *idx = NULL;
    PetscCall(DMPlexGetClosureIndices(clone, full, full, L->cStart + i, PETSC_TRUE, &n, &idx, NULL, NULL));
    PetscCheck(n == L->ndof, PETSC_COMM_SELF, PETSC_ERR_PLIB, "cell %" PetscInt_FMT ": %" PetscInt_FMT " dofs", i, n);
    IndDiscCellDofs(L, i, PETSC_FALSE, dofs);
    for (PetscInt k = 0; k < n; ++k) bad += dofs[k] != idx[k];
    PetscCall(ISLocalToGlobalMappingApply(ltog, n, idx, gdofs));
    IndDiscCellDofs(L, i, PETSC_TRUE, dofs);
    for (PetscInt k = 0; k < n; ++k) bad += dofs[k] != gdofs[k];
    PetscCall(DMPlexRestoreClosureIndices(clone, full, full, L->cStart + i, PETSC_TRUE, &n, &idx, NULL, NULL));
  }
  PetscCall(PetscFree2(dofs, gdofs));
  points  = fEnd - fStart;
  charted = pEnd - pStart;
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &bad, 1, MPIU_INT, MPI_SUM, PETSC_COMM_WORLD));
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &points, 1, MPIU_INT, MPI_SUM, PETSC_COMM_WORLD));
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &charted, 1, MPIU_INT, MPI_SUM, PETSC_COMM_WORLD));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD,
                        "%s%" PetscInt_FMT ": section charted over %" PetscInt_FMT " of %" PetscInt_FMT
                        " points; %" PetscInt_FMT " mismatches\n",
                        L->simplex ? "P" : "Q", L->degree, charted, points, bad));
  if (L->degree == 1 && charted >= points) ++bad; /* L is the app's: read before it goes */
  PetscCall(DMDestroy(&clone));
  PetscCall(IndAppDestroy(&app));
  PetscCall(PetscFinalize());
  return bad ? 1 : 0;
}
