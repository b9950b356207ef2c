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

/* Whether rows rbs i .. rbs i + rbs - 1 have one column pattern made of whole blocks (c .. c + cbs - 1, c a
   multiple of cbs). */
PetscBool IndBlockRowsGroupFits(const PetscInt *ia, const PetscInt *ja, PetscInt rbs, PetscInt cbs, PetscInt i)
{
  const PetscInt s = ia[rbs * i], len = ia[rbs * i + 1] - s;

  if (len % cbs) return PETSC_FALSE;
  for (PetscInt r = 1; r < rbs; ++r)
    if (ia[rbs * i + r + 1] - ia[rbs * i + r] != len) return PETSC_FALSE;
  for (PetscInt k = 0; k < len; k += cbs) {
    if (ja[s + k] % cbs) return PETSC_FALSE;
    for (PetscInt d = 1; d < cbs; ++d)
      if (ja[s + k + d] != ja[s + k] + d) return PETSC_FALSE;
  }
  for (PetscInt r = 1; r < rbs; ++r)
    for (PetscInt k = 0; k < len; ++k)
      if (ja[s + r * len + k] != ja[s + k]) return PETSC_FALSE;
  return PETSC_TRUE;
}

/* Values from the matrix's own array (af NULL) or from its single-precision copy (af, same positions). The loops
   below take single as a constant and are inlined once for each, so that neither reads a branch per value. */
IND_INLINE PetscScalar Value(const PetscScalar *a, const float *af, PetscInt k, const int single)
{
  return single ? (PetscScalar)af[k] : a[k];
}

IND_INLINE void RowsMultT(PetscInt m, const PetscInt *ia, const PetscInt *ja, const PetscScalar *a, const float *af,
                          const PetscScalar *x, const PetscScalar *w, PetscScalar *y, const int single)
{
  for (PetscInt r = 0; r < m; ++r) {
    PetscScalar s = w ? w[r] : 0;
    for (PetscInt k = ia[r]; k < ia[r + 1]; ++k) s += Value(a, af, k, single) * x[ja[k]];
    y[r] = s;
  }
}

void IndRowsMult(PetscInt m, const PetscInt *ia, const PetscInt *ja, const PetscScalar *a, const float *af,
                 const PetscScalar *x, const PetscScalar *w, PetscScalar *y)
{
  if (af) RowsMultT(m, ia, ja, a, af, x, w, y, 1);
  else RowsMultT(m, ia, ja, a, af, x, w, y, 0);
}

IND_INLINE void RowsMultTransposeT(PetscInt m, PetscInt ncol, const PetscInt *ia, const PetscInt *ja,
                                   const PetscScalar *a, const float *af, const PetscScalar *x, PetscScalar *y,
                                   const int single)
{
  for (PetscInt c = 0; c < ncol; ++c) y[c] = 0;
  for (PetscInt r = 0; r < m; ++r)
    for (PetscInt k = ia[r]; k < ia[r + 1]; ++k) y[ja[k]] += Value(a, af, k, single) * x[r];
}

void IndRowsMultTranspose(PetscInt m, PetscInt ncol, const PetscInt *ia, const PetscInt *ja, const PetscScalar *a,
                          const float *af, const PetscScalar *x, PetscScalar *y)
{
  if (af) RowsMultTransposeT(m, ncol, ia, ja, a, af, x, y, 1);
  else RowsMultTransposeT(m, ncol, ia, ja, a, af, x, y, 0);
}

/* Any block sizes: a group's rows one after the other, each reading its cbs values per block against the block
   of x (in cache after the group's first row). */
IND_INLINE void GroupMultT(const IndBlockRows *b, const PetscInt *ia, const PetscScalar *a, const float *af,
                           const PetscScalar *x, const PetscScalar *w, PetscScalar *y, const int single)
{
  const PetscInt rbs = b->rbs, cbs = b->cbs;

  for (PetscInt i = 0; i < b->ngroup; ++i) {
    const PetscInt nb = b->bi[i + 1] - b->bi[i], *c = b->bj + b->bi[i];
    for (PetscInt r = 0; r < rbs; ++r) {
      const PetscInt row = rbs * i + r, v = ia[row];
      PetscScalar    s   = 0;
      for (PetscInt k = 0; k < nb; ++k)
        for (PetscInt d = 0; d < cbs; ++d) s += Value(a, af, v + cbs * k + d, single) * x[c[k] + d];
      y[row] = (w ? w[row] : 0) + s;
    }
  }
}

IND_INLINE void Group33MultT(const IndBlockRows *b, const PetscInt *ia, const PetscScalar *a, const float *af,
                             const PetscScalar *x, const PetscScalar *w, PetscScalar *y, const int single)
{
  for (PetscInt i = 0; i < b->ngroup; ++i) {
    const PetscInt nb = b->bi[i + 1] - b->bi[i], *c = b->bj + b->bi[i];
    const PetscInt v0 = ia[3 * i], v1 = ia[3 * i + 1], v2 = ia[3 * i + 2];
    PetscScalar    y0 = 0, y1 = 0, y2 = 0;
    for (PetscInt k = 0; k < nb; ++k) {
      const PetscScalar *xb = x + c[k], x0 = xb[0], x1 = xb[1], x2 = xb[2];
      const PetscInt     o  = 3 * k;
      y0 += Value(a, af, v0 + o, single) * x0 + Value(a, af, v0 + o + 1, single) * x1 +
            Value(a, af, v0 + o + 2, single) * x2;
      y1 += Value(a, af, v1 + o, single) * x0 + Value(a, af, v1 + o + 1, single) * x1 +
            Value(a, af, v1 + o + 2, single) * x2;
      y2 += Value(a, af, v2 + o, single) * x0 + Value(a, af, v2 + o + 1, single) * x1 +
            Value(a, af, v2 + o + 2, single) * x2;
    }
    y[3 * i]     = (w ? w[3 * i] : 0) + y0;
    y[3 * i + 1] = (w ? w[3 * i + 1] : 0) + y1;
    y[3 * i + 2] = (w ? w[3 * i + 2] : 0) + y2;
  }
}

IND_INLINE void GroupMultTransposeT(const IndBlockRows *b, PetscInt ncol, const PetscInt *ia, const PetscScalar *a,
                                    const float *af, const PetscScalar *x, PetscScalar *y, const int single)
{
  const PetscInt rbs = b->rbs, cbs = b->cbs;

  for (PetscInt c = 0; c < ncol; ++c) y[c] = 0;
  for (PetscInt i = 0; i < b->ngroup; ++i) {
    const PetscInt nb = b->bi[i + 1] - b->bi[i], *c = b->bj + b->bi[i];
    for (PetscInt r = 0; r < rbs; ++r) {
      const PetscInt    row = rbs * i + r, v = ia[row];
      const PetscScalar xr  = x[row];
      for (PetscInt k = 0; k < nb; ++k)
        for (PetscInt d = 0; d < cbs; ++d) y[c[k] + d] += Value(a, af, v + cbs * k + d, single) * xr;
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

/* 4 values from position k, as doubles */
IND_AVX2 IND_INLINE __m256d Load4(const double *a, const float *af, PetscInt k, const int single)
{
  return single ? _mm256_cvtps_pd(_mm_loadu_ps(af + k)) : _mm256_loadu_pd(a + k);
}

/* 3 values from position k, the fourth lane 0, reading nothing past the third */
IND_AVX2 IND_INLINE __m256d Load3(const double *a, const float *af, PetscInt k, const int single)
{
  if (single) return _mm256_cvtps_pd(_mm_maskload_ps(af + k, _mm_set_epi32(0, -1, -1, -1)));
  return _mm256_maskload_pd(a + k, _mm256_set_epi64x(0, -1, -1, -1));
}

/* 2 values from position k */
IND_AVX2 IND_INLINE __m128d Load2(const double *a, const float *af, PetscInt k, const int single)
{
  return single ? _mm_cvtps_pd(_mm_castsi128_ps(_mm_loadl_epi64((const __m128i *)(af + k)))) : _mm_loadu_pd(a + k);
}

/* 3 x 3 blocks: each block row of 3 values and the block of x in one 4-wide register. The fourth lane reads the
   next block's first value and x's next entry, both inside their arrays because the columns of a row ascend
   and this is not the row's last block, and is never summed; the last block is loaded masked. */
IND_AVX2 IND_INLINE void Group33MultAvx2T(const IndBlockRows *b, const PetscInt *ia, const double *a, const float *af,
                                          const double *x, const double *w, double *y, const int single)
{
  for (PetscInt i = 0; i < b->ngroup; ++i) {
    const PetscInt nb = b->bi[i + 1] - b->bi[i], *c = b->bj + b->bi[i];
    const PetscInt v0 = ia[3 * i], v1 = ia[3 * i + 1], v2 = ia[3 * i + 2];
    __m256d        s0 = _mm256_setzero_pd(), s1 = _mm256_setzero_pd(), s2 = _mm256_setzero_pd();
    PetscInt       k;

    for (k = 0; k + 1 < nb; ++k) {
      const __m256d xb = _mm256_loadu_pd(x + c[k]);
      s0               = _mm256_fmadd_pd(Load4(a, af, v0 + 3 * k, single), xb, s0);
      s1               = _mm256_fmadd_pd(Load4(a, af, v1 + 3 * k, single), xb, s1);
      s2               = _mm256_fmadd_pd(Load4(a, af, v2 + 3 * k, single), xb, s2);
    }
    if (nb) {
      const __m256d xb = _mm256_maskload_pd(x + c[k], _mm256_set_epi64x(0, -1, -1, -1));
      s0               = _mm256_fmadd_pd(Load3(a, af, v0 + 3 * k, single), xb, s0);
      s1               = _mm256_fmadd_pd(Load3(a, af, v1 + 3 * k, single), xb, s1);
      s2               = _mm256_fmadd_pd(Load3(a, af, v2 + 3 * k, single), xb, s2);
    }
    y[3 * i]     = (w ? w[3 * i] : 0) + Sum3(s0);
    y[3 * i + 1] = (w ? w[3 * i + 1] : 0) + Sum3(s1);
    y[3 * i + 2] = (w ? w[3 * i + 2] : 0) + Sum3(s2);
  }
}

/* Blocks of 6 columns (GAMG's rigid-body modes) under groups of R rows: a block row of 6 values as 4 + 2 lanes.
   Inlined for each R, so that the accumulators stay in registers. */
IND_AVX2 IND_INLINE void GroupR6MultAvx2T(const IndBlockRows *b, const PetscInt *ia, const double *a, const float *af,
                                          const double *x, const double *w, double *y, const int R, const int single)
{
  for (PetscInt i = 0; i < b->ngroup; ++i) {
    const PetscInt nb = b->bi[i + 1] - b->bi[i], *c = b->bj + b->bi[i];
    PetscInt       v[6];
    __m256d        lo[6];
    __m128d        hi[6];

    for (int r = 0; r < R; ++r) {
      v[r]  = ia[R * i + r];
      lo[r] = _mm256_setzero_pd();
      hi[r] = _mm_setzero_pd();
    }
    for (PetscInt k = 0; k < nb; ++k) {
      const __m256d xl = _mm256_loadu_pd(x + c[k]);
      const __m128d xh = _mm_loadu_pd(x + c[k] + 4);
      for (int r = 0; r < R; ++r) {
        lo[r] = _mm256_fmadd_pd(Load4(a, af, v[r] + 6 * k, single), xl, lo[r]);
        hi[r] = _mm_fmadd_pd(Load2(a, af, v[r] + 6 * k + 4, single), xh, hi[r]);
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

/* y = A^T x with blocks of 6 columns: each block of y gathers its R rows' contributions in registers. */
IND_AVX2 IND_INLINE void GroupR6MultTransposeAvx2T(const IndBlockRows *b, PetscInt ncol, const PetscInt *ia,
                                                   const double *a, const float *af, const double *x, double *y,
                                                   const int R, const int single)
{
  for (PetscInt c = 0; c < ncol; ++c) y[c] = 0;
  for (PetscInt i = 0; i < b->ngroup; ++i) {
    const PetscInt nb = b->bi[i + 1] - b->bi[i], *c = b->bj + b->bi[i];
    PetscInt       v[6];
    __m256d        xl[6];
    __m128d        xh[6];

    for (int r = 0; r < R; ++r) {
      v[r]  = ia[R * i + r];
      xl[r] = _mm256_set1_pd(x[R * i + r]);
      xh[r] = _mm_set1_pd(x[R * i + r]);
    }
    for (PetscInt k = 0; k < nb; ++k) {
      double *yb = y + c[k];
      __m256d yl = _mm256_loadu_pd(yb);
      __m128d yh = _mm_loadu_pd(yb + 4);
      for (int r = 0; r < R; ++r) {
        yl = _mm256_fmadd_pd(Load4(a, af, v[r] + 6 * k, single), xl[r], yl);
        yh = _mm_fmadd_pd(Load2(a, af, v[r] + 6 * k + 4, single), xh[r], yh);
      }
      _mm256_storeu_pd(yb, yl);
      _mm_storeu_pd(yb + 4, yh);
    }
  }
}

/* The kernels, each instantiated for double and single values: [block sizes][single] */
IND_AVX2 static void M33d(const IndBlockRows *b, const PetscInt *ia, const double *a, const float *af,
                          const double *x, const double *w, double *y)
{
  Group33MultAvx2T(b, ia, a, af, x, w, y, 0);
}
IND_AVX2 static void M33s(const IndBlockRows *b, const PetscInt *ia, const double *a, const float *af,
                          const double *x, const double *w, double *y)
{
  Group33MultAvx2T(b, ia, a, af, x, w, y, 1);
}
IND_AVX2 static void M36d(const IndBlockRows *b, const PetscInt *ia, const double *a, const float *af,
                          const double *x, const double *w, double *y)
{
  GroupR6MultAvx2T(b, ia, a, af, x, w, y, 3, 0);
}
IND_AVX2 static void M36s(const IndBlockRows *b, const PetscInt *ia, const double *a, const float *af,
                          const double *x, const double *w, double *y)
{
  GroupR6MultAvx2T(b, ia, a, af, x, w, y, 3, 1);
}
IND_AVX2 static void M66d(const IndBlockRows *b, const PetscInt *ia, const double *a, const float *af,
                          const double *x, const double *w, double *y)
{
  GroupR6MultAvx2T(b, ia, a, af, x, w, y, 6, 0);
}
IND_AVX2 static void M66s(const IndBlockRows *b, const PetscInt *ia, const double *a, const float *af,
                          const double *x, const double *w, double *y)
{
  GroupR6MultAvx2T(b, ia, a, af, x, w, y, 6, 1);
}
IND_AVX2 static void T36d(const IndBlockRows *b, PetscInt ncol, const PetscInt *ia, const double *a,
                          const float *af, const double *x, double *y)
{
  GroupR6MultTransposeAvx2T(b, ncol, ia, a, af, x, y, 3, 0);
}
IND_AVX2 static void T36s(const IndBlockRows *b, PetscInt ncol, const PetscInt *ia, const double *a,
                          const float *af, const double *x, double *y)
{
  GroupR6MultTransposeAvx2T(b, ncol, ia, a, af, x, y, 3, 1);
}
IND_AVX2 static void T66d(const IndBlockRows *b, PetscInt ncol, const PetscInt *ia, const double *a,
                          const float *af, const double *x, double *y)
{
  GroupR6MultTransposeAvx2T(b, ncol, ia, a, af, x, y, 6, 0);
}
IND_AVX2 static void T66s(const IndBlockRows *b, PetscInt ncol, const PetscInt *ia, const double *a,
                          const float *af, const double *x, double *y)
{
  GroupR6MultTransposeAvx2T(b, ncol, ia, a, af, x, y, 6, 1);
}
#endif

void IndBlockRowsMult(const IndBlockRows *b, PetscBool simd, const PetscInt *ia, const PetscScalar *a,
                      const float *af, const PetscScalar *x, const PetscScalar *w, PetscScalar *y)
{
  const int single = af != NULL;
#if defined(IND_BLOCKMULT_AVX2)
  if (simd && b->cbs == 3 && b->rbs == 3) {
    (single ? M33s : M33d)(b, ia, a, af, x, w, y);
    return;
  }
  if (simd && b->cbs == 6 && b->rbs == 3) {
    (single ? M36s : M36d)(b, ia, a, af, x, w, y);
    return;
  }
  if (simd && b->cbs == 6 && b->rbs == 6) {
    (single ? M66s : M66d)(b, ia, a, af, x, w, y);
    return;
  }
#else
  (void)simd;
#endif
  if (b->cbs == 3 && b->rbs == 3) {
    if (single) Group33MultT(b, ia, a, af, x, w, y, 1);
    else Group33MultT(b, ia, a, af, x, w, y, 0);
  } else if (single) GroupMultT(b, ia, a, af, x, w, y, 1);
  else GroupMultT(b, ia, a, af, x, w, y, 0);
}

void IndBlockRowsMultTranspose(const IndBlockRows *b, PetscBool simd, PetscInt ncol, const PetscInt *ia,
                               const PetscScalar *a, const float *af, const PetscScalar *x, PetscScalar *y)
{
  const int single = af != NULL;
#if defined(IND_BLOCKMULT_AVX2)
  if (simd && b->cbs == 6 && b->rbs == 3) {
    (single ? T36s : T36d)(b, ncol, ia, a, af, x, y);
    return;
  }
  if (simd && b->cbs == 6 && b->rbs == 6) {
    (single ? T66s : T66d)(b, ncol, ia, a, af, x, y);
    return;
  }
#else
  (void)simd;
#endif
  if (single) GroupMultTransposeT(b, ncol, ia, a, af, x, y, 1);
  else GroupMultTransposeT(b, ncol, ia, a, af, x, y, 0);
}
