#pragma once
/* Implementations registered by name and chosen by an option (as PETSc's KSPRegister / KSPSetType): a strategy is a
   file with its table, listed in its family's registry (IndHardeningRegistry, IndKinematicsRegistry,
   IndContactCouplingRegistry) or added at run time with IndRegistryAdd. The names keep the order of registration,
   which -help lists; PETSc's PetscFunctionList would do, but it does not keep that order. */
#include <petscsys.h>

#define IND_REGISTRY_MAX      16
#define IND_REGISTRY_NAME_LEN 64

typedef void (*IndRegistryFn)(void);

typedef struct {
  const char   *name;
  IndRegistryFn fn;
} IndRegistryEntry;

typedef struct {
  const IndRegistryEntry *builtin; /* registered before any other use, in order; ends with {NULL, NULL} */
  PetscBool               ready;
  PetscInt                n;
  char                    name[IND_REGISTRY_MAX][IND_REGISTRY_NAME_LEN];
  const char             *names[IND_REGISTRY_MAX + 1]; /* name[0..n-1], then NULL: the option's choices */
  IndRegistryFn           fn[IND_REGISTRY_MAX];
} IndRegistry;

/* Adds name, or replaces the function of a name already there. */
PetscErrorCode IndRegistryAdd(IndRegistry *registry, const char name[], IndRegistryFn fn);
/* Registers the built-in entries if not done yet. */
PetscErrorCode IndRegistryReady(IndRegistry *registry);
/* The function registered as name; an error naming the option (e.g. "-film_hardening") when there is none. */
PetscErrorCode IndRegistryGet(IndRegistry *registry, MPI_Comm comm, const char option[], const char name[],
                              IndRegistryFn *fn);
