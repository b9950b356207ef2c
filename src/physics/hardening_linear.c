#include "ind_hardening.h"
#include "ind_options.h"

/* Linear: R(p) = R0 + h p (perfect plasticity with h = 0). */
#define SLOPE(m) ((m)->c[0])

static PetscReal R(const IndPlasticParams *m, PetscReal p)
{
  return m->R0 + SLOPE(m) * p;
}

static PetscReal dR(const IndPlasticParams *m, PetscReal p)
{
  (void)p;
  return SLOPE(m);
}

static PetscErrorCode Read(PetscOptionItems *PetscOptionsObject, MPI_Comm comm, const char region[],
                           IndPlasticParams *m)
{
  PetscFunctionBeginUser;
  PetscCall(IndHardeningReadYield(PetscOptionsObject, comm, region, m));
  PetscCall(IndOptionsReal("-hardening_slope", "Linear isotropic hardening slope h", "GPa", NULL, SLOPE(m), &SLOPE(m),
                           NULL));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Check(const IndPlasticParams *m, const char pre[], MPI_Comm comm)
{
  PetscFunctionBeginUser;
  PetscCheck(SLOPE(m) >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-%shardening_slope must be >= 0 (GPa), got %g", pre,
             (double)SLOPE(m));
  PetscFunctionReturn(PETSC_SUCCESS);
}

const IndHardeningLaw *IndHardeningLinear(void)
{
  static const IndHardeningLaw law = {"linear", R, dR, Read, Check, NULL};
  return &law;
}

void IndHardeningSetLinear(IndPlasticParams *m, PetscReal h)
{
  m->law   = IndHardeningLinear();
  SLOPE(m) = h;
}
