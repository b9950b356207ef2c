#pragma once
/* 3 x 3 matrices, row-major: determinant and inverse. Pure. */
#include <petscsys.h>

static inline PetscReal IndDet3(const PetscReal F[9])
{
  return F[0] * (F[4] * F[8] - F[5] * F[7]) - F[1] * (F[3] * F[8] - F[5] * F[6]) + F[2] * (F[3] * F[7] - F[4] * F[6]);
}

/* Ai = A^-1 from the cofactors, det = IndDet3(A) (nonzero). */
static inline void IndInverse3(const PetscReal A[9], PetscReal det, PetscReal Ai[9])
{
  const PetscReal r = 1.0 / det;
  Ai[0] = r * (A[4] * A[8] - A[5] * A[7]);
  Ai[1] = r * (A[2] * A[7] - A[1] * A[8]);
  Ai[2] = r * (A[1] * A[5] - A[2] * A[4]);
  Ai[3] = r * (A[5] * A[6] - A[3] * A[8]);
  Ai[4] = r * (A[0] * A[8] - A[2] * A[6]);
  Ai[5] = r * (A[2] * A[3] - A[0] * A[5]);
  Ai[6] = r * (A[3] * A[7] - A[4] * A[6]);
  Ai[7] = r * (A[1] * A[6] - A[0] * A[7]);
  Ai[8] = r * (A[0] * A[4] - A[1] * A[3]);
}
