#pragma once
/* The displacement space (PetscFE on the mesh), its one quadrature rule, and per-cell data cached
   once so the assembly loops never query the mesh: closure indices and inverse Jacobians. */
#include <petscdmplex.h>
#include "ind_mesh.h"
#include "ind_mat3.h"

typedef struct _p_IndDisc *IndDisc;

/* The discrete space as the cell loops read it: tabulations and per-cell indices, owned by the IndDisc and
   read-only to everyone else (IndDiscGetLayout), so a loop touches plain arrays and calls no function per point. */
typedef struct {
  PetscInt         degree;
  PetscBool        simplex;
  PetscBool        axisymmetric; /* 2D cells in the plane y = 0, x the radius: weights 2 pi r, hoop strain u_x / r */
  PetscInt         nq;    /* quadrature points per cell */
  PetscInt         nb;    /* scalar basis functions (nodes) per cell */
  PetscInt         ndof;  /* 3 * nb */
  const PetscReal *w;     /* reference quadrature weights */
  const PetscReal *N;     /* nq x nb reference shape function values */
  const PetscReal *dN;    /* nq x nb x 3 reference gradients (the third 0 on 2D cells) */
  PetscInt         ncell; /* local cells, numbered cStart + i */
  PetscInt         cStart;
  const PetscInt  *lnode; /* ncell x nb local node numbers, closure order: node n's dofs are 3 n, 3 n + 1, 3 n + 2 in
                             a local vector (in a global one for gnode) */
  const PetscInt  *gnode; /* ncell x nb global node numbers (the same nodes) */
  const PetscReal *wdetJ; /* ncell x nq: weight times det J, and */
  const PetscReal *invJ;  /* ncell x nq x 9: invJ[k*3+j] = d xi_k / d x_j, kept only for cells whose coordinate map
                             the displacement basis cannot hold (second-order cells under P1/Q1); NULL otherwise */
} IndDiscLayout;

PetscErrorCode IndDiscCreate(IndMesh mesh, IndDisc *disc);
/* The layout above (valid until IndDiscDestroy). */
PetscErrorCode IndDiscGetLayout(IndDisc disc, const IndDiscLayout **layout);
/* The mesh's DM, which carries the displacement field and its section (borrowed). */
PetscErrorCode IndDiscGetDM(IndDisc disc, DM *dm);
/* The position of every displacement node, a local vector of the displacement's layout (borrowed). */
PetscErrorCode IndDiscGetNodePositions(IndDisc disc, Vec *Xloc);
PetscErrorCode IndDiscDestroy(IndDisc *disc);
/* Positions of the quadrature points, ncell x nq x 3 (PetscFree them): for body forces. */
PetscErrorCode IndDiscQuadraturePoints(IndDisc disc, PetscReal **xq);
/* Global vector of the position of every displacement node (for the rigid-body modes). */
PetscErrorCode IndDiscNodeCoordinates(IndDisc disc, Vec *coords);

/* The dofs of mesh point p in the displacement's section s: 0 outside its chart, which spans only the points that
   carry dofs (a closure's faces and edges lie outside it on a P1 mesh). */
static inline PetscErrorCode IndDiscPointDof(PetscSection s, PetscInt p, PetscInt *dof)
{
  PetscInt pStart, pEnd;

  PetscFunctionBeginUser;
  PetscCall(PetscSectionGetChart(s, &pStart, &pEnd));
  *dof = 0;
  if (p >= pStart && p < pEnd) PetscCall(PetscSectionGetDof(s, p, dof));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The positions (nb x 3) of the nodes of local cell i, from xn, the array of Xloc. */
static inline void IndDiscCellNodes(const IndDiscLayout *disc, PetscInt i, const PetscScalar *xn, PetscReal *xc)
{
  const PetscInt *node = disc->lnode + i * disc->nb;
  for (PetscInt a = 0; a < disc->nb; ++a)
    for (int c = 0; c < 3; ++c) xc[3 * a + c] = PetscRealPart(xn[3 * node[a] + c]);
}

/* The dofs (3 nb) of local cell i, in a global vector's numbering if global, else in a local vector's. */
static inline void IndDiscCellDofs(const IndDiscLayout *disc, PetscInt i, PetscBool global, PetscInt *dofs)
{
  const PetscInt *node = (global ? disc->gnode : disc->lnode) + i * disc->nb;
  for (PetscInt a = 0; a < disc->nb; ++a)
    for (int c = 0; c < 3; ++c) dofs[3 * a + c] = 3 * node[a] + c;
}

/* The Jacobian J (row-major, J[3 d + k] = d x_d / d xi_k) of the map from the reference cell, from the node
   positions xc and the reference gradients dN of one point. A 2D cell lies in the plane y = 0: its third
   reference direction is mapped onto -y, so that det J is its area's and the gradients have no y part. */
static inline PetscReal IndDiscJacobian(PetscInt n, PetscBool planar, const PetscReal *xc, const PetscReal *dN,
                                        PetscReal J[9])
{
  for (int k = 0; k < 9; ++k) J[k] = 0.0;
  for (PetscInt a = 0; a < n; ++a)
    for (int d = 0; d < 3; ++d)
      for (int k = 0; k < 3; ++k) J[3 * d + k] += xc[3 * a + d] * dN[3 * a + k];
  if (planar) J[5] = -1.0;
  return IndDet3(J);
}

/* Physical shape-function gradients G (nb x 3) at quadrature point q of local cell i, whose node
   positions are xc (IndDiscCellNodes); returns the quadrature weight times det J, and on an axisymmetric
   section times 2 pi r, the volume of revolution. There hoop (nb) receives N_a / r, the hoop strain's
   derivative in u_x of node a; it is left alone in 3D. The Jacobian of the coordinate map is recomputed here
   rather than stored: 80 bytes a quadrature point, 640 a hexahedron, against some 80 flops a point. */
static inline PetscReal IndDiscGradients(const IndDiscLayout *disc, PetscInt i, const PetscReal *xc, PetscInt q,
                                         PetscReal *G, PetscReal *hoop)
{
  const PetscInt   nb = disc->nb;
  const PetscReal *dN = disc->dN + q * nb * 3, *iJ;
  PetscReal        Ji[9], w;

  if (disc->invJ) {
    iJ = disc->invJ + (i * disc->nq + q) * 9;
    w  = disc->wdetJ[i * disc->nq + q];
  } else {
    PetscReal J[9], det;
    det = IndDiscJacobian(nb, disc->axisymmetric, xc, dN, J);
    IndInverse3(J, det, Ji);
    iJ = Ji;
    w  = disc->w[q] * PetscAbsReal(det); /* a section's cells may be drawn either way round */
  }
  for (PetscInt a = 0; a < nb; ++a)
    for (PetscInt j = 0; j < 3; ++j) G[a * 3 + j] = dN[a * 3 + 0] * iJ[0 * 3 + j] + dN[a * 3 + 1] * iJ[1 * 3 + j]
      + dN[a * 3 + 2] * iJ[2 * 3 + j];
  if (disc->axisymmetric) {
    const PetscReal *N = disc->N + q * nb;
    PetscReal        r = 0.0;
    for (PetscInt a = 0; a < nb; ++a) r += N[a] * xc[3 * a];
    /* quadrature points lie inside the cells, so r > 0 even on cells that touch the axis */
    for (PetscInt a = 0; a < nb; ++a) hoop[a] = N[a] / r;
    w *= 2.0 * PETSC_PI * r;
  }
  return w;
}
