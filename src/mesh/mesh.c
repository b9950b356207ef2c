#include "mesh_impl.h"
#include <stdint.h>
#include <math.h>
#include <petscsf.h>
#include "ind_mesh.h"
#include "ind_files.h"

/* gmsh writes "dim tag "name"" lines in $PhysicalNames in both format 2.2 and 4.1, also in binary
   files. On rank 0; why says what is wrong with the file, or is "". */
static void ParsePhysicalNames(const char file[], int *n, int dims[], int tags[], char names[][IND_NAME_LEN],
  char why[], size_t len)
{
  FILE *fp = fopen(file, "r");
  char  line[1024];

  *n     = 0;
  why[0] = 0;
  if (!fp) {
    snprintf(why, len, "Cannot open mesh file '%s' (-mesh_file)", file);
    return;
  }
  while (fgets(line, sizeof(line), fp)) {
    if (strncmp(line, "$PhysicalNames", 14)) {
      if (!strncmp(line, "$Nodes", 6) || !strncmp(line, "$Entities", 9)) break;
      continue;
    }
    if (!fgets(line, sizeof(line), fp) || sscanf(line, "%d", n) != 1 || *n < 0) {
      snprintf(why, len, "Malformed $PhysicalNames in mesh file '%s' (-mesh_file)", file);
      *n = 0;
      break;
    }
    if (*n > IND_MAX_REGIONS) {
      snprintf(why, len, "Mesh file '%s' (-mesh_file) has %d physical names; at most %d are supported", file, *n,
        IND_MAX_REGIONS);
      *n = 0;
      break;
    }
    for (int i = 0; i < *n && !why[0]; ++i) {
      char *q1 = NULL, *q2 = NULL;
      if (fgets(line, sizeof(line), fp) && sscanf(line, "%d %d", &dims[i], &tags[i]) == 2) {
        q1 = strchr(line, '"');
        q2 = q1 ? strchr(q1 + 1, '"') : NULL;
      }
      if (!q1 || !q2 || q2 - q1 - 1 >= IND_NAME_LEN) snprintf(why, len,
        "Malformed physical name on line %d of $PhysicalNames in mesh file '%s' (-mesh_file)", i + 1, file);
      else {
        *q2 = 0;
        snprintf(names[i], IND_NAME_LEN, "%s", q1 + 1);
      }
    }
    if (why[0]) *n = 0;
    break;
  }
  fclose(fp);
}

/* PETSc turns the tags into "Cell Sets"/"Face Sets" values, and we give them their names. A physical
   group without elements still becomes a region, an empty one, so that its options are recognised and
   using it is an error saying so (IndMeshCheckRegionNotEmpty). */
static PetscErrorCode ReadGmshPhysicalNames(MPI_Comm comm, const char file[], IndMesh mesh)
{
  PetscMPIInt rank;
  int         n = 0, dims[IND_MAX_REGIONS], tags[IND_MAX_REGIONS];
  char        names[IND_MAX_REGIONS][IND_NAME_LEN], why[PETSC_MAX_PATH_LEN + 128] = "";

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0) ParsePhysicalNames(file, &n, dims, tags, names, why, sizeof(why));
  PetscCallMPI(MPI_Bcast(why, sizeof(why), MPI_CHAR, 0, comm));
  PetscCheck(!why[0], comm, PETSC_ERR_FILE_UNEXPECTED, "%s", why);
  PetscCallMPI(MPI_Bcast(&n, 1, MPI_INT, 0, comm));
  PetscCallMPI(MPI_Bcast(dims, n, MPI_INT, 0, comm));
  PetscCallMPI(MPI_Bcast(tags, n, MPI_INT, 0, comm));
  PetscCallMPI(MPI_Bcast(names, n * IND_NAME_LEN, MPI_CHAR, 0, comm));
  {
    /* A 2D mesh's physical surfaces are its volumes (of revolution) and its physical curves its surfaces. */
    PetscInt mdim;
    PetscCall(DMGetDimension(mesh->dm, &mdim));
    for (int k = 0; k < n; ++k) dims[k] += 3 - (int)mdim;
  }

  /* Regions in the file without a physical name still get a usable name. */
  for (PetscInt d = 2; d <= 3; ++d) {
    DMLabel     set;
    IS          valueIS = NULL;
    PetscInt    nv      = 0;
    const PetscInt *vals = NULL;
    PetscInt    gvals[IND_MAX_REGIONS], ng = 0;

    PetscCall(DMGetLabel(mesh->dm, d == 3 ? "Cell Sets" : "Face Sets", &set));
    if (set) {
      PetscCall(DMLabelGetValueIS(set, &valueIS));
      PetscCall(ISGetLocalSize(valueIS, &nv));
      PetscCall(ISGetIndices(valueIS, &vals));
    }
    for (PetscInt i = 0; i < nv && ng < IND_MAX_REGIONS; ++i) gvals[ng++] = vals[i];
    if (valueIS) {
      PetscCall(ISRestoreIndices(valueIS, &vals));
      PetscCall(ISDestroy(&valueIS));
    }
    PetscCallMPI(MPI_Bcast(&ng, 1, MPIU_INT, 0, comm));
    PetscCallMPI(MPI_Bcast(gvals, ng, MPIU_INT, 0, comm));
    for (PetscInt i = 0; i < ng; ++i) {
      const char *name = NULL;
      char        fallback[IND_NAME_LEN];
      DMLabel     label;
      IS          pts = NULL;

      for (int k = 0; k < n; ++k)
        if (dims[k] == d && tags[k] == gvals[i]) name = names[k];
      if (!name) {
        PetscCall(PetscSNPrintf(fallback, sizeof(fallback), "%s%" PetscInt_FMT, d == 3 ? "volume" : "surface",
          gvals[i]));
        name = fallback;
      }
      PetscCheck(mesh->nregions < IND_MAX_REGIONS, comm, PETSC_ERR_SUP,
        "Too many regions in mesh file '%s' (-mesh_file): at most %d are supported", file, IND_MAX_REGIONS);
      PetscCall(PetscStrncpy(mesh->regions[mesh->nregions].name, name, IND_NAME_LEN));
      mesh->regions[mesh->nregions++].dim = d;
      PetscCall(DMCreateLabel(mesh->dm, name));
      PetscCall(DMGetLabel(mesh->dm, name, &label));
      if (set) PetscCall(DMLabelGetStratumIS(set, gvals[i], &pts));
      if (pts) {
        PetscCall(DMLabelSetStratumIS(label, 1, pts));
        PetscCall(ISDestroy(&pts));
      }
    }
  }
  for (int k = 0; k < n; ++k) {
    PetscBool known = PETSC_FALSE;
    if (dims[k] != 2 && dims[k] != 3) continue;
    for (PetscInt r = 0; r < mesh->nregions && !known; ++r) {
      PetscCall(PetscStrcmp(mesh->regions[r].name, names[k], &known));
      known = known && mesh->regions[r].dim == dims[k] ? PETSC_TRUE : PETSC_FALSE;
    }
    if (known) continue;
    PetscCheck(mesh->nregions < IND_MAX_REGIONS, comm, PETSC_ERR_SUP,
      "Too many regions in mesh file '%s' (-mesh_file): at most %d are supported", file, IND_MAX_REGIONS);
    PetscCall(PetscStrncpy(mesh->regions[mesh->nregions].name, names[k], IND_NAME_LEN));
    mesh->regions[mesh->nregions++].dim = dims[k];
    PetscCall(DMCreateLabel(mesh->dm, names[k]));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode AddRegion(IndMesh mesh, const char name[], PetscInt dim, const char setname[], PetscInt value)
{
  DMLabel set, label;
  IS      pts = NULL;

  PetscFunctionBeginUser;
  PetscCall(PetscStrncpy(mesh->regions[mesh->nregions].name, name, IND_NAME_LEN));
  mesh->regions[mesh->nregions++].dim = dim;
  PetscCall(DMCreateLabel(mesh->dm, name));
  PetscCall(DMGetLabel(mesh->dm, name, &label));
  PetscCall(DMGetLabel(mesh->dm, setname, &set));
  if (set) PetscCall(DMLabelGetStratumIS(set, value, &pts));
  if (pts) PetscCall(DMLabelSetStratumIS(label, 1, pts));
  PetscCall(ISDestroy(&pts));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode CreateBoxMesh(MPI_Comm comm, PetscBool blocks, IndMesh mesh)
{
  PetscInt  faces[3] = {2, 2, 2}, n = 3, cStart, cEnd;
  PetscBool set;
  PetscReal lower[3] = {0, 0, 0}, upper[3] = {1, 1, 1};
  DMLabel   cells;
  /* PETSc's hexahedral box marks its faces in "Face Sets" with these values. */
  const char *names[6] = {"bottom", "top", "front", "back", "right", "left"};

  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, NULL, IND_TITLE "Built-in box mesh (without -mesh_file)", "Mesh");
  PetscCall(IndOptionsIntArray("-dm_plex_box_faces", "Number of hexahedra along x, y, z", "nx,ny,nz", NULL, faces, &n,
    &set));
  PetscCheck(!set || n == 3, comm, PETSC_ERR_ARG_SIZ,
    "-dm_plex_box_faces needs three counts nx,ny,nz, got %" PetscInt_FMT, n);
  n = 3;
  PetscCall(IndOptionsRealArray("-dm_plex_box_lower", "Lower corner", "x,y,z in nm", NULL, lower, &n, &set));
  PetscCheck(!set || n == 3, comm, PETSC_ERR_ARG_SIZ,
    "-dm_plex_box_lower needs three coordinates x,y,z (nm), got %" PetscInt_FMT, n);
  n = 3;
  PetscCall(IndOptionsRealArray("-dm_plex_box_upper", "Upper corner", "x,y,z in nm", NULL, upper, &n, &set));
  PetscCheck(!set || n == 3, comm, PETSC_ERR_ARG_SIZ,
    "-dm_plex_box_upper needs three coordinates x,y,z (nm), got %" PetscInt_FMT, n);
  PetscOptionsEnd();
  for (int d = 0; d < 3; ++d) {
    PetscCheck(faces[d] > 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-dm_plex_box_faces needs three positive counts");
    PetscCheck(upper[d] > lower[d], comm, PETSC_ERR_ARG_OUTOFRANGE,
      "-dm_plex_box_upper must exceed -dm_plex_box_lower in every direction");
  }
  if (blocks) PetscCall(IndBoxCreateDistributed(comm, faces, lower, upper, &mesh->dm));
  else PetscCall(DMPlexCreateBoxMesh(comm, 3, PETSC_FALSE, faces, lower, upper, NULL, PETSC_TRUE, &mesh->dm));
  PetscCall(DMCreateLabel(mesh->dm, "Cell Sets"));
  PetscCall(DMGetLabel(mesh->dm, "Cell Sets", &cells));
  PetscCall(DMPlexGetHeightStratum(mesh->dm, 0, &cStart, &cEnd));
  for (PetscInt c = cStart; c < cEnd; ++c) PetscCall(DMLabelSetValue(cells, c, 1));
  PetscCall(AddRegion(mesh, "domain", 3, "Cell Sets", 1));
  for (PetscInt i = 0; i < 6; ++i) PetscCall(AddRegion(mesh, names[i], 2, "Face Sets", i + 1));
  PetscCall(PetscStrncpy(mesh->source, "box", sizeof(mesh->source)));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Decided on the serial mesh: after distribution a rank may hold no cell. */
static PetscErrorCode CheckCellTypes(MPI_Comm comm, IndMesh mesh)
{
  PetscInt dim, cStart, cEnd, flags[2] = {0, 0}; /* simplices, tensor cells */

  PetscFunctionBeginUser;
  PetscCall(DMGetDimension(mesh->dm, &dim));
  PetscCheck(dim == 3 || dim == 2, comm, PETSC_ERR_ARG_WRONG,
    "Mesh '%s' is %" PetscInt_FMT "D; indent needs a 3D mesh, or a 2D one in (r, z) for the axisymmetric model",
    mesh->source, dim);
  mesh->dim = dim;
  PetscCall(DMPlexGetHeightStratum(mesh->dm, 0, &cStart, &cEnd));
  for (PetscInt c = cStart; c < cEnd; ++c) {
    DMPolytopeType ct;
    PetscCall(DMPlexGetCellType(mesh->dm, c, &ct));
    if (ct == (dim == 3 ? DM_POLYTOPE_TETRAHEDRON : DM_POLYTOPE_TRIANGLE)) flags[0] = 1;
    else if (ct == (dim == 3 ? DM_POLYTOPE_HEXAHEDRON : DM_POLYTOPE_QUADRILATERAL)) flags[1] = 1;
    else SETERRQ(comm, PETSC_ERR_SUP, "Mesh '%s' has a cell of type %s; only %s are supported", mesh->source,
      DMPolytopeTypes[ct], dim == 3 ? "tetrahedra and hexahedra" : "triangles and quadrilaterals (axisymmetric)");
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, flags, 2, MPIU_INT, MPI_MAX, comm));
  PetscCheck(flags[0] + flags[1] == 1, comm, PETSC_ERR_SUP, "Mesh '%s' mixes %s (or has no cells)", mesh->source,
    dim == 3 ? "tetrahedra and hexahedra" : "triangles and quadrilaterals");
  mesh->simplex = flags[0] ? PETSC_TRUE : PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A 2D mesh is the axisymmetric model's section (r, z). gmsh draws it in the plane z = 0 with y the axis (as
   Abaqus and FEniCS do), or in the plane y = 0; either way it is placed in y = 0 with x = r and z the axis, so
   that the indenter, the contact and the outputs see the section of the 3D body through its axis. */
static PetscErrorCode PlaceSectionInXZ(MPI_Comm comm, IndMesh mesh)
{
  DM           dm = mesh->dm;
  Vec          X;
  PetscScalar *x;
  PetscInt     n, cdim;
  PetscReal    ext[3] = {0, 0, 0}, rmin = PETSC_MAX_REAL, tol;

  PetscFunctionBeginUser;
  PetscCall(DMGetCoordinateDim(dm, &cdim));
  PetscCheck(cdim == 3, comm, PETSC_ERR_PLIB, "2D mesh '%s' read with %" PetscInt_FMT " coordinates", mesh->source,
    cdim);
  PetscCall(DMGetCoordinatesLocal(dm, &X));
  PetscCall(VecGetLocalSize(X, &n));
  PetscCall(VecGetArray(X, &x));
  for (PetscInt k = 0; k < n; ++k) ext[k % 3] = PetscMax(ext[k % 3], PetscAbsReal(PetscRealPart(x[k])));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, ext, 3, MPIU_REAL, MPIU_MAX, comm));
  tol = 1e-12 * (ext[0] + ext[1] + ext[2]);
  PetscCheck(ext[1] <= tol || ext[2] <= tol, comm, PETSC_ERR_ARG_WRONG,
    "2D mesh '%s' is not plane: an axisymmetric section must lie in the plane z = 0 (x = r, y the axis) or y = 0",
    mesh->source);
  for (PetscInt k = 0; k < n; k += 3) {
    if (ext[2] <= tol) { /* drawn in z = 0: y is the axis */
      x[k + 2] = x[k + 1];
      x[k + 1] = 0;
    }
    rmin = PetscMin(rmin, PetscRealPart(x[k]));
  }
  PetscCall(VecRestoreArray(X, &x));
  PetscCall(DMSetCoordinatesLocal(dm, X));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &rmin, 1, MPIU_REAL, MPIU_MIN, comm));
  PetscCheck(rmin >= -tol, comm, PETSC_ERR_ARG_WRONG,
    "2D mesh '%s' reaches x = %g: an axisymmetric section lies at x = r >= 0, its axis at x = 0", mesh->source,
    (double)rmin);
  PetscFunctionReturn(PETSC_SUCCESS);
}

static inline uint64_t SplitMix64(uint64_t z)
{
  z += 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

/* The vertices on the boundary: the closure of the box's "Face Sets" (all six sides, on the box built in blocks
   as on the serial one), or of the faces with one cell of a mesh read from a file (still serial here: on a
   distributed mesh the faces between ranks would count too). */
static PetscErrorCode MarkBoundary(IndMesh mesh, PetscBool box, DMLabel boundary)
{
  PetscFunctionBeginUser;
  if (box) {
    DMLabel         faceSets;
    IS              values;
    PetscInt        nvalues;
    const PetscInt *v;
    PetscCall(DMGetLabel(mesh->dm, "Face Sets", &faceSets));
    PetscCall(DMLabelGetValueIS(faceSets, &values));
    PetscCall(ISGetLocalSize(values, &nvalues));
    PetscCall(ISGetIndices(values, &v));
    for (PetscInt i = 0; i < nvalues; ++i) {
      IS              pts;
      PetscInt        npts = 0;
      const PetscInt *p    = NULL;
      PetscCall(DMLabelGetStratumIS(faceSets, v[i], &pts));
      if (pts) PetscCall(ISGetLocalSize(pts, &npts));
      if (pts) PetscCall(ISGetIndices(pts, &p));
      for (PetscInt k = 0; k < npts; ++k) PetscCall(DMLabelSetValue(boundary, p[k], 1));
      if (pts) PetscCall(ISRestoreIndices(pts, &p));
      PetscCall(ISDestroy(&pts));
    }
    PetscCall(ISRestoreIndices(values, &v));
    PetscCall(ISDestroy(&values));
  } else PetscCall(DMPlexMarkBoundaryFaces(mesh->dm, 1, boundary));
  PetscCall(DMPlexLabelComplete(mesh->dm, boundary));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Moves interior vertices by up to frac * (shortest edge) in a direction hashed from the vertex's
   own coordinates, so the distorted mesh does not depend on the numbering. */
static PetscErrorCode PerturbInteriorVertices(IndMesh mesh, PetscBool box, PetscReal frac)
{
  DM           dm = mesh->dm, cdm;
  DMLabel      boundary;
  Vec          X;
  PetscScalar *x;
  PetscSection cs;
  PetscInt     vStart, vEnd, eStart, eEnd, csStart, csEnd;
  PetscReal    hmin = PETSC_MAX_REAL;

  PetscFunctionBeginUser;
  PetscCall(DMGetCoordinateDM(dm, &cdm));
  PetscCall(DMGetLocalSection(cdm, &cs));
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
  PetscCall(DMPlexGetDepthStratum(dm, 1, &eStart, &eEnd));
  PetscCall(PetscSectionGetChart(cs, &csStart, &csEnd));
  for (PetscInt e = PetscMax(eStart, csStart); e < PetscMin(eEnd, csEnd); ++e) {
    PetscInt dof;
    PetscCall(PetscSectionGetDof(cs, e, &dof));
    PetscCheck(dof == 0, PETSC_COMM_SELF, PETSC_ERR_SUP,
      "-mesh_perturb supports only straight-sided (first-order) meshes");
  }
  PetscCall(DMGetCoordinatesLocal(dm, &X));
  PetscCall(VecGetArray(X, &x));
  for (PetscInt e = eStart; e < eEnd; ++e) {
    const PetscInt *cone;
    PetscInt        o0, o1;
    PetscReal       l2 = 0;
    PetscCall(DMPlexGetCone(dm, e, &cone));
    PetscCall(PetscSectionGetOffset(cs, cone[0], &o0));
    PetscCall(PetscSectionGetOffset(cs, cone[1], &o1));
    for (int d = 0; d < 3; ++d) l2 += PetscSqr(PetscRealPart(x[o0 + d] - x[o1 + d]));
    hmin = PetscMin(hmin, PetscSqrtReal(l2));
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &hmin, 1, MPIU_REAL, MPI_MIN, PetscObjectComm((PetscObject)dm)));
  PetscCall(DMLabelCreate(PETSC_COMM_SELF, "boundary", &boundary));
  PetscCall(MarkBoundary(mesh, box, boundary));
  for (PetscInt v = vStart; v < vEnd; ++v) {
    PetscInt    off, val;
    uint64_t h = 0;
    PetscCall(DMLabelGetValue(boundary, v, &val));
    if (val == 1) continue;
    PetscCall(PetscSectionGetOffset(cs, v, &off));
    for (int d = 0; d < 3; ++d) h = SplitMix64(h ^ (uint64_t)(int64_t)round(PetscRealPart(x[off + d]) / hmin * 1e6));
    for (int d = 0; d < 3; ++d) {
      h = SplitMix64(h);
      if (mesh->dim == 2 && d == 1) continue; /* an axisymmetric section stays in its plane */
      x[off + d] += frac * hmin * ((PetscReal)(h >> 11) / 9007199254740992.0 - 0.5);
    }
  }
  PetscCall(VecRestoreArray(X, &x));
  PetscCall(DMSetCoordinatesLocal(dm, X));
  PetscCall(DMLabelDestroy(&boundary));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* On rank 0, before PETSc reads it there (a reader that fails on rank 0 leaves the others waiting): a
   gmsh file starts with $MeshFormat and, unless cut short, ends with an $End... line. */
static PetscErrorCode CheckMeshFile(MPI_Comm comm, const char file[])
{
  PetscMPIInt rank;
  char        why[256] = "";

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (!rank) {
    FILE *fp = fopen(file, "rb");
    char  head[16] = "", tail[512];
    long  size = 0;
    if (!fp) snprintf(why, sizeof(why), "cannot be opened");
    else if (fseek(fp, 0, SEEK_END) || (size = ftell(fp)) <= 0) snprintf(why, sizeof(why), "is empty");
    else {
      size_t n, got;
      rewind(fp);
      got = fread(head, 1, 11, fp);
      head[got] = 0;
      if (strncmp(head, "$MeshFormat", 11)) snprintf(why, sizeof(why),
        "is not a gmsh mesh (it does not start with $MeshFormat)");
      n = (size_t)PetscMin(size, (long)sizeof(tail) - 1);
      if (!why[0] && (fseek(fp, size - (long)n, SEEK_SET) || fread(tail, 1, n, fp) != n)) snprintf(why, sizeof(why),
        "cannot be read");
      if (!why[0]) {
        char *last;
        tail[n] = 0;
        while (n && (tail[n - 1] == '\n' || tail[n - 1] == '\r' || tail[n - 1] == ' ' || tail[n - 1] == 0))
          tail[--n] = 0;
        /* a binary mesh has NULs before its last line: search the bytes, not the string */
        last = tail + n;
        while (last > tail && last[-1] != '\n') --last;
        if (strncmp(last, "$End", 4)) snprintf(why, sizeof(why),
          "is truncated or corrupt: it does not end with an $End... line");
      }
    }
    if (fp) fclose(fp);
  }
  PetscCallMPI(MPI_Bcast(why, sizeof(why), MPI_CHAR, 0, comm));
  PetscCheck(!why[0], comm, PETSC_ERR_FILE_UNEXPECTED, "Mesh file '%s' (-mesh_file) %s", file, why);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* PETSc's reader, whose messages ("Insufficient data, read only 7105 < 30705 items") do not name the
   file. It fails on rank 0, where it reads. */
static PetscErrorCode ReadMeshFileAs(MPI_Comm comm, const char file[], PetscBool linear, DM *dm, char **why)
{
  PetscErrorCode ierr;

  PetscFunctionBeginUser;
  *why = NULL;
  /* three coordinates also for a 2D mesh, the axisymmetric section (PlaceSectionInXZ) */
  PetscCall(PetscOptionsSetValue(NULL, "-dm_plex_gmsh_spacedim", "3"));
  if (linear) PetscCall(PetscOptionsSetValue(NULL, "-dm_plex_gmsh_highorder", "0"));
  PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
  ierr = DMPlexCreateFromFile(comm, file, "indent", PETSC_TRUE, dm);
  PetscCall(PetscPopErrorHandler());
  PetscCall(PetscOptionsClearValue(NULL, "-dm_plex_gmsh_spacedim"));
  if (linear) PetscCall(PetscOptionsClearValue(NULL, "-dm_plex_gmsh_highorder"));
  if (ierr) {
    PetscCall(PetscErrorMessage(ierr, NULL, why));
    if (!*why || !(*why)[0]) *why = (char *)"PETSc's gmsh reader failed";
    *dm = NULL;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Whether a gmsh file has a section that starts with a line "name" (the section markers are text also in a binary
   file). Only after a failed read: it reads the whole file. */
static PetscBool HasSection(const char file[], const char name[])
{
  FILE  *fp = fopen(file, "rb");
  char   line[256];
  size_t len = strlen(name);
  int    found = 0;

  if (!fp) return PETSC_FALSE;
  while (!found && fgets(line, sizeof(line), fp)) found = !strncmp(line, name, len) && (line[len] == '\n' ||
    line[len] == '\r' || line[len] == 0);
  fclose(fp);
  return found ? PETSC_TRUE : PETSC_FALSE;
}

/* A second-order gmsh mesh (gmsh -order 2) comes from PETSc's reader with coordinates over a quadratic space, which
   indent's geometry (coordinates at the vertices) would misread as degenerate cells: it is read again by its corner
   nodes, straight-sided, and said so. The element order is -disc_degree's. A read that fails does so on rank 0 alone,
   the others waiting inside the reader: the error is raised there at once, not retried. */
static PetscErrorCode ReadMeshFile(MPI_Comm comm, const char file[], DM *dm)
{
  char       *why = NULL;
  PetscMPIInt curved;

  PetscFunctionBeginUser;
  PetscCall(ReadMeshFileAs(comm, file, PETSC_FALSE, dm, &why));
  /* PETSc 3.18's reader stops at the partitions' section with "expecting $Nodes" */
  PetscCheck(*dm || !HasSection(file, "$PartitionedEntities"), PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED,
    "Cannot read mesh file '%s' (-mesh_file): it was partitioned by gmsh (-part), which PETSc's reader does not "
    "take; save it unpartitioned (indent partitions the mesh over its ranks itself)", file);
  PetscCheck(*dm, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "Cannot read mesh file '%s' (-mesh_file): %s", file, why);
  {
    Vec      X;
    PetscInt n, vStart, vEnd, cdim;
    /* linear coordinates are cdim numbers a vertex; higher-order ones have more */
    PetscCall(DMGetCoordinatesLocal(*dm, &X));
    PetscCall(DMGetCoordinateDim(*dm, &cdim));
    PetscCall(VecGetLocalSize(X, &n));
    PetscCall(DMPlexGetDepthStratum(*dm, 0, &vStart, &vEnd));
    curved = n != cdim * (vEnd - vStart);
    PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &curved, 1, MPI_INT, MPI_MAX, comm));
  }
  if (!curved) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(DMDestroy(dm));
  PetscCall(ReadMeshFileAs(comm, file, PETSC_TRUE, dm, &why));
  PetscCheck(*dm, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "Cannot read mesh file '%s' (-mesh_file) by its corner "
    "nodes: %s", file, why);
  PetscCall(PetscFPrintf(comm, PETSC_STDERR,
    "indent: warning: mesh '%s' has cells of order 2 or higher (gmsh -order): indent takes their corner nodes, so "
    "curved edges become straight; the element order is -disc_degree's\n", file));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* -help with a .geo: not meshed (a listing must not run gmsh), but the options of its regions must be
   listed. A box of one hexahedron per physical volume stands in for it, every physical surface being
   its (flat) top, so that the set-up reads every option it would read on the real mesh. */
static PetscErrorCode CreateListingMesh(MPI_Comm comm, const char geo[], const IndGeoInfo *info, IndMesh mesh)
{
  PetscInt  faces[3] = {PetscMax(1, info->nvolumes), 1, 1}, cStart, cEnd;
  PetscReal lower[3] = {0, 0, 0}, upper[3] = {(PetscReal)faces[0], 1, 1};
  DMLabel   cells;

  PetscFunctionBeginUser;
  PetscCall(DMPlexCreateBoxMesh(comm, 3, PETSC_FALSE, faces, lower, upper, NULL, PETSC_TRUE, &mesh->dm));
  PetscCall(DMCreateLabel(mesh->dm, "Cell Sets"));
  PetscCall(DMGetLabel(mesh->dm, "Cell Sets", &cells));
  PetscCall(DMPlexGetHeightStratum(mesh->dm, 0, &cStart, &cEnd));
  if (info->nvolumes)
    for (PetscInt c = cStart; c < cEnd; ++c) PetscCall(DMLabelSetValue(cells, c, 1 + (c - cStart) % info->nvolumes));
  for (PetscInt k = 0; k < info->nvolumes; ++k) PetscCall(AddRegion(mesh, info->volumes[k], 3, "Cell Sets", k + 1));
  for (PetscInt k = 0; k < info->nsurfaces; ++k) PetscCall(AddRegion(mesh, info->surfaces[k], 2, "Face Sets", 2));
  PetscCall(PetscSNPrintf(mesh->source, sizeof(mesh->source), "%s (its physical names, read before meshing)", geo));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A mesh read from gmsh numbers its cells in no useful order, and the cell loops then scatter into the
   matrix and the vectors at random. The serial mesh is renumbered by reverse Cuthill-McKee (cells by
   their adjacency, and the faces, edges and vertices after them) before it is distributed, which
   keeps each rank's part in that order: neighbours stay close in memory. (DMPlexPermute on the
   distributed mesh left PETSc 3.18's point SF inconsistent: linear solves on 2 ranks failed.)
   Nothing depends on the numbering: checkpoints are keyed by position, and the fields' order already
   changes with the rank count (scripts/h5compare.py matches by position). Measured on the paper's
   case at h_tip 6, 4 steps, 2 ranks: the Jacobians 24% and the Newton solves 14% faster.
   PETSc's DMPlexPermute (3.18) duplicates the coordinates, and the copy carries the coordinate DM of the mesh as
   read, which shares that mesh's whole topology: the old mesh would live as long as the new one (on rank 0 until
   it is distributed, on one rank for the whole run; 152 of 337 MB held after reading the paper's mesh at h_tip 3).
   The copy is handed the new mesh's own coordinate DM. */
static PetscErrorCode ReorderForLocality(IndMesh mesh)
{
  IS  perm;
  DM  permuted, cdm;
  Vec coordinates;

  PetscFunctionBeginUser;
  PetscCall(DMPlexGetOrdering(mesh->dm, MATORDERINGRCM, NULL, &perm));
  PetscCall(DMPlexPermute(mesh->dm, perm, &permuted));
  PetscCall(ISDestroy(&perm));
  PetscCall(DMGetCoordinatesLocal(permuted, &coordinates));
  PetscCall(DMGetCoordinateDM(permuted, &cdm));
  PetscCall(VecSetDM(coordinates, cdm));
  PetscCall(DMDestroy(&mesh->dm));
  mesh->dm = permuted;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndMeshCreate(MPI_Comm comm, IndMesh *out)
{
  IndMesh   mesh;
  char      file[PETSC_MAX_PATH_LEN] = "", gmsh[PETSC_MAX_PATH_LEN] = "gmsh", *params[64];
  char      dir[PETSC_MAX_PATH_LEN] = "output";
  PetscInt  nparams = 64;
  PetscBool has_file, has_params, is_geo = PETSC_FALSE, listing = IndHelpListing(), listed = PETSC_FALSE;
  PetscInt  refine = 0;
  PetscReal perturb = 0;
  PetscBool reorder = PETSC_TRUE, blocks;
  IndPartitionerType partitioner;

  PetscFunctionBeginUser;
  /* Before anything is read or made: a run that cannot write its results should not start. */
  PetscCall(PetscOptionsGetString(NULL, NULL, "-output_dir", dir, sizeof(dir), NULL));
  PetscCall(IndCheckDirectory(comm, dir, "-output_dir"));
  PetscCall(PetscCalloc1(1, &mesh));
  PetscOptionsBegin(comm, NULL, IND_TITLE "Mesh (-mesh_*)", "Mesh");
  PetscCall(IndOptionsString("-mesh_file",
    "gmsh mesh (.msh, format 2.2 or 4.1, ASCII or binary), or geometry (.geo, meshed by gmsh into "
    "<output_dir>/mesh.msh)", "file", "the built-in box", file, file, sizeof(file), &has_file));
  PetscCall(IndOptionsString("-mesh_gmsh", "gmsh executable for a .geo -mesh_file", "file", NULL, gmsh, gmsh,
    sizeof(gmsh), NULL));
  PetscCall(IndOptionsStringArray("-mesh_geo_parameters",
    "Parameters of a .geo -mesh_file, passed to gmsh as -setnumber name value", "name=value,...", params, &nparams,
    &has_params));
  if (!has_params) nparams = 0;
  /* "h_tip = 4": the blanks around '=' go (those around an entry are gone already) */
  for (PetscInt i = 0; i < nparams; ++i) {
    char  *eq = strchr(params[i], '='), *value;
    size_t len;
    if (!eq) continue;
    value = eq + 1 + strspn(eq + 1, " \t");
    len   = (size_t)(eq - params[i]);
    while (len && (params[i][len - 1] == ' ' || params[i][len - 1] == '\t')) --len;
    params[i][len] = '=';
    memmove(params[i] + len + 1, value, strlen(value) + 1);
  }
  PetscCall(IndOptionsInt("-mesh_refine", "Uniform refinements after distribution", NULL, refine, &refine, NULL));
  PetscCall(IndOptionsReal("-mesh_perturb",
    "Random displacement of interior vertices of the mesh as read, as a fraction of its shortest edge (tests)", "",
    NULL, perturb, &perturb, NULL));
  PetscCall(IndOptionsBool("-mesh_reorder",
    "Renumber the mesh made on rank 0 by reverse Cuthill-McKee before distribution (locality of assembly and "
    "solves; the box built in blocks is in lexicographic order already)",
    reorder, &reorder, NULL));
  PetscOptionsEnd();
  PetscCheck(refine >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-mesh_refine must be >= 0, got %" PetscInt_FMT, refine);
  PetscCheck(perturb >= 0 && perturb < 0.5, comm, PETSC_ERR_ARG_OUTOFRANGE,
    "-mesh_perturb must lie in [0, 0.5), got %g", (double)perturb);

  PetscCall(PetscLogEventBegin(IndLog.mesh_create, 0, 0, 0, 0));
  if (has_file) {
    PetscBool exists;
    size_t    len;
    PetscCall(PetscTestFile(file, 'r', &exists));
    PetscCheck(exists, comm, PETSC_ERR_FILE_OPEN, "Mesh file '%s' (-mesh_file) does not exist or is not readable",
      file);
    PetscCall(PetscStrlen(file, &len));
    if (len > 4) PetscCall(PetscStrcmp(file + len - 4, ".geo", &is_geo));
    if (is_geo) {
      IndGeoInfo info;
      PetscCall(IndGeoRead(comm, file, &info));
      PetscCall(IndGeoCheckParameters(comm, file, &info, params, nparams));
      if (listing) {
        PetscCall(CreateListingMesh(comm, file, &info, mesh));
        listed = PETSC_TRUE;
      } else {
        /* The mesh lands in the run's directory, so a run keeps the mesh it was computed on. */
        char msh[PETSC_MAX_PATH_LEN];
        PetscCall(IndMakeDirectory(comm, dir, "-output_dir"));
        PetscCall(PetscSNPrintf(msh, sizeof(msh), "%s/mesh.msh", dir));
        PetscCall(IndGmshMesh(comm, gmsh, file, params, nparams, msh));
        PetscCall(PetscStrncpy(file, msh, sizeof(file)));
      }
    }
  }
  PetscCheck(!nparams || is_geo, comm, PETSC_ERR_ARG_WRONG, "-mesh_geo_parameters needs a .geo -mesh_file");
  PetscCall(IndMeshGetPartitionerType(comm, has_file ? PETSC_FALSE : PETSC_TRUE, &partitioner));
  blocks = !has_file && partitioner == IND_PARTITIONER_BLOCKS ? PETSC_TRUE : PETSC_FALSE;
  for (PetscInt i = 0; i < nparams; ++i) PetscCall(PetscFree(params[i]));
  if (has_file && !listed) {
    PetscCall(CheckMeshFile(comm, file));
    PetscCall(ReadMeshFile(comm, file, &mesh->dm));
    PetscCall(PetscStrncpy(mesh->source, file, sizeof(mesh->source)));
    PetscCall(ReadGmshPhysicalNames(comm, file, mesh));
  } else if (!has_file) PetscCall(CreateBoxMesh(comm, blocks, mesh));
  PetscCall(PetscObjectSetName((PetscObject)mesh->dm, "mesh"));
  PetscCall(CheckCellTypes(comm, mesh));
  if (mesh->dim == 2) PetscCall(PlaceSectionInXZ(comm, mesh));
  /* Hashed from positions, so any rank count gets the same mesh. */
  if (perturb > 0) PetscCall(PerturbInteriorVertices(mesh, has_file ? PETSC_FALSE : PETSC_TRUE, perturb));
  PetscCall(PetscLogEventEnd(IndLog.mesh_create, 0, 0, 0, 0));

  PetscCall(PetscLogEventBegin(IndLog.mesh_distribute, 0, 0, 0, 0));
  /* before the distribution, which keeps the order within each rank's part; the box in blocks is born
     distributed, each rank's cells in lexicographic order */
  if (reorder && !blocks) PetscCall(ReorderForLocality(mesh));
  if (!blocks) {
    DM dist = NULL;
    PetscCall(IndMeshSetPartitioner(mesh->dm, partitioner));
    PetscCall(DMPlexDistribute(mesh->dm, 0, NULL, &dist));
    if (dist) { /* NULL on one rank: keep the serial mesh */
      PetscCall(DMDestroy(&mesh->dm));
      mesh->dm = dist;
    }
  }
  for (PetscInt r = 0; r < refine; ++r) {
    DM fine;
    PetscCall(DMRefine(mesh->dm, comm, &fine));
    PetscCall(DMDestroy(&mesh->dm));
    mesh->dm = fine;
  }
  PetscCall(PetscObjectSetName((PetscObject)mesh->dm, "mesh"));
  PetscCall(PetscLogEventEnd(IndLog.mesh_distribute, 0, 0, 0, 0));
  PetscCall(DMViewFromOptions(mesh->dm, NULL, "-mesh_view"));
  *out = mesh;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndMeshDestroy(IndMesh *mesh)
{
  PetscFunctionBeginUser;
  if (!*mesh) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(DMDestroy(&(*mesh)->dm));
  PetscCall(PetscFree(*mesh));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndMeshGetRegionLabel(IndMesh mesh, const char name[], PetscInt dim, const char option[], DMLabel *label)
{
  char list[2048] = "";

  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < mesh->nregions; ++i) {
    PetscBool same;
    PetscCall(PetscStrcmp(mesh->regions[i].name, name, &same));
    if (same && mesh->regions[i].dim == dim) {
      PetscCall(DMGetLabel(mesh->dm, name, label));
      PetscFunctionReturn(PETSC_SUCCESS);
    }
    if (mesh->regions[i].dim == dim) {
      PetscCall(PetscStrlcat(list, " ", sizeof(list)));
      PetscCall(PetscStrlcat(list, mesh->regions[i].name, sizeof(list)));
    }
  }
  SETERRQ(PetscObjectComm((PetscObject)mesh->dm), PETSC_ERR_ARG_WRONG,
    "Mesh '%s' has no %s named '%s' (required by %s); its %ss are:%s", mesh->source, dim == 3 ? "volume" : "surface",
          name, option, dim == 3 ? "volume" : "surface", list[0] ? list : " (none)");
}

PetscErrorCode IndMeshCheckRegionNotEmpty(IndMesh mesh, const char name[], PetscInt dim, const char option[])
{
  MPI_Comm comm = PetscObjectComm((PetscObject)mesh->dm);
  DMLabel  label;
  PetscInt n = 0, pStart, pEnd;

  PetscFunctionBeginUser;
  PetscCall(DMGetLabel(mesh->dm, name, &label));
  PetscCall(DMPlexGetHeightStratum(mesh->dm, dim == 3 ? 0 : 1, &pStart, &pEnd));
  if (label) {
    IS pts = NULL;
    PetscCall(DMLabelGetStratumIS(label, 1, &pts));
    if (pts) {
      const PetscInt *p;
      PetscInt        np;
      PetscCall(ISGetLocalSize(pts, &np));
      PetscCall(ISGetIndices(pts, &p));
      for (PetscInt k = 0; k < np; ++k) n += p[k] >= pStart && p[k] < pEnd;
      PetscCall(ISRestoreIndices(pts, &p));
      PetscCall(ISDestroy(&pts));
    }
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &n, 1, MPIU_INT, MPI_SUM, comm));
  if (dim == 3)
    PetscCheck(n, comm, PETSC_ERR_USER_INPUT,
      "Volume region '%s' of mesh '%s' is empty: its physical volume has no cells, so its options (-%s_young, ...) "
      "cannot apply; fix the physical volume in the mesh",
               name, mesh->source, name);
  else PetscCheck(n, comm, PETSC_ERR_USER_INPUT,
    "Surface '%s' of mesh '%s' (required by %s) is empty: its physical surface has no faces", name, mesh->source,
    option);
  PetscFunctionReturn(PETSC_SUCCESS);
}

IND_GETTER_OUT(DM, IndMeshGetDM, IndMesh, o->dm)
IND_GETTER_OUT(PetscBool, IndMeshIsSimplex, IndMesh, o->simplex)
IND_GETTER_OUT(PetscBool, IndMeshIsAxisymmetric, IndMesh, o->dim == 2 ? PETSC_TRUE : PETSC_FALSE)

PetscErrorCode IndMeshGetRegions(IndMesh mesh, PetscInt *n, const IndRegion **regions)
{
  PetscFunctionBeginUser;
  if (n) *n = mesh->nregions;
  if (regions) *regions = mesh->regions;
  PetscFunctionReturn(PETSC_SUCCESS);
}

IND_GETTER_OUT(const char *, IndMeshGetSource, IndMesh, o->source)
