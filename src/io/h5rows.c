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

static PetscErrorCode WriteRows(PetscViewer v, const char name[], PetscInt n, PetscInt bs, hid_t type,
                                const void *rows)
{
  MPI_Comm  comm = PetscObjectComm((PetscObject)v);
  PetscBool timestepping, dim2, collective;
  PetscInt  step = -1, below = 0, N = 0;
  Layout    L    = {0};
  hid_t     file, group, dset, fspace, mspace, dxpl;
  htri_t    exists;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Scan(&n, &below, 1, MPIU_INT, MPI_SUM, comm));
  below -= n;
  PetscCallMPI(MPI_Allreduce(&n, &N, 1, MPIU_INT, MPI_SUM, comm));
  PetscCall(PetscViewerHDF5IsTimestepping(v, &timestepping));
  if (timestepping) PetscCall(PetscViewerHDF5GetTimestep(v, &step));
  PetscCall(PetscViewerHDF5GetBaseDimension2(v, &dim2));
  PetscCall(PetscViewerHDF5GetCollective(v, &collective));
  if (step >= 0) AddDimension(&L, (hsize_t)step + 1, H5S_UNLIMITED, 1, (hsize_t)step, 1);
  AddDimension(&L, (hsize_t)N, (hsize_t)N, (hsize_t)PetscMax(N, 1), (hsize_t)below, (hsize_t)n);
  if (bs > 1 || dim2) AddDimension(&L, (hsize_t)bs, (hsize_t)bs, (hsize_t)bs, 0, (hsize_t)bs);

  PetscCall(PetscViewerHDF5OpenGroup(v, NULL, &file, &group));
  IndCallHDF5(exists = H5Lexists(group, name, H5P_DEFAULT));
  if (!exists) {
    hid_t dcpl;
    IndCallHDF5(fspace = H5Screate_simple(L.nd, L.dims, L.maxdims));
    IndCallHDF5(dcpl = H5Pcreate(H5P_DATASET_CREATE));
    if (step >= 0) IndCallHDF5(H5Pset_chunk(dcpl, L.nd, L.chunk));
    IndCallHDF5(H5Pset_fill_time(dcpl, H5D_FILL_TIME_NEVER));
    IndCallHDF5(dset = H5Dcreate2(group, name, type, fspace, H5P_DEFAULT, dcpl, H5P_DEFAULT));
    IndCallHDF5(H5Pclose(dcpl));
    IndCallHDF5(H5Sclose(fspace));
  } else {
    IndCallHDF5(dset = H5Dopen2(group, name, H5P_DEFAULT));
    if (step >= 0) IndCallHDF5(H5Dset_extent(dset, L.dims));
  }
  IndCallHDF5(fspace = H5Dget_space(dset));
  IndCallHDF5(mspace = H5Screate_simple(L.nd, L.count, NULL));
  if (n > 0) IndCallHDF5(H5Sselect_hyperslab(fspace, H5S_SELECT_SET, L.start, NULL, L.count, NULL));
  else {
    IndCallHDF5(H5Sselect_none(fspace));
    IndCallHDF5(H5Sselect_none(mspace));
  }
  IndCallHDF5(dxpl = H5Pcreate(H5P_DATASET_XFER));
#if defined(H5_HAVE_PARALLEL)
  if (collective) IndCallHDF5(H5Pset_dxpl_mpio(dxpl, H5FD_MPIO_COLLECTIVE));
#endif
  IndCallHDF5(H5Dwrite(dset, type, mspace, fspace, dxpl, rows));
  IndCallHDF5(H5Fflush(file, H5F_SCOPE_GLOBAL));
  IndCallHDF5(H5Pclose(dxpl));
  IndCallHDF5(H5Sclose(mspace));
  IndCallHDF5(H5Sclose(fspace));
  IndCallHDF5(H5Dclose(dset));
  IndCallHDF5(H5Gclose(group));
  if (step >= 0) {
    PetscBool yes = PETSC_TRUE; /* VecLoad reads the steps of a dataset that says so */
    PetscCall(PetscViewerHDF5WriteAttribute(v, name, "timestepping", PETSC_BOOL, &yes));
  }
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
