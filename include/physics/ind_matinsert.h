#pragma once
/* Adding element matrices into the Jacobian without searching its rows: the position of every
   3 x 3 node block of every cell in the rank's AIJ arrays, found once. Blocks of rows another rank owns are
   summed on this rank and only their values sent to the owner's positions at the end (J then takes no
   off-process MatSetValues: MAT_NO_OFF_PROC_ENTRIES). NULL (and MatSetValues for everything) for other matrix
   types or patterns that are not made of node blocks. */
#include <petscmat.h>
#include "ind_disc.h"

typedef struct _p_IndMatInsert *IndMatInsert;

/* J: assembled, with its final nonzero pattern (preallocated by the cells of disc). */
PetscErrorCode IndMatInsertCreate(IndDisc disc, Mat J, IndMatInsert *insert);
PetscErrorCode IndMatInsertDestroy(IndMatInsert *insert);
/* Zeroes J and opens its arrays; then IndMatInsertCell for any cells; End closes and assembles. */
PetscErrorCode IndMatInsertBegin(IndMatInsert insert, Mat J);
PetscErrorCode IndMatInsertCell(IndMatInsert insert, PetscInt cell, const PetscReal *Ke);
/* Asks the memory for the matrix entries IndMatInsertCell will add cell's matrix to, so that their loads overlap
   the arithmetic of the cell matrix instead of waiting at the insertion; between Begin and End. */
void IndMatInsertPrefetch(IndMatInsert insert, PetscInt cell);
PetscErrorCode IndMatInsertEnd(IndMatInsert insert, Mat J);
