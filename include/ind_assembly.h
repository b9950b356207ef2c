#pragma once
/* The project's own cell loop: residual B^T sigma and Jacobian B^T D B over cached quadrature data.
   This is where the constitutive update of each quadrature point is called. */
#include <petscmat.h>
#include "ind_disc.h"
#include "ind_material.h"

/* A vector field of position, e.g. a body force (nN/nm^3) or a boundary displacement (nm). */
typedef PetscErrorCode (*IndVectorFn)(const PetscReal x[3], PetscReal v[3], void *ctx);

typedef struct _p_IndAssembly *IndAssembly;
struct _p_IndAssembly {
  IndDisc      disc;
  IndMaterials mats;
  IndVectorFn  body_force;
  void        *body_ctx;
  PetscReal   *ue, *fe, *Ke, *G, *DB; /* per-cell work arrays, allocated once */
};

PetscErrorCode IndAssemblyCreate(IndDisc disc, IndMaterials mats, IndAssembly *assembly);
PetscErrorCode IndAssemblyDestroy(IndAssembly *assembly);
/* Creates the AIJ matrix (block size 3) preallocated by a dry run of the cell loop. */
PetscErrorCode IndAssemblyCreateMatrix(IndAssembly assembly, Mat *J);
/* Floc = internal minus external forces, over local cells (Floc is zeroed first). */
PetscErrorCode IndAssemblyResidual(IndAssembly assembly, Vec Uloc, Vec Floc);
PetscErrorCode IndAssemblyJacobian(IndAssembly assembly, Vec Uloc, Mat J);
/* Volume averages per local cell of stress and strain (6 Voigt components each). */
PetscErrorCode IndAssemblyCellAverages(IndAssembly assembly, Vec Uloc, PetscReal *stress, PetscReal *strain);
