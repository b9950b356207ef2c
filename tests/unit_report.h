#pragma once
/* Shared by the unit-test programs: a line per check with its worst error and tolerance, a failure
   count for the exit code, and deterministic random numbers. */
#include <stdio.h>
#include <petscsys.h>

static PetscInt failures = 0;

static inline void Report(const char *what, PetscReal worst, PetscReal tol)
{
  const PetscBool ok = worst <= tol ? PETSC_TRUE : PETSC_FALSE;
  if (!ok) failures++;
  printf("  %-66s worst %.2e (tol %.0e)%s\n", what, (double)worst, (double)tol, ok ? "" : "  FAIL");
}

/* Deterministic uniform numbers in [0, 1). */
static inline PetscReal Rand(unsigned long long *s)
{
  *s = *s * 6364136223846793005ULL + 1442695040888963407ULL;
  return (PetscReal)((*s >> 11) * (1.0 / 9007199254740992.0));
}
