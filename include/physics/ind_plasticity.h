#pragma once
/* Small-strain von Mises plasticity at one quadrature point (doc/theory.md section 1): Voce or linear
   isotropic hardening, linear Prager kinematic hardening, radial return and consistent tangent.
   Pure: depends only on petscsys.h, holds no PETSc objects and no globals, so every quadrature point
   can call it independently and it can be unit tested alone.

   Voigt order [xx, yy, zz, xy, yz, xz]. Conventions of the vectors:
   - total strain eps and plastic strain eps_p carry ENGINEERING shears (gamma_xy = 2 eps_xy), so
     eps - eps_p is an elastic strain in the same convention as the B matrix produces;
   - stress sigma and back stress x carry TENSOR components;
   - D (6x6, row-major) maps an engineering strain increment to a stress increment,
     dsigma[i] = sum_j D[6 i + j] deps[j]; it is symmetric.
   Units: stresses and moduli in GPa, strains and p dimensionless. */
#include <petscsys.h>

#ifndef PETSC_SUCCESS
  #define PETSC_SUCCESS 0 /* PETSc < 3.19 returns plain 0 */
#endif

/* The isotropic hardening law R(p), an implementation registered by name (ind_hardening.h). */
typedef struct _IndHardeningLaw IndHardeningLaw;
#define IND_HARDENING_NPARAM 4

typedef struct {
  PetscReal              kappa, mu; /* bulk and shear moduli, GPa */
  const IndHardeningLaw *law;       /* R(p) and R'(p) (NULL: elastic_only) */
  PetscReal              R0;        /* initial yield stress, GPa: -<region>_yield */
  PetscReal              c[IND_HARDENING_NPARAM]; /* the law's own parameters, named in its file */
  const PetscReal       *table;  /* a tabulated law's points, ntable pairs (eps_p, stress in GPa); its own */
  PetscInt               ntable;
  PetscReal              H;         /* Prager kinematic modulus, GPa: -<region>_kinematic */
  PetscReal              yield_pressure; /* densifying: hydrostatic yield pressure p_c at no compaction, GPa */
  PetscReal              densification_modulus; /* densifying: dp_c / d(compaction), GPa */
  PetscBool              elastic_only;   /* skip the return: linear elasticity with the same moduli */
  PetscInt               max_iterations; /* cap on the scalar return solve; 0 means 100 */
} IndPlasticParams;

/* A hardening law: R(p) and its derivative, pure; reading its parameters from the region's options (inside the
   region's PetscOptionsBegin block, which `po` is; R0 too, which a law may derive from its own parameters) and
   checking them, naming the offending option by prefix. */
struct _IndHardeningLaw {
  const char *name;
  PetscReal (*R)(const IndPlasticParams *m, PetscReal p);
  PetscReal (*dR)(const IndPlasticParams *m, PetscReal p);
  PetscErrorCode (*read)(PetscOptionItems *po, MPI_Comm comm, const char region[], IndPlasticParams *m);
  PetscErrorCode (*check)(const IndPlasticParams *m, const char prefix[], MPI_Comm comm);
  /* frees what read allocated (NULL: nothing) */
  PetscErrorCode (*destroy)(IndPlasticParams *m);
};

/* History of a quadrature point at the end of a converged step; all zero for a virgin material. */
typedef struct {
  PetscReal eps_p[6]; /* plastic strain, engineering shears; deviatoric but for a densifying material */
  PetscReal x[6];     /* back stress, tensor components, deviatoric, GPa */
  PetscReal p;        /* accumulated equivalent plastic strain */
} IndPlasticState;

typedef enum { IND_PLASTIC_OK, IND_PLASTIC_NOT_CONVERGED } IndPlasticStatus;

PetscReal IndPlasticR(const IndPlasticParams *m, PetscReal p);
PetscReal IndPlasticdR(const IndPlasticParams *m, PetscReal p);

/* The checks every plastic model shares: elastic moduli > 0 and, unless elastic_only, the return's iteration
   cap >= 0; prefix as below. */
PetscErrorCode IndPlasticCommonCheck(const IndPlasticParams *m, const char prefix[], MPI_Comm comm);

/* Rejects non-physical parameters; prefix is the region's option prefix ("film_") used to name the
   offending option in the message. Plastic parameters are not checked when elastic_only is set. */
PetscErrorCode IndPlasticParamsCheck(const IndPlasticParams *m, const char prefix[], MPI_Comm comm);
/* E from the moduli the material has set (kappa, mu). */
static inline PetscReal IndPlasticYoung(const IndPlasticParams *m)
{
  return 9 * m->kappa * m->mu / (3 * m->kappa + m->mu);
}

/* Rejects an initial yield stress R0 at or above the Young's modulus of kappa and mu (a yield strain of 1 or more:
   stresses given in MPa), naming the option R0 came from; pre is the region's option prefix. */
PetscErrorCode IndPlasticYieldCheckModulus(const IndPlasticParams *m, const char pre[], MPI_Comm comm);

/* Stress update from the total strain eps at t_{n+1} and the history old at t_n.
   Writes new_state (may be the same pointer as old), sigma, and, when not NULL, the consistent
   tangent D and the increment dp of p (0 for an elastic step).
   On IND_PLASTIC_NOT_CONVERGED new_state is a copy of old and sigma, D and *dp_out are NaN, so a
   caller that forgets the status still cannot converge on an invented state: reject the step
   (e.g. SNESSetFunctionDomainError) and cut it. */
IndPlasticStatus IndPlasticUpdate(const IndPlasticParams *m, const PetscReal eps[6], const IndPlasticState *old,
  IndPlasticState *new_state, PetscReal sigma[6], PetscReal D[36], PetscReal *dp_out);

/* The consistent tangent by its parts, D = kappa J + 2 mu theta (I - J/3) - 2 mu thetabar n n^T (n the unit flow
   direction, tensor components; theta = 1, thetabar = 0 and n = 0 at an elastic step): an isotropic tensor and a
   rank-one term. A caller that needs D in another basis rotates n alone, not the 6 x 6 D. */
typedef struct {
  PetscReal kappa, mu, theta, thetabar;
  PetscReal n[6];
} IndPlasticTangent;

/* IndPlasticUpdate with the tangent by its parts (t may be NULL; NaN where D would be). */
IndPlasticStatus IndPlasticUpdateParts(const IndPlasticParams *m, const PetscReal eps[6], const IndPlasticState *old,
  IndPlasticState *new_state, PetscReal sigma[6], IndPlasticTangent *t, PetscReal *dp_out);
/* The parts' D with the flow direction n given in the basis wanted (t->n itself, or rotated). */
void IndPlasticTangentMatrix(const IndPlasticTangent *t, const PetscReal n[6], PetscReal D[36]);
/* The parts of the elastic tangent. */
void IndPlasticTangentElastic(PetscReal kappa, PetscReal mu, IndPlasticTangent *t);
