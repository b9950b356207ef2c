#pragma once
/* Private to src/physics/: the fields of IndHistory. Other groups use the accessors of
   ind_history.h. */
#include "ind_history.h"

struct _p_IndHistory {
  DM       dm;     /* clone of the mesh carrying the cell section */
  PetscInt nq;     /* quadrature points per cell */
  PetscInt stride; /* values per cell: nq * IND_HISTORY_NVAL; local cell i starts at i * stride */
  Vec      committed;
};
