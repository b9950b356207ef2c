#pragma once
/* A scratch test: once the indenter has reached its depth (or load, under load control) and held, its
   axis slides -scratch_length nm along -scratch_direction in the surface's plane, at that depth (or
   load), over the load program's scratch segment (loadpath.c); then it unloads where it stopped. A
   half model must be mirrored along the scratch: the axis stays in its symmetry plane. Plain data, so
   the scratch's state is the load program's and the contact's. */
#include "ind_contact.h"

#define IND_SCRATCH_FILE "scratch.csv" /* in the output directory; a restart truncates it (stepcsv.c) */

typedef struct {
  PetscReal length;    /* nm; 0: no scratch */
  PetscReal dir[2];    /* unit direction of the slide */
  PetscInt  steps;     /* equal steps of the slide when none fails */
  PetscReal origin[2]; /* the axis before sliding (-indenter_axis) */
} IndScratch;

/* Reads -scratch_length, -scratch_direction and -scratch_steps; indenter: whether the run has one. */
PetscErrorCode IndScratchSetFromOptions(MPI_Comm comm, PetscBool indenter, IndScratch *scratch);
/* Takes the start from the contact's indenter and refuses a direction that leaves a symmetry plane
   through the axis and a path that leaves the contact surface. */
PetscErrorCode IndScratchSetUp(IndScratch *scratch, IndContact contact, IndBC bc);
/* The axis after sliding the fraction f of the length. */
void           IndScratchAxis(const IndScratch *scratch, PetscReal f, PetscReal axis[2]);
/* The forces of the indenter on the body, uN: normal (the load), along the slide (what the instrument
   pushes against) and across it in the surface's plane (to the left of the slide). */
void           IndScratchForces(const IndScratch *scratch, const IndContactSummary *contact, PetscReal *normal,
                                PetscReal *lateral, PetscReal *side);
/* Rank 0 appends accepted step `step` (pseudo-time t, fraction f of the slide, depth nm, contact state)
   to <dir>/scratch.csv: the position, normal and lateral forces in uN and the apparent friction. */
PetscErrorCode IndScratchWrite(MPI_Comm comm, const char dir[], const IndScratch *scratch, PetscInt step,
                               PetscReal t, PetscReal f, PetscReal depth, const IndContactSummary *contact);
