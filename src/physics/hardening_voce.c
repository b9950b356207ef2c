#include "ind_hardening.h"
#include "ind_options.h"

/* Voce: R(p) = Rs - (Rs - R0) exp(-gamma p), saturating at Rs (softening towards it when Rs < R0). */
#define RS(m)    ((m)->c[0])
#define GAMMA(m) ((m)->c[1])

static PetscReal R(const IndPlasticParams *m, PetscReal p)
{
  return RS(m) - (RS(m) - m->R0) * PetscExpReal(-GAMMA(m) * p);
}

static PetscReal dR(const IndPlasticParams *m, PetscReal p)
{
  return GAMMA(m) * (RS(m) - m->R0) * PetscExpReal(-GAMMA(m) * p);
}

static PetscErrorCode Read(PetscOptionItems *PetscOptionsObject, MPI_Comm comm, const char region[],
                           IndPlasticParams *m)
{
  PetscBool set;

  PetscFunctionBeginUser;
  PetscCall(IndHardeningReadYield(PetscOptionsObject, comm, region, m));
  PetscCall(IndOptionsReal("-saturation", "Voce saturation stress Rs", "GPa", IND_REQUIRED " with voce", RS(m),
                           &RS(m), &set));
  if (!IndHelpListing()) PetscCall(IndHardeningRequire(comm, region, "saturation", set, "Voce saturation stress, GPa"));
  PetscCall(IndOptionsReal("-voce_rate", "Voce rate gamma", "", IND_REQUIRED " with voce", GAMMA(m), &GAMMA(m),
                           &set));
  if (!IndHelpListing()) PetscCall(IndHardeningRequire(comm, region, "voce_rate", set, "Voce rate"));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Check(const IndPlasticParams *m, const char pre[], MPI_Comm comm)
{
  PetscFunctionBeginUser;
  PetscCheck(RS(m) > 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-%ssaturation must be > 0 (GPa), got %g", pre,
             (double)RS(m));
  PetscCheck(GAMMA(m) >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-%svoce_rate must be >= 0, got %g", pre,
             (double)GAMMA(m));
  /* Softening (Rs < R0) is allowed while the return equation stays strictly decreasing in dp, which keeps its
     root unique and the tangent finite. */
  PetscCheck(GAMMA(m) * (m->R0 - RS(m)) < 3.0 * m->mu + m->H, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "Voce softening too steep: -%svoce_rate * (-%syield - -%ssaturation) = %g GPa must be < 3 mu + H = %g "
             "GPa", pre, pre, pre, (double)(GAMMA(m) * (m->R0 - RS(m))), (double)(3.0 * m->mu + m->H));
  PetscFunctionReturn(PETSC_SUCCESS);
}

const IndHardeningLaw *IndHardeningVoce(void)
{
  static const IndHardeningLaw law = {"voce", R, dR, Read, Check, NULL};
  return &law;
}

void IndHardeningSetVoce(IndPlasticParams *m, PetscReal Rs, PetscReal gamma)
{
  m->law   = IndHardeningVoce();
  RS(m)    = Rs;
  GAMMA(m) = gamma;
}
