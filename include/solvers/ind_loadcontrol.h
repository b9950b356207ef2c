#pragma once
/* Load control (-load_force): the depth is an unknown of each step's Newton iteration (bordered.c); this object
   chooses the depth that iteration starts from, from the dP/dh of the last accepted step, and keeps the load and
   slope it needs, part of the run's state. */
#include "ind_loadpath.h"
#include "ind_state.h"

typedef struct _p_IndLoadControl *IndLoadControl;

PetscErrorCode IndLoadControlCreate(IndLoadControl *control);
PetscErrorCode IndLoadControlDestroy(IndLoadControl *control);
/* The depth the step to load `target` (uN) starts from: the last step's dP/dh predicts it, at first the load
   program's share of -load_depth (lambda); a slide (sliding true) starts from the accepted depth d_c. Within
   [0, -load_depth]. */
PetscReal      IndLoadControlStartDepth(IndLoadControl control, const IndLoadPath *path, PetscReal lambda,
                                        PetscReal target, PetscReal d_c, PetscBool sliding);
/* An accepted step reached load (uN) after a change of depth dd (nm). */
void           IndLoadControlAccept(IndLoadControl control, PetscReal load, PetscReal dd);
/* Its part of the state: the last load and dP/dh. */
PetscErrorCode IndLoadControlState(void *control, IndStateFile file);
