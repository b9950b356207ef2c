#include <stdio.h>
#include "contact_impl.h"

/* The contact's verdicts on a run (run_checks.c and the summary ask them). */

PetscErrorCode IndContactCheckTouched(IndContact c, PetscReal depth_max, PetscInt touching)
{
  PetscFunctionBeginUser;
  PetscCheck(touching > 0, c->comm, PETSC_ERR_USER_INPUT,
             "The indenter did not touch the contact surface '%s' during loading: at the full depth (-load_depth %.6g "
             "nm) no node is in contact (its lowest point at z = %.6g nm, the surface's highest node at z = %.6g "
             "nm); check -load_depth, -indenter_axis, -indenter_surface and the boundary displacements",
             c->surface, (double)depth_max, (double)(c->indenter.surface - depth_max), (double)c->top);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndContactCheckMirror(IndContact c, IndBC bc, PetscReal depth_max, char warning[], size_t len)
{
  const PetscReal edge = IndIndenterEdgeRadius(&c->indenter, depth_max);
  const IndBCSpec *spec;
  PetscInt         nspec;

  PetscFunctionBeginUser;
  warning[0] = 0;
  if (c->axisymmetric) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(IndBCGetSpecs(bc, &nspec, &spec));
  for (PetscInt k = 0; k < nspec; ++k) {
    PetscBool sym;
    PetscCall(PetscStrcmp(spec[k].option, "-bc_symmetry", &sym));
    for (int a = 0; a < 2 && sym; ++a) {
      const PetscReal gap = c->indenter.axis[a] - spec[k].plane;
      if (spec[k].mask != (1 << a) || IndContactPlaneThroughAxis(&spec[k], &c->indenter)) continue;
      PetscCheck(PetscAbsReal(gap) >= edge, c->comm, PETSC_ERR_USER_INPUT,
                 "-bc_symmetry '%s' (the plane %c = %.6g nm) cuts the indenter, whose axis is %.6g nm from it and "
                 "whose contact reaches %.6g nm from the axis at -load_depth %.6g nm: the model would hold it and its "
                 "mirror image overlapping; put -indenter_axis on the plane (a half model) or %.6g nm or more from it "
                 "(a pair of indents)",
                 spec[k].label, "xy"[a], (double)spec[k].plane, (double)PetscAbsReal(gap), (double)edge,
                 (double)depth_max, (double)edge);
      PetscCall(PetscSNPrintf(warning, len,
                              "-bc_symmetry '%s' (the plane %c = %.6g nm) misses the indenter's axis (%.6g, %.6g nm): "
                              "the model holds the indenter's mirror image too, %.6g nm away (a pair of indents), and "
                              "the load is one indenter's; put the axis on the plane for a half model",
                              spec[k].label, "xy"[a], (double)spec[k].plane, (double)c->indenter.axis[0],
                              (double)c->indenter.axis[1], (double)(2 * PetscAbsReal(gap))));
      PetscFunctionReturn(PETSC_SUCCESS);
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndContactCheckEdge(IndContact c, PetscReal depth, char warning[], size_t len)
{
  PetscInt touching = 0;

  PetscFunctionBeginUser;
  warning[0] = 0;
  for (PetscInt i = 0; i < c->n; ++i) touching += c->edge[i] && c->status[i] != IND_CONTACT_OPEN ? 1 : 0;
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &touching, 1, MPIU_INT, MPI_SUM, c->comm));
  if (touching)
    PetscCall(PetscSNPrintf(warning, len,
                            "at depth %.6g nm the contact reaches the edge of the modelled surface '%s' (%" PetscInt_FMT
                            " of its %" PetscInt_FMT " edge nodes touch the indenter): the body is too small for this "
                            "indenter and depth, and the load, hardness and modulus are those of a finite block",
                            (double)depth, c->surface, touching, c->nedge));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndContactCheckArea(IndContact c, PetscReal area_hc, char why[], size_t len)
{
  PetscFunctionBeginUser;
  why[0] = 0;
  if (area_hc > c->surface_area)
    PetscCall(PetscSNPrintf(why, len,
                            "H and E_r withheld: the Oliver-Pharr contact area A(h_c) = %.6g nm^2 exceeds the area of "
                            "the modelled surface '%s' (%.6g nm^2, symmetry included): the indenter is too large for "
                            "this block; model a wider one",
                            (double)area_hc, c->surface, (double)c->surface_area));
  PetscFunctionReturn(PETSC_SUCCESS);
}

void IndContactCheckResolved(IndContact c, PetscInt nodes, PetscInt min_nodes, char why[], size_t len)
{
  /* a section's contact nodes are rings, each one node spacing further out: n of them resolve the contact radius
     as well as the pi n^2 nodes a 3D surface would need */
  const PetscReal whole = c->axisymmetric ? PETSC_PI * nodes * nodes : c->symmetry * (PetscReal)nodes;

  why[0] = 0;
  if (whole < (PetscReal)min_nodes)
    snprintf(why, len,
             "H and E_r withheld: at P_max %" PetscInt_FMT " nodes touch the indenter (about %.0f over the whole "
             "indent%s), fewer than -op_min_contact_nodes %" PetscInt_FMT ": %.1f node spacings across the contact "
             "radius do not resolve its area; indent deeper or refine the mesh under the tip",
             nodes, (double)whole, c->axisymmetric ? " of a 3D mesh as fine" : "", min_nodes,
             (double)PetscSqrtReal(whole / PETSC_PI));
}
