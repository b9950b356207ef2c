#include <errno.h>
#include <stdio.h>
#include <string.h>
#include "xdmf.h"
#include "ind_h5rows.h"

#if !H5_VERSION_GE(1, 10, 0)
  #error "indent's XDMF index needs HDF5 >= 1.10 (virtual datasets)"
#endif

/* One virtual dataset: the whole of it is the slab [k, :, :] of the source. */
static PetscErrorCode AddView(hid_t file, hid_t group, PetscInt k, const IndXdmfField *f)
{
  char    src[PETSC_MAX_PATH_LEN];
  hid_t   dset, sspace, vspace, type, dcpl, view;
  hsize_t dims[3], start[3], count[3];
  int     ndims;

  PetscFunctionBeginUser;
  PetscCall(PetscSNPrintf(src, sizeof(src), "/fields/%s", f->name));
  IndCallHDF5(dset = H5Dopen2(file, src, H5P_DEFAULT));
  IndCallHDF5(sspace = H5Dget_space(dset));
  IndCallHDF5(ndims = H5Sget_simple_extent_dims(sspace, dims, NULL));
  PetscCheck(ndims == 3 && dims[0] > (hsize_t)k && dims[2] == (hsize_t)f->bs, PETSC_COMM_SELF, PETSC_ERR_PLIB,
             "%s is not a (steps > %" PetscInt_FMT ", n, %" PetscInt_FMT ") dataset", src, k, f->bs);
  IndCallHDF5(type = H5Dget_type(dset));
  start[0] = (hsize_t)k;
  start[1] = start[2] = 0;
  count[0] = 1;
  count[1] = dims[1];
  count[2] = dims[2];
  IndCallHDF5(H5Sselect_hyperslab(sspace, H5S_SELECT_SET, start, NULL, count, NULL));
  IndCallHDF5(vspace = H5Screate_simple(2, dims + 1, NULL));
  IndCallHDF5(dcpl = H5Pcreate(H5P_DATASET_CREATE));
  /* "." is the file holding the virtual dataset itself, so the file can be moved or renamed. */
  IndCallHDF5(H5Pset_virtual(dcpl, vspace, ".", src, sspace));
  IndCallHDF5(view = H5Dcreate2(group, f->name, type, vspace, H5P_DEFAULT, dcpl, H5P_DEFAULT));
  IndCallHDF5(H5Dclose(view));
  IndCallHDF5(H5Pclose(dcpl));
  IndCallHDF5(H5Sclose(vspace));
  IndCallHDF5(H5Tclose(type));
  IndCallHDF5(H5Sclose(sspace));
  IndCallHDF5(H5Dclose(dset));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndXdmfAddStepViews(PetscViewer viewer, PetscInt k, PetscInt nfields, const IndXdmfField fields[])
{
  hid_t  file, lcpl, group;
  htri_t exists;
  char   name[64];

  PetscFunctionBeginUser;
  PetscCall(PetscViewerHDF5GetFileId(viewer, &file));
  PetscCall(PetscSNPrintf(name, sizeof(name), "/xdmf/%" PetscInt_FMT, k));
  /* A restarted run writes again the steps after its checkpoint. */
  IndCallHDF5(exists = H5Lexists(file, "/xdmf", H5P_DEFAULT));
  if (exists) IndCallHDF5(exists = H5Lexists(file, name, H5P_DEFAULT));
  if (exists) IndCallHDF5(H5Ldelete(file, name, H5P_DEFAULT));
  IndCallHDF5(lcpl = H5Pcreate(H5P_LINK_CREATE));
  IndCallHDF5(H5Pset_create_intermediate_group(lcpl, 1));
  IndCallHDF5(group = H5Gcreate2(file, name, lcpl, H5P_DEFAULT, H5P_DEFAULT));
  for (PetscInt f = 0; f < nfields; ++f) PetscCall(AddView(file, group, k, &fields[f]));
  IndCallHDF5(H5Gclose(group));
  IndCallHDF5(H5Pclose(lcpl));
  PetscCall(PetscViewerFlush(viewer));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static void WriteInformation(FILE *fp, const char *name, PetscReal value)
{
  if (!PetscIsNanReal(value)) fprintf(fp, "<Information Name=\"%s\" Value=\"%.12g\"/>\n", name, (double)value);
}

/* The whole dataset dset of the HDF5 file h5: rows x cols numbers of the given type and bytes. */
static void WriteHDFItem(FILE *fp, const char *type, int bytes, PetscInt rows, PetscInt cols, const char *h5,
                         const char *dset)
{
  fprintf(fp, "<DataItem Format=\"HDF\" NumberType=\"%s\" Precision=\"%d\" ", type, bytes);
  fprintf(fp, "Dimensions=\"%" PetscInt_FMT " %" PetscInt_FMT "\">%s:%s</DataItem>\n", rows, cols, h5, dset);
}

static void WriteStepGrid(FILE *fp, const IndXdmfMesh *m, PetscInt nfields, const IndXdmfField fields[], PetscInt k,
                          const IndXdmfStep *s)
{
  char dset[PETSC_MAX_PATH_LEN];

  /* Named by output step, the index of /xdmf and of the first axis of /fields; "step" is the load step.
     Times to 15 digits: adaptive steps may be closer than 1e-10 apart and must stay distinct. */
  fprintf(fp, "<Grid Name=\"output %" PetscInt_FMT "\" GridType=\"Uniform\">\n", k);
  fprintf(fp, "<Time Value=\"%.15g\"/>\n", (double)s->t);
  if (s->step >= 0) fprintf(fp, "<Information Name=\"step\" Value=\"%" PetscInt_FMT "\"/>\n", s->step);
  WriteInformation(fp, "load_factor", s->lambda);
  WriteInformation(fp, "depth_nm", s->depth);
  WriteInformation(fp, "load_uN", s->load);
  fprintf(fp, "<Topology TopologyType=\"%s\" NumberOfElements=\"%" PetscInt_FMT "\">\n",
          m->topology, m->ncell);
  WriteHDFItem(fp, "Int", (int)sizeof(PetscInt), m->ncell, m->corners, m->h5name, "/topology/cells");
  fprintf(fp, "</Topology>\n<Geometry GeometryType=\"XYZ\">\n");
  WriteHDFItem(fp, "Float", (int)sizeof(PetscReal), m->nvert, 3, m->h5name, "/geometry/vertices");
  fprintf(fp, "</Geometry>\n");
  for (PetscInt f = 0; f < nfields; ++f) {
    const IndXdmfField *a = &fields[f];

    fprintf(fp, "<Attribute Name=\"%s\" AttributeType=\"%s\" Center=\"%s\">\n", a->name, a->type,
            a->cells ? "Cell" : "Node");
    (void)PetscSNPrintf(dset, sizeof(dset), "/xdmf/%" PetscInt_FMT "/%s", k, a->name);
    WriteHDFItem(fp, "Float", (int)sizeof(PetscScalar), a->cells ? m->ncell : m->nvert, a->bs, m->h5name, dset);
    fprintf(fp, "</Attribute>\n");
  }
  fprintf(fp, "</Grid>\n");
}

PetscErrorCode IndXdmfWrite(MPI_Comm comm, const char path[], const IndXdmfMesh *mesh, PetscInt nfields,
                            const IndXdmfField fields[], PetscInt nsteps, const IndXdmfStep steps[])
{
  PetscMPIInt rank;
  char        tmp[PETSC_MAX_PATH_LEN];
  FILE       *fp;
  int         failed;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscSNPrintf(tmp, sizeof(tmp), "%s.tmp", path));
  fp = fopen(tmp, "w");
  PetscCheck(fp, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "Cannot write '%s' (-output_dir): %s", tmp,
             strerror(errno));
  fprintf(fp, "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n<Domain>\n");
  fprintf(fp, "<Information Name=\"time\" Value=\"pseudo-time of the load program: 0 to 1 loading, then the hold, then "
              "unloading\"/>\n");
  fprintf(fp, "<Grid Name=\"steps\" GridType=\"Collection\" CollectionType=\"Temporal\">\n");
  for (PetscInt k = 0; k < nsteps; ++k) WriteStepGrid(fp, mesh, nfields, fields, k, &steps[k]);
  fprintf(fp, "</Grid>\n</Domain>\n</Xdmf>\n");
  failed = ferror(fp);
  failed = fclose(fp) || failed;
  PetscCheck(!failed, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "Error writing '%s'", tmp);
  PetscCheck(rename(tmp, path) == 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "Cannot rename '%s' to '%s': %s", tmp, path,
             strerror(errno));
  PetscFunctionReturn(PETSC_SUCCESS);
}
