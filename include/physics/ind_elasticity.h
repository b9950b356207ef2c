#pragma once
/* Isotropic linear elasticity on Voigt vectors: strain [xx,yy,zz,xy,yz,xz] with engineering shears
   (gamma = 2 eps), stress with tensor components. Pure: no PETSc objects. */
#include <petscsys.h>

/* Bulk modulus kappa and shear modulus mu from Young's modulus and Poisson's ratio. */
static inline void IndElasticModuli(PetscReal E, PetscReal nu, PetscReal *kappa, PetscReal *mu)
{
  *kappa = E / (3.0 * (1.0 - 2.0 * nu));
  *mu    = E / (2.0 * (1.0 + nu));
}

void IndElasticStress(PetscReal kappa, PetscReal mu, const PetscReal eps[6], PetscReal sigma[6]);
void IndElasticTangent(PetscReal kappa, PetscReal mu, PetscReal D[36]);
/* von Mises equivalent of a stress vector. */
PetscReal IndVonMises(const PetscReal sigma[6]);
