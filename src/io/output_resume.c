#include <string.h>
#include "output_impl.h"
#include "ind_keyedio.h"
#include "ind_rundir.h"
#include "ind_h5rows.h"

#define MAXBS 6

/* Scatters from this run's vertex (k = 0) or cell (k = 1) vectors of block size bs to the file's order. */
struct _n_IndOutputPerm {
  PetscInt  *index[2]; /* file row of each owned vertex and local cell */
  PetscInt   n[2], N[2];
  VecScatter sc[2][MAXBS + 1];
  Vec        out[2][MAXBS + 1];
};

void IndOutputCurveHeader(FILE *fp)
{
  fprintf(fp,
    "step,t,depth_nm,load_uN,contact_nodes,stick,slip,newton,uzawa,linear,cutbacks,penetration_nm,contact_area_nm2,"
              "pileup_nm,deepest_nm,seconds\n");
}

void IndOutputCurveLine(FILE *fp, const IndCurvePoint *p)
{
  const PetscInt ints[3] = {p->contact, p->stick, p->slip}, its[4] = {p->newton, p->outer, p->linear, p->cutbacks};

  fprintf(fp, "%" PetscInt_FMT ",%.10g,%.12g,%.12g", p->step, (double)p->t, (double)p->depth, (double)p->load);
  for (int k = 0; k < 3; ++k) fprintf(fp, ",%" PetscInt_FMT, ints[k]);
  for (int k = 0; k < 4; ++k) fprintf(fp, ",%" PetscInt_FMT, its[k]);
  fprintf(fp, ",%.6g,%.10g,%.8g,%.10g,%.4f\n", (double)p->penetration, (double)p->area, (double)p->pileup,
          (double)p->deepest, (double)p->seconds);
}

PetscErrorCode IndOutputResume(IndOutput o, PetscInt npts, const IndCurvePoint *pts)
{
  PetscMPIInt rank;
  PetscBool   exists = PETSC_FALSE;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(PetscObjectComm((PetscObject)o->dm), &rank));
  if (o->curve && !rank) {
    char  path[PETSC_MAX_PATH_LEN], tmp[PETSC_MAX_PATH_LEN];
    FILE *fp;
    PetscCall(PetscSNPrintf(path, sizeof(path), "%s/load_displacement.csv", o->dir));
    PetscCall(PetscSNPrintf(tmp, sizeof(tmp), "%s.tmp", path));
    fp = fopen(tmp, "w");
    PetscCheck(fp, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "Cannot write '%s' (-output_dir)", tmp);
    IndOutputCurveHeader(fp);
    for (PetscInt i = 0; i < npts; ++i) IndOutputCurveLine(fp, &pts[i]);
    PetscCheck(fclose(fp) == 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "Error writing '%s'", tmp);
    PetscCall(IndRenameInto(tmp, path));
    o->csv = fopen(path, "a");
    PetscCheck(o->csv, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "Cannot append to '%s' (-output_dir)", path);
  }
  /* Without the earlier part's field file (it ran with -output_fields 0) the fields start afresh. */
  if (o->enabled) PetscCall(PetscTestFile(o->h5name, 'r', &exists));
  o->resume = exists;
  if (!exists) o->nsteps = 0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndOutputWriteCellKeys(IndOutput o)
{
  PetscReal *keys;

  PetscFunctionBeginUser;
  PetscCall(IndCellCentroids(o->disc, &keys));
  PetscCall(PetscViewerHDF5PushGroup(o->viewer, "/topology"));
  PetscCall(IndRowsWrite(o->viewer, "cell_centroids", o->layout->ncell, 3, keys));
  PetscCall(PetscViewerHDF5PopGroup(o->viewer));
  PetscCall(PetscFree(keys));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndOutputOpenResumed(IndOutput o)
{
  MPI_Comm           comm = PetscObjectComm((PetscObject)o->dm);
  DM                 cdm;
  PetscSection       cs, vs;
  Vec                X, coords;
  const PetscScalar *x;
  PetscReal         *vkeys, *ckeys;
  char               file[PETSC_MAX_PATH_LEN + 2];
  PetscInt           vStart, vEnd, n;
  struct _n_IndOutputPerm *pm;

  PetscFunctionBeginUser;
  PetscCall(PetscNew(&pm));
  o->perm = pm;
  PetscCall(PetscViewerHDF5Open(comm, o->h5name, FILE_MODE_APPEND, &o->viewer));
  PetscCall(PetscViewerHDF5SetBaseDimension2(o->viewer, PETSC_TRUE));

  /* The vertices' keys are their coordinates, in the order of this run's vertex vectors. */
  PetscCall(DMGetCoordinateDM(o->dm, &cdm));
  PetscCall(DMGetLocalSection(cdm, &cs));
  PetscCall(DMGetCoordinatesLocal(o->dm, &X));
  PetscCall(DMGetLocalSection(o->vdm, &vs));
  PetscCall(DMPlexGetDepthStratum(o->vdm, 0, &vStart, &vEnd));
  PetscCall(DMCreateGlobalVector(o->vdm, &coords));
  {
    PetscScalar *v;
    PetscCall(VecGetArrayRead(X, &x));
    PetscCall(VecGetArray(o->vloc, &v));
    for (PetscInt p = vStart; p < vEnd; ++p) {
      PetscInt so, vo;
      PetscCall(PetscSectionGetOffset(cs, p, &so));
      PetscCall(PetscSectionGetOffset(vs, p, &vo));
      for (int c = 0; c < 3; ++c) v[vo + c] = x[so + c];
    }
    PetscCall(VecRestoreArray(o->vloc, &v));
    PetscCall(VecRestoreArrayRead(X, &x));
    PetscCall(DMLocalToGlobal(o->vdm, o->vloc, INSERT_VALUES, coords));
  }
  PetscCall(VecGetLocalSize(coords, &n));
  pm->n[0] = n / 3;
  PetscCall(PetscMalloc1(n + 1, &vkeys));
  PetscCall(VecGetArrayRead(coords, &x));
  for (PetscInt k = 0; k < n; ++k) vkeys[k] = PetscRealPart(x[k]);
  PetscCall(VecRestoreArrayRead(coords, &x));
  PetscCall(VecDestroy(&coords));
  PetscCall(PetscViewerHDF5PushGroup(o->viewer, "/geometry"));
  PetscCall(PetscSNPrintf(file, sizeof(file), "'%s'", o->h5name));
  PetscCall(IndRowsLocate(o->viewer, "vertices", "vertices", file, pm->n[0], vkeys, &pm->index[0]));
  PetscCall(PetscViewerHDF5PopGroup(o->viewer));
  PetscCall(PetscFree(vkeys));

  pm->n[1] = o->layout->ncell;
  PetscCall(IndCellCentroids(o->disc, &ckeys));
  PetscCall(PetscViewerHDF5PushGroup(o->viewer, "/topology"));
  PetscCall(IndRowsLocate(o->viewer, "cell_centroids", "cells", file, pm->n[1], ckeys, &pm->index[1]));
  PetscCall(PetscViewerHDF5PopGroup(o->viewer));
  PetscCall(PetscFree(ckeys));
  for (int k = 0; k < 2; ++k) {
    pm->N[k] = pm->n[k];
    PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &pm->N[k], 1, MPIU_INT, MPI_SUM, comm));
  }
  o->nvert   = pm->N[0];
  o->ncell   = pm->N[1];
  o->corners = IndOutputCorners(o);
  PetscCall(PetscViewerHDF5PushTimestepping(o->viewer));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndOutputViewField(IndOutput o, Vec x, PetscBool cells)
{
  struct _n_IndOutputPerm *pm = o->perm;
  const int                k  = cells ? 1 : 0;
  Vec                      y  = x; /* the rows in the file's order */
  const PetscScalar       *a;
  const char              *name;
  PetscInt                 nloc, bs;

  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(x, &nloc));
  PetscCall(VecGetBlockSize(x, &bs));
  if (pm) {
    bs = pm->n[k] ? nloc / pm->n[k] : 0;
    PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &bs, 1, MPIU_INT, MPI_MAX, PetscObjectComm((PetscObject)x)));
    PetscCheck(bs >= 1 && bs <= MAXBS, PETSC_COMM_SELF, PETSC_ERR_PLIB, "Field of %" PetscInt_FMT " values per point",
      bs);
    if (!pm->sc[k][bs]) {
      IS is;
      PetscCall(VecCreate(PetscObjectComm((PetscObject)x), &pm->out[k][bs]));
      PetscCall(VecSetBlockSize(pm->out[k][bs], bs));
      PetscCall(VecSetSizes(pm->out[k][bs], PETSC_DECIDE, bs * pm->N[k]));
      PetscCall(VecSetType(pm->out[k][bs], VECMPI));
      PetscCall(ISCreateBlock(PetscObjectComm((PetscObject)x), bs, pm->n[k], pm->index[k], PETSC_COPY_VALUES, &is));
      PetscCall(VecScatterCreate(x, NULL, pm->out[k][bs], is, &pm->sc[k][bs]));
      PetscCall(ISDestroy(&is));
    }
    y = pm->out[k][bs];
    PetscCall(VecScatterBegin(pm->sc[k][bs], x, y, INSERT_VALUES, SCATTER_FORWARD));
    PetscCall(VecScatterEnd(pm->sc[k][bs], x, y, INSERT_VALUES, SCATTER_FORWARD));
    PetscCall(VecGetLocalSize(y, &nloc));
  }
  PetscCall(PetscObjectGetName((PetscObject)x, &name));
  PetscCall(VecGetArrayRead(y, &a));
  PetscCall(IndH5WriteRows(o->viewer, name, nloc / bs, bs, a));
  PetscCall(VecRestoreArrayRead(y, &a));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndOutputPermDestroy(IndOutput o)
{
  struct _n_IndOutputPerm *pm = o->perm;

  PetscFunctionBeginUser;
  if (!pm) PetscFunctionReturn(PETSC_SUCCESS);
  for (int k = 0; k < 2; ++k) {
    PetscCall(PetscFree(pm->index[k]));
    for (int b = 0; b <= MAXBS; ++b) {
      PetscCall(VecScatterDestroy(&pm->sc[k][b]));
      PetscCall(VecDestroy(&pm->out[k][b]));
    }
  }
  PetscCall(PetscFree(o->perm));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndOutputState(void *obj, IndStateFile f)
{
  IndOutput  o = (IndOutput)obj;
  PetscInt   n = o->nsteps;
  PetscReal *times = o->times;

  PetscFunctionBeginUser;
  PetscCall(IndStateRealArray(f, "times", &n, &times));
  if (IndStateReading(f)) {
    PetscCheck(n <= IND_MAX_OUTPUT_STEPS, PetscObjectComm((PetscObject)o->dm), PETSC_ERR_FILE_UNEXPECTED,
               "The state holds %" PetscInt_FMT " output steps, more than %d", n, IND_MAX_OUTPUT_STEPS);
    if (n) PetscCall(PetscArraycpy(o->times, times, n));
    PetscCall(PetscFree(times));
    o->nsteps = n;
  }
  PetscCall(IndStateReals(f, "info", IND_OUTPUT_INFO * n, o->info));
  PetscFunctionReturn(PETSC_SUCCESS);
}
