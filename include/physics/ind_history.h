#pragma once
/* The history of every quadrature point (plastic strain, back stress, accumulated plastic strain and
   the increment of the last step) at the end of the last accepted load step, as a distributed vector
   laid out by a PetscSection on the cells. Every residual recomputes the points' update from it and
   the current displacement without storing it; an accepted step writes the update over it
   (IndAssemblyCommit). A rejected step therefore needs no undo, and the whole state can be saved,
   restored and compared as an ordinary vector on any number of ranks. */
#include <petscdm.h>
#include "ind_disc.h"
#include "ind_state.h"
#include "ind_plasticity.h"

/* A quadrature point's record as the constitutive kernels read and write it: IndPlasticState (eps_p 6, x 6,
   p 1), then dp of the step. The history stores it whole only where a back stress can grow (a kinematic
   modulus); otherwise without x (8 values: eps_p, p, dp), which on the plastic cube at 824k dofs is 100 MB. */
#define IND_HISTORY_NVAL 14
#define IND_HISTORY_DP   13
#define IND_HISTORY_NVAL_NO_BACK_STRESS 8

typedef struct _p_IndHistory *IndHistory;

/* back_stress: store each point's back stress (some material hardens kinematically) */
PetscErrorCode IndHistoryCreate(IndDisc disc, PetscBool back_stress, IndHistory *history);
PetscErrorCode IndHistoryDestroy(IndHistory *history);
/* The committed history (borrowed): stride values per local cell, cell i at i * stride of the owned part. */
PetscErrorCode IndHistoryGetCommitted(IndHistory history, Vec *committed, PetscInt *stride);

/* Its part of the state (ind_state.h): the committed history, by cell. */
PetscErrorCode IndHistoryState(void *history, IndStateFile file);
