#pragma once
/* The output directory of a run and the rule that protects an earlier run's results there:
   - a fresh run refuses a directory that already holds a run's files (indent.h5, the curve, the summary,
     a checkpoint, ...) unless -output_overwrite is given, which removes those files (and only those) first;
   - -restart <dir or checkpoint file> continues the run whose checkpoint lies in -output_dir, appending;
   - the run holds the directory's lock (ind_runlock.h) for its life: a live run's directory is refused.
   Decided before anything is written (the mesh module may mesh a .geo into the directory). */
#include "ind_common.h"

typedef struct {
  char      dir[PETSC_MAX_PATH_LEN];        /* -output_dir */
  char      checkpoint[PETSC_MAX_PATH_LEN]; /* <dir>/checkpoint.h5: where checkpoints go */
  PetscBool restart;                        /* -restart was given: continue from restart_file */
  char      restart_file[PETSC_MAX_PATH_LEN]; /* checkpoint or its previous one, in <dir> */
  PetscBool overwrite;                      /* -output_overwrite */
  PetscBool ready;                          /* the directory exists and belongs to this run */
} IndRunDir;

/* Reads -output_dir, -output_overwrite and -restart; with writes true (the run will write files)
   applies the rule above and creates the directory. Collective; errors name the option. */
PetscErrorCode IndRunDirSetUp(MPI_Comm comm, PetscBool writes, IndRunDir *rundir);
/* Writes path atomically: the caller wrote path.tmp; this renames it over path (rank 0 only calls it). */
PetscErrorCode IndRenameInto(const char tmp[], const char path[]);
/* The marker a run stopped by a signal leaves beside its checkpoint ("stopped by SIGTERM after step 17"):
   a job script whose launcher reports a status of its own (Open MPI's mpiexec after a forwarded SIGTERM)
   still knows the run stopped to be continued. A restart removes it. */
#define IND_STOPPED_FILE "indent.stopped"
/* The name under which checkpoint path is kept when a newer one replaces it (x.h5: x.previous.h5). */
void           IndRunDirPreviousCheckpoint(const char path[], char *previous, size_t len);
