#pragma once
/* An indenter of revolution given as a table (-indenter_type table -indenter_profile FILE): its lower surface's
   height above the tip against the radius, one point per line, "r,height" in nm (commas, semicolons or blanks
   between; a header line and lines starting with # are skipped). The first point is the tip, r = 0; r increases
   and the height does not fall; past the last point the surface goes on along the last segment, which must
   rise. Heights are taken relative to the first point's. */
#include "ind_indenter.h" /* petscsys.h, and PETSC_SUCCESS on PETSc < 3.19 */

/* Reads FILE on rank 0 and broadcasts it: *profile (2 n reals, pairs r, height; free with PetscFree) and n. A
   bad file is an error (PETSC_ERR_USER_INPUT) of one line naming it and, where there is one, the line. */
PetscErrorCode IndIndenterReadProfile(MPI_Comm comm, const char file[], PetscReal **profile, PetscInt *n);
