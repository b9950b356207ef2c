#pragma once
/* Isotropic hardening laws R(p), registered by name and chosen per region by -<region>_hardening (PETSc's
   XXXRegister / XXXSetType): a new law is a file (hardening_<name>.c) that fills an IndHardeningLaw, plus one
   entry in IndHardeningRegistry (hardening.c). The laws here:
   - voce:   R(p) = Rs - (Rs - R0) exp(-gamma p)  (-<region>_saturation Rs, -<region>_voce_rate gamma);
   - linear: R(p) = R0 + h p                      (-<region>_hardening_slope h). */
#include "ind_plasticity.h"
#include "ind_registry.h"

/* The laws by name: each entry's function returns the law's table (a new one: IndRegistryAdd). */
extern IndRegistry IndHardeningRegistry;
/* The law registered as name; an error naming the option when there is none. */
PetscErrorCode IndHardeningFind(MPI_Comm comm, const char option[], const char name[], const IndHardeningLaw **law);
/* A parameter the law needs and has no default for (region plastic, option -<region>_<name> missing). */
PetscErrorCode IndHardeningRequire(MPI_Comm comm, const char region[], const char name[], PetscBool set,
                                   const char what[]);

/* The laws, for code that builds parameters by hand (tests, drivers). */
const IndHardeningLaw *IndHardeningVoce(void);
const IndHardeningLaw *IndHardeningLinear(void);
void                   IndHardeningSetVoce(IndPlasticParams *m, PetscReal Rs, PetscReal gamma);
void                   IndHardeningSetLinear(IndPlasticParams *m, PetscReal h);
