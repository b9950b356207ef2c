#pragma once
/* Private to src/mesh/: the fields of IndDisc. Other groups use the accessors of
   ind_disc.h. */
#include "ind_disc.h"

struct _p_IndDisc {
  DM               dm; /* borrowed from the mesh; carries the field and its section */
  PetscFE          fe;
  PetscInt         degree;
  PetscBool        simplex;
  PetscInt         dim;   /* of the cells: 3, or 2 for the axisymmetric model */
  PetscInt         nq;    /* quadrature points per cell */
  PetscInt         nb;    /* scalar basis functions (nodes) per cell */
  PetscInt         ndof;  /* 3 * nb */
  const PetscReal *w;     /* reference quadrature weights (owned by the quadrature) */
  PetscReal       *N;     /* nq x nb reference shape function values */
  PetscReal       *dN;    /* nq x nb x 3 reference gradients (the third 0 on 2D cells) */
  PetscInt         ncell; /* local cells, numbered cStart + i */
  PetscInt         cStart;
  PetscInt        *lnode; /* ncell x nb local node numbers, closure order: node n's dofs are 3 n, 3 n + 1, 3 n + 2 */
  PetscInt        *gnode; /* ncell x nb global node numbers (the same nodes) */
  PetscReal       *wdetJ; /* ncell x nq: weight times det J, and */
  PetscReal       *invJ;  /* ncell x nq x 9: invJ[k*3+j] = d xi_k / d x_j, kept only for cells whose coordinate map
                             the displacement basis cannot hold (second-order cells under P1/Q1); NULL otherwise */
  Vec              Xloc;  /* position of every displacement node, local vector of the displacement's layout */
  IndDiscLayout    layout; /* the fields above, as the other groups read them */
};
