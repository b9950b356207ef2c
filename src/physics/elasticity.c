#include "ind_elasticity.h"

void IndElasticStress(PetscReal kappa, PetscReal mu, const PetscReal eps[6], PetscReal sigma[6])
{
  const PetscReal tr = eps[0] + eps[1] + eps[2];
  for (int i = 0; i < 3; ++i) sigma[i] = kappa * tr + 2.0 * mu * (eps[i] - tr / 3.0);
  for (int i = 3; i < 6; ++i) sigma[i] = mu * eps[i]; /* 2 mu (gamma / 2) */
}

void IndElasticTangent(PetscReal kappa, PetscReal mu, PetscReal D[36])
{
  for (int i = 0; i < 36; ++i) D[i] = 0.0;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) D[i * 6 + j] = kappa - 2.0 * mu / 3.0;
    D[i * 6 + i] += 2.0 * mu;
    D[(i + 3) * 6 + i + 3] = mu;
  }
}

PetscReal IndVonMises(const PetscReal s[6])
{
  const PetscReal p = (s[0] + s[1] + s[2]) / 3.0;
  const PetscReal j2 = 0.5 * (PetscSqr(s[0] - p) + PetscSqr(s[1] - p) + PetscSqr(s[2] - p)) + PetscSqr(s[3])
    + PetscSqr(s[4]) + PetscSqr(s[5]);
  return PetscSqrtReal(3.0 * j2);
}
