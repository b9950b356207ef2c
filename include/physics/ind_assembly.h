#pragma once
/* The project's own cell loop: residual B^T sigma and Jacobian B^T D B over cached quadrature data.
   This is where the constitutive update of each quadrature point is called: from the committed
   history and the current strain; the history changes only when a step is accepted. */
#include <petscmat.h>
#include "ind_disc.h"
#include "ind_material.h"
#include "ind_registry.h"
#include "ind_history.h"
#include "ind_matinsert.h"

/* A vector field of position, e.g. a body force (nN/nm^3) or a boundary displacement (nm). */
typedef PetscErrorCode (*IndVectorFn)(const PetscReal x[3], PetscReal v[3], void *ctx);

typedef enum { IND_TANGENT_CONSISTENT, IND_TANGENT_ELASTIC } IndTangent;
extern const char *const IndTangentTypes[];

/* -formulation: small strain (the paper's model), or finite strain: total Lagrangian, the same
   constitutive kernel in the logarithmic strain space (ind_logstrain.h). */
/* The kinematics (-formulation: small or finite strain), registered by name (as PETSc's KSPRegister): its table of
   quadrature-point operations lives in the physics group (assembly_impl.h); a new one is a file there and an
   entry in IndKinematicsRegistry (assembly.c), whose functions return the tables. */
typedef struct _IndKinematics IndKinematics;
extern IndRegistry IndKinematicsRegistry;

typedef struct _p_IndAssembly *IndAssembly;

/* Per local cell, volume averages over the committed history (after IndHistoryCommit). At finite
   strain the Cauchy stress and the spatial Hencky strain are averaged over the current volume, the
   material's state (p, back stress, yielding) over the reference volume. */
typedef struct {
  PetscReal *stress;      /* 6 per cell, Voigt, GPa */
  PetscReal *strain;      /* 6 per cell, engineering shears */
  PetscReal *plastic;     /* accumulated equivalent plastic strain p */
  PetscReal *back_stress; /* equivalent back stress sqrt(3/2) |x|, GPa */
  PetscReal *yielding;    /* fraction of the cell's volume that yielded in the last step, 0..1 */
  PetscReal *compaction;  /* plastic compaction -tr(eps_p) (a densifying material's); NULL: not wanted */
} IndCellFields;

PetscErrorCode IndAssemblyCreate(IndDisc disc, IndMaterials mats, IndHistory history, IndAssembly *assembly);
PetscErrorCode IndAssemblyDestroy(IndAssembly *assembly);
/* Whether the kinematics is of large deformation (-formulation finite). */
PetscBool      IndAssemblyIsFiniteStrain(IndAssembly assembly);
/* Whether its cells are an axisymmetric section (a 2D mesh). */
PetscBool      IndAssemblyIsAxisymmetric(IndAssembly assembly);
/* The discretisation it assembles on (borrowed). */
IndDisc        IndAssemblyGetDisc(IndAssembly assembly);
/* Quadrature points of this rank whose return map failed, and those yielding, in the last residual. */
void           IndAssemblyGetPointCounts(IndAssembly assembly, PetscInt *failed, PetscInt *plastic);
/* Jacobians on this rank that reused the points' work of the residual at their displacement (finite strain). */
PetscInt       IndAssemblyGetKeptUses(IndAssembly assembly);
/* A body force (nN/nm^3) at every quadrature point, for manufactured solutions; NULL removes it. */
PetscErrorCode IndAssemblySetBodyForce(IndAssembly assembly, IndVectorFn fn, void *ctx);
/* Creates the AIJ matrix (block size 3) preallocated by a dry run of the cell loop. */
PetscErrorCode IndAssemblyCreateMatrix(IndAssembly assembly, Mat *J);
/* Whether the matrices of the linear solves multiply by PETSc's inode kernel (-jac_inodes; off by default). */
PetscBool      IndAssemblyJacobianInodes(IndAssembly assembly);
/* Whether the Jacobian, GAMG's coarse operators and its interpolations are multiplied by block rows
   (-jac_block_products). */
PetscBool      IndAssemblyJacobianBlockProducts(IndAssembly assembly);
/* Floc = internal minus external forces, over local cells (Floc is zeroed first), from the committed
   history and the displacement Uloc (the constitutive update of every point, not stored); sets
   nfailed and nplastic. */
PetscErrorCode IndAssemblyResidual(IndAssembly assembly, Vec Uloc, Vec Floc);
/* Accepts the displacement Uloc: the constitutive update of every point, as the residual computes it
   there, becomes its committed history. Sets nplastic. */
PetscErrorCode IndAssemblyCommit(IndAssembly assembly, Vec Uloc);
PetscErrorCode IndAssemblyJacobian(IndAssembly assembly, Vec Uloc, Mat J);
/* The Jacobian with the elastic tangent at every point (an elastic unloading from the current state), into any
   matrix of J's layout (J itself at its cached positions, any other with MatSetValues). */
PetscErrorCode IndAssemblyElasticJacobian(IndAssembly assembly, Vec Uloc, Mat K);
PetscErrorCode IndAssemblyCellAverages(IndAssembly assembly, Vec Uloc, IndCellFields *fields);
/* Local cells whose deformation gradient F = I + grad u has det F <= 0 at a quadrature point (inverted
   by the displacement Uloc), and the smallest det F met. The finite-strain residual fails such a point,
   so Newton cuts the step back; at small strain nothing stops them, and an accepted state is checked
   with this (run_checks.c). */
PetscErrorCode IndAssemblyCountInverted(IndAssembly assembly, Vec Uloc, PetscInt *ncells, PetscReal *jmin);
