#pragma once
/* The displacement space (PetscFE on the mesh), its one quadrature rule, and per-cell data cached
   once so the assembly loops never query the mesh: closure indices and inverse Jacobians. */
#include <petscdmplex.h>
#include "ind_mesh.h"

typedef struct _p_IndDisc *IndDisc;
struct _p_IndDisc {
  DM               dm; /* borrowed from the mesh; carries the field and its section */
  PetscFE          fe;
  PetscInt         degree;
  PetscBool        simplex;
  PetscInt         nq;    /* quadrature points per cell */
  PetscInt         nb;    /* scalar basis functions (nodes) per cell */
  PetscInt         ndof;  /* 3 * nb */
  const PetscReal *w;     /* reference quadrature weights (owned by the quadrature) */
  PetscReal       *N;     /* nq x nb reference shape function values */
  PetscReal       *dN;    /* nq x nb x 3 reference gradients */
  PetscInt         ncell; /* local cells, numbered cStart + i */
  PetscInt         cStart;
  PetscInt        *lidx;  /* ncell x ndof local-vector indices, closure order */
  PetscInt        *gidx;  /* ncell x ndof global indices (the same dofs) */
  PetscReal       *wdetJ; /* ncell x nq: weight times Jacobian determinant */
  PetscReal       *invJ;  /* ncell x nq x 9: invJ[k*3+j] = d xi_k / d x_j */
  PetscReal       *xq;    /* ncell x nq x 3: physical quadrature points */
};

PetscErrorCode IndDiscCreate(IndMesh mesh, IndDisc *disc);
PetscErrorCode IndDiscDestroy(IndDisc *disc);
/* Global vector of the position of every displacement node (for the rigid-body modes). */
PetscErrorCode IndDiscNodeCoordinates(IndDisc disc, Vec *coords);

/* Physical shape-function gradients G (nb x 3) of local cell i at quadrature point q. */
static inline void IndDiscGradients(IndDisc disc, PetscInt i, PetscInt q, PetscReal *G)
{
  const PetscReal *dN = disc->dN + q * disc->nb * 3, *iJ = disc->invJ + (i * disc->nq + q) * 9;
  for (PetscInt a = 0; a < disc->nb; ++a)
    for (PetscInt j = 0; j < 3; ++j) G[a * 3 + j] = dN[a * 3 + 0] * iJ[0 * 3 + j] + dN[a * 3 + 1] * iJ[1 * 3 + j]
      + dN[a * 3 + 2] * iJ[2 * 3 + j];
}
