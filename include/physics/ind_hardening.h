#pragma once
/* Isotropic hardening laws R(p), registered by name and chosen per region by -<region>_hardening (as PETSc's
   KSPRegister / KSPSetType): a new law is a file (hardening_<name>.c) that fills an IndHardeningLaw, plus one
   entry in IndHardeningRegistry (hardening.c). The laws here:
   - voce:   R(p) = Rs - (Rs - R0) exp(-gamma p)  (-<region>_yield R0, -<region>_saturation Rs, -<region>_voce_rate);
   - linear: R(p) = R0 + h p                      (-<region>_yield, -<region>_hardening_slope h);
   - power:  R(p) = R0 (1 + E p / R0)^n, E the region's modulus (Dao et al. 2001; -<region>_yield,
             -<region>_hardening_exponent n);
   - swift:  R(p) = K (eps0 + p)^n                (-<region>_swift_k, -<region>_swift_eps0,
             -<region>_hardening_exponent);
   - table:  R(p) piecewise linear through a tensile curve (-<region>_hardening_file, a CSV of plastic strain and
             stress in GPa; -<region>_hardening_beyond flat|slope past its last point). */
#include "ind_plasticity.h"
#include "ind_registry.h"

/* The laws by name: each entry's function returns the law's table (a new one: IndRegistryAdd). */
extern IndRegistry IndHardeningRegistry;
/* The law registered as name; an error naming the option when there is none. */
PetscErrorCode IndHardeningFind(MPI_Comm comm, const char option[], const char name[], const IndHardeningLaw **law);
/* A parameter the law needs and has no default for (region plastic, option -<region>_<name> missing). */
PetscErrorCode IndHardeningRequire(MPI_Comm comm, const char region[], const char name[], PetscBool set,
                                   const char what[]);

/* -<region>_yield, for the laws that take R0 as given (inside the region's options block). */
PetscErrorCode IndHardeningReadYield(PetscOptionItems *po, MPI_Comm comm, const char region[], IndPlasticParams *m);
/* The points (eps_p, stress) of a tabulated curve from the text of its CSV file (two numbers a line, separated by
   commas, semicolons, tabs or spaces; blank lines, '#' comments and one header line skipped): at least 2, the
   first at zero plastic strain with a stress > 0, the strain increasing, the stress not falling. An error naming
   `what` (the option and file) and the line otherwise. Collective on comm; *points allocated (PetscFree). */
PetscErrorCode IndHardeningTableParse(MPI_Comm comm, const char text[], const char what[], PetscInt *n,
                                      PetscReal **points);

/* The laws, for code that builds parameters by hand (tests, drivers); set kappa and mu first (power uses E). */
const IndHardeningLaw *IndHardeningVoce(void);
const IndHardeningLaw *IndHardeningLinear(void);
const IndHardeningLaw *IndHardeningPower(void);
const IndHardeningLaw *IndHardeningSwift(void);
const IndHardeningLaw *IndHardeningTable(void);
void                   IndHardeningSetVoce(IndPlasticParams *m, PetscReal Rs, PetscReal gamma);
void                   IndHardeningSetLinear(IndPlasticParams *m, PetscReal h);
void                   IndHardeningSetPower(IndPlasticParams *m, PetscReal n);
/* sets R0 = K eps0^n too */
void                   IndHardeningSetSwift(IndPlasticParams *m, PetscReal K, PetscReal eps0, PetscReal n);
/* borrows points (n pairs); sets R0 to the first stress */
void                   IndHardeningSetTable(IndPlasticParams *m, PetscInt n, const PetscReal *points,
                                            PetscBool slope_beyond);
