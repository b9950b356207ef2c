#pragma once
/* The whole evolving state of a run, saved to one HDF5 file and restored on any number of ranks:
   displacement and its last increment, the committed quadrature-point history, the committed contact
   reactions, the load program's position and step size, the contact penalty scale, the curve and
   field-output steps so far, and the options and wall time of the run. Mesh values are stored beside
   their keys (reference centroids, see ind_keyjoin.h), so that a checkpoint made on one rank count is
   read on another, and one made on another mesh is refused. The file is written under a temporary name
   and renamed, so a kill at any moment leaves the previous checkpoint whole. */
#include "ind_app.h"

/* Collective: writes the state of the last accepted step; the checkpoint it replaces is kept whole
   as IndRunDirPreviousCheckpoint(path) until the next one is complete. */
PetscErrorCode IndCheckpointWrite(IndApp app, const char path[]);
/* Collective: whether path is a checkpoint whose model options are this run's (an error names the
   first that differs); before the mesh is made, so that a refused restart changes no file. */
PetscErrorCode IndCheckpointCheck(MPI_Comm comm, const char path[]);
/* Collective: whether every dataset of the checkpoint at path is there and matches the checksum written
   with it; why is "" when it does, or says what is wrong (for "'path' is damaged: <why>"). step: the
   checkpoint's accepted steps (NULL: not wanted; -1 when unknown). */
PetscErrorCode IndCheckpointVerify(MPI_Comm comm, const char path[], PetscInt *step, char why[], size_t len);
/* Collective: restores the state into app, created from the checked options; a checkpoint of another
   mesh is refused. */
PetscErrorCode IndCheckpointRead(IndApp app, const char path[]);
/* The model options of this run (solver, output and run-control options left out), sorted, one
   "-name value" per line; *text is allocated (PetscFree). */
PetscErrorCode IndCheckpointModelOptions(char **text);
/* First line where the two model-option texts differ, described for a message: "" when they agree. */
void           IndCheckpointOptionsDiffer(const char *saved, const char *here, char *what, size_t len);
