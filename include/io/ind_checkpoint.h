#pragma once
/* The whole evolving state of a run in one HDF5 file, restored on any number of ranks: the parts that the
   objects with state save themselves (ind_state.h: the application lists them), beside the provenance and the
   model options of the run. The file is written under a temporary name and renamed, so a kill at any moment
   leaves the previous checkpoint whole. */
#include "ind_state.h"

/* Collective: writes the parts, the state of accepted step `step`; the checkpoint it replaces is kept whole as
   IndRunDirPreviousCheckpoint(path) until the next one is complete. */
PetscErrorCode IndCheckpointWrite(MPI_Comm comm, IndDisc disc, const char path[], PetscInt step, PetscInt nparts,
                                  const IndStatePart parts[]);
/* Collective: whether path is a checkpoint whose model options are this run's (an error names the
   first that differs); before the mesh is made, so that a refused restart changes no file. */
PetscErrorCode IndCheckpointCheck(MPI_Comm comm, const char path[]);
/* Collective: whether every dataset of the checkpoint at path is there and matches the checksum written
   with it; why is "" when it does, or says what is wrong (for "'path' is damaged: <why>"). step: the
   checkpoint's accepted steps (NULL: not wanted; -1 when unknown). */
PetscErrorCode IndCheckpointVerify(MPI_Comm comm, const char path[], PetscInt *step, char why[], size_t len);
/* Collective: restores the parts, into objects created from the checked options; a checkpoint of another mesh
   is refused. */
PetscErrorCode IndCheckpointRead(MPI_Comm comm, IndDisc disc, const char path[], PetscInt nparts,
                                 const IndStatePart parts[]);
/* The model options of this run (solver, output and run-control options left out), sorted, one
   "-name value" per line; *text is allocated (PetscFree). */
PetscErrorCode IndCheckpointModelOptions(char **text);
/* First line where the two model-option texts differ, described for a message: "" when they agree. */
void           IndCheckpointOptionsDiffer(const char *saved, const char *here, char *what, size_t len);
