#include <string.h>
#include "ind_state.h"
#include "ind_keyedio.h"

/* The keys and places of the displacement's nodes owned here: points with 3 dofs in the owned part of a global
   vector, at local offsets off[i]. */
typedef struct {
  PetscInt   n;
  PetscInt  *off;
  PetscReal *keys;
} Nodes;

struct _p_IndStateFile {
  MPI_Comm      comm;
  PetscViewer   v;
  IndDisc       disc;
  DM            dm;
  PetscFileMode mode;
  char          what[PETSC_MAX_PATH_LEN + 64];
  char          part[64];   /* the part being saved or loaded */
  Nodes         nodes;      /* made at the first node dataset */
  PetscBool     has_nodes, wrote_node_keys;
  PetscReal    *cell_keys;  /* made at the first cell dataset */
  PetscBool     wrote_cell_keys;
  char         *datasets;   /* written: "group/name\n" of each dataset, for the verification */
  size_t        len, cap;
};

static PetscErrorCode NodesCreate(DM dm, Nodes *nd)
{
  PetscSection gs;
  PetscInt     pStart, pEnd, dof, off, rstart;

  PetscFunctionBeginUser;
  PetscCall(DMGetGlobalSection(dm, &gs));
  PetscCall(PetscSectionGetChart(gs, &pStart, &pEnd));
  nd->n = 0;
  for (PetscInt p = pStart; p < pEnd; ++p) {
    PetscCall(PetscSectionGetDof(gs, p, &dof));
    PetscCall(PetscSectionGetOffset(gs, p, &off));
    if (dof > 0 && off >= 0) nd->n++;
  }
  {
    Vec x;
    PetscCall(DMGetGlobalVector(dm, &x));
    PetscCall(VecGetOwnershipRange(x, &rstart, NULL));
    PetscCall(DMRestoreGlobalVector(dm, &x));
  }
  PetscCall(PetscMalloc2(nd->n + 1, &nd->off, 3 * nd->n + 1, &nd->keys));
  nd->n = 0;
  for (PetscInt p = pStart; p < pEnd; ++p) {
    PetscCall(PetscSectionGetDof(gs, p, &dof));
    PetscCall(PetscSectionGetOffset(gs, p, &off));
    if (dof <= 0 || off < 0) continue;
    PetscCheck(dof == 3, PETSC_COMM_SELF, PETSC_ERR_SUP, "State: mesh point %" PetscInt_FMT " has %" PetscInt_FMT
               " dofs, not 3", p, dof);
    nd->off[nd->n] = off - rstart;
    PetscCall(IndPointCentroid(dm, p, nd->keys + 3 * nd->n));
    nd->n++;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Record(IndStateFile f, const char group[], const char name[])
{
  size_t need;

  PetscFunctionBeginUser;
  need = f->len + strlen(group) + strlen(name) + 3;
  if (need > f->cap) {
    char *more;
    f->cap = 2 * need + 256;
    PetscCall(PetscCalloc1(f->cap, &more));
    if (f->datasets) PetscCall(PetscArraycpy(more, f->datasets, f->len));
    PetscCall(PetscFree(f->datasets));
    f->datasets = more;
  }
  f->len += (size_t)snprintf(f->datasets + f->len, f->cap - f->len, "%s/%s\n", group, name);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndStateFileOpen(MPI_Comm comm, IndDisc disc, const char path[], PetscFileMode mode, const char what[],
                                IndStateFile *out)
{
  IndStateFile f;

  PetscFunctionBeginUser;
  PetscCall(PetscNew(&f));
  f->comm = comm;
  f->disc = disc;
  f->mode = mode;
  PetscCall(IndDiscGetDM(disc, &f->dm));
  PetscCall(PetscStrncpy(f->what, what, sizeof(f->what)));
  PetscCall(PetscViewerHDF5Open(comm, path, mode, &f->v));
  *out = f;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndStateFileClose(IndStateFile *f)
{
  PetscFunctionBeginUser;
  if (!*f) PetscFunctionReturn(PETSC_SUCCESS);
  if ((*f)->mode == FILE_MODE_WRITE)
    PetscCall(PetscViewerHDF5WriteAttribute((*f)->v, "/", "datasets", PETSC_STRING, (*f)->datasets ? (*f)->datasets
                                                                                                        : ""));
  PetscCall(PetscViewerDestroy(&(*f)->v));
  if ((*f)->has_nodes) PetscCall(PetscFree2((*f)->nodes.off, (*f)->nodes.keys));
  PetscCall(PetscFree((*f)->cell_keys));
  PetscCall(PetscFree((*f)->datasets));
  PetscCall(PetscFree(*f));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndStateFileGetViewer(IndStateFile f, PetscViewer *v)
{
  PetscFunctionBeginUser;
  *v = f->v;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Datasets of mesh values are named <part>_<name> in /nodes or /cells, beside the keys they share. */
static PetscErrorCode MeshName(IndStateFile f, const char name[], char out[], size_t len)
{
  PetscFunctionBeginUser;
  PetscCall(PetscSNPrintf(out, len, "%s_%s", f->part, name));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode PartGroup(IndStateFile f, char out[], size_t len)
{
  PetscFunctionBeginUser;
  PetscCheck(f->part[0], f->comm, PETSC_ERR_ORDER, "State written or read outside IndStateSave/IndStateLoad");
  PetscCall(PetscSNPrintf(out, len, "/%s", f->part));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode WriteReals(IndStateFile f, const char name[], PetscInt n, const PetscReal v[])
{
  PetscMPIInt rank;
  char        group[80];

  PetscFunctionBeginUser;
  if (!n) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PartGroup(f, group, sizeof(group)));
  PetscCallMPI(MPI_Comm_rank(f->comm, &rank));
  PetscCall(PetscViewerHDF5PushGroup(f->v, group));
  PetscCall(IndRowsWrite(f->v, name, rank ? 0 : n, 1, v));
  PetscCall(PetscViewerHDF5PopGroup(f->v));
  PetscCall(Record(f, group, name));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode ReadRealsAlloc(IndStateFile f, const char name[], PetscInt *n, PetscReal **v)
{
  Vec                x, all;
  VecScatter         sc;
  const PetscScalar *xa;
  PetscBool          has;
  char               group[80];

  PetscFunctionBeginUser;
  *n = 0;
  *v = NULL;
  PetscCall(PartGroup(f, group, sizeof(group)));
  PetscCall(PetscViewerHDF5PushGroup(f->v, group));
  PetscCall(PetscViewerHDF5HasDataset(f->v, name, &has));
  if (has) PetscCall(IndRowsRead(f->v, name, 1, &x));
  PetscCall(PetscViewerHDF5PopGroup(f->v));
  if (!has) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(VecScatterCreateToAll(x, &sc, &all));
  PetscCall(VecScatterBegin(sc, x, all, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(sc, x, all, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecGetSize(all, n));
  PetscCall(PetscMalloc1(*n + 1, v));
  PetscCall(VecGetArrayRead(all, &xa));
  for (PetscInt k = 0; k < *n; ++k) (*v)[k] = PetscRealPart(xa[k]);
  PetscCall(VecRestoreArrayRead(all, &xa));
  PetscCall(VecScatterDestroy(&sc));
  PetscCall(VecDestroy(&all));
  PetscCall(VecDestroy(&x));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscBool IndStateReading(IndStateFile f)
{
  return f->mode == FILE_MODE_READ ? PETSC_TRUE : PETSC_FALSE;
}

PetscErrorCode IndStateTransfer(IndStateFile f, PetscInt n, const IndStatePart parts[])
{
  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < n; ++k) {
    PetscCall(PetscStrncpy(f->part, parts[k].name, sizeof(f->part)));
    PetscCall(parts[k].transfer(parts[k].obj, f));
  }
  f->part[0] = 0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndStateRealArray(IndStateFile f, const char name[], PetscInt *n, PetscReal **v)
{
  PetscFunctionBeginUser;
  if (IndStateReading(f)) PetscCall(ReadRealsAlloc(f, name, n, v));
  else PetscCall(WriteReals(f, name, *n, *v));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndStateReals(IndStateFile f, const char name[], PetscInt n, PetscReal v[])
{
  PetscInt   m = n;
  PetscReal *a = v;

  PetscFunctionBeginUser;
  PetscCall(IndStateRealArray(f, name, &m, &a));
  if (!IndStateReading(f)) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCheck(m == n, f->comm, PETSC_ERR_FILE_UNEXPECTED, "%s: /%s/%s holds %" PetscInt_FMT " values, this run keeps %"
             PetscInt_FMT, f->what, f->part, name, m, n);
  if (n) PetscCall(PetscArraycpy(v, a, n));
  PetscCall(PetscFree(a));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndStateString(IndStateFile f, const char name[], char value[], size_t len)
{
  char *text = NULL;

  PetscFunctionBeginUser;
  if (!IndStateReading(f)) {
    PetscCall(PetscViewerHDF5WriteAttribute(f->v, "/", name, PETSC_STRING, value));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(PetscViewerHDF5ReadAttribute(f->v, "/", name, PETSC_STRING, NULL, &text));
  PetscCall(PetscStrncpy(value, text, len));
  PetscCall(PetscFree(text));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndStateNodes(IndStateFile f, const char name[], Vec x)
{
  PetscScalar *a;
  PetscReal   *vals;
  char         dset[160];

  PetscFunctionBeginUser;
  if (!f->has_nodes) PetscCall(NodesCreate(f->dm, &f->nodes));
  f->has_nodes = PETSC_TRUE;
  PetscCall(MeshName(f, name, dset, sizeof(dset)));
  PetscCall(PetscMalloc1(3 * f->nodes.n + 1, &vals));
  PetscCall(VecGetArray(x, &a));
  PetscCall(PetscViewerHDF5PushGroup(f->v, "/nodes"));
  if (IndStateReading(f)) {
    PetscCall(IndRowsJoin(f->v, "keys", dset, 3, "nodes", f->what, f->nodes.n, f->nodes.keys, vals));
    for (PetscInt i = 0; i < f->nodes.n; ++i)
      for (int d = 0; d < 3; ++d) a[f->nodes.off[i] + d] = vals[3 * i + d];
  } else {
    for (PetscInt i = 0; i < f->nodes.n; ++i)
      for (int d = 0; d < 3; ++d) vals[3 * i + d] = PetscRealPart(a[f->nodes.off[i] + d]);
    if (!f->wrote_node_keys) {
      PetscCall(IndRowsWrite(f->v, "keys", f->nodes.n, 3, f->nodes.keys));
      PetscCall(Record(f, "/nodes", "keys"));
      f->wrote_node_keys = PETSC_TRUE;
    }
    PetscCall(IndRowsWrite(f->v, dset, f->nodes.n, 3, vals));
    PetscCall(Record(f, "/nodes", dset));
  }
  PetscCall(PetscViewerHDF5PopGroup(f->v));
  PetscCall(VecRestoreArray(x, &a));
  PetscCall(PetscFree(vals));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndStateCells(IndStateFile f, const char name[], PetscInt stride, PetscReal *v)
{
  const IndDiscLayout *L;
  char                 dset[160];

  PetscFunctionBeginUser;
  PetscCall(IndDiscGetLayout(f->disc, &L));
  PetscCall(MeshName(f, name, dset, sizeof(dset)));
  if (!f->cell_keys) PetscCall(IndCellCentroids(f->disc, &f->cell_keys));
  PetscCall(PetscViewerHDF5PushGroup(f->v, "/cells"));
  if (IndStateReading(f))
    PetscCall(IndRowsJoin(f->v, "keys", dset, stride, "cells", f->what, L->ncell, f->cell_keys, v));
  else {
    if (!f->wrote_cell_keys) {
      PetscCall(IndRowsWrite(f->v, "keys", L->ncell, 3, f->cell_keys));
      PetscCall(Record(f, "/cells", "keys"));
      f->wrote_cell_keys = PETSC_TRUE;
    }
    PetscCall(IndRowsWrite(f->v, dset, L->ncell, stride, v));
    PetscCall(Record(f, "/cells", dset));
  }
  PetscCall(PetscViewerHDF5PopGroup(f->v));
  PetscFunctionReturn(PETSC_SUCCESS);
}
