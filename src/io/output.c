#include <sys/statvfs.h>
#include <string.h>
#include <petscsf.h>
#include "output_impl.h"
#include "ind_options.h"
#include "ind_files.h"
#include "ind_elasticity.h"
#include "ind_version.h"
#include "xdmf.h"
#include "ind_h5rows.h"

/* A clone of the mesh with 3 values on each vertex, its section charted over the vertices alone: a section over
   every mesh point (faces and edges too) costs about 20 bytes a point once more for each layout. */
static PetscErrorCode CreateVertexDM(DM dm, DM *out)
{
  PetscSection s;
  PetscInt     vStart, vEnd;

  PetscFunctionBeginUser;
  PetscCall(DMClone(dm, out));
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
  PetscCall(PetscSectionCreate(PetscObjectComm((PetscObject)dm), &s));
  PetscCall(PetscSectionSetChart(s, vStart, vEnd));
  for (PetscInt p = vStart; p < vEnd; ++p) PetscCall(PetscSectionSetDof(s, p, 3));
  PetscCall(PetscSectionSetUp(s));
  PetscCall(DMSetLocalSection(*out, s));
  PetscCall(PetscSectionDestroy(&s));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A field vector without a mesh: n rows of bs values on this rank. DMPlex's own view of a mesh's vector would
   build a local copy, its numberings and a cell layout at the first write (about 200 bytes a cell) to write the
   same rows. */
static PetscErrorCode CreateRowsVec(MPI_Comm comm, PetscInt n, PetscInt bs, const char name[], Vec *v)
{
  PetscFunctionBeginUser;
  PetscCall(VecCreateMPI(comm, n * bs, PETSC_DETERMINE, v));
  PetscCall(VecSetBlockSize(*v, bs));
  if (name) PetscCall(PetscObjectSetName((PetscObject)*v, name));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The vertices this rank owns in the vertex layout (the rows of its share of a vertex field). */
static PetscErrorCode OwnedVertices(IndOutput o, PetscInt *n)
{
  PetscSection gs;

  PetscFunctionBeginUser;
  PetscCall(DMGetGlobalSection(o->vdm, &gs));
  PetscCall(PetscSectionGetConstrainedStorageSize(gs, n));
  *n /= 3;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Copies 3 values per vertex from a vector laid out by section src into the vertex layout (global: a vector of
   the owned vertices' rows, in the layout's order). */
static PetscErrorCode GatherVertexValues(IndOutput o, PetscSection src, const PetscScalar *in, Vec global)
{
  PetscSection vs;
  PetscScalar *v;
  PetscInt     vStart, vEnd;

  PetscFunctionBeginUser;
  PetscCall(DMGetLocalSection(o->vdm, &vs));
  PetscCall(DMPlexGetDepthStratum(o->vdm, 0, &vStart, &vEnd));
  PetscCall(VecGetArray(o->vloc, &v));
  for (PetscInt p = vStart; p < vEnd; ++p) {
    PetscInt so, vo;
    PetscCall(PetscSectionGetOffset(src, p, &so));
    PetscCall(PetscSectionGetOffset(vs, p, &vo));
    for (int c = 0; c < 3; ++c) v[vo + c] = in[so + c];
  }
  PetscCall(VecRestoreArray(o->vloc, &v));
  PetscCall(DMLocalToGlobal(o->vdm, o->vloc, INSERT_VALUES, global));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Cell-to-vertex connectivity of the local cells in global vertex numbers and VTK/XDMF vertex order (PetscFree). */
static PetscErrorCode CreateTopology(IndOutput o, PetscInt **topo)
{
  DM           dm = o->vdm;
  PetscSection gs;
  PetscInt     cStart, cEnd, vStart, vEnd, *conn, n = 0;
  /* DMPlex orders a hexahedron's top face the other way round from VTK, and its tetrahedra with the
     opposite orientation; these maps give VTK's positive-volume order. */
  const PetscInt hex[8] = {0, 3, 2, 1, 4, 7, 6, 5}, tet[4] = {1, 0, 2, 3}, plane[4] = {0, 1, 2, 3};
  const PetscInt *perm = o->planar ? plane : o->simplex ? tet : hex;

  PetscFunctionBeginUser;
  o->corners = IndOutputCorners(o);
  PetscCall(DMGetGlobalSection(dm, &gs));
  PetscCall(DMPlexGetHeightStratum(dm, 0, &cStart, &cEnd));
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
  PetscCall(PetscMalloc1((cEnd - cStart) * o->corners, &conn));
  for (PetscInt c = cStart; c < cEnd; ++c) {
    PetscInt *closure = NULL, ncl, verts[8], nv = 0;
    PetscCall(DMPlexGetTransitiveClosure(dm, c, PETSC_TRUE, &ncl, &closure));
    for (PetscInt j = 0; j < ncl; ++j) {
      PetscInt p = closure[2 * j], off;
      if (p < vStart || p >= vEnd) continue;
      PetscCall(PetscSectionGetOffset(gs, p, &off));
      verts[nv++] = (off >= 0 ? off : -(off + 1)) / 3;
    }
    PetscCall(DMPlexRestoreTransitiveClosure(dm, c, PETSC_TRUE, &ncl, &closure));
    PetscCheck(nv == o->corners, PETSC_COMM_SELF, PETSC_ERR_PLIB,
      "Cell %" PetscInt_FMT " has %" PetscInt_FMT " vertices", c, nv);
    for (PetscInt k = 0; k < nv; ++k) conn[n++] = verts[perm[k]];
  }
  *topo = conn;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode WriteProvenance(IndOutput o)
{
  PetscMPIInt size;
  PetscInt    ranks;
  char       *opts, petsc[256], date[256];

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(PetscObjectComm((PetscObject)o->dm), &size));
  ranks = size;
  PetscCall(PetscGetVersion(petsc, sizeof(petsc)));
  PetscCall(PetscGetDate(date, sizeof(date)));
  PetscCall(PetscOptionsGetAll(NULL, &opts));
  PetscCall(PetscViewerHDF5WriteAttribute(o->viewer, "/", "indent_version", PETSC_STRING, INDENT_VERSION));
  PetscCall(PetscViewerHDF5WriteAttribute(o->viewer, "/", "git_commit", PETSC_STRING, INDENT_GIT_COMMIT));
  PetscCall(PetscViewerHDF5WriteAttribute(o->viewer, "/", "petsc_version", PETSC_STRING, petsc));
  PetscCall(PetscViewerHDF5WriteAttribute(o->viewer, "/", "mpi_ranks", PETSC_INT, &ranks));
  PetscCall(PetscViewerHDF5WriteAttribute(o->viewer, "/", "options", PETSC_STRING, opts));
  PetscCall(PetscViewerHDF5WriteAttribute(o->viewer, "/", "mesh", PETSC_STRING, o->source));
  PetscCall(PetscViewerHDF5WriteAttribute(o->viewer, "/", "disc_degree", PETSC_INT, &o->layout->degree));
  PetscCall(PetscViewerHDF5WriteAttribute(o->viewer, "/", "created", PETSC_STRING, date));
  PetscCall(PetscFree(opts));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* mkdir -p on rank 0, checked before any solve so that a bad -output_dir costs nothing. */
static PetscErrorCode OpenFile(IndOutput o)
{
  MPI_Comm     comm = PetscObjectComm((PetscObject)o->dm);
  DM           cdm;
  Vec          X, coords;
  PetscSection cs;
  const PetscScalar *x;
  PetscInt    *topo;
  PetscInt     n;

  PetscFunctionBeginUser;
  if (o->resume) {
    PetscCall(IndOutputOpenResumed(o));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(PetscViewerHDF5Open(comm, o->h5name, FILE_MODE_WRITE, &o->viewer));
  PetscCall(PetscViewerHDF5SetBaseDimension2(o->viewer, PETSC_TRUE));
  PetscCall(WriteProvenance(o));

  PetscCall(DMGetCoordinateDM(o->dm, &cdm));
  PetscCall(DMGetLocalSection(cdm, &cs));
  PetscCall(DMGetCoordinatesLocal(o->dm, &X));
  PetscCall(OwnedVertices(o, &n));
  PetscCall(CreateRowsVec(comm, n, 3, "vertices", &coords));
  PetscCall(VecGetArrayRead(X, &x));
  PetscCall(GatherVertexValues(o, cs, x, coords));
  PetscCall(VecRestoreArrayRead(X, &x));
  PetscCall(VecGetSize(coords, &n));
  o->nvert = n / 3;
  PetscCall(PetscViewerHDF5PushGroup(o->viewer, "/geometry"));
  PetscCall(VecGetLocalSize(coords, &n));
  PetscCall(VecGetArrayRead(coords, &x));
  PetscCall(IndH5WriteRows(o->viewer, "vertices", n / 3, 3, x));
  PetscCall(VecRestoreArrayRead(coords, &x));
  PetscCall(PetscViewerHDF5PopGroup(o->viewer));
  PetscCall(VecDestroy(&coords));

  PetscCall(CreateTopology(o, &topo));
  n = o->layout->ncell;
  PetscCallMPI(MPI_Allreduce(&n, &o->ncell, 1, MPIU_INT, MPI_SUM, comm));
  PetscCall(PetscViewerHDF5PushGroup(o->viewer, "/topology"));
  PetscCall(IndH5WriteIntRows(o->viewer, "cells", n, o->corners, topo));
  PetscCall(PetscViewerHDF5PopGroup(o->viewer));
  PetscCall(PetscFree(topo));
  PetscCall(IndOutputWriteCellKeys(o));
  PetscCall(PetscViewerHDF5PushTimestepping(o->viewer));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Records output step o->nsteps (from IndOutputSetStepInfo; else time is its time value and nothing else is
   known), adds its views to indent.h5 and rewrites the XDMF index (xdmf.c). */
static PetscErrorCode WriteXdmf(IndOutput o, PetscReal time)
{
  const IndXdmfField all[] = {
    {"displacement", "Vector", PETSC_FALSE, 3},
    {"stress", "Matrix", PETSC_TRUE, 6}, /* Voigt xx,yy,zz,xy,yz,xz: not XDMF Tensor6 order */
    {"strain", "Matrix", PETSC_TRUE, 6},
    {"von_mises", "Scalar", PETSC_TRUE, 1},
    {"plastic_strain", "Scalar", PETSC_TRUE, 1},
    {"back_stress", "Scalar", PETSC_TRUE, 1},
    {"yielding", "Scalar", PETSC_TRUE, 1},
    {"compaction", "Scalar", PETSC_TRUE, 1},
    {"contact_pressure", "Scalar", PETSC_FALSE, 1},
    {"contact_status", "Scalar", PETSC_FALSE, 1},
  };
  IndXdmfField      fields[sizeof(all) / sizeof(all[0])];
  PetscInt          nfields = 0;
  const IndXdmfMesh mesh    = {"indent.h5",
                               o->planar ? (o->simplex ? "Triangle" : "Quadrilateral")
                                         : (o->simplex ? "Tetrahedron" : "Hexahedron"),
                               IndOutputCorners(o), o->nvert, o->ncell};
  PetscReal        *info    = o->info + IND_OUTPUT_INFO * o->nsteps;
  IndXdmfStep      *steps;
  char              path[PETSC_MAX_PATH_LEN];

  PetscFunctionBeginUser;
  for (size_t k = 0; k < sizeof(all) / sizeof(all[0]); ++k) {
    const PetscBool contact = !strncmp(all[k].name, "contact_", 8) ? PETSC_TRUE : PETSC_FALSE;
    if ((contact && !o->contact) || (!strcmp(all[k].name, "compaction") && !o->densifying)) continue;
    fields[nfields++] = all[k];
  }
  if (!o->info_set) {
    o->times[o->nsteps] = time;
    for (int i = 0; i < IND_OUTPUT_INFO; ++i) info[i] = NAN;
  }
  o->info_set = PETSC_FALSE;
  PetscCall(IndXdmfAddStepViews(o->viewer, o->nsteps, nfields, fields));
  o->nsteps++;
  PetscCall(PetscMalloc1(o->nsteps, &steps));
  for (PetscInt k = 0; k < o->nsteps; ++k) {
    const PetscReal *in = o->info + IND_OUTPUT_INFO * k;
    steps[k] = (IndXdmfStep){PetscIsNanReal(in[0]) ? -1 : (PetscInt)in[0], o->times[k], in[1], in[2], in[3]};
  }
  PetscCall(PetscSNPrintf(path, sizeof(path), "%s/indent.xdmf", o->dir));
  PetscCall(IndXdmfWrite(PetscObjectComm((PetscObject)o->dm), path, &mesh, nfields, fields, o->nsteps, steps));
  PetscCall(PetscFree(steps));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndOutputSetStepInfo(IndOutput o, PetscInt step, PetscReal t, PetscReal lambda, PetscReal depth,
                                    PetscReal load)
{
  MPI_Comm   comm = PetscObjectComm((PetscObject)o->dm);
  PetscReal *info;

  PetscFunctionBeginUser;
  if (!o->enabled) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCheck(o->nsteps < IND_MAX_OUTPUT_STEPS, comm, PETSC_ERR_SUP, "More than %d output steps", IND_MAX_OUTPUT_STEPS);
  /* ParaView and meshio order the steps by their time values. */
  PetscCheck(o->nsteps == 0 || t > o->times[o->nsteps - 1], comm, PETSC_ERR_ARG_WRONG,
             "Output step %" PetscInt_FMT " at pseudo-time %g does not follow the last one's %g", o->nsteps, (double)t,
             (double)o->times[o->nsteps - 1]);
  info                = o->info + IND_OUTPUT_INFO * o->nsteps;
  o->times[o->nsteps] = t;
  info[0]             = (PetscReal)step;
  info[1]             = lambda;
  info[2]             = o->contact ? depth : NAN;
  info[3]             = o->contact ? load : NAN;
  o->info_set         = PETSC_TRUE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The vertex layout, made at the first write, and the fields' vectors, made for each write and destroyed after it:
   a run without field output never holds them, and one with it not during its solves, where the memory peaks. */
static PetscErrorCode CreateFieldObjects(IndOutput o)
{
  MPI_Comm comm = PetscObjectComm((PetscObject)o->dm);
  PetscInt nv, nc = o->layout->ncell;

  PetscFunctionBeginUser;
  if (!o->vdm) PetscCall(CreateVertexDM(o->dm, &o->vdm));
  PetscCall(OwnedVertices(o, &nv));
  PetscCall(DMCreateLocalVector(o->dm, &o->Uloc));
  PetscCall(DMCreateLocalVector(o->vdm, &o->vloc));
  /* cells are not shared (no overlap): local cell i is row i of this rank's share of a cell field */
  PetscCall(CreateRowsVec(comm, nv, 3, "displacement", &o->disp));
  PetscCall(CreateRowsVec(comm, nc, 6, "stress", &o->stress));
  PetscCall(CreateRowsVec(comm, nc, 6, "strain", &o->strain));
  PetscCall(CreateRowsVec(comm, nc, 1, "von_mises", &o->vonmises));
  PetscCall(CreateRowsVec(comm, nc, 1, "plastic_strain", &o->plastic));
  PetscCall(CreateRowsVec(comm, nc, 1, "back_stress", &o->back));
  PetscCall(CreateRowsVec(comm, nc, 1, "yielding", &o->yielding));
  if (o->densifying) PetscCall(CreateRowsVec(comm, nc, 1, "compaction", &o->compaction));
  if (o->contact) {
    PetscCall(DMCreateGlobalVector(o->dm, &o->Gc));
    PetscCall(DMCreateLocalVector(o->dm, &o->Cloc));
    PetscCall(CreateRowsVec(comm, nv, 3, NULL, &o->c3));
    PetscCall(CreateRowsVec(comm, nv, 1, "contact_pressure", &o->pressure));
    PetscCall(CreateRowsVec(comm, nv, 1, "contact_status", &o->status));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode DestroyFieldVectors(IndOutput o)
{
  Vec *v[] = {&o->Uloc, &o->vloc, &o->disp, &o->stress, &o->strain, &o->vonmises, &o->plastic, &o->back, &o->yielding,
              &o->compaction, &o->Gc, &o->Cloc, &o->c3, &o->pressure, &o->status};

  PetscFunctionBeginUser;
  for (size_t k = 0; k < sizeof(v) / sizeof(v[0]); ++k) PetscCall(VecDestroy(v[k]));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndOutputCreate(IndMesh mesh, IndDisc disc, IndOutput *out)
{
  IndOutput o;
  MPI_Comm  comm;

  PetscFunctionBeginUser;
  PetscCall(PetscCalloc1(1, &o));
  o->disc = disc;
  PetscCall(IndMeshGetDM(mesh, &o->dm));
  PetscCall(IndMeshIsSimplex(mesh, &o->simplex));
  PetscCall(IndMeshIsAxisymmetric(mesh, &o->planar));
  PetscCall(IndMeshGetSource(mesh, &o->source));
  PetscCall(IndDiscGetLayout(disc, &o->layout));
  comm = PetscObjectComm((PetscObject)o->dm);
  o->enabled = PETSC_TRUE;
  o->curve   = PETSC_TRUE;
  o->size_warning = 10;
  o->every        = 10;
  PetscCall(PetscStrncpy(o->dir, "output", sizeof(o->dir)));
  PetscOptionsBegin(comm, NULL, IND_TITLE "Output files", "Output");
  PetscCall(PetscOptionsGetString(NULL, NULL, "-output_dir", o->dir, sizeof(o->dir), NULL)); /* listed by rundir.c */
  PetscCall(IndOptionsBool("-output_fields", "Write field output (HDF5 + XDMF)", o->enabled, &o->enabled, NULL));
  PetscCall(IndOptionsInt("-output_fields_every", "Fields of every N-th accepted step, and always of each segment's "
    "end (loading, hold, scratch) and of the last step; 1: every step", NULL, o->every, &o->every, NULL));
  PetscCall(IndOptionsBool("-output_curve", "Write the load-displacement curve (CSV) of an indentation", o->curve,
    &o->curve,
                           NULL));
  PetscCall(IndOptionsReal("-output_size_warning", "Warn before step 1 when the field output would exceed this size",
                           "GB", NULL, o->size_warning, &o->size_warning, NULL));
  PetscOptionsEnd();
  PetscCheck(o->size_warning >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-output_size_warning must be >= 0 (GB), got %g",
             (double)o->size_warning);
  PetscCheck(o->every >= 1, comm, PETSC_ERR_ARG_OUTOFRANGE, "-output_fields_every must be >= 1, got %" PetscInt_FMT,
             o->every);
  PetscCheck(o->dir[0], comm, PETSC_ERR_ARG_WRONG, "-output_dir must not be empty");
  PetscCall(PetscSNPrintf(o->h5name, sizeof(o->h5name), "%s/indent.h5", o->dir));
  if (o->enabled || o->curve) PetscCall(IndMakeDirectory(comm, o->dir, "-output_dir"));
  PetscCall(PetscMalloc1(IND_MAX_OUTPUT_STEPS, &o->times));
  PetscCall(PetscMalloc1(IND_OUTPUT_INFO * IND_MAX_OUTPUT_STEPS, &o->info));
  for (PetscInt i = 0; i < IND_OUTPUT_INFO * IND_MAX_OUTPUT_STEPS; ++i) o->info[i] = NAN;
  *out = o;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The mesh's vertices, each counted on the rank that owns it (not a leaf of the point SF). */
static PetscErrorCode CountVertices(DM dm, PetscInt *n)
{
  PetscSF         sf;
  const PetscInt *leaves;
  PetscInt        nleaves, vStart, vEnd, ghosts = 0;

  PetscFunctionBeginUser;
  PetscCall(DMGetPointSF(dm, &sf));
  PetscCall(PetscSFGetGraph(sf, NULL, &nleaves, &leaves, NULL));
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
  for (PetscInt i = 0; i < PetscMax(nleaves, 0); ++i) {
    const PetscInt p = leaves ? leaves[i] : i;
    ghosts += p >= vStart && p < vEnd;
  }
  *n = vEnd - vStart - ghosts;
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, n, 1, MPIU_INT, MPI_SUM, PetscObjectComm((PetscObject)dm)));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndOutputBytesPerStep(IndOutput o, PetscReal *bytes)
{
  PetscInt nvert, ncell = o->layout->ncell;

  PetscFunctionBeginUser;
  *bytes = 0;
  if (!o->enabled) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(CountVertices(o->dm, &nvert));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &ncell, 1, MPIU_INT, MPI_SUM, PetscObjectComm((PetscObject)o->dm)));
  /* per vertex: displacement (3), contact pressure and status (2); per cell: stress and strain (6 each),
     von Mises, plastic strain, back stress, yielding (and compaction) */
  *bytes = sizeof(PetscReal) * ((PetscReal)nvert * (o->contact ? 5 : 3) + (PetscReal)ncell * (o->densifying ? 17 : 16));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndOutputCheckSize(IndOutput o, PetscInt steps_left, IndWarnings *w)
{
  MPI_Comm    comm = PetscObjectComm((PetscObject)o->dm);
  PetscReal   per, total, avail = -1;
  PetscMPIInt rank;
  char        text[IND_WARNING_LEN];

  PetscFunctionBeginUser;
  PetscCall(IndOutputBytesPerStep(o, &per));
  if (per == 0) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCheck(o->nsteps + steps_left <= IND_MAX_OUTPUT_STEPS, comm, PETSC_ERR_USER_INPUT,
             "The load program has %s%" PetscInt_FMT " steps to write and indent.h5 holds at most %d: give fewer "
             "-load_steps or -load_unload_steps, or -output_fields 0",
             steps_left > IND_MAX_OUTPUT_STEPS ? "more than " : "",
             PetscMin(steps_left, (PetscInt)IND_MAX_OUTPUT_STEPS),
             IND_MAX_OUTPUT_STEPS);
  total = per * (PetscReal)steps_left;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (!rank) {
    struct statvfs fs;
    if (!statvfs(o->dir, &fs)) avail = (PetscReal)fs.f_bavail * (PetscReal)fs.f_frsize;
  }
  PetscCallMPI(MPI_Bcast(&avail, 1, MPIU_REAL, 0, comm));
  if (total <= o->size_warning * 1e9 && (avail < 0 || total <= avail)) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscSNPrintf(text, sizeof(text),
                          "the field output would take about %.3g GB (up to %" PetscInt_FMT
                          " steps of %.3g MB) in '%s', "
                          "more than %s (%.3g GB); -output_fields 0 writes none, fewer -load_steps less",
                          total / 1e9, steps_left, per / 1e6, o->dir,
                          avail >= 0 && total > avail ? "the free space there" : "-output_size_warning",
                          avail >= 0 && total > avail ? avail / 1e9 : (double)o->size_warning));
  PetscCall(IndWarningsAdd(comm, w, "output_size", PETSC_TRUE, text));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndOutputSetContact(IndOutput o, IndContact contact)
{
  PetscFunctionBeginUser;
  PetscCheck(!o->vdm, PetscObjectComm((PetscObject)o->dm), PETSC_ERR_ORDER, "Set the contact before the first write");
  o->contact = contact;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndOutputSetDensifying(IndOutput o, PetscBool densifying)
{
  PetscFunctionBeginUser;
  PetscCheck(!o->vdm, PetscObjectComm((PetscObject)o->dm), PETSC_ERR_ORDER, "Set the fields before the first write");
  o->densifying = densifying;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The contact's node values (pressure, status) moved onto the vertices, one vector each. */
static PetscErrorCode GatherContactFields(IndOutput o)
{
  PetscSection       us;
  const PetscScalar *cl, *c3;
  PetscScalar       *p, *st;
  PetscInt           n;

  PetscFunctionBeginUser;
  PetscCall(IndContactNodalFields(o->contact, o->Gc));
  PetscCall(DMGlobalToLocal(o->dm, o->Gc, INSERT_VALUES, o->Cloc));
  PetscCall(DMGetLocalSection(o->dm, &us));
  PetscCall(VecGetArrayRead(o->Cloc, &cl));
  PetscCall(GatherVertexValues(o, us, cl, o->c3));
  PetscCall(VecRestoreArrayRead(o->Cloc, &cl));
  /* Both layouts own the same vertices in the same order: entry i of a 1-dof vector is entries
     3i .. 3i + 2 of the 3-dof one. */
  PetscCall(VecGetLocalSize(o->pressure, &n));
  PetscCall(VecGetArrayRead(o->c3, &c3));
  PetscCall(VecGetArray(o->pressure, &p));
  PetscCall(VecGetArray(o->status, &st));
  for (PetscInt i = 0; i < n; ++i) {
    p[i]  = c3[3 * i];
    st[i] = c3[3 * i + 1];
  }
  PetscCall(VecRestoreArray(o->status, &st));
  PetscCall(VecRestoreArray(o->pressure, &p));
  PetscCall(VecRestoreArrayRead(o->c3, &c3));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndOutputWriteStep(IndOutput o, PetscReal time, Vec U, IndAssembly assembly)
{
  PetscSection       us;
  const PetscScalar *u;
  PetscScalar       *vm;

  PetscFunctionBeginUser;
  if (!o->enabled) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCheck(o->nsteps < IND_MAX_OUTPUT_STEPS, PetscObjectComm((PetscObject)U), PETSC_ERR_SUP,
    "More than %d output steps", IND_MAX_OUTPUT_STEPS);
  PetscCall(PetscLogStagePush(IndLog.output));
  PetscCall(PetscLogEventBegin(IndLog.output_write, 0, 0, 0, 0));
  PetscCall(CreateFieldObjects(o));
  if (!o->viewer) PetscCall(OpenFile(o));
  PetscCall(DMGlobalToLocal(o->dm, U, INSERT_VALUES, o->Uloc));
  PetscCall(DMGetLocalSection(o->dm, &us));
  PetscCall(VecGetArrayRead(o->Uloc, &u));
  PetscCall(GatherVertexValues(o, us, u, o->disp));
  PetscCall(VecRestoreArrayRead(o->Uloc, &u));

  /* Cells are not shared (no overlap), so local cell i is the i-th owned entry of each cell vector:
     the assembly writes straight into them. */
  PetscCall(VecGetArray(o->stress, &o->cells.stress));
  PetscCall(VecGetArray(o->strain, &o->cells.strain));
  PetscCall(VecGetArray(o->plastic, &o->cells.plastic));
  PetscCall(VecGetArray(o->back, &o->cells.back_stress));
  PetscCall(VecGetArray(o->yielding, &o->cells.yielding));
  if (o->compaction) PetscCall(VecGetArray(o->compaction, &o->cells.compaction));
  PetscCall(IndAssemblyCellAverages(assembly, o->Uloc, &o->cells));
  PetscCall(VecGetArray(o->vonmises, &vm));
  for (PetscInt i = 0; i < o->layout->ncell; ++i) vm[i] = IndVonMises(o->cells.stress + 6 * i);
  PetscCall(VecRestoreArray(o->vonmises, &vm));
  PetscCall(VecRestoreArray(o->stress, &o->cells.stress));
  PetscCall(VecRestoreArray(o->strain, &o->cells.strain));
  PetscCall(VecRestoreArray(o->plastic, &o->cells.plastic));
  PetscCall(VecRestoreArray(o->back, &o->cells.back_stress));
  PetscCall(VecRestoreArray(o->yielding, &o->cells.yielding));
  if (o->compaction) PetscCall(VecRestoreArray(o->compaction, &o->cells.compaction));

  PetscCall(PetscViewerHDF5SetTimestep(o->viewer, o->nsteps));
  PetscCall(PetscViewerHDF5PushGroup(o->viewer, "/fields"));
  PetscCall(IndOutputViewField(o, o->disp, PETSC_FALSE));
  PetscCall(IndOutputViewField(o, o->stress, PETSC_TRUE));
  PetscCall(IndOutputViewField(o, o->strain, PETSC_TRUE));
  PetscCall(IndOutputViewField(o, o->vonmises, PETSC_TRUE));
  PetscCall(IndOutputViewField(o, o->plastic, PETSC_TRUE));
  PetscCall(IndOutputViewField(o, o->back, PETSC_TRUE));
  PetscCall(IndOutputViewField(o, o->yielding, PETSC_TRUE));
  if (o->compaction) PetscCall(IndOutputViewField(o, o->compaction, PETSC_TRUE));
  if (o->contact) {
    PetscCall(GatherContactFields(o));
    PetscCall(IndOutputViewField(o, o->pressure, PETSC_FALSE));
    PetscCall(IndOutputViewField(o, o->status, PETSC_FALSE));
  }
  /* Which accepted step each output step is (-1: not an accepted step of a load program), since not every
     step is written: readers match fields to the curve's rows by it. */
  {
    const PetscReal step = o->info[IND_OUTPUT_INFO * o->nsteps];
    const PetscReal value = o->info_set && !PetscIsNanReal(step) ? step : -1.0;
    PetscMPIInt     rank;
    PetscCallMPI(MPI_Comm_rank(PetscObjectComm((PetscObject)o->dm), &rank));
    PetscCall(IndH5WriteRows(o->viewer, "step", rank ? 0 : 1, 1, &value)); /* one value, on rank 0 */
  }
  PetscCall(PetscViewerHDF5PopGroup(o->viewer));
  PetscCall(PetscViewerFlush(o->viewer));
  PetscCall(WriteXdmf(o, time));
  PetscCall(DestroyFieldVectors(o));
  PetscCall(PetscLogEventEnd(IndLog.output_write, 0, 0, 0, 0));
  PetscCall(PetscLogStagePop());
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndOutputCurvePoint(IndOutput o, const IndCurvePoint *p)
{
  PetscMPIInt rank;

  PetscFunctionBeginUser;
  if (!o->curve) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCallMPI(MPI_Comm_rank(PetscObjectComm((PetscObject)o->dm), &rank));
  if (rank) PetscFunctionReturn(PETSC_SUCCESS);
  if (!o->csv) {
    char path[PETSC_MAX_PATH_LEN];
    PetscCall(PetscSNPrintf(path, sizeof(path), "%s/load_displacement.csv", o->dir));
    o->csv = fopen(path, "w");
    PetscCheck(o->csv, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "Cannot write '%s' (-output_dir)", path);
    IndOutputCurveHeader(o->csv);
  }
  IndOutputCurveLine(o->csv, p);
  PetscCheck(fflush(o->csv) == 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "Error writing %s/load_displacement.csv",
    o->dir);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndOutputDestroy(IndOutput *o)
{
  PetscFunctionBeginUser;
  if (!*o) PetscFunctionReturn(PETSC_SUCCESS);
  if ((*o)->csv) fclose((*o)->csv);
  if ((*o)->viewer) PetscCall(PetscViewerHDF5PopTimestepping((*o)->viewer));
  PetscCall(PetscViewerDestroy(&(*o)->viewer));
  PetscCall(IndOutputPermDestroy(*o));
  PetscCall(DestroyFieldVectors(*o));
  PetscCall(DMDestroy(&(*o)->vdm));
  PetscCall(PetscFree((*o)->times));
  PetscCall(PetscFree((*o)->info));
  PetscCall(PetscFree(*o));
  PetscFunctionReturn(PETSC_SUCCESS);
}

IND_GETTER(const char *, IndOutputGetDir, IndOutput, o->dir)
IND_GETTER(const char *, IndOutputGetFieldFile, IndOutput, o->h5name)
IND_GETTER(PetscBool, IndOutputFieldsEnabled, IndOutput, o->enabled)
IND_GETTER(PetscBool, IndOutputCurveEnabled, IndOutput, o->curve)
IND_GETTER(PetscInt, IndOutputFieldsEvery, IndOutput, o->every)
