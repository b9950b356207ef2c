#pragma once
/* Private to src/analysis/: the fields of IndSummary. Other groups use the accessors of
   ind_summary.h. */
#include "ind_summary.h"

struct _p_IndSummary {
  MPI_Comm       comm;
  IndOPParams    op;
  IndCurvePoint *pts; /* accepted steps */
  PetscInt       n, cap;
  PetscInt       min_contact_nodes; /* nodes in contact at P_max, whole indent, for an Oliver-Pharr analysis */
};
