#include "ind_hardening.h"
#include "ind_options.h"

IndRegistry IndHardeningRegistry = {
  .builtin = (const IndRegistryEntry[]){{"voce", (IndRegistryFn)IndHardeningVoce},
                                        {"linear", (IndRegistryFn)IndHardeningLinear},
                                        {"power", (IndRegistryFn)IndHardeningPower},
                                        {"swift", (IndRegistryFn)IndHardeningSwift},
                                        {"table", (IndRegistryFn)IndHardeningTable},
                                        {NULL, NULL}}
};

PetscErrorCode IndHardeningFind(MPI_Comm comm, const char option[], const char name[], const IndHardeningLaw **law)
{
  IndRegistryFn fn;

  PetscFunctionBeginUser;
  PetscCall(IndRegistryGet(&IndHardeningRegistry, comm, option, name, &fn));
  *law = ((const IndHardeningLaw *(*)(void))fn)();
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndHardeningRequire(MPI_Comm comm, const char region[], const char name[], PetscBool set,
                                   const char what[])
{
  PetscFunctionBeginUser;
  PetscCheck(set, comm, PETSC_ERR_ARG_WRONG,
    "Region '%s' is plastic (-%s_model plastic) but option -%s_%s (%s) is missing", region, region, region, name, what);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndHardeningReadYield(PetscOptionItems *PetscOptionsObject, MPI_Comm comm, const char region[],
                                     IndPlasticParams *m)
{
  PetscBool set;

  PetscFunctionBeginUser;
  PetscCall(IndOptionsReal("-yield", "Initial yield stress R0", "GPa", IND_REQUIRED, m->R0, &m->R0, &set));
  if (!IndHelpListing()) PetscCall(IndHardeningRequire(comm, region, "yield", set, "initial yield stress, GPa"));
  PetscFunctionReturn(PETSC_SUCCESS);
}
