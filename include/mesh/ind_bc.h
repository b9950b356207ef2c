#pragma once
/* Dirichlet conditions on named surfaces: fixed, roller (chosen components), symmetry plane and
   prescribed displacement. Rows are zeroed with their columns, so the matrix keeps block size 3
   (GAMG) and stays symmetric (CG). */
#include <petscmat.h>
#include "ind_mesh.h"
#include "ind_disc.h"
#include "ind_assembly.h"

#define IND_MAX_BC 64

typedef struct {
  char        label[IND_NAME_LEN];
  char        option[32];   /* the option that asked for it, for messages */
  PetscInt    mask;         /* bit c set: component c constrained */
  PetscReal   value[3];     /* nm, at full load (constant conditions) */
  PetscReal   plane;        /* symmetry planes: the coordinate along their normal axis */
  IndVectorFn fn;           /* or a function of position, nm at full load */
  void       *ctx;
} IndBCSpec;

typedef struct _p_IndBC *IndBC;

PetscErrorCode IndBCCreate(IndMesh mesh, IndDisc disc, IndBC *bc);
PetscErrorCode IndBCDestroy(IndBC *bc);
/* The conditions as given, in the order of their options (borrowed). */
PetscErrorCode IndBCGetSpecs(IndBC bc, PetscInt *n, const IndBCSpec **specs);
/* The constrained rows owned by this rank, global numbers, after IndBCSetUp (borrowed). local: the same rows
   in the owned part of a global vector (NULL if not wanted). */
PetscErrorCode IndBCGetRows(IndBC bc, PetscInt *n, const PetscInt **rows, const PetscInt **local);
PetscErrorCode IndBCAddFunction(IndBC bc, const char label[], PetscInt mask, IndVectorFn fn, void *ctx);
PetscErrorCode IndBCSetUp(IndBC bc);
/* Makes the next IndBCSetUp re-evaluate every condition, e.g. after the state behind a function's
   context changed (a non-proportional load path). */
PetscErrorCode IndBCInvalidate(IndBC bc);
/* U[row] = load_factor * value at every constrained row. */
PetscErrorCode IndBCApplySolution(IndBC bc, PetscReal load_factor, Vec U);
/* F[row] = U[row] - load_factor * value. */
PetscErrorCode IndBCApplyResidual(IndBC bc, PetscReal load_factor, Vec U, Vec F);
PetscErrorCode IndBCApplyJacobian(IndBC bc, Mat J);
