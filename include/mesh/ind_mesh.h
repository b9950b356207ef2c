#pragma once
/* The distributed DMPlex mesh and its named regions (gmsh physical names or box faces). */
#include <petscdmplex.h>
#include "ind_common.h"

#define IND_MAX_REGIONS 64

typedef struct {
  char     name[IND_NAME_LEN];
  PetscInt dim; /* 3: volume (a set of cells), 2: surface (a set of faces); so also on a 2D (axisymmetric) mesh,
                   whose cells and faces are the volumes and surfaces of revolution */
} IndRegion;

typedef struct _p_IndMesh *IndMesh;

PetscErrorCode IndMeshCreate(MPI_Comm comm, IndMesh *mesh);
PetscErrorCode IndMeshDestroy(IndMesh *mesh);
/* The distributed DM (borrowed); each region is a DMLabel of its name with value 1. */
PetscErrorCode IndMeshGetDM(IndMesh mesh, DM *dm);
/* Tetrahedra or triangles (true), hexahedra or quadrilaterals (false), the same on every rank. */
PetscErrorCode IndMeshIsSimplex(IndMesh mesh, PetscBool *simplex);
/* A 2D mesh: the axisymmetric model. Its cells lie in the plane y = 0 with x the radius r >= 0 and z the axis;
   every node carries three displacements, the hoop one (y) held at zero (doc/axisymmetric.md). */
PetscErrorCode IndMeshIsAxisymmetric(IndMesh mesh, PetscBool *axisymmetric);
/* The named regions, in the mesh file's order (borrowed). */
PetscErrorCode IndMeshGetRegions(IndMesh mesh, PetscInt *n, const IndRegion **regions);
/* The mesh file, or "box". */
PetscErrorCode IndMeshGetSource(IndMesh mesh, const char **source);
/* The label of a region; a missing region is an error naming the option that asked for it. */
PetscErrorCode IndMeshGetRegionLabel(IndMesh mesh, const char name[], PetscInt dim, const char option[],
  DMLabel *label);
/* Errors (collectively) when the region has no cells (dim 3) or faces (dim 2): a physical group of the
   mesh file without elements. option names what uses it (surfaces). */
PetscErrorCode IndMeshCheckRegionNotEmpty(IndMesh mesh, const char name[], PetscInt dim, const char option[]);
