#pragma once
/* Rows of values written straight to HDF5 in the layout of PETSc's VecView and ISView, which PETSc's VecLoad reads
   back: a dataset of fixed size (N, bs) (N alone for bs 1 unless the viewer's base dimension 2 is on), or, while
   the viewer is timestepping, the slab of the current step of an extensible (steps, N, bs) dataset chunked by one
   step. PETSc's own views chunk every dataset by its global size and let HDF5 fill each new chunk, which takes a
   buffer of the whole dataset on every rank: on a cluster a transient as large as the whole field on each
   process. These datasets are never filled (every value is written). */
#include <petscviewerhdf5.h>
#include "ind_common.h"

/* HDF5 reports failure as a negative id or status. */
#define IndCallHDF5(expr) \
  do { \
    if ((expr) < 0) SETERRQ(PETSC_COMM_SELF, PETSC_ERR_LIB, "HDF5 call failed: %s", #expr); \
  } while (0)

/* Collective: this rank's n rows of bs reals as dataset name of the viewer's current group, after the rows of the
   ranks below it. */
PetscErrorCode IndH5WriteRows(PetscViewer viewer, const char name[], PetscInt n, PetscInt bs, const PetscReal *rows);
/* The same for integers (PetscInt), as ISView writes them. */
PetscErrorCode IndH5WriteIntRows(PetscViewer viewer, const char name[], PetscInt n, PetscInt bs, const PetscInt *rows);
