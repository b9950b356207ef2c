#pragma once
/* The nonzero pattern of the Jacobian (AIJ, block size 3) from the cells' nodes: every pair of
   nodes that share a cell couples all their components. */
#include <petscmat.h>
#include "ind_disc.h"

/* J: created, sized, of type MATSEQAIJ or MATMPIAIJ with block size 3; on return assembled with its
   pattern, zero. */
PetscErrorCode IndPatternFromCells(IndDisc disc, Mat J);
