#pragma once
/* A direct solve that leaves out the held rows (src/solvers/heldlu.c). The boundary conditions replace every
   held (constrained) row and column of the Jacobian by the identity's (IndBCApplyJacobian), so the system is
   block diagonal: [A_ff 0; 0 D_hh]. The free block is factored alone and the held rows divided by their
   diagonal, which is exact. A factorization of the whole matrix would carry the held rows' stored zeros into
   its pattern: on an axisymmetric section the hoop third of the unknowns, held everywhere, would couple every
   node's three unknowns in the fill instead of two. */
#include <petscksp.h>
#include "ind_bc.h"

/* Makes pc that preconditioner (a PCSHELL) over the rows bc holds at each set-up. The free block's solver is
   -free_ksp_type preonly -free_pc_type lu with MUMPS by default; -free_* options change it. */
PetscErrorCode IndHeldLUSetUp(PC pc, IndBC bc);
/* The free block's KSP of pc (NULL if pc is not a held-rows LU). */
PetscErrorCode IndHeldLUGetFreeKSP(PC pc, KSP *free);
