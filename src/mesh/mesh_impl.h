#pragma once
/* Private to src/mesh/: the fields of IndMesh. Other groups use the accessors of
   ind_mesh.h. */
#include "ind_mesh.h"

struct _p_IndMesh {
  DM        dm;        /* owned; distributed; each region is a DMLabel of that name with value 1 */
  PetscBool simplex;   /* tetrahedra or triangles (true), hexahedra or quadrilaterals (false); the same on every rank */
  PetscInt  dim;       /* 3, or 2: the axisymmetric model, a mesh in (r, z) placed in the plane y = 0 */
  PetscInt  nregions;
  IndRegion regions[IND_MAX_REGIONS];
  char      source[PETSC_MAX_PATH_LEN]; /* mesh file, or "box" */
};
