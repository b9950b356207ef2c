#pragma once
/* Products y = A x (and w + A x, A^T x) of an AIJ matrix by block rows. The Jacobian's rows come in node triples
   that share one column pattern made of whole 3 x 3 node blocks (the pattern of IndPatternFromCells), GAMG's
   coarse operators in groups of 6 rows with 6 x 6 blocks, its interpolations in node triples with blocks of 6
   columns: a group's rows can be multiplied together, reading one column index per block instead of one per
   entry and each block of x once, 8.4 bytes per entry of a 3 x 3 block instead of 12. The products are bound by
   memory bandwidth, so this is what a Krylov iteration gains (doc/performance.md, "Products by block rows"). The
   values stay in the matrix's own AIJ arrays; the block index (one integer per block) is built at the first
   product and again when the pattern changes.

   Installed on the rank's diagonal block (MPIAIJ) or on the matrix itself (SeqAIJ) as its MATOP_MULT,
   MATOP_MULT_ADD and MATOP_MULT_TRANSPOSE. A pattern that is not made of whole blocks is multiplied row by row,
   as PETSc would. */
#include <petscmat.h>
#include "ind_common.h"

/* Installs the products on A (AIJ with row and column block sizes of 2 or more; any other matrix is left alone,
   *installed false). */
PetscErrorCode IndBlockMultInstall(Mat A, PetscBool *installed);
/* Whether the products of A use the CPU's vector units where it has them (AVX2; the default) or the portable
   loops: for comparisons and for the tests of both on one machine. Installs nothing by itself. */
PetscErrorCode IndBlockMultUseVectorUnits(Mat A, PetscBool use);
/* Whether the last product of A (its diagonal block) ran by block rows: false before the first product, without
   the product installed, or when the pattern is not made of whole blocks. */
PetscErrorCode IndBlockMultActive(Mat A, PetscBool *active);
/* Single precision for a preconditioner's matrices (doc/performance.md, "Single-precision preconditioner"): the
   products of A read a single-precision copy of its local block's values (4 bytes an entry instead of 8; the sums
   stay in double), made again whenever A's values have changed (PETSc's object state). For matrices that only a
   preconditioner multiplies: GAMG's coarse operators and interpolations. Needs the products installed
   (IndBlockMultInstall); *set (may be NULL) says whether they were there, in a real double-precision build. */
PetscErrorCode IndBlockMultSetSingle(Mat A, PetscBool single, PetscBool *set);
/* Whether the products of A read single precision (IndBlockMultSetSingle). */
PetscErrorCode IndBlockMultGetSingle(Mat A, PetscBool *single);
/* A shell S whose product is J's with J's local block read in single precision, for a smoother of J (J itself
   keeps its double-precision products for the Krylov method). S holds a reference to J; its diagonal is J's.
   Without products by block rows on J, S's products are J's own. */
PetscErrorCode IndBlockMultCreateSingleOperator(Mat J, Mat *S);
