#pragma once
/* Values keyed by reference positions, moved between two distributions of the same mesh.

   A checkpoint stores each mesh point's values next to its key (the centroid of the point's vertices
   in the undeformed mesh, exact bits), in whatever order the writing ranks held them. Reading on any
   number of ranks is then a parallel join: each key goes to the rank its hash names, where the
   file's entries and the requests meet; the values travel back to the requesting rank. No rank holds
   more than its share, and a key that the file lacks (another mesh) is counted, not guessed. */
#include "ind_common.h"

/* The hash of a key (3 coordinates; -0 and +0 hash alike), for assigning it to a rank. */
PetscInt IndKeyHash(const PetscReal key[3]);

/* Collective. The file's part on this rank: nfile keys (3 reals each) with bs values each. The
   requests: nwant keys; vals_want (bs * nwant) receives the file's values of each. *nmissing is the
   number of requested keys, over all ranks, that the file does not hold; *nduplicate the number of
   file keys, over all ranks, that appear more than once (either means the file is of another mesh). */
PetscErrorCode IndKeyJoin(MPI_Comm comm, PetscInt bs, PetscInt nfile, const PetscReal *keys_file,
                          const PetscReal *vals_file, PetscInt nwant, const PetscReal *keys_want, PetscReal *vals_want,
                          PetscInt *nmissing, PetscInt *nduplicate);
