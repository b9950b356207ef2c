#define _POSIX_C_SOURCE 200809L /* sigaction, gmtime_r, strtok_r */
#include <stdio.h>
#include <string.h>
#include <petscviewerhdf5.h>
#include "ind_checkpoint.h"
#include "ind_keyedio.h"
#include "ind_rundir.h"
#include "ind_version.h"

#define FORMAT      "indent checkpoint 3" /* 3: a checksum on every dataset */
#define CURVE_WIDTH 16 /* reals per IndCurvePoint */

/* Options that do not change the answer, only how it is computed, shown or stored: a restart may
   change them (a tighter tolerance to get past a hard step, another output directory layout...). */
static const char *const RunControl[] = {
  "ksp_",    "snes_",    "pc_",       "mg_",         "log",           "malloc",          "options_",      "help",
  "quiet",   "restart",  "output_",   "checkpoint_", "op_",           "info",            "on_error",      "viewer",
  "vec_view", "mat_",    "mesh_view", "dm_view",     "contact_monitor", "history",       "check_pointer", "fp_trap",
  "memory_view", "objects_dump", "newton_stall_its", "load_max_cutbacks", "version", "matptap_", "matmatmult_"};

static PetscBool IsRunControl(const char *name)
{
  for (size_t k = 0; k < sizeof(RunControl) / sizeof(RunControl[0]); ++k)
    if (!strncmp(name, RunControl[k], strlen(RunControl[k]))) return PETSC_TRUE;
  return PETSC_FALSE;
}

static int LineCompare(const void *a, const void *b)
{
  return strcmp(*(char *const *)a, *(char *const *)b);
}

PetscErrorCode IndCheckpointModelOptions(char **text)
{
  char  *all, *tok, *save = NULL, **lines;
  size_t len, n = 0, cap;

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsGetAll(NULL, &all));
  PetscCall(PetscStrlen(all, &len));
  cap = len / 2 + 2;
  PetscCall(PetscCalloc1(cap, &lines));
  /* "-a 1 -b -c x": a token starting with '-' and a letter names an option, others are its value */
  for (tok = strtok_r(all, " ", &save); tok; tok = strtok_r(NULL, " ", &save)) {
    const PetscBool name = tok[0] == '-' && ((tok[1] >= 'a' && tok[1] <= 'z') || (tok[1] >= 'A' && tok[1] <= 'Z'));
    if (name) {
      PetscCall(PetscStrallocpy(tok, &lines[n++]));
    } else if (n) {
      char  *joined;
      size_t l0, l1;
      PetscCall(PetscStrlen(lines[n - 1], &l0));
      PetscCall(PetscStrlen(tok, &l1));
      PetscCall(PetscMalloc1(l0 + l1 + 2, &joined));
      PetscCall(PetscSNPrintf(joined, l0 + l1 + 2, "%s %s", lines[n - 1], tok));
      PetscCall(PetscFree(lines[n - 1]));
      lines[n - 1] = joined;
    }
  }
  qsort(lines, n, sizeof(char *), LineCompare);
  PetscCall(PetscCalloc1(len + n + 2, text));
  for (size_t i = 0; i < n; ++i) {
    if (!IsRunControl(lines[i] + 1)) {
      PetscCall(PetscStrlcat(*text, lines[i], len + n + 2));
      PetscCall(PetscStrlcat(*text, "\n", len + n + 2));
    }
    PetscCall(PetscFree(lines[i]));
  }
  PetscCall(PetscFree(lines));
  PetscCall(PetscFree(all));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Copies the line of text starting at s (without its newline) into out. */
static void Line(const char *s, char *out, size_t len)
{
  size_t k = 0;
  for (; s && s[k] && s[k] != '\n' && k + 1 < len; ++k) out[k] = s[k];
  out[k] = 0;
}

void IndCheckpointOptionsDiffer(const char *saved, const char *here, char *what, size_t len)
{
  const char *a = saved, *b = here;

  what[0] = 0;
  while (*a || *b) {
    char la[256], lb[256], na[256], nb[256];
    Line(a, la, sizeof(la));
    Line(b, lb, sizeof(lb));
    if (strcmp(la, lb)) {
      int c;
      Line(a, na, sizeof(na));
      Line(b, nb, sizeof(nb));
      strtok(na, " ");
      strtok(nb, " ");
      c = !*a ? 1 : !*b ? -1 : strcmp(na, nb);
      if (c < 0) snprintf(what, len, "the checkpoint was made with %s, which this run does not give", la);
      else if (c > 0) snprintf(what, len, "this run gives %s, which the checkpoint was made without", lb);
      else snprintf(what, len, "the checkpoint was made with %s, this run gives %s", la, lb);
      return;
    }
    a += strlen(la) + (a[strlen(la)] == '\n');
    b += strlen(lb) + (b[strlen(lb)] == '\n');
  }
}

/* The keys and places of the displacement's nodes owned here: points with 3 dofs in the owned part
   of a global vector, at local offsets off[i]. */
typedef struct {
  PetscInt   n;
  PetscInt  *off;
  PetscReal *keys;
} Nodes;

static PetscErrorCode NodesCreate(DM dm, Vec U, Nodes *nd)
{
  PetscSection gs;
  PetscInt     pStart, pEnd, rstart, dof, off;

  PetscFunctionBeginUser;
  PetscCall(DMGetGlobalSection(dm, &gs));
  PetscCall(PetscSectionGetChart(gs, &pStart, &pEnd));
  PetscCall(VecGetOwnershipRange(U, &rstart, NULL));
  nd->n = 0;
  for (PetscInt p = pStart; p < pEnd; ++p) {
    PetscCall(PetscSectionGetDof(gs, p, &dof));
    PetscCall(PetscSectionGetOffset(gs, p, &off));
    if (dof > 0 && off >= 0) nd->n++;
  }
  PetscCall(PetscMalloc2(nd->n + 1, &nd->off, 3 * nd->n + 1, &nd->keys));
  nd->n = 0;
  for (PetscInt p = pStart; p < pEnd; ++p) {
    PetscCall(PetscSectionGetDof(gs, p, &dof));
    PetscCall(PetscSectionGetOffset(gs, p, &off));
    if (dof <= 0 || off < 0) continue;
    PetscCheck(dof == 3, PETSC_COMM_SELF, PETSC_ERR_SUP,
      "Checkpoint: mesh point %" PetscInt_FMT " has %" PetscInt_FMT " dofs, not 3", p, dof);
    nd->off[nd->n] = off - rstart;
    PetscCall(IndPointCentroid(dm, p, nd->keys + 3 * nd->n));
    nd->n++;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A short array (the curve, the output steps) written by rank 0 and read whole by every rank. */
static PetscErrorCode WriteSmall(PetscViewer v, const char name[], PetscInt n, const PetscReal *a)
{
  PetscMPIInt rank;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(PetscObjectComm((PetscObject)v), &rank));
  if (n) PetscCall(IndRowsWrite(v, name, rank ? 0 : n, 1, a));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode ReadSmall(PetscViewer v, const char name[], PetscInt n, PetscReal *a)
{
  Vec                x, all;
  VecScatter         sc;
  const PetscScalar *xa;

  PetscFunctionBeginUser;
  if (!n) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(IndRowsRead(v, name, 1, &x));
  PetscCall(VecScatterCreateToAll(x, &sc, &all));
  PetscCall(VecScatterBegin(sc, x, all, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(sc, x, all, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecGetArrayRead(all, &xa));
  for (PetscInt k = 0; k < n; ++k) a[k] = PetscRealPart(xa[k]);
  PetscCall(VecRestoreArrayRead(all, &xa));
  PetscCall(VecScatterDestroy(&sc));
  PetscCall(VecDestroy(&all));
  PetscCall(VecDestroy(&x));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static void PackPoint(const IndCurvePoint *p, PetscReal *r)
{
  const PetscReal v[CURVE_WIDTH] = {(PetscReal)p->step,    p->t,        p->depth,          p->load,
                                    (PetscReal)p->contact, (PetscReal)p->stick, (PetscReal)p->slip,
                                      (PetscReal)p->newton,
                                    (PetscReal)p->outer,   (PetscReal)p->linear, (PetscReal)p->cutbacks, p->penetration,
                                    p->area,               p->pileup,   p->deepest,        (PetscReal)p->seconds};
  for (int k = 0; k < CURVE_WIDTH; ++k) r[k] = v[k];
}

static void UnpackPoint(const PetscReal *r, IndCurvePoint *p)
{
  p->step        = (PetscInt)r[0];
  p->t           = r[1];
  p->depth       = r[2];
  p->load        = r[3];
  p->contact     = (PetscInt)r[4];
  p->stick       = (PetscInt)r[5];
  p->slip        = (PetscInt)r[6];
  p->newton      = (PetscInt)r[7];
  p->outer       = (PetscInt)r[8];
  p->linear      = (PetscInt)r[9];
  p->cutbacks    = (PetscInt)r[10];
  p->penetration = r[11];
  p->area        = r[12];
  p->pileup      = r[13];
  p->deepest     = r[14];
  p->seconds     = r[15];
}

/* The evolving scalars, in a fixed order. */
#define NSCALARS 15
static void PackScalars(IndApp app, PetscReal s[NSCALARS])
{
  const IndLoadPath *lp = &app->path;
  s[0]  = lp->t;
  s[1]  = lp->dt;
  s[2]  = (PetscReal)lp->accepted;
  s[3]  = (PetscReal)lp->cutbacks;
  s[4]  = (PetscReal)lp->cutbacks_in_a_row;
  s[5]  = app->dlambda_last;
  s[6]  = app->contact ? app->contact->rho_scale : 0;
  s[7]  = app->contact ? app->contact->depth_c : 0;
  s[8]  = (PetscReal)(app->summary ? app->summary->n : 0);
  s[9]  = (PetscReal)app->output->nsteps;
  s[10] = app->elapsed_before + app->elapsed_now;
  s[11] = app->ddepth_last;
  s[12] = app->load_last;
  s[13] = app->slope_last;
  s[14] = app->dslide_last;
}

/* U (3 per node), its last increment, and with contact the committed reactions in U's layout. */
static PetscErrorCode NodeValues(IndApp app, const Nodes *nd, PetscReal **vals)
{
  const PetscScalar *u, *du;
  const IndContact   c = app->contact;
  PetscReal         *R = NULL;
  PetscInt           nloc;

  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(app->U, &nloc));
  PetscCall(PetscCalloc1(nloc + 1, &R));
  if (c)
    for (PetscInt i = 0; i < c->n; ++i)
      for (int d = 0; d < 3; ++d) R[c->row[i] + d] = c->Rc[3 * i + d];
  PetscCall(PetscMalloc1(9 * nd->n + 1, vals));
  PetscCall(VecGetArrayRead(app->U, &u));
  PetscCall(VecGetArrayRead(app->dU, &du));
  for (PetscInt i = 0; i < nd->n; ++i)
    for (int d = 0; d < 3; ++d) {
      (*vals)[9 * i + d]     = PetscRealPart(u[nd->off[i] + d]);
      (*vals)[9 * i + 3 + d] = PetscRealPart(du[nd->off[i] + d]);
      (*vals)[9 * i + 6 + d] = R[nd->off[i] + d];
    }
  PetscCall(VecRestoreArrayRead(app->U, &u));
  PetscCall(VecRestoreArrayRead(app->dU, &du));
  PetscCall(PetscFree(R));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndCheckpointWrite(IndApp app, const char path[])
{
  MPI_Comm         comm = app->comm;
  PetscViewer      v;
  Nodes            nd;
  PetscReal       *vals, *ckeys, scal[NSCALARS], *curve = NULL;
  const PetscReal *hist;
  char             tmp[PETSC_MAX_PATH_LEN], petsc[256], *model;
  PetscMPIInt      rank, size;
  PetscInt         ranks, stride = app->history->stride, npts = app->summary ? app->summary->n : 0;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  ranks = size;
  PetscCall(PetscSNPrintf(tmp, sizeof(tmp), "%s.tmp", path));
  PetscCall(PetscViewerHDF5Open(comm, tmp, FILE_MODE_WRITE, &v));
  PetscCall(PetscGetVersion(petsc, sizeof(petsc)));
  PetscCall(IndCheckpointModelOptions(&model));
  PetscCall(PetscViewerHDF5WriteAttribute(v, "/", "format", PETSC_STRING, FORMAT));
  PetscCall(PetscViewerHDF5WriteAttribute(v, "/", "indent_version", PETSC_STRING, INDENT_VERSION));
  PetscCall(PetscViewerHDF5WriteAttribute(v, "/", "git_commit", PETSC_STRING, INDENT_GIT_COMMIT));
  PetscCall(PetscViewerHDF5WriteAttribute(v, "/", "petsc_version", PETSC_STRING, petsc));
  PetscCall(PetscViewerHDF5WriteAttribute(v, "/", "mpi_ranks", PETSC_INT, &ranks));
  PetscCall(PetscViewerHDF5WriteAttribute(v, "/", "model_options", PETSC_STRING, model[0] ? model : "(none)"));
  PetscCall(PetscViewerHDF5WriteAttribute(v, "/", "start_time", PETSC_STRING, app->start_time));
  PetscCall(PetscViewerHDF5WriteAttribute(v, "/", "history_stride", PETSC_INT, &stride));
  PetscCall(PetscFree(model));

  PackScalars(app, scal);
  PetscCall(PetscViewerHDF5PushGroup(v, "/run"));
  PetscCall(WriteSmall(v, "scalars", NSCALARS, scal));
  if (npts) {
    PetscCall(PetscMalloc1(CURVE_WIDTH * npts, &curve));
    for (PetscInt i = 0; i < npts; ++i) PackPoint(&app->summary->pts[i], curve + CURVE_WIDTH * i);
    PetscCall(WriteSmall(v, "curve", CURVE_WIDTH * npts, curve));
    PetscCall(PetscFree(curve));
  }
  PetscCall(WriteSmall(v, "output_times", app->output->nsteps, app->output->times));
  PetscCall(WriteSmall(v, "output_info", IND_OUTPUT_INFO * app->output->nsteps, app->output->info));
  PetscCall(PetscViewerHDF5PopGroup(v));

  PetscCall(NodesCreate(app->disc->dm, app->U, &nd));
  PetscCall(NodeValues(app, &nd, &vals));
  PetscCall(PetscViewerHDF5PushGroup(v, "/nodes"));
  PetscCall(IndRowsWrite(v, "keys", nd.n, 3, nd.keys));
  PetscCall(IndRowsWrite(v, "values", nd.n, 9, vals));
  PetscCall(PetscViewerHDF5PopGroup(v));
  PetscCall(PetscFree(vals));
  PetscCall(PetscFree2(nd.off, nd.keys));

  PetscCall(IndCellCentroids(app->disc, &ckeys));
  PetscCall(VecGetArrayRead(app->history->committed, &hist));
  PetscCall(PetscViewerHDF5PushGroup(v, "/cells"));
  PetscCall(IndRowsWrite(v, "keys", app->disc->ncell, 3, ckeys));
  PetscCall(IndRowsWrite(v, "history", app->disc->ncell, stride, hist));
  PetscCall(PetscViewerHDF5PopGroup(v));
  PetscCall(VecRestoreArrayRead(app->history->committed, &hist));
  PetscCall(PetscFree(ckeys));
  PetscCall(PetscViewerDestroy(&v));

  PetscCallMPI(MPI_Barrier(comm));
  if (!rank) {
    char      previous[PETSC_MAX_PATH_LEN];
    PetscBool exists;
    IndRunDirPreviousCheckpoint(path, previous, sizeof(previous));
    PetscCall(PetscTestFile(path, 'r', &exists));
    if (exists) PetscCall(IndRenameInto(path, previous));
    PetscCall(IndRenameInto(tmp, path));
  }
  PetscCallMPI(MPI_Barrier(comm));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode RestoreNodes(IndApp app, const Nodes *nd, const PetscReal *vals)
{
  PetscScalar *u, *du;
  IndContact   c = app->contact;
  PetscReal   *R;
  PetscInt     nloc;

  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(app->U, &nloc));
  PetscCall(PetscCalloc1(nloc + 1, &R));
  PetscCall(VecGetArray(app->U, &u));
  PetscCall(VecGetArray(app->dU, &du));
  for (PetscInt i = 0; i < nd->n; ++i)
    for (int d = 0; d < 3; ++d) {
      u[nd->off[i] + d]  = vals[9 * i + d];
      du[nd->off[i] + d] = vals[9 * i + 3 + d];
      R[nd->off[i] + d]  = vals[9 * i + 6 + d];
    }
  if (c)
    for (PetscInt i = 0; i < c->n; ++i)
      for (int d = 0; d < 3; ++d) {
        c->Rc[3 * i + d] = c->R[3 * i + d] = R[c->row[i] + d];
        c->Uc[3 * i + d]                   = PetscRealPart(u[c->row[i] + d]);
      }
  PetscCall(VecRestoreArray(app->U, &u));
  PetscCall(VecRestoreArray(app->dU, &du));
  PetscCall(PetscFree(R));
  PetscCall(VecCopy(app->U, app->Uprev));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A damaged checkpoint is refused in one line that names what is wrong and, when the one it replaced
   is whole, how to continue from that one. */
static PetscErrorCode CheckWhole(MPI_Comm comm, const char path[])
{
  char     why[256], previous[PETSC_MAX_PATH_LEN], why_previous[256], advice[PETSC_MAX_PATH_LEN + 128] = "";
  PetscInt step = -1;

  PetscFunctionBeginUser;
  PetscCall(IndCheckpointVerify(comm, path, NULL, why, sizeof(why)));
  if (!why[0]) PetscFunctionReturn(PETSC_SUCCESS);
  IndRunDirPreviousCheckpoint(path, previous, sizeof(previous));
  {
    PetscBool exists;
    PetscCall(PetscTestFile(previous, 'r', &exists));
    if (exists) PetscCall(IndCheckpointVerify(comm, previous, &step, why_previous, sizeof(why_previous)));
    if (exists && !why_previous[0])
      PetscCall(PetscSNPrintf(advice, sizeof(advice), "; the checkpoint before it, after step %" PetscInt_FMT
                              ", is whole: continue from it with -restart %s", step, previous));
    else if (exists)
      PetscCall(PetscSNPrintf(advice, sizeof(advice), "; the one before it, %s, is damaged too: %s", previous,
                              why_previous));
  }
  SETERRQ(comm, PETSC_ERR_FILE_UNEXPECTED, "-restart: checkpoint '%s' is damaged: %s%s", path, why, advice);
}

PetscErrorCode IndCheckpointCheck(MPI_Comm comm, const char path[])
{
  PetscViewer v;
  PetscBool   has, same = PETSC_FALSE;
  char       *format = NULL, *saved = NULL, *here = NULL, differ[600];

  PetscFunctionBeginUser;
  PetscCall(CheckWhole(comm, path));
  PetscCall(PetscViewerHDF5Open(comm, path, FILE_MODE_READ, &v));
  PetscCall(PetscViewerHDF5HasAttribute(v, "/", "format", &has));
  if (has) PetscCall(PetscViewerHDF5ReadAttribute(v, "/", "format", PETSC_STRING, NULL, &format));
  if (has) PetscCall(PetscStrcmp(format, FORMAT, &same));
  PetscCheck(same, comm, PETSC_ERR_FILE_UNEXPECTED, "-restart: '%s' is %s", path,
             has ? "a checkpoint of another indent version (its format differs)" : "not an indent checkpoint");
  PetscCall(PetscViewerHDF5ReadAttribute(v, "/", "model_options", PETSC_STRING, NULL, &saved));
  PetscCall(IndCheckpointModelOptions(&here));
  IndCheckpointOptionsDiffer(strcmp(saved, "(none)") ? saved : "", here, differ, sizeof(differ));
  PetscCheck(!differ[0], comm, PETSC_ERR_ARG_INCOMP,
    "-restart %s: %s (model options must match; solver and output options may differ)", path, differ);
  PetscCall(PetscViewerDestroy(&v));
  PetscCall(PetscFree(format));
  PetscCall(PetscFree(saved));
  PetscCall(PetscFree(here));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndCheckpointRead(IndApp app, const char path[])
{
  MPI_Comm    comm = app->comm;
  PetscViewer v;
  Nodes       nd;
  PetscReal  *vals, *ckeys, scal[NSCALARS];
  PetscScalar *hist;
  char       *start = NULL, what[PETSC_MAX_PATH_LEN + 32];
  PetscInt    stride = 0, npts, nsteps;

  PetscFunctionBeginUser;
  PetscCall(PetscSNPrintf(what, sizeof(what), "-restart: checkpoint '%s'", path));
  PetscCall(PetscViewerHDF5Open(comm, path, FILE_MODE_READ, &v));
  PetscCall(PetscViewerHDF5ReadAttribute(v, "/", "history_stride", PETSC_INT, NULL, &stride));
  PetscCheck(stride == app->history->stride, comm, PETSC_ERR_ARG_INCOMP,
    "-restart: checkpoint '%s' holds %" PetscInt_FMT " history values per cell, this run %" PetscInt_FMT " (another "
    "element or quadrature)", path, stride,
             app->history->stride);
  PetscCall(PetscViewerHDF5ReadAttribute(v, "/", "start_time", PETSC_STRING, NULL, &start));
  PetscCall(PetscStrncpy(app->start_time, start, sizeof(app->start_time)));

  PetscCall(PetscViewerHDF5PushGroup(v, "/run"));
  PetscCall(ReadSmall(v, "scalars", NSCALARS, scal));
  npts   = (PetscInt)scal[8];
  nsteps = (PetscInt)scal[9];
  PetscCheck(!npts || app->summary, comm, PETSC_ERR_ARG_INCOMP,
    "-restart: checkpoint '%s' is of an indentation, this run has no indenter", path);
  if (npts) {
    PetscReal *curve;
    PetscCall(PetscMalloc1(CURVE_WIDTH * npts, &curve));
    PetscCall(ReadSmall(v, "curve", CURVE_WIDTH * npts, curve));
    app->summary->n = 0;
    for (PetscInt i = 0; i < npts; ++i) {
      IndCurvePoint p;
      UnpackPoint(curve + CURVE_WIDTH * i, &p);
      PetscCall(IndSummaryAddPoint(app->summary, &p));
    }
    PetscCall(PetscFree(curve));
  }
  PetscCheck(nsteps <= IND_MAX_OUTPUT_STEPS, comm, PETSC_ERR_FILE_UNEXPECTED,
    "Checkpoint '%s': %" PetscInt_FMT " output steps", path, nsteps);
  PetscCall(ReadSmall(v, "output_times", nsteps, app->output->times));
  PetscCall(ReadSmall(v, "output_info", IND_OUTPUT_INFO * nsteps, app->output->info));
  app->output->nsteps = nsteps;
  PetscCall(PetscViewerHDF5PopGroup(v));

  PetscCall(NodesCreate(app->disc->dm, app->U, &nd));
  PetscCall(PetscMalloc1(9 * nd.n + 1, &vals));
  PetscCall(PetscViewerHDF5PushGroup(v, "/nodes"));
  PetscCall(IndRowsJoin(v, "keys", "values", 9, "nodes", what, nd.n, nd.keys, vals));
  PetscCall(PetscViewerHDF5PopGroup(v));
  PetscCall(RestoreNodes(app, &nd, vals));
  PetscCall(PetscFree(vals));
  PetscCall(PetscFree2(nd.off, nd.keys));

  PetscCall(IndCellCentroids(app->disc, &ckeys));
  PetscCall(VecGetArray(app->history->committed, &hist));
  PetscCall(PetscViewerHDF5PushGroup(v, "/cells"));
  PetscCall(IndRowsJoin(v, "keys", "history", stride, "cells", what, app->disc->ncell, ckeys, (PetscReal *)hist));
  PetscCall(PetscViewerHDF5PopGroup(v));
  PetscCall(VecRestoreArray(app->history->committed, &hist));
  PetscCall(PetscFree(ckeys));
  PetscCall(PetscViewerDestroy(&v));

  app->path.t                 = scal[0];
  app->path.dt                = scal[1];
  app->path.accepted          = (PetscInt)scal[2];
  app->path.cutbacks          = (PetscInt)scal[3];
  app->path.cutbacks_in_a_row = (PetscInt)scal[4];
  app->dlambda_last           = scal[5];
  app->elapsed_before         = scal[10];
  app->ddepth_last            = scal[11];
  app->load_last              = scal[12];
  app->slope_last             = scal[13];
  app->dslide_last            = scal[14];
  if (app->contact) {
    PetscReal axis[2];
    /* the axis of a scratch follows from the load program's time */
    IndScratchAxis(&app->scratch, IndLoadPathScratchFraction(&app->path, app->path.t), axis);
    app->contact->rho_scale = scal[6];
    PetscCall(IndContactSetIndenterPosition(app->contact, scal[7], axis));
    app->contact->depth_c   = scal[7];
    app->contact->axis_c[0] = axis[0];
    app->contact->axis_c[1] = axis[1];
  }
  PetscCall(PetscFree(start));
  PetscFunctionReturn(PETSC_SUCCESS);
}
