#include "ind_h5rows.h"

#if defined(PETSC_USE_REAL_SINGLE)
  #define IND_H5_REAL H5T_NATIVE_FLOAT
#else
  #define IND_H5_REAL H5T_NATIVE_DOUBLE
#endif
#if defined(PETSC_USE_64BIT_INDICES)
  #define IND_H5_INT H5T_NATIVE_LLONG
#else
  #define IND_H5_INT H5T_NATIVE_INT
#endif

/* The dataset's dimensions, its chunk and this rank's slab: [step,] rows[, bs]. */
typedef struct {
  int     nd;
  hsize_t dims[3], maxdims[3], chunk[3], start[3], count[3];
} Layout;

static void AddDimension(Layout *L, hsize_t dim, hsize_t maxdim, hsize_t chunk, hsize_t start, hsize_t count)
{
  L->dims[L->nd]    = dim;
  L->maxdims[L->nd] = maxdim;
  L->chunk[L->nd]   = chunk;
  L->start[L->nd]   = start;
  L->count[L->nd]   = count;
  L->nd++;
}

struct _n_IndH5Rows {
  PetscViewer v;
  char        name[256];
  hid_t       type, file, group, dset, fspace;
  Layout      L;
  PetscInt    n, bs, step;
};

static PetscErrorCode RowsBegin(PetscViewer v, const char name[], PetscInt n, PetscInt bs, hid_t type, IndH5Rows *out)
{
  MPI_Comm  comm = PetscObjectComm((PetscObject)v);
  PetscBool timestepping, dim2;
  PetscInt  below = 0, N = 0;
  IndH5Rows w;
  htri_t    exists;

  PetscFunctionBeginUser;
  PetscCall(PetscNew(&w));
  w->v    = v;
  w->n    = n;
  w->bs   = bs;
  w->step = -1;
  w->type = type;
  PetscCall(PetscStrncpy(w->name, name, sizeof(w->name)));
  PetscCallMPI(MPI_Scan(&n, &below, 1, MPIU_INT, MPI_SUM, comm));
  below -= n;
  PetscCallMPI(MPI_Allreduce(&n, &N, 1, MPIU_INT, MPI_SUM, comm));
  PetscCall(PetscViewerHDF5IsTimestepping(v, &timestepping));
  if (timestepping) PetscCall(PetscViewerHDF5GetTimestep(v, &w->step));
  PetscCall(PetscViewerHDF5GetBaseDimension2(v, &dim2));
  if (w->step >= 0) AddDimension(&w->L, (hsize_t)w->step + 1, H5S_UNLIMITED, 1, (hsize_t)w->step, 1);
  AddDimension(&w->L, (hsize_t)N, (hsize_t)N, (hsize_t)PetscMax(N, 1), (hsize_t)below, (hsize_t)n);
  if (bs > 1 || dim2) AddDimension(&w->L, (hsize_t)bs, (hsize_t)bs, (hsize_t)bs, 0, (hsize_t)bs);

  PetscCall(PetscViewerHDF5OpenGroup(v, NULL, &w->file, &w->group));
  IndCallHDF5(exists = H5Lexists(w->group, name, H5P_DEFAULT));
  if (!exists) {
    hid_t dcpl;
    IndCallHDF5(w->fspace = H5Screate_simple(w->L.nd, w->L.dims, w->L.maxdims));
    IndCallHDF5(dcpl = H5Pcreate(H5P_DATASET_CREATE));
    if (w->step >= 0) IndCallHDF5(H5Pset_chunk(dcpl, w->L.nd, w->L.chunk));
    IndCallHDF5(H5Pset_fill_time(dcpl, H5D_FILL_TIME_NEVER));
    IndCallHDF5(w->dset = H5Dcreate2(w->group, name, w->type, w->fspace, H5P_DEFAULT, dcpl, H5P_DEFAULT));
    IndCallHDF5(H5Pclose(dcpl));
    IndCallHDF5(H5Sclose(w->fspace));
  } else {
    IndCallHDF5(w->dset = H5Dopen2(w->group, name, H5P_DEFAULT));
    if (w->step >= 0) IndCallHDF5(H5Dset_extent(w->dset, w->L.dims));
  }
  IndCallHDF5(w->fspace = H5Dget_space(w->dset));
  *out = w;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndH5RowsBegin(PetscViewer v, const char name[], PetscInt n, PetscInt bs, IndH5Rows *w)
{
  PetscFunctionBeginUser;
  PetscCall(RowsBegin(v, name, n, bs, IND_H5_REAL, w));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode RowsWrite(IndH5Rows w, PetscInt first, PetscInt count, const void *rows)
{
  PetscBool collective;
  Layout    part = w->L;
  const int r    = w->step >= 0 ? 1 : 0; /* the rows' dimension */
  hid_t     mspace, dxpl;

  PetscFunctionBeginUser;
  PetscCheck(first >= 0 && count >= 0 && first + count <= w->n, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE,
             "Rows %" PetscInt_FMT " to %" PetscInt_FMT " of %" PetscInt_FMT, first, first + count, w->n);
  part.start[r] += (hsize_t)first;
  part.count[r] = (hsize_t)count;
  IndCallHDF5(mspace = H5Screate_simple(part.nd, part.count, NULL));
  if (count > 0) IndCallHDF5(H5Sselect_hyperslab(w->fspace, H5S_SELECT_SET, part.start, NULL, part.count, NULL));
  else {
    IndCallHDF5(H5Sselect_none(w->fspace));
    IndCallHDF5(H5Sselect_none(mspace));
  }
  IndCallHDF5(dxpl = H5Pcreate(H5P_DATASET_XFER));
  PetscCall(PetscViewerHDF5GetCollective(w->v, &collective));
#if defined(H5_HAVE_PARALLEL)
  if (collective) IndCallHDF5(H5Pset_dxpl_mpio(dxpl, H5FD_MPIO_COLLECTIVE));
#endif
  IndCallHDF5(H5Dwrite(w->dset, w->type, mspace, w->fspace, dxpl, rows));
  IndCallHDF5(H5Pclose(dxpl));
  IndCallHDF5(H5Sclose(mspace));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndH5RowsWrite(IndH5Rows w, PetscInt first, PetscInt count, const PetscReal *rows)
{
  PetscFunctionBeginUser;
  PetscCall(RowsWrite(w, first, count, rows));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndH5RowsEnd(IndH5Rows *w)
{
  PetscFunctionBeginUser;
  if (!*w) PetscFunctionReturn(PETSC_SUCCESS);
  IndCallHDF5(H5Fflush((*w)->file, H5F_SCOPE_GLOBAL));
  IndCallHDF5(H5Sclose((*w)->fspace));
  IndCallHDF5(H5Dclose((*w)->dset));
  IndCallHDF5(H5Gclose((*w)->group));
  if ((*w)->step >= 0) {
    PetscBool yes = PETSC_TRUE; /* VecLoad reads the steps of a dataset that says so */
    PetscCall(PetscViewerHDF5WriteAttribute((*w)->v, (*w)->name, "timestepping", PETSC_BOOL, &yes));
  }
  PetscCall(PetscFree(*w));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode WriteRows(PetscViewer v, const char name[], PetscInt n, PetscInt bs, hid_t type,
                                const void *rows)
{
  IndH5Rows w;

  PetscFunctionBeginUser;
  PetscCall(RowsBegin(v, name, n, bs, type, &w));
  PetscCall(RowsWrite(w, 0, n, rows));
  PetscCall(IndH5RowsEnd(&w));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndH5WriteRows(PetscViewer v, const char name[], PetscInt n, PetscInt bs, const PetscReal *rows)
{
  PetscFunctionBeginUser;
  PetscCall(WriteRows(v, name, n, bs, IND_H5_REAL, rows));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndH5WriteIntRows(PetscViewer v, const char name[], PetscInt n, PetscInt bs, const PetscInt *rows)
{
  PetscFunctionBeginUser;
  PetscCall(WriteRows(v, name, n, bs, IND_H5_INT, rows));
  PetscFunctionReturn(PETSC_SUCCESS);
}
