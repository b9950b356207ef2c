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

/* Values per quadrature point: IndPlasticState (eps_p 6, x 6, p 1), then dp of the step. */
#define IND_HISTORY_NVAL 14
#define IND_HISTORY_DP   13

typedef struct _p_IndHistory *IndHistory;

PetscErrorCode IndHistoryCreate(IndDisc disc, IndHistory *history);
PetscErrorCode IndHistoryDestroy(IndHistory *history);
/* The committed history (borrowed): stride values per local cell, cell i at i * stride of the owned part. */
PetscErrorCode IndHistoryGetCommitted(IndHistory history, Vec *committed, PetscInt *stride);

/* Its part of the state (ind_state.h): the committed history, by cell. */
PetscErrorCode IndHistoryState(void *history, IndStateFile file);
