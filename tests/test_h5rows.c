static const char help[] = "Rows written straight to HDF5 are read back by PETSc's VecLoad in PETSc's layout, on\n"
                           "any rank count, fixed and by timestep, and their chunks are never filled.\n";

#include <petscvec.h>
#include "ind_h5rows.h"
#include "unit_report.h"

/* Value k of global row i of a dataset (step s). */
static PetscReal Value(PetscInt i, PetscInt k, PetscInt s)
{
  return 0.5 * (PetscReal)i + 0.01 * (PetscReal)k + 100.0 * (PetscReal)s + 1.0;
}

/* Rows of uneven sizes; on 2 or more ranks rank 1 has none. */
static PetscInt LocalRows(PetscMPIInt rank)
{
  return rank == 1 ? 0 : 3 + 2 * rank;
}

static PetscErrorCode WriteStep(PetscViewer v, const char name[], PetscInt bs, PetscInt s, PetscInt below)
{
  PetscMPIInt rank;
  PetscInt    n;
  PetscReal  *rows;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(PETSC_COMM_WORLD, &rank));
  n = LocalRows(rank);
  PetscCall(PetscMalloc1(n * bs + 1, &rows));
  for (PetscInt i = 0; i < n; ++i)
    for (PetscInt k = 0; k < bs; ++k) rows[i * bs + k] = Value(below + i, k, s);
  PetscCall(IndH5WriteRows(v, name, n, bs, rows));
  PetscCall(PetscFree(rows));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The largest difference of a dataset read by VecLoad (step s, or none) from the values written. */
static PetscErrorCode ReadBack(PetscViewer v, const char name[], PetscInt bs, PetscInt s, PetscReal *worst)
{
  Vec                x;
  const PetscScalar *a;
  PetscInt           lo, hi;

  PetscFunctionBeginUser;
  PetscCall(VecCreate(PETSC_COMM_WORLD, &x));
  PetscCall(VecSetBlockSize(x, bs));
  PetscCall(PetscObjectSetName((PetscObject)x, name));
  if (s >= 0) PetscCall(PetscViewerHDF5SetTimestep(v, s));
  PetscCall(VecLoad(x, v));
  PetscCall(VecGetOwnershipRange(x, &lo, &hi));
  PetscCall(VecGetArrayRead(x, &a));
  *worst = 0;
  for (PetscInt j = lo; j < hi; ++j)
    *worst = PetscMax(*worst, PetscAbsReal(a[j - lo] - Value(j / bs, j % bs, PetscMax(s, 0))));
  PetscCall(VecRestoreArrayRead(x, &a));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, worst, 1, MPIU_REAL, MPIU_MAX, PETSC_COMM_WORLD));
  PetscCall(VecDestroy(&x));
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  char        file[PETSC_MAX_PATH_LEN] = "h5rows.h5";
  PetscViewer v;
  PetscMPIInt rank, size;
  PetscInt    below = 0, N = 0, n;
  PetscReal   worst;

  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  PetscCall(PetscOptionsGetString(NULL, NULL, "-h5rows_file", file, sizeof(file), NULL));
  PetscCallMPI(MPI_Comm_rank(PETSC_COMM_WORLD, &rank));
  PetscCallMPI(MPI_Comm_size(PETSC_COMM_WORLD, &size));
  for (PetscMPIInt r = 0; r < size; ++r) {
    if (r < rank) below += LocalRows(r);
    N += LocalRows(r);
  }
  n = LocalRows(rank);

  PetscCall(PetscViewerHDF5Open(PETSC_COMM_WORLD, file, FILE_MODE_WRITE, &v));
  PetscCall(PetscViewerHDF5PushGroup(v, "/fixed"));
  PetscCall(WriteStep(v, "rows", 4, 0, below));
  PetscCall(WriteStep(v, "single", 1, 0, below));
  {
    PetscInt *ints;
    PetscCall(PetscMalloc1(2 * n + 1, &ints));
    for (PetscInt i = 0; i < 2 * n; ++i) ints[i] = 2 * below + i;
    PetscCall(IndH5WriteIntRows(v, "ints", n, 2, ints));
    PetscCall(PetscFree(ints));
  }
  PetscCall(PetscViewerHDF5PopGroup(v));
  PetscCall(PetscViewerHDF5SetBaseDimension2(v, PETSC_TRUE));
  PetscCall(PetscViewerHDF5PushGroup(v, "/steps"));
  PetscCall(PetscViewerHDF5PushTimestepping(v));
  for (PetscInt s = 0; s < 3; ++s) {
    PetscCall(PetscViewerHDF5SetTimestep(v, s));
    PetscCall(WriteStep(v, "field", 3, s, below));
  }
  PetscCall(PetscViewerHDF5PopTimestepping(v));
  PetscCall(PetscViewerHDF5PopGroup(v));
  PetscCall(PetscViewerDestroy(&v));

  PetscCall(PetscViewerHDF5Open(PETSC_COMM_WORLD, file, FILE_MODE_READ, &v));
  PetscCall(PetscViewerHDF5PushGroup(v, "/fixed"));
  PetscCall(ReadBack(v, "rows", 4, -1, &worst));
  if (!rank) Report("fixed rows of 4, read by VecLoad", worst, 0);
  PetscCall(ReadBack(v, "single", 1, -1, &worst));
  if (!rank) Report("fixed rows of 1, read by VecLoad", worst, 0);
  PetscCall(PetscViewerHDF5PopGroup(v));
  PetscCall(PetscViewerHDF5SetBaseDimension2(v, PETSC_TRUE));
  PetscCall(PetscViewerHDF5PushGroup(v, "/steps"));
  PetscCall(PetscViewerHDF5PushTimestepping(v));
  for (PetscInt s = 0; s < 3; ++s) {
    PetscCall(ReadBack(v, "field", 3, s, &worst));
    if (!rank) Report("step of an extensible field, read by VecLoad", worst, 0);
  }
  PetscCall(PetscViewerHDF5PopTimestepping(v));
  PetscCall(PetscViewerHDF5PopGroup(v));
  PetscCall(PetscViewerDestroy(&v));

  /* The layout itself, read on rank 0 with HDF5 */
  if (!rank) {
    hid_t   f, d, sp, dcpl;
    hsize_t dims[3], chunk[3];
    int     nd;
    H5D_fill_time_t fill;
    PetscInt       *ints;

    IndCallHDF5(f = H5Fopen(file, H5F_ACC_RDONLY, H5P_DEFAULT));
    IndCallHDF5(d = H5Dopen2(f, "/steps/field", H5P_DEFAULT));
    IndCallHDF5(sp = H5Dget_space(d));
    IndCallHDF5(nd = H5Sget_simple_extent_dims(sp, dims, NULL));
    Report("field's dimensions are (steps, rows, 3)", (PetscReal)(nd != 3 || dims[0] != 3 || dims[1] != (hsize_t)N ||
           dims[2] != 3), 0);
    IndCallHDF5(dcpl = H5Dget_create_plist(d));
    IndCallHDF5(nd = H5Pget_chunk(dcpl, 3, chunk));
    Report("field's chunk is one step", (PetscReal)(nd != 3 || chunk[0] != 1 || chunk[1] != (hsize_t)N), 0);
    IndCallHDF5(H5Pget_fill_time(dcpl, &fill));
    Report("field's chunks are never filled", (PetscReal)(fill != H5D_FILL_TIME_NEVER), 0);
    IndCallHDF5(H5Pclose(dcpl));
    IndCallHDF5(H5Sclose(sp));
    IndCallHDF5(H5Dclose(d));
    IndCallHDF5(d = H5Dopen2(f, "/fixed/single", H5P_DEFAULT));
    IndCallHDF5(sp = H5Dget_space(d));
    IndCallHDF5(nd = H5Sget_simple_extent_dims(sp, dims, NULL));
    Report("rows of 1 without base dimension 2 are one-dimensional", (PetscReal)(nd != 1 || dims[0] != (hsize_t)N), 0);
    IndCallHDF5(H5Sclose(sp));
    IndCallHDF5(H5Dclose(d));
    PetscCall(PetscMalloc1(2 * N + 1, &ints));
    IndCallHDF5(d = H5Dopen2(f, "/fixed/ints", H5P_DEFAULT));
    IndCallHDF5(H5Dread(d, sizeof(PetscInt) == 8 ? H5T_NATIVE_LLONG : H5T_NATIVE_INT, H5S_ALL, H5S_ALL, H5P_DEFAULT,
                        ints));
    worst = 0;
    for (PetscInt i = 0; i < 2 * N; ++i) worst = PetscMax(worst, PetscAbsReal((PetscReal)(ints[i] - i)));
    Report("integer rows in order of the ranks", worst, 0);
    IndCallHDF5(H5Dclose(d));
    IndCallHDF5(H5Fclose(f));
    PetscCall(PetscFree(ints));
  }
  PetscCall(PetscFinalize());
  return failures ? 1 : 0;
}
