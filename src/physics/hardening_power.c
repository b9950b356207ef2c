#include "ind_hardening.h"
#include "ind_options.h"

/* Power law in Dao et al.'s form (Acta Mater. 49 (2001) 3899): R(p) = R0 (1 + E p / R0)^n, E the region's Young's
   modulus, so that the uniaxial curve sigma = K eps^n past yield, with K = R0 (E / R0)^n, meets the elastic line
   at sigma = R0. */
#define EXPONENT(m) ((m)->c[0])
#define YOUNG(m)    ((m)->c[1])

static PetscReal R(const IndPlasticParams *m, PetscReal p)
{
  return m->R0 * PetscPowReal(1 + YOUNG(m) * p / m->R0, EXPONENT(m));
}

static PetscReal dR(const IndPlasticParams *m, PetscReal p)
{
  return EXPONENT(m) * YOUNG(m) * PetscPowReal(1 + YOUNG(m) * p / m->R0, EXPONENT(m) - 1);
}

static PetscErrorCode Read(PetscOptionItems *PetscOptionsObject, MPI_Comm comm, const char region[],
                           IndPlasticParams *m)
{
  PetscBool set;

  PetscFunctionBeginUser;
  PetscCall(IndHardeningReadYield(PetscOptionsObject, comm, region, m));
  PetscCall(IndOptionsReal("-hardening_exponent", "Power-law exponent n: R = R0 (1 + E p / R0)^n", "",
                           IND_REQUIRED " with power", EXPONENT(m), &EXPONENT(m), &set));
  if (!IndHelpListing()) PetscCall(IndHardeningRequire(comm, region, "hardening_exponent", set, "power-law exponent"));
  YOUNG(m) = IndPlasticYoung(m);
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Check(const IndPlasticParams *m, const char pre[], MPI_Comm comm)
{
  PetscFunctionBeginUser;
  PetscCheck(EXPONENT(m) >= 0 && EXPONENT(m) <= 1, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-%shardening_exponent must lie in [0, 1] (0: perfectly plastic), got %g", pre, (double)EXPONENT(m));
  PetscCheck(YOUNG(m) > 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-%shardening power needs the region's Young's modulus "
             "> 0, got %g GPa", pre, (double)YOUNG(m));
  PetscFunctionReturn(PETSC_SUCCESS);
}

const IndHardeningLaw *IndHardeningPower(void)
{
  static const IndHardeningLaw law = {"power", R, dR, Read, Check, NULL};
  return &law;
}

void IndHardeningSetPower(IndPlasticParams *m, PetscReal n)
{
  m->law      = IndHardeningPower();
  EXPONENT(m) = n;
  YOUNG(m)    = IndPlasticYoung(m);
}
