#pragma once
/* The Galerkin products by blocks (ind_galerkin.h), shared by galerkin.c (the product's set-up and its phases),
   galerkin_pattern.c (C's pattern, on every rank) and galerkin_rows.c (the loops over the fine rows). */
#include "ind_galerkin.h"
#include "blockmult_kernels.h"

/* The rows of P that the rank's rows of A reach come from up to three SeqAIJ matrices, read in place: P's diagonal
   and off-process blocks (the rank's own rows) and the ghost rows fetched for A's off-process columns. */
enum { IND_GALERKIN_DIAG, IND_GALERKIN_OFF, IND_GALERKIN_GHOST, IND_GALERKIN_NSOURCE };

typedef struct {
  Mat                M;    /* not referenced; NULL where there is none (no off-process part on one rank) */
  PetscInt           row0; /* its first block row among the rows of P that A reaches */
  PetscInt           nrow; /* its block rows */
  PetscInt          *bi, *bj; /* its blocks by rows; bj compact coarse blocks */
  const PetscInt    *ia;      /* during a phase: M's row starts and values */
  const PetscScalar *va;
} IndGalerkinSource;

/* One product C = P^T A P. Fine blocks are A's fbs x fbs blocks (node rows), coarse blocks P's columns in groups of
   cbs, numbered compactly over those the rank's rows reach (cglob gives the global ones, in the same order). */
typedef struct {
  PetscInt          fbs, cbs;
  PetscInt          nfb, ngb; /* the rank's fine block rows; A's off-process fine blocks */
  IndGalerkinSource src[IND_GALERKIN_NSOURCE];
  Mat              *Pg; /* P's rows for A's off-process columns (MPIAIJ) */
  IS                gis, allcols;
  PetscObjectState  pstate, anz, pnz;
  PetscInt          ncomp;
  PetscInt         *cglob;
  PetscInt         *crow; /* compact block -> C's owned block row (>= 0), ghost row g (-(g + 2)), or none (-1) */
  PetscBool         ab;   /* the product A P, not P^T A P */
  PetscInt          cb0, nown; /* the rank's coarse blocks: P's columns */
  /* C's owned block rows (crows of crbs rows: P^T A P's are coarse, A P's fine): their sorted global block columns,
     and where they sit in C's local arrays */
  PetscInt          crows, crbs;
  PetscInt         *ci, *cj;
  PetscInt         *dpos, *opos, *nleft, *ndiag;
  PetscInt          dnz, onz;
  /* C's ghost block rows: the blocks this rank adds to rows that other ranks own, sent to them */
  PetscInt          ngr;
  PetscInt         *gi, *gj;
  PetscScalar      *gv;
  PetscMPIInt      *scount, *sdispl, *rcount, *rdispl; /* scalars sent to and received from each rank */
  PetscInt          nrb;                               /* blocks received */
  PetscInt         *rrow, *rk;                         /* the owned block row and position of each */
  PetscScalar      *rv;
  /* work: one row of blocks of A P */
  PetscInt         *slot, *list, maxap;
  PetscScalar      *apv;
} IndGalerkinPlan;

typedef struct {
  PetscInt  n, cap;
  PetscInt *v;
} IndGalerkinSet;

/* The sources of block row K of the rows of P that A reaches: [first, last] */
static inline void IndGalerkinSources(const IndGalerkinPlan *pl, PetscInt K, int *first, int *last)
{
  *first = K < pl->nfb ? IND_GALERKIN_DIAG : IND_GALERKIN_GHOST;
  *last  = K < pl->nfb ? IND_GALERKIN_OFF : IND_GALERKIN_GHOST;
}

/* galerkin.c: the rank's rows of M, its diagonal block with the off-process block and the latter's global columns
   (SeqAIJ: M itself, no off-process block) */
PetscErrorCode IndGalerkinLocalParts(Mat M, Mat *Md, Mat *Mo, const PetscInt **garray);

/* galerkin_pattern.c */
PetscErrorCode IndGalerkinCompactColumns(IndGalerkinPlan *pl);
PetscErrorCode IndGalerkinSetMerge(IndGalerkinSet *s, PetscInt n, const PetscInt *v, PetscInt **work, PetscInt *nwork);
PetscErrorCode IndGalerkinExchangePatterns(IndGalerkinPlan *pl, Mat P, IndGalerkinSet *sets);
PetscErrorCode IndGalerkinCreateC(IndGalerkinPlan *pl, Mat A, Mat P, Mat C);

/* galerkin_rows.c: ia, ja, av are A's diagonal and off-process blocks (NULL: none), the sources' ia and va set.
   RowsNumeric adds P^T A P, ProductNumeric sets A P. */
PetscErrorCode IndGalerkinApPattern(IndGalerkinPlan *pl, const PetscInt *ia[2], const PetscInt *ja[2], PetscInt row,
                                    PetscInt *nap);
void           IndGalerkinRowsNumeric(IndGalerkinPlan *pl, const PetscInt *ia[2], const PetscInt *ja[2],
                                      const PetscScalar *av[2], PetscScalar *cd, PetscScalar *co,
                                      PetscLogDouble *flops);
void           IndGalerkinProductNumeric(IndGalerkinPlan *pl, const PetscInt *ia[2], const PetscInt *ja[2],
                                         const PetscScalar *av[2], PetscScalar *cd, PetscScalar *co,
                                         PetscLogDouble *flops);
/* Where block k of C's owned block row j sits in the diagonal (cd) or off-process (co) array; *ld its row stride */
PetscScalar   *IndGalerkinOwnedBlock(const IndGalerkinPlan *pl, PetscScalar *cd, PetscScalar *co, PetscInt j,
                                     PetscInt k, PetscInt *ld);
