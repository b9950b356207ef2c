#pragma once
/* Private to the output (output.c): the XDMF 3 index of indent.h5 that ParaView (XDMF Reader,
   Xdmf3ReaderS/T) and meshio's XdmfTimeSeriesReader read.

   Layout, and why:
   - one Uniform grid per output step in a Temporal collection, each with its own Topology and Geometry
     pointing straight at the HDF5 datasets (meshio takes the first step's grid as the mesh and does not
     follow XML references);
   - each attribute of step k points at /xdmf/<k>/<field>, an HDF5 virtual dataset that maps the slab
     [k, :, :] of /fields/<field>: meshio reads whole datasets (no hyperslabs) and ParaView's Xdmf3
     readers drop XDMF HyperSlab items, while the data stays once in /fields;
   - the time value is the load program's pseudo-time, increasing through loading, hold and unloading;
     the step number, load factor, depth and load are Information elements of each step grid (meshio
     refuses attributes with Center="Grid"; ParaView ignores Information). */
#include <petscviewerhdf5.h>
#include "ind_common.h"

typedef struct {
  const char *name;  /* dataset /fields/<name>, and the attribute's name */
  const char *type;  /* XDMF AttributeType: Scalar, Vector or Matrix */
  PetscBool   cells; /* one value block per cell, else per vertex */
  PetscInt    bs;    /* values per cell or vertex */
} IndXdmfField;

typedef struct {
  PetscInt  step;               /* accepted load step */
  PetscReal t;                  /* time value: pseudo-time of the load program */
  PetscReal lambda, depth, load; /* load factor, nm, uN; NaN when not known (left out of the index) */
} IndXdmfStep;

typedef struct {
  const char *h5name; /* the HDF5 file's name relative to the XDMF file */
  const char *topology; /* XDMF's name of the cells: Tetrahedron, Hexahedron, Triangle, Quadrilateral */
  PetscInt    corners;  /* vertices per cell */
  PetscInt    nvert, ncell;
} IndXdmfMesh;

/* Collective on the viewer's communicator: (re)creates /xdmf/<k>/<name> for every field, the views of
   step k that the index points at, and flushes the file. */
PetscErrorCode IndXdmfAddStepViews(PetscViewer viewer, PetscInt k, PetscInt nfields, const IndXdmfField fields[]);
/* Collective; rank 0 writes "<path>.tmp" and renames it over path, so that a reader or a killed run
   never sees a half-written index. */
PetscErrorCode IndXdmfWrite(MPI_Comm comm, const char path[], const IndXdmfMesh *mesh, PetscInt nfields,
                            const IndXdmfField fields[], PetscInt nsteps, const IndXdmfStep steps[]);
