#pragma once
/* Write faults as ordinary events (iofault.c): a full disk, a quota, a file-size limit or a vanished
   directory while a step's files are written ends the run with one line naming the file, the step and the
   cause, exit status IND_EXIT_IO, and a checkpoint of the last accepted step when there is room for it. */
#include "ind_common.h"

/* The exit status of a run ended by a failed write (EX_IOERR of sysexits.h). */
#define IND_EXIT_IO 74

typedef struct {
  PetscBool failed; /* on any rank */
  int       cause;  /* errno of the first failure (the largest over the ranks), 0 when unknown */
} IndIOFault;

/* Once, after PetscInitialize: HDF5 prints no diagnostic stack of its own (the line says what failed),
   and a file-size limit (ulimit -f) makes a write fail with EFBIG instead of killing the process. */
PetscErrorCode IndIOFaultSetUp(void);
/* Collective, before a parallel write that HDF5 cannot take back once a rank fails (a rank that fails
   inside a collective write leaves the others waiting in it): raises PETSC_ERR_FILE_WRITE on every rank,
   with errno ENOSPC or EFBIG, when bytes more do not fit in the file at path, by the free space of its
   filesystem or by the file-size limit. */
PetscErrorCode IndIOFaultCheckRoom(MPI_Comm comm, const char path[], double bytes);
/* For a file another program wrote without checking its writes (gmsh): ENOSPC when its filesystem has less
   than 1 MiB free, EFBIG when it reached the file-size limit, else 0. */
int            IndIOFaultFileCause(const char path[]);
/* Brackets one write phase: between them an error returns quietly, recording errno where it was raised.
   End is collective: it tells every rank whether a rank failed. A rank that failed and whose partners
   do not arrive within seconds (they wait inside the collective write it left) prints "<program>: error:
   <alone>: <cause>" on stderr and ends the job with MPI_Abort(IND_EXIT_IO). */
PetscErrorCode IndIOFaultBegin(void);
PetscErrorCode IndIOFaultEnd(MPI_Comm comm, PetscErrorCode ierr, const char alone[], IndIOFault *fault);
/* The cause in words: strerror of the errno, or "write failed" without one. */
const char    *IndIOFaultCause(const IndIOFault *fault);
