#pragma once
/* The loops of the products by block rows (blockmult.c), on raw CSR arrays: pure, no PETSc objects. A matrix's
   rows come in groups of rbs that share one column pattern made of whole blocks of cbs columns; bi and bj index
   the blocks of each group. */
#include <petscsys.h>

/* Inlined into each caller, so that block sizes and flags passed as constants unroll the loops. */
#if defined(__GNUC__) || defined(__clang__)
  #define IND_INLINE static inline __attribute__((always_inline))
#else
  #define IND_INLINE static inline
#endif

typedef struct {
  PetscInt        rbs, cbs; /* rows per group, columns per block */
  PetscInt        ngroup;
  const PetscInt *bi; /* group i's blocks are bj[bi[i]] .. bj[bi[i + 1] - 1] */
  const PetscInt *bj; /* a block's first column */
} IndBlockRows;

/* Whether rows rbs i .. rbs i + rbs - 1 of the CSR (ia, ja) have one column pattern made of whole blocks of cbs
   columns (c .. c + cbs - 1, c a multiple of cbs). */
PetscBool IndBlockRowsGroupFits(const PetscInt *ia, const PetscInt *ja, PetscInt rbs, PetscInt cbs, PetscInt i);
/* Whether this CPU runs the vector kernels (x86-64 with AVX2 and FMA, double precision). */
PetscBool IndBlockRowsCpuSimd(void);
/* y = w + A x (w NULL: y = A x; w may be y); simd: the vector kernels where the block sizes have one. The values
   are a, or af where it is not NULL: a single-precision copy of a (same positions), the sums still in double. */
void IndBlockRowsMult(const IndBlockRows *b, PetscBool simd, const PetscInt *ia, const PetscScalar *a,
                      const float *af, const PetscScalar *x, const PetscScalar *w, PetscScalar *y);
/* y = A^T x, y of ncol entries. */
void IndBlockRowsMultTranspose(const IndBlockRows *b, PetscBool simd, PetscInt ncol, const PetscInt *ia,
                               const PetscScalar *a, const float *af, const PetscScalar *x, PetscScalar *y);
/* The same row by row, for any CSR pattern (m rows). */
void IndRowsMult(PetscInt m, const PetscInt *ia, const PetscInt *ja, const PetscScalar *a, const float *af,
                 const PetscScalar *x, const PetscScalar *w, PetscScalar *y);
void IndRowsMultTranspose(PetscInt m, PetscInt ncol, const PetscInt *ia, const PetscInt *ja, const PetscScalar *a,
                          const float *af, const PetscScalar *x, PetscScalar *y);
