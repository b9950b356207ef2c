#pragma once
/* HDF5 rows of mesh values and their keys, for the checkpoint and for continuing a field file: the
   helpers that write a local block of rows as one dataset, read a dataset back laid out by PETSc, and
   find where each of this rank's keys sits in a file written on any number of ranks. */
#include <petscdmplex.h>
#include <petscviewerhdf5.h>
#include "ind_keyjoin.h"
#include "ind_disc.h"

/* The centroid of point p's vertices in the undeformed mesh (its key). */
PetscErrorCode IndPointCentroid(DM dm, PetscInt p, PetscReal c[3]);
#define IND_ROWS_CHECKSUM_LEN 17
/* Collective: a checksum of x's values and their global positions (16 hex digits), the same on any
   number of ranks. */
PetscErrorCode IndRowsChecksum(Vec x, char sum[IND_ROWS_CHECKSUM_LEN]);
/* Collective: n local rows of bs reals as dataset name of the viewer's current group, with their
   checksum as the dataset's attribute "checksum". */
PetscErrorCode IndRowsWrite(PetscViewer viewer, const char name[], PetscInt n, PetscInt bs, const PetscReal *rows);
/* Collective: dataset name of the current group into a new vector of block size bs, laid out by PETSc;
   an error naming the file and the dataset when its values do not match the checksum written with them. */
PetscErrorCode IndRowsRead(PetscViewer viewer, const char name[], PetscInt bs, Vec *x);
/* Collective: whether dataset name (current group) has a checksum, and whether x, read from it, matches it. */
PetscErrorCode IndRowsChecksumMatches(PetscViewer viewer, const char name[], Vec x, PetscBool *has, PetscBool *same);
/* The keys of this rank's cells (their centroids), allocated (PetscFree). */
PetscErrorCode IndCellCentroids(IndDisc disc, PetscReal **keys);
/* Collective: for each of the n keys mine, the bs values that dataset values (NULL: the row number)
   holds beside it in the file's key dataset keys (both in the current group); an error naming what
   and file (as the message should name it, e.g. "-restart: checkpoint 'x.h5'") when a key is missing
   or the counts differ (the file is of another mesh). */
PetscErrorCode IndRowsJoin(PetscViewer viewer, const char keys[], const char values[], PetscInt bs, const char what[],
                           const char file[], PetscInt n, const PetscReal *mine, PetscReal *out);
/* Collective: the row of the file's key dataset (current group) holding each of the n keys; an error
   (naming what and file) when a key is missing or the counts differ. index is allocated (PetscFree). */
PetscErrorCode IndRowsLocate(PetscViewer viewer, const char keys[], const char what[], const char file[], PetscInt n,
                             const PetscReal *mine, PetscInt **index);
