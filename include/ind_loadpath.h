#pragma once
/* Adaptive stepping of the load factor t from 0 to 1: a failed step (Newton or return map) is cut
   back and retried, an easy one lets the next increment grow back. Plain data, so the whole stepping
   state can be saved with the rest of the run. */
#include <petscsys.h>
#include "ind_common.h"

typedef struct {
  PetscReal t;          /* load factor of the last accepted step */
  PetscReal dt;         /* increment of the next attempt */
  PetscReal dt_initial; /* 1 / -load_steps */
  PetscReal dt_min, dt_max;
  PetscReal cutback; /* dt *= cutback after a failure */
  PetscReal growth;  /* dt *= growth after an easy step, up to dt_max */
  PetscInt  easy_its; /* a step needing at most this many Newton iterations is easy */
  PetscInt  max_cutbacks; /* in a row, before giving up */
  PetscInt  accepted, cutbacks, cutbacks_in_a_row;
} IndLoadPath;

PetscErrorCode IndLoadPathSetFromOptions(MPI_Comm comm, IndLoadPath *path);
PetscBool      IndLoadPathDone(const IndLoadPath *path);
/* The load factor the next attempt should reach. */
PetscReal      IndLoadPathTarget(const IndLoadPath *path);
void           IndLoadPathAccept(IndLoadPath *path, PetscInt newton_its);
/* Cuts the increment; errors (naming the options) once it falls below dt_min or after
   max_cutbacks failures in a row. */
PetscErrorCode IndLoadPathReject(IndLoadPath *path, MPI_Comm comm, const char why[]);
