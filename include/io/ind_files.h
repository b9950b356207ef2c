#pragma once
/* Files and directories the run makes for itself, and what it reads of a gmsh geometry. */
#include "ind_common.h"

#define IND_GEO_MAX 64

/* What a .geo declares, read from its text (comments removed), not by running gmsh:
   - params: the names -setnumber can set, i.e. those of DefineConstant[ name = ..., ... ],
     name = DefineNumber[ ... ] and Exists(name); gmsh ignores -setnumber of any other name (an assignment
     in the file overrides it);
   - volumes, surfaces: the physical groups, by name (Physical Volume("film") = ...) or, unnamed, as
     volume<tag> and surface<tag> as indent names them in the mesh. */
typedef struct {
  PetscInt nparams, nvolumes, nsurfaces;
  char     params[IND_GEO_MAX][IND_NAME_LEN];
  char     volumes[IND_GEO_MAX][IND_NAME_LEN];
  char     surfaces[IND_GEO_MAX][IND_NAME_LEN];
} IndGeoInfo;

/* Creates the output directory dir and its missing parents on rank 0 and checks it is a writable
   directory; option names the option the path came from, for the error message. Collective. In a -help
   run (IndHelpListing()) it does nothing: a listing writes no file. */
PetscErrorCode IndMakeDirectory(MPI_Comm comm, const char dir[], const char option[]);
/* Checks, without creating anything, that dir is a directory or can be made one: an existing path that
   is not a directory, or a parent that is a file, is an error naming option. Collective. */
PetscErrorCode IndCheckDirectory(MPI_Comm comm, const char dir[], const char option[]);
/* Meshes the gmsh geometry geo into msh (format 4.1) by running the gmsh executable on rank 0, with
   "-setnumber name value" for each "name=value" of params; gmsh's output goes to msh.log. gmsh writes
   msh.tmp, renamed to msh only on success, so a failed run leaves an earlier msh as it was. Collective;
   a failure is an error naming the file, the log and the command. */
PetscErrorCode IndGmshMesh(MPI_Comm comm, const char gmsh[], const char geo[], char *params[], PetscInt nparams,
  const char msh[]);
/* Reads geo on rank 0 into info on every rank. Collective; an unreadable file is an error. */
PetscErrorCode IndGeoRead(MPI_Comm comm, const char geo[], IndGeoInfo *info);
/* The same from text in memory (pure; for tests). */
void IndGeoScan(const char text[], IndGeoInfo *info);
/* Checks each "name=value" of -mesh_geo_parameters against info: name must be one of its parameters
   (or a gmsh option, with a dot: Mesh.MeshSizeMax) and value a finite number. Collective. */
PetscErrorCode IndGeoCheckParameters(MPI_Comm comm, const char geo[], const IndGeoInfo *info, char *params[],
  PetscInt nparams);
/* A line of a table of numbers the user wrote (a tensile curve, an indenter profile), as a spreadsheet may save it,
   made blank-separated with decimal points in place: a UTF-8 byte-order mark at its start (first: the file's first
   line) and carriage returns removed; with semicolons or tabs between the cells a comma is a decimal comma (a
   European locale) and becomes a point, and otherwise commas separate. Pure. */
void IndTableLineNormalize(char line[], PetscBool first);
