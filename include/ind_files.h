#pragma once
/* Files and directories the run makes for itself. */
#include "ind_common.h"

/* Creates the output directory dir and its missing parents on rank 0 and checks it is writable; option names the
   option the path came from, for the error message. Collective. */
PetscErrorCode IndMakeDirectory(MPI_Comm comm, const char dir[], const char option[]);
/* Meshes the gmsh geometry geo into msh (format 4.1) by running the gmsh executable on rank 0, with
   "-setnumber name value" for each "name=value" of params; gmsh's output goes to msh.log. Collective;
   a failure is an error naming the file, the log and the command. */
PetscErrorCode IndGmshMesh(MPI_Comm comm, const char gmsh[], const char geo[], char *params[], PetscInt nparams, const char msh[]);
