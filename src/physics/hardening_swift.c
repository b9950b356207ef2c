#include "ind_hardening.h"
#include "ind_options.h"

/* Swift: R(p) = K (eps0 + p)^n, as tensile curves of sheet metals are given; its yield stress is R0 = K eps0^n. */
#define SWIFT_K(m)    ((m)->c[0])
#define SWIFT_EPS0(m) ((m)->c[1])
#define EXPONENT(m)   ((m)->c[2])

static PetscReal R(const IndPlasticParams *m, PetscReal p)
{
  return SWIFT_K(m) * PetscPowReal(SWIFT_EPS0(m) + p, EXPONENT(m));
}

static PetscReal dR(const IndPlasticParams *m, PetscReal p)
{
  return EXPONENT(m) * SWIFT_K(m) * PetscPowReal(SWIFT_EPS0(m) + p, EXPONENT(m) - 1);
}

static PetscErrorCode Read(PetscOptionItems *PetscOptionsObject, MPI_Comm comm, const char region[],
                           IndPlasticParams *m)
{
  PetscBool set;

  PetscFunctionBeginUser;
  PetscCall(IndOptionsReal("-swift_k", "Swift strength K: R = K (eps0 + p)^n", "GPa", IND_REQUIRED " with swift",
                           SWIFT_K(m), &SWIFT_K(m), &set));
  if (!IndHelpListing()) PetscCall(IndHardeningRequire(comm, region, "swift_k", set, "Swift strength, GPa"));
  PetscCall(IndOptionsReal("-swift_eps0", "Swift pre-strain eps0", "", IND_REQUIRED " with swift", SWIFT_EPS0(m),
                           &SWIFT_EPS0(m), &set));
  if (!IndHelpListing()) PetscCall(IndHardeningRequire(comm, region, "swift_eps0", set, "Swift pre-strain"));
  PetscCall(IndOptionsReal("-hardening_exponent", "Swift exponent n", "", IND_REQUIRED " with swift", EXPONENT(m),
                           &EXPONENT(m), &set));
  if (!IndHelpListing()) PetscCall(IndHardeningRequire(comm, region, "hardening_exponent", set, "Swift exponent"));
  IndHardeningSetSwift(m, SWIFT_K(m), SWIFT_EPS0(m), EXPONENT(m));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Check(const IndPlasticParams *m, const char pre[], MPI_Comm comm)
{
  PetscFunctionBeginUser;
  PetscCheck(SWIFT_K(m) > 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-%sswift_k must be > 0 (GPa), got %g", pre,
             (double)SWIFT_K(m));
  PetscCheck(SWIFT_EPS0(m) > 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-%sswift_eps0 must be > 0, got %g", pre,
             (double)SWIFT_EPS0(m));
  PetscCheck(EXPONENT(m) >= 0 && EXPONENT(m) <= 1, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-%shardening_exponent must lie in [0, 1], got %g", pre, (double)EXPONENT(m));
  PetscFunctionReturn(PETSC_SUCCESS);
}

const IndHardeningLaw *IndHardeningSwift(void)
{
  static const IndHardeningLaw law = {"swift", R, dR, Read, Check, NULL};
  return &law;
}

void IndHardeningSetSwift(IndPlasticParams *m, PetscReal K, PetscReal eps0, PetscReal n)
{
  m->law        = IndHardeningSwift();
  SWIFT_K(m)    = K;
  SWIFT_EPS0(m) = eps0;
  EXPONENT(m)   = n;
  m->R0         = eps0 > 0 ? K * PetscPowReal(eps0, n) : 0;
}
