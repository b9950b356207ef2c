#pragma once
/* The evolving state of a run, saved and restored one object at a time (as VecView and VecLoad do): each object
   with state writes its own part into an IndStateFile and reads it back, in a layout that does not depend on
   the number of ranks. Mesh values are stored beside their keys (the reference centroids of their nodes or
   cells, ind_keyjoin.h), so that they are read back on any rank count and a file of another mesh is refused.
   The checkpoint (ind_checkpoint.h) is such a file, and knows the parts only through IndStatePart. */
#include <petscviewerhdf5.h>
#include "ind_disc.h"

typedef struct _p_IndStateFile *IndStateFile;

/* One object's part of the state: transfer writes it into a file opened for writing, or reads it back from one
   opened for reading into an object made from the same options and mesh, with the same calls (IndStateReals,
   ...), so that what is saved and what is restored cannot drift apart. name is its group in the file. */
typedef struct {
  const char *name;
  PetscErrorCode (*transfer)(void *obj, IndStateFile file);
  void *obj;
} IndStatePart;

/* Collective. Open for writing (FILE_MODE_WRITE) or reading (FILE_MODE_READ); what names the file in the errors
   of reading ("-restart: checkpoint 'x.h5'"). Closing a file written lists its datasets in it, for
   IndCheckpointVerify. */
PetscErrorCode IndStateFileOpen(MPI_Comm comm, IndDisc disc, const char path[], PetscFileMode mode, const char what[],
                                IndStateFile *file);
PetscErrorCode IndStateFileClose(IndStateFile *file);
/* For attributes of the file itself (the checkpoint's provenance). */
PetscErrorCode IndStateFileGetViewer(IndStateFile file, PetscViewer *viewer);
/* Whether the file is being read: a part restores what follows from its values after the transfers. */
PetscBool      IndStateReading(IndStateFile file);
/* Transfers every part in order, each in a group of its name. */
PetscErrorCode IndStateTransfer(IndStateFile file, PetscInt n, const IndStatePart parts[]);

/* The transfers, each writing or reading as the file was opened:
   - n reals, the same on every rank (rank 0's are written), as /<part>/<name>; reading, the dataset must hold n;
   - an array of reals whose length the file keeps: writing *n values of *v; reading, *v is allocated (PetscFree;
     NULL and *n = 0 when the file has none);
   - a string, the same on every rank, as an attribute (reading: at most len bytes);
   - a global vector of the displacement's layout (3 values per node), by node, as /nodes/<part>_<name>;
   - stride values per local cell of the discretisation, by cell, as /cells/<part>_<name>. */
PetscErrorCode IndStateReals(IndStateFile file, const char name[], PetscInt n, PetscReal v[]);
PetscErrorCode IndStateRealArray(IndStateFile file, const char name[], PetscInt *n, PetscReal **v);
PetscErrorCode IndStateString(IndStateFile file, const char name[], char value[], size_t len);
PetscErrorCode IndStateNodes(IndStateFile file, const char name[], Vec x);
PetscErrorCode IndStateCells(IndStateFile file, const char name[], PetscInt stride, PetscReal *v);
