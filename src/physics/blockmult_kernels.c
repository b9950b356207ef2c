#include "blockmult_kernels.h"
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__)) && defined(PETSC_USE_REAL_DOUBLE) && \
  !defined(PETSC_USE_COMPLEX)
  #include <immintrin.h>
  #define IND_BLOCKMULT_AVX2 1
  #define IND_AVX2           __attribute__((target("avx2,fma")))
#endif

PetscBool IndBlockRowsCpuSimd(void)
{
#if defined(IND_BLOCKMULT_AVX2)
  __builtin_cpu_init();
  return (PetscBool)(__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma"));
#else
  return PETSC_FALSE;
#endif
}

void IndRowsMult(PetscInt m, const PetscInt *ia, const PetscInt *ja, const PetscScalar *a, const PetscScalar *x,
                 const PetscScalar *w, PetscScalar *y)
{
  for (PetscInt r = 0; r < m; ++r) {
    PetscScalar s = w ? w[r] : 0;
    for (PetscInt k = ia[r]; k < ia[r + 1]; ++k) s += a[k] * x[ja[k]];
    y[r] = s;
  }
}

void IndRowsMultTranspose(PetscInt m, PetscInt ncol, const PetscInt *ia, const PetscInt *ja, const PetscScalar *a,
                          const PetscScalar *x, PetscScalar *y)
{
  for (PetscInt c = 0; c < ncol; ++c) y[c] = 0;
  for (PetscInt r = 0; r < m; ++r)
    for (PetscInt k = ia[r]; k < ia[r + 1]; ++k) y[ja[k]] += a[k] * x[r];
}

/* Any block sizes: a group's rows one after the other, each reading its cbs values per block against the block
   of x (in cache after the group's first row). */
static void GroupMult(const IndBlockRows *b, const PetscInt *ia, const PetscScalar *a, const PetscScalar *x,
                      const PetscScalar *w, PetscScalar *y)
{
  const PetscInt rbs = b->rbs, cbs = b->cbs;

  for (PetscInt i = 0; i < b->ngroup; ++i) {
    const PetscInt nb = b->bi[i + 1] - b->bi[i], *c = b->bj + b->bi[i];
    for (PetscInt r = 0; r < rbs; ++r) {
      const PetscInt     row = rbs * i + r;
      const PetscScalar *v   = a + ia[row];
      PetscScalar        s   = 0;
      for (PetscInt k = 0; k < nb; ++k)
        for (PetscInt d = 0; d < cbs; ++d) s += v[cbs * k + d] * x[c[k] + d];
      y[row] = (w ? w[row] : 0) + s;
    }
  }
}

static void Group33Mult(const IndBlockRows *b, const PetscInt *ia, const PetscScalar *a, const PetscScalar *x,
                        const PetscScalar *w, PetscScalar *y)
{
  for (PetscInt i = 0; i < b->ngroup; ++i) {
    const PetscInt     nb = b->bi[i + 1] - b->bi[i], *c = b->bj + b->bi[i];
    const PetscScalar *v0 = a + ia[3 * i], *v1 = a + ia[3 * i + 1], *v2 = a + ia[3 * i + 2];
    PetscScalar        y0 = 0, y1 = 0, y2 = 0;
    for (PetscInt k = 0; k < nb; ++k) {
      const PetscScalar *xb = x + c[k], x0 = xb[0], x1 = xb[1], x2 = xb[2];
      y0 += v0[3 * k] * x0 + v0[3 * k + 1] * x1 + v0[3 * k + 2] * x2;
      y1 += v1[3 * k] * x0 + v1[3 * k + 1] * x1 + v1[3 * k + 2] * x2;
      y2 += v2[3 * k] * x0 + v2[3 * k + 1] * x1 + v2[3 * k + 2] * x2;
    }
    y[3 * i]     = (w ? w[3 * i] : 0) + y0;
    y[3 * i + 1] = (w ? w[3 * i + 1] : 0) + y1;
    y[3 * i + 2] = (w ? w[3 * i + 2] : 0) + y2;
  }
}

static void GroupMultTranspose(const IndBlockRows *b, PetscInt ncol, const PetscInt *ia, const PetscScalar *a,
                               const PetscScalar *x, PetscScalar *y)
{
  const PetscInt rbs = b->rbs, cbs = b->cbs;

  for (PetscInt c = 0; c < ncol; ++c) y[c] = 0;
  for (PetscInt i = 0; i < b->ngroup; ++i) {
    const PetscInt nb = b->bi[i + 1] - b->bi[i], *c = b->bj + b->bi[i];
    for (PetscInt r = 0; r < rbs; ++r) {
      const PetscInt     row = rbs * i + r;
      const PetscScalar *v   = a + ia[row], xr = x[row];
      for (PetscInt k = 0; k < nb; ++k)
        for (PetscInt d = 0; d < cbs; ++d) y[c[k] + d] += v[cbs * k + d] * xr;
    }
  }
}

#if defined(IND_BLOCKMULT_AVX2)
IND_AVX2 static inline double Sum3(__m256d s)
{
  double t[4];
  _mm256_storeu_pd(t, s);
  return t[0] + t[1] + t[2];
}

/* 3 x 3 blocks: each block row of 3 values and the block of x in one 4-wide register. The fourth lane reads the
   next block's first value and x's next entry, both inside their arrays because the columns of a row ascend
   and this is not the row's last block, and is never summed; the last block is loaded masked. */
IND_AVX2 static void Group33MultAvx2(const IndBlockRows *b, const PetscInt *ia, const double *a, const double *x,
                                     const double *w, double *y)
{
  const __m256i three = _mm256_set_epi64x(0, -1, -1, -1);

  for (PetscInt i = 0; i < b->ngroup; ++i) {
    const PetscInt nb = b->bi[i + 1] - b->bi[i], *c = b->bj + b->bi[i];
    const double  *v0 = a + ia[3 * i], *v1 = a + ia[3 * i + 1], *v2 = a + ia[3 * i + 2];
    __m256d        s0 = _mm256_setzero_pd(), s1 = _mm256_setzero_pd(), s2 = _mm256_setzero_pd();
    PetscInt       k;

    for (k = 0; k + 1 < nb; ++k) {
      const __m256d xb = _mm256_loadu_pd(x + c[k]);
      s0               = _mm256_fmadd_pd(_mm256_loadu_pd(v0 + 3 * k), xb, s0);
      s1               = _mm256_fmadd_pd(_mm256_loadu_pd(v1 + 3 * k), xb, s1);
      s2               = _mm256_fmadd_pd(_mm256_loadu_pd(v2 + 3 * k), xb, s2);
    }
    if (nb) {
      const __m256d xb = _mm256_maskload_pd(x + c[k], three);
      s0               = _mm256_fmadd_pd(_mm256_maskload_pd(v0 + 3 * k, three), xb, s0);
      s1               = _mm256_fmadd_pd(_mm256_maskload_pd(v1 + 3 * k, three), xb, s1);
      s2               = _mm256_fmadd_pd(_mm256_maskload_pd(v2 + 3 * k, three), xb, s2);
    }
    y[3 * i]     = (w ? w[3 * i] : 0) + Sum3(s0);
    y[3 * i + 1] = (w ? w[3 * i + 1] : 0) + Sum3(s1);
    y[3 * i + 2] = (w ? w[3 * i + 2] : 0) + Sum3(s2);
  }
}

/* Blocks of 6 columns (GAMG's rigid-body modes) under groups of R rows: a block row of 6 values as 4 + 2 lanes.
   Inlined for each R, so that the accumulators stay in registers. */
IND_AVX2 static inline __attribute__((always_inline)) void GroupR6MultAvx2(const IndBlockRows *b, const PetscInt *ia,
                                                                           const double *a, const double *x,
                                                                           const double *w, double *y, const int R)
{
  for (PetscInt i = 0; i < b->ngroup; ++i) {
    const PetscInt nb = b->bi[i + 1] - b->bi[i], *c = b->bj + b->bi[i];
    const double  *v[6];
    __m256d        lo[6];
    __m128d        hi[6];

    for (int r = 0; r < R; ++r) {
      v[r]  = a + ia[R * i + r];
      lo[r] = _mm256_setzero_pd();
      hi[r] = _mm_setzero_pd();
    }
    for (PetscInt k = 0; k < nb; ++k) {
      const __m256d xl = _mm256_loadu_pd(x + c[k]);
      const __m128d xh = _mm_loadu_pd(x + c[k] + 4);
      for (int r = 0; r < R; ++r) {
        lo[r] = _mm256_fmadd_pd(_mm256_loadu_pd(v[r] + 6 * k), xl, lo[r]);
        hi[r] = _mm_fmadd_pd(_mm_loadu_pd(v[r] + 6 * k + 4), xh, hi[r]);
      }
    }
    for (int r = 0; r < R; ++r) {
      double t[4], u[2];
      _mm256_storeu_pd(t, lo[r]);
      _mm_storeu_pd(u, hi[r]);
      y[R * i + r] = (w ? w[R * i + r] : 0) + t[0] + t[1] + t[2] + t[3] + u[0] + u[1];
    }
  }
}

IND_AVX2 static void Group36MultAvx2(const IndBlockRows *b, const PetscInt *ia, const double *a, const double *x,
                                     const double *w, double *y)
{
  GroupR6MultAvx2(b, ia, a, x, w, y, 3);
}

IND_AVX2 static void Group66MultAvx2(const IndBlockRows *b, const PetscInt *ia, const double *a, const double *x,
                                     const double *w, double *y)
{
  GroupR6MultAvx2(b, ia, a, x, w, y, 6);
}

/* y = A^T x with blocks of 6 columns: each block of y gathers its R rows' contributions in registers. */
IND_AVX2 static inline __attribute__((always_inline)) void GroupR6MultTransposeAvx2(const IndBlockRows *b,
                                                                                    PetscInt ncol, const PetscInt *ia,
                                                                                    const double *a, const double *x,
                                                                                    double *y, const int R)
{
  for (PetscInt c = 0; c < ncol; ++c) y[c] = 0;
  for (PetscInt i = 0; i < b->ngroup; ++i) {
    const PetscInt nb = b->bi[i + 1] - b->bi[i], *c = b->bj + b->bi[i];
    const double  *v[6];
    __m256d        xl[6];
    __m128d        xh[6];

    for (int r = 0; r < R; ++r) {
      v[r]  = a + ia[R * i + r];
      xl[r] = _mm256_set1_pd(x[R * i + r]);
      xh[r] = _mm_set1_pd(x[R * i + r]);
    }
    for (PetscInt k = 0; k < nb; ++k) {
      double *yb = y + c[k];
      __m256d yl = _mm256_loadu_pd(yb);
      __m128d yh = _mm_loadu_pd(yb + 4);
      for (int r = 0; r < R; ++r) {
        yl = _mm256_fmadd_pd(_mm256_loadu_pd(v[r] + 6 * k), xl[r], yl);
        yh = _mm_fmadd_pd(_mm_loadu_pd(v[r] + 6 * k + 4), xh[r], yh);
      }
      _mm256_storeu_pd(yb, yl);
      _mm_storeu_pd(yb + 4, yh);
    }
  }
}

IND_AVX2 static void Group36MultTransposeAvx2(const IndBlockRows *b, PetscInt ncol, const PetscInt *ia,
                                              const double *a, const double *x, double *y)
{
  GroupR6MultTransposeAvx2(b, ncol, ia, a, x, y, 3);
}

IND_AVX2 static void Group66MultTransposeAvx2(const IndBlockRows *b, PetscInt ncol, const PetscInt *ia,
                                              const double *a, const double *x, double *y)
{
  GroupR6MultTransposeAvx2(b, ncol, ia, a, x, y, 6);
}
#endif

void IndBlockRowsMult(const IndBlockRows *b, PetscBool simd, const PetscInt *ia, const PetscScalar *a,
                      const PetscScalar *x, const PetscScalar *w, PetscScalar *y)
{
#if defined(IND_BLOCKMULT_AVX2)
  if (simd && b->cbs == 3 && b->rbs == 3) {
    Group33MultAvx2(b, ia, a, x, w, y);
    return;
  }
  if (simd && b->cbs == 6 && b->rbs == 3) {
    Group36MultAvx2(b, ia, a, x, w, y);
    return;
  }
  if (simd && b->cbs == 6 && b->rbs == 6) {
    Group66MultAvx2(b, ia, a, x, w, y);
    return;
  }
#else
  (void)simd;
#endif
  if (b->cbs == 3 && b->rbs == 3) Group33Mult(b, ia, a, x, w, y);
  else GroupMult(b, ia, a, x, w, y);
}

void IndBlockRowsMultTranspose(const IndBlockRows *b, PetscBool simd, PetscInt ncol, const PetscInt *ia,
                               const PetscScalar *a, const PetscScalar *x, PetscScalar *y)
{
#if defined(IND_BLOCKMULT_AVX2)
  if (simd && b->cbs == 6 && b->rbs == 3) {
    Group36MultTransposeAvx2(b, ncol, ia, a, x, y);
    return;
  }
  if (simd && b->cbs == 6 && b->rbs == 6) {
    Group66MultTransposeAvx2(b, ncol, ia, a, x, y);
    return;
  }
#else
  (void)simd;
#endif
  GroupMultTranspose(b, ncol, ia, a, x, y);
}
