#include "contact_impl.h"

/* The contact's part of the state: the committed reactions and node displacements (by node, in the
   displacement's layout), the penalty scale (which the fixed point may have halved), the indenter's
   committed position and a table indenter's points (checked on reading, not restored). */

/* a (3 per contact node) into the contact nodes' rows of the global vector G, zero elsewhere, or back */
static PetscErrorCode Scatter(IndContact c, PetscReal *a, Vec G, PetscBool into)
{
  PetscScalar *g;

  PetscFunctionBeginUser;
  if (into) PetscCall(VecZeroEntries(G));
  PetscCall(VecGetArray(G, &g));
  for (PetscInt i = 0; i < c->n; ++i)
    for (int d = 0; d < 3; ++d) {
      if (into) g[c->row[i] + d] = a[3 * i + d];
      else a[3 * i + d] = PetscRealPart(g[c->row[i] + d]);
    }
  PetscCall(VecRestoreArray(G, &g));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndContactState(void *obj, IndStateFile f)
{
  IndContact c    = (IndContact)obj;
  PetscReal  s[4] = {c->rho_scale, c->depth_c, c->axis_c[0], c->axis_c[1]};
  DM         dm;
  Vec        G;
  struct {
    const char *name;
    PetscReal  *values;
  } nodes[2] = {{"reactions", c->Rc}, {"displacements", c->Uc}};

  PetscFunctionBeginUser;
  PetscCall(IndStateReals(f, "scalars", 4, s));
  if (c->profile) {
    /* the table is read from a file the options only name: a restart must find the same points in it */
    PetscInt   n = 2 * c->indenter.nprofile;
    PetscReal *v = c->profile;
    PetscCall(IndStateRealArray(f, "profile", &n, &v));
    if (IndStateReading(f)) {
      PetscBool same = n == 2 * c->indenter.nprofile ? PETSC_TRUE : PETSC_FALSE;
      for (PetscInt k = 0; same && k < n; ++k) same = v[k] == c->profile[k] ? PETSC_TRUE : PETSC_FALSE;
      PetscCall(PetscFree(v));
      PetscCheck(same, c->comm, PETSC_ERR_USER_INPUT,
        "-indenter_profile: the file's points are not those the checkpoint was made with (%" PetscInt_FMT
        " points now, %" PetscInt_FMT " then): restart with the file as it was", c->indenter.nprofile, n / 2);
    }
  }
  PetscCall(IndDiscGetDM(c->disc, &dm));
  PetscCall(DMGetGlobalVector(dm, &G));
  for (int k = 0; k < 2; ++k) {
    if (!IndStateReading(f)) PetscCall(Scatter(c, nodes[k].values, G, PETSC_TRUE));
    PetscCall(IndStateNodes(f, nodes[k].name, G));
    if (IndStateReading(f)) PetscCall(Scatter(c, nodes[k].values, G, PETSC_FALSE));
  }
  PetscCall(DMRestoreGlobalVector(dm, &G));
  if (!IndStateReading(f)) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscArraycpy(c->R, c->Rc, 3 * c->n));
  c->rho_scale = s[0];
  c->depth_c   = s[1];
  c->axis_c[0] = s[2];
  c->axis_c[1] = s[3];
  PetscCall(IndContactSetIndenterPosition(c, c->depth_c, c->axis_c));
  PetscFunctionReturn(PETSC_SUCCESS);
}
