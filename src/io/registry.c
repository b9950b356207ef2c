#include <string.h>
#include "ind_common.h"
#include "ind_registry.h"

static PetscErrorCode Add(IndRegistry *r, const char name[], IndRegistryFn fn)
{
  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < r->n; ++k)
    if (!strcmp(r->name[k], name)) {
      r->fn[k] = fn;
      PetscFunctionReturn(PETSC_SUCCESS);
    }
  PetscCheck(r->n < IND_REGISTRY_MAX, PETSC_COMM_SELF, PETSC_ERR_SUP, "More than %d implementations registered: '%s'",
             IND_REGISTRY_MAX, name);
  PetscCall(PetscStrncpy(r->name[r->n], name, sizeof(r->name[0])));
  r->fn[r->n]    = fn;
  r->names[r->n] = r->name[r->n];
  r->n++;
  r->names[r->n] = NULL;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndRegistryReady(IndRegistry *r)
{
  PetscFunctionBeginUser;
  if (r->ready) PetscFunctionReturn(PETSC_SUCCESS);
  r->ready = PETSC_TRUE;
  for (const IndRegistryEntry *e = r->builtin; e && e->name; ++e) PetscCall(Add(r, e->name, e->fn));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndRegistryAdd(IndRegistry *r, const char name[], IndRegistryFn fn)
{
  PetscFunctionBeginUser;
  PetscCall(IndRegistryReady(r));
  PetscCall(Add(r, name, fn));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndRegistryGet(IndRegistry *r, MPI_Comm comm, const char option[], const char name[], IndRegistryFn *fn)
{
  PetscFunctionBeginUser;
  PetscCall(IndRegistryReady(r));
  *fn = NULL;
  for (PetscInt k = 0; k < r->n; ++k)
    if (!strcmp(r->name[k], name)) *fn = r->fn[k];
  PetscCheck(*fn, comm, PETSC_ERR_ARG_UNKNOWN_TYPE, "%s: '%s' is not registered", option, name);
  PetscFunctionReturn(PETSC_SUCCESS);
}
