#pragma once
/* Private to src/physics/: the fields of IndHistory. Other groups use the accessors of
   ind_history.h. */
#include "ind_history.h"

struct _p_IndHistory {
  DM       dm;     /* clone of the mesh carrying the cell section */
  PetscInt nq;     /* quadrature points per cell */
  PetscInt nval;   /* values stored per point: IND_HISTORY_NVAL, or IND_HISTORY_NVAL_NO_BACK_STRESS */
  PetscInt stride; /* values per cell: nq * nval; local cell i starts at i * stride */
  Vec      committed;
};

/* A point's stored values h (nval of them) as the whole record the kernels read, and back. */
static inline void IndHistoryUnpack(PetscInt nval, const PetscReal *h, PetscReal rec[IND_HISTORY_NVAL])
{
  if (nval == IND_HISTORY_NVAL) {
    for (int k = 0; k < IND_HISTORY_NVAL; ++k) rec[k] = h[k];
    return;
  }
  for (int k = 0; k < 6; ++k) rec[k] = h[k];
  for (int k = 6; k < 12; ++k) rec[k] = 0.0;
  rec[12] = h[6];
  rec[13] = h[7];
}

static inline void IndHistoryPack(PetscInt nval, const PetscReal rec[IND_HISTORY_NVAL], PetscReal *h)
{
  if (nval == IND_HISTORY_NVAL) {
    for (int k = 0; k < IND_HISTORY_NVAL; ++k) h[k] = rec[k];
    return;
  }
  for (int k = 0; k < 6; ++k) h[k] = rec[k];
  h[6] = rec[12];
  h[7] = rec[13];
}
