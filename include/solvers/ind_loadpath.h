#pragma once
/* The load program and its adaptive stepping. A pseudo-time t runs over the program's segments:
   loading for t in [0, 1], an optional hold of length -load_hold, an optional scratch of length 1
   (the indenter slides, scratch.c), an optional unloading of length 1; the load factor lambda(t) goes
   0 -> 1, stays at 1 through the hold and the scratch, goes back to 0. Prescribed displacements are
   lambda times their values and the indenter's depth is lambda times -load_depth. A failed step
   (Newton, return map or contact loop) is cut back and retried, an easy one lets the next increment
   grow back; steps end exactly on the segments' ends. Plain data, so the whole stepping state can be
   saved with the rest of the run. */
#include <petscsys.h>
#include "ind_common.h"
#include "ind_state.h"

typedef struct {
  PetscReal t;          /* pseudo-time of the last accepted step */
  PetscReal hold;       /* length of the hold segment (0: none) */
  PetscBool unload;     /* whether the program unloads */
  PetscReal scratch;    /* length of the scratch segment: 1, or 0 for none */
  PetscReal t_end;      /* 1 + hold + scratch (+ 1 when unloading) */
  PetscReal depth_max;  /* -load_depth, nm (0: no indenter); under load control the largest depth allowed */
  PetscReal force_max;  /* -load_force, uN: load control (0: the depth is prescribed) */
  PetscReal force_rtol; /* load control: |P - P*| <= force_rtol * force_max */
  PetscReal unload_to;  /* load control: unloading ends at this fraction of force_max (0: at zero load) */
  PetscReal dt;         /* increment of the next attempt */
  PetscReal dt_initial; /* 1 / -load_steps */
  PetscReal dt_unload;  /* 1 / -load_unload_steps: the unloading segment's first increment */
  PetscReal dt_scratch; /* 1 / -scratch_steps: the scratch segment's increment, and its largest */
  PetscReal unload_growth; /* factor on the increment after each accepted unloading step */
  PetscReal dt_min, dt_max;
  PetscReal cutback; /* dt *= cutback after a failure */
  PetscReal growth;  /* dt *= growth after an easy step, up to dt_max */
  PetscInt  easy_its; /* a step needing at most this many Newton iterations is easy */
  PetscInt  max_cutbacks; /* in a row, before giving up */
  PetscReal edge_steps;   /* -load_edge_steps: loading steps at least this many per node spacing the contact's
                             edge crosses (0: no limit) */
  PetscInt  accepted, cutbacks, cutbacks_in_a_row;
  PetscInt  rejected_newton, rejected_linear; /* iterations spent in the attempts that were cut back */
} IndLoadPath;

/* unload_default: whether the program unloads unless -load_unload says otherwise (an indentation does). */
PetscErrorCode IndLoadPathSetFromOptions(MPI_Comm comm, PetscBool unload_default, IndLoadPath *path);
/* Adds the scratch segment, in `steps` equal increments (after SetFromOptions, before any step). */
void           IndLoadPathSetScratch(IndLoadPath *path, PetscInt steps);
/* lambda(t) of the program. */
PetscReal      IndLoadPathFactor(const IndLoadPath *path, PetscReal t);
/* Whether t lies in the unloading segment. */
PetscBool      IndLoadPathUnloading(const IndLoadPath *path, PetscReal t);
/* The fraction of the scratch's length slid at t: 0 before the scratch segment, 1 after it. */
PetscReal      IndLoadPathScratchFraction(const IndLoadPath *path, PetscReal t);
/* Whether t lies in the scratch segment. */
PetscBool      IndLoadPathScratching(const IndLoadPath *path, PetscReal t);
/* Ends the program now (the indenter has left the surface during unloading). */
void           IndLoadPathFinish(IndLoadPath *path);
PetscBool      IndLoadPathDone(const IndLoadPath *path);
/* Whether the last accepted step ended a segment of the program: the loading (the largest depth, or load),
   the hold, the scratch, or the unloading (also when IndLoadPathFinish ended it early). */
PetscBool      IndLoadPathAtSegmentEnd(const IndLoadPath *path);
/* Whether the fields of the step just accepted are written: with every = N, every N-th accepted step,
   every segment's end (IndLoadPathAtSegmentEnd) and the program's last step; every = 1 writes all. */
PetscBool      IndLoadPathFieldStep(const IndLoadPath *path, PetscInt every);
/* The steps the program has left if none is cut back nor grows on an easy step (the loading's
   increment is at its largest from the start by default), counting only the field steps of
   IndLoadPathFieldStep(every) (every = 1: all steps): at most limit. */
PetscInt       IndLoadPathStepsLeft(const IndLoadPath *path, PetscInt every, PetscInt limit);
/* The load factor the next attempt should reach. */
PetscReal      IndLoadPathTarget(const IndLoadPath *path);
/* Caps the next step's end at t_max (not below the smallest increment): a limit of accuracy, not a failure. */
void           IndLoadPathLimit(IndLoadPath *path, PetscReal t_max);
void           IndLoadPathAccept(IndLoadPath *path, PetscInt newton_its);
/* Cuts the increment; errors (naming the options) once it falls below dt_min or after
   max_cutbacks failures in a row, ending with remedy (NULL: more cutbacks or smaller steps). */
PetscErrorCode IndLoadPathReject(IndLoadPath *path, MPI_Comm comm, const char why[], const char remedy[]);
/* Its part of the state (ind_state.h): the position in the program, the next increment and the counters. */
PetscErrorCode IndLoadPathState(void *path, IndStateFile file);
