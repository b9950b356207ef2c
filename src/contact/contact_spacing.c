/* The spacing of the contact surface's nodes against the distance from the indenter's axis, which the
   load steps follow (IndContactEdgeDepth): how far the contact's edge may move in one step
   (doc/load-steps.md). */
#include "contact_impl.h"

/* Bins of the table: enough for the finest spacing on the largest surface, but bounded. */
#define IND_SPACING_MAX_BINS 65536

/* The node's spacing from its tributary area: the side of a square of that area on a 3D surface, the
   radial width of a ring of that area on a section (the axis node, a disc, has no width of its own: its
   neighbour's covers it). */
static PetscReal NodeSpacing(IndContact c, PetscInt i, PetscReal r)
{
  if (!c->axisymmetric) return PetscSqrtReal(PetscMax(c->A[i], 0.0));
  return r > 0 ? PetscMax(c->A[i], 0.0) / (2 * PETSC_PI * r) : 0.0;
}

static PetscReal NodeRadius(IndContact c, PetscInt i)
{
  return PetscSqrtReal(PetscSqr(c->X[3 * i] - c->axis_c[0]) + PetscSqr(c->X[3 * i + 1] - c->axis_c[1]));
}

PetscErrorCode IndContactSpacingSetUp(IndContact c)
{
  PetscReal lim[2] = {PETSC_MAX_REAL, 0}; /* smallest spacing, largest radius + spacing */

  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < c->n; ++i) {
    const PetscReal r = NodeRadius(c, i), s = NodeSpacing(c, i, r);
    if (s <= 0) continue;
    lim[0] = PetscMin(lim[0], s);
    lim[1] = PetscMax(lim[1], r + s);
  }
  lim[0] = -lim[0];
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, lim, 2, MPIU_REAL, MPIU_MAX, c->comm));
  lim[0] = -lim[0];
  c->spacing_nbins = 0;
  if (lim[0] >= PETSC_MAX_REAL || lim[1] <= 0) PetscFunctionReturn(PETSC_SUCCESS); /* no surface with an area */
  c->spacing_width = PetscMax(0.5 * lim[0], lim[1] / (IND_SPACING_MAX_BINS - 1));
  c->spacing_nbins = (PetscInt)(lim[1] / c->spacing_width) + 2;
  PetscCall(PetscCalloc1(c->spacing_nbins, &c->spacing));
  /* each node's spacing holds over its neighbourhood, r - s to r + s; where several cover a radius the
     largest holds (a node on a symmetry plane has half an area, a P2 corner less than its edges) */
  for (PetscInt i = 0; i < c->n; ++i) {
    const PetscReal r = NodeRadius(c, i), s = NodeSpacing(c, i, r);
    const PetscInt  b0 = (PetscInt)(PetscMax(r - s, 0.0) / c->spacing_width);
    const PetscInt  b1 = PetscMin((PetscInt)((r + s) / c->spacing_width), c->spacing_nbins - 1);
    for (PetscInt b = b0; b <= b1; ++b) c->spacing[b] = PetscMax(c->spacing[b], s);
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, c->spacing, (PetscMPIInt)c->spacing_nbins, MPIU_REAL, MPIU_MAX, c->comm));
  /* the finest within each radius: a contact of radius r holds every node inside it, and where its cells are
     finest a step's strain increment is largest (3D meshes coarsen before the contact's edge) */
  for (PetscInt b = 1; b < c->spacing_nbins; ++b)
    if (c->spacing[b - 1] > 0 && (c->spacing[b] <= 0 || c->spacing[b - 1] < c->spacing[b]))
      c->spacing[b] = c->spacing[b - 1];
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscReal IndContactSpacing(IndContact c, PetscReal r)
{
  PetscInt b;

  if (c->spacing_nbins == 0 || r < 0) return 0.0;
  b = (PetscInt)(r / c->spacing_width);
  return b < c->spacing_nbins ? c->spacing[b] : 0.0;
}

PetscReal IndContactEdgeDepth(IndContact c, PetscReal depth0, PetscReal depth1, PetscReal per_cell)
{
  const PetscReal r0 = IndIndenterEdgeRadius(&c->indenter, depth0), s = IndContactSpacing(c, r0);
  PetscReal       depth;

  /* until the edge has passed the first spacing the contact is a node or a ring: there is no edge to follow */
  if (per_cell <= 0 || s <= 0 || r0 < s) return depth1;
  depth = IndIndenterEdgeDepth(&c->indenter, r0 + s / per_cell);
  return PetscMin(depth1, depth);
}

PetscReal IndContactEdgeAdvance(IndContact c, PetscReal depth0, PetscReal depth1)
{
  const PetscReal r0 = IndIndenterEdgeRadius(&c->indenter, depth0), s = IndContactSpacing(c, r0);

  if (s <= 0 || depth1 <= depth0 || r0 < s) return 0.0; /* as IndContactEdgeDepth: no edge before the first spacing */
  return (IndIndenterEdgeRadius(&c->indenter, depth1) - r0) / s;
}
