#pragma once
/* Private to src/mesh/: the fields of IndMesh. Other groups use the accessors of
   ind_mesh.h. */
#include "ind_mesh.h"

struct _p_IndMesh {
  DM        dm;        /* owned; distributed; each region is a DMLabel of that name with value 1 */
  PetscBool simplex;   /* tetrahedra or triangles (true), hexahedra or quadrilaterals (false); the same on every rank */
  PetscInt  dim;       /* 3, or 2: the axisymmetric model, a mesh in (r, z) placed in the plane y = 0 */
  PetscInt  nregions;
  IndRegion regions[IND_MAX_REGIONS];
  char      source[PETSC_MAX_PATH_LEN]; /* mesh file, or "box" */
};

/* The built-in box made on every rank at once, each rank its own block of cells (box.c). */
PetscErrorCode IndBoxChooseGrid(PetscMPIInt size, const PetscInt faces[3], PetscInt grid[3]);
PetscErrorCode IndBoxCreateDistributed(MPI_Comm, const PetscInt faces[3], const PetscReal lower[3],
  const PetscReal upper[3], DM *);

/* -mesh_partitioner (partition.c): how the cells go to the ranks. The graph partitioners split a mesh made on rank 0
   (read from a file, or the box); "blocks" builds the box on every rank at once (box.c), its default. */
typedef enum {
  IND_PARTITIONER_PTSCOTCH,
  IND_PARTITIONER_METIS,
  IND_PARTITIONER_SIMPLE,
  IND_PARTITIONER_BLOCKS
} IndPartitionerType;
PetscErrorCode IndMeshGetPartitionerType(MPI_Comm, PetscBool box, IndPartitionerType *);
/* Sets a graph partitioner on the serial mesh. */
PetscErrorCode IndMeshSetPartitioner(DM dm, IndPartitionerType);
