#pragma once
/* Galerkin products C = P^T A P by blocks, for GAMG's coarse operators. The Jacobian's rows come in node triples with
   one pattern of whole 3 x 3 blocks, GAMG's interpolations in node triples with blocks of 6 columns (the rigid-body
   modes of an aggregate), its coarse operators in 6 x 6 blocks (ind_blockmult.h). PETSc's AIJ products walk that
   structure one entry at a time and hold the product A P (or its pieces) while they run; here each block is a small
   dense product, C's pattern is found from the blocks, and A P is never held: a row of blocks of A P is made, added
   into C and dropped. On several ranks the rows of P that A's ghost columns need are fetched once per pattern, and
   the blocks of C that other ranks own are sent to them (doc/performance.md, "The Galerkin products by blocks").

   Installed on A: PETSc's PtAP with A (MatPtAP, MatProductCreate) then runs here when A and P are both SeqAIJ or
   both MPIAIJ and made of whole blocks on every rank (A's block size, P's column block size, both 2 or more), and
   through PETSc's own product otherwise, as do A's other products. The C it makes has the products installed in
   turn, so that a hierarchy built level by level from A uses them all the way down. A change of A's nonzero pattern
   after C was made is an error (GAMG makes C anew when it rebuilds). */
#include <petscmat.h>
#include "ind_common.h"

/* Routes A's PtAP products through the products by blocks (any other matrix type is left alone). */
PetscErrorCode IndGalerkinInstall(Mat A);
/* Whether C was made by the products by blocks (false for a product PETSc made, or any other matrix). */
PetscErrorCode IndGalerkinByBlocks(Mat C, PetscBool *by_blocks);
