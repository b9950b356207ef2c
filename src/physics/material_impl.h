#pragma once
/* Private to src/physics/: the fields of IndMaterials. Other groups use the accessors of
   ind_material.h. */
#include "ind_material.h"

struct _p_IndMaterials {
  PetscInt    n;
  IndMaterial mat[IND_MAX_REGIONS];
  PetscInt   *cell_material; /* per local cell of the discretisation: index into mat */
};
