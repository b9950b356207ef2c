#include <stdio.h>
#include <string.h>
#include "ind_runchecks.h"

static PetscBool HasWarning(const IndWarnings *w, const char key[])
{
  for (PetscInt k = 0; k < w->n; ++k)
    if (!strcmp(w->key[k], key)) return PETSC_TRUE;
  return PETSC_FALSE;
}

PetscErrorCode IndWarningsAdd(MPI_Comm comm, IndWarnings *w, const char key[], PetscBool print, const char text[])
{
  PetscFunctionBeginUser;
  if (HasWarning(w, key)) PetscFunctionReturn(PETSC_SUCCESS);
  if (w->n < IND_MAX_WARNINGS) {
    PetscCall(PetscStrncpy(w->key[w->n], key, sizeof(w->key[0])));
    PetscCall(PetscStrncpy(w->text[w->n], text, sizeof(w->text[0])));
    w->n++;
  }
  if (print) PetscCall(PetscFPrintf(comm, PETSC_STDERR, "indent: warning: %s\n", text));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndRunCheckLoadingContact(IndApp app, const IndStepResult *r)
{
  IndContact c = app->contact;

  PetscFunctionBeginUser;
  if (!c || PetscAbsReal(r->t - 1.0) > 1e-12) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCheck(r->contact.contact > 0, app->comm, PETSC_ERR_USER_INPUT,
             "The indenter did not touch the contact surface '%s' during loading: at the full depth (-load_depth %.6g "
               "nm) no node is in contact (its lowest point at z = %.6g nm, the surface's highest node at z = %.6g "
               "nm); check -load_depth, -indenter_axis, -indenter_surface and the boundary displacements",
             c->surface, (double)app->path.depth_max, (double)(c->indenter.surface - app->path.depth_max),
               (double)c->top);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndRunCheckContactEdge(IndContact c, PetscReal depth, char warning[], size_t len)
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

PetscErrorCode IndRunCheckInverted(IndApp app, const char label[], char warning[], size_t len)
{
  DM        dm = app->disc->dm;
  Vec       Uloc;
  PetscInt  counts[2];
  PetscReal jmin;

  PetscFunctionBeginUser;
  warning[0] = 0;
  PetscCall(DMGetLocalVector(dm, &Uloc));
  PetscCall(DMGlobalToLocal(dm, app->U, INSERT_VALUES, Uloc));
  PetscCall(IndAssemblyCountInverted(app->assembly, Uloc, &counts[0], &jmin));
  PetscCall(DMRestoreLocalVector(dm, &Uloc));
  counts[1] = app->disc->ncell;
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, counts, 2, MPIU_INT, MPI_SUM, app->comm));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &jmin, 1, MPIU_REAL, MPIU_MIN, app->comm));
  if (counts[0])
    PetscCall(PetscSNPrintf(warning, len,
                            "%" PetscInt_FMT " of %" PetscInt_FMT " cells are inverted %s (det F <= 0 at a quadrature "
                            "point, smallest %.6g): the displacement there is not physical; refine the mesh, reduce "
                            "the load or depth, or use -formulation finite, which cuts such steps back",
                            counts[0], counts[1], label, (double)jmin));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndRunCheckContactArea(IndContact c, PetscReal area_hc, char warning[], size_t len)
{
  PetscFunctionBeginUser;
  warning[0] = 0;
  if (area_hc > c->surface_area)
    PetscCall(PetscSNPrintf(warning, len,
                            "the Oliver-Pharr contact area A(h_c) = %.6g nm^2 exceeds the area of the modelled "
                            "surface '%s' (%.6g nm^2, symmetry included): the indenter is too large for this block, "
                            "and the hardness and modulus are meaningless",
                            (double)area_hc, c->surface, (double)c->surface_area));
  PetscFunctionReturn(PETSC_SUCCESS);
}

void IndRunCheckContactResolved(IndContact c, PetscInt nodes, PetscInt min_nodes, char why[], size_t len)
{
  const PetscReal whole = c->symmetry * (PetscReal)nodes;

  why[0] = 0;
  if (whole < (PetscReal)min_nodes)
    snprintf(why, len,
             "H and E_r withheld: at P_max %" PetscInt_FMT " nodes touch the indenter (about %.0f over the whole "
             "indent), "
             "fewer than -op_min_contact_nodes %" PetscInt_FMT ": %.1f node spacings across the contact radius do not "
             "resolve its area; indent deeper or refine the mesh under the tip",
             nodes, (double)whole, min_nodes, (double)PetscSqrtReal(whole / PETSC_PI));
}

PetscErrorCode IndRunCheckStep(IndApp app, const IndStepResult *r, IndWarnings *w, PetscBool print)
{
  char text[IND_WARNING_LEN], label[64];

  PetscFunctionBeginUser;
  PetscCall(IndRunCheckLoadingContact(app, r));
  if (app->contact) {
    PetscCall(IndRunCheckContactEdge(app->contact, r->depth, text, sizeof(text)));
    if (text[0]) PetscCall(IndWarningsAdd(app->comm, w, "contact_edge", print, text));
    PetscCall(PetscSNPrintf(label, sizeof(label), "at depth %.6g nm", (double)r->depth));
  } else PetscCall(PetscSNPrintf(label, sizeof(label), "at load factor %.6g", (double)r->lambda));
  /* At finite strain an inverted point fails the step, so an accepted state has none; a warning once
     given is not given again, so the pass over every quadrature point is spared after it. */
  if (app->assembly->formulation == IND_FORMULATION_SMALL && !HasWarning(w, "inverted_cells")) {
    PetscCall(IndRunCheckInverted(app, label, text, sizeof(text)));
    if (text[0]) PetscCall(IndWarningsAdd(app->comm, w, "inverted_cells", print, text));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}
