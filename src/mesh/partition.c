#include "mesh_impl.h"
#if defined(INDENT_HAVE_METIS)
  #include <metis.h>
#endif

#if defined(INDENT_HAVE_METIS)
/* The mesh is still serial here (read on rank 0), so METIS runs on rank 0 and hands its answer to
   PETSc's shell partitioner; Debian's PETSc has no ParMETIS. */
static PetscErrorCode SetMetisPartition(DM dm, PetscPartitioner part)
{
  MPI_Comm    comm = PetscObjectComm((PetscObject)dm);
  PetscMPIInt size;
  PetscInt    nv, *offsets = NULL, *adjacency = NULL, *sizes, *points;
  IS          numbering;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCall(DMPlexCreatePartitionerGraph(dm, 0, &nv, &offsets, &adjacency, &numbering));
  PetscCall(PetscCalloc1(size, &sizes));
  PetscCall(PetscMalloc1(nv, &points));
  if (nv > 0) {
    idx_t  n = (idx_t)nv, ncon = 1, nparts = (idx_t)size, objval, *xadj, *adj, *where, opts[METIS_NOPTIONS];
    PetscInt *fill;
    PetscCall(PetscMalloc4(nv + 1, &xadj, offsets[nv], &adj, nv, &where, size, &fill));
    for (PetscInt i = 0; i <= nv; ++i) xadj[i] = (idx_t)offsets[i];
    for (PetscInt i = 0; i < offsets[nv]; ++i) adj[i] = (idx_t)adjacency[i];
    METIS_SetDefaultOptions(opts);
    opts[METIS_OPTION_SEED]    = 1; /* same partition every run */
    opts[METIS_OPTION_NUMBERING] = 0;
    if (size > 1) {
      int status = METIS_PartGraphKway(&n, &ncon, xadj, adj, NULL, NULL, NULL, &nparts, NULL, NULL, opts, &objval,
        where);
      PetscCheck(status == METIS_OK, PETSC_COMM_SELF, PETSC_ERR_LIB, "METIS_PartGraphKway failed with status %d",
        status);
    } else
      for (PetscInt i = 0; i < nv; ++i) where[i] = 0;
    for (PetscInt i = 0; i < nv; ++i) sizes[where[i]]++;
    fill[0] = 0;
    for (PetscMPIInt r = 1; r < size; ++r) fill[r] = fill[r - 1] + sizes[r - 1];
    for (PetscInt i = 0; i < nv; ++i) points[fill[where[i]]++] = i;
    PetscCall(PetscFree4(xadj, adj, where, fill));
  }
  PetscCall(PetscPartitionerSetType(part, PETSCPARTITIONERSHELL));
  PetscCall(PetscPartitionerShellSetPartition(part, size, sizes, points));
  PetscCall(PetscFree(sizes));
  PetscCall(PetscFree(points));
  PetscCall(PetscFree(offsets));
  PetscCall(PetscFree(adjacency));
  PetscCall(ISDestroy(&numbering));
  PetscFunctionReturn(PETSC_SUCCESS);
}
#endif

PetscErrorCode IndMeshGetPartitionerType(MPI_Comm comm, PetscBool box, IndPartitionerType *type)
{
  const char *types[] = {"ptscotch", "metis", "simple", "blocks"};
  PetscInt    choice  = box ? IND_PARTITIONER_BLOCKS : IND_PARTITIONER_PTSCOTCH;

  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, NULL, IND_TITLE "Mesh partitioning", "Mesh");
  PetscCall(IndOptionsEList("-mesh_partitioner",
    "How the cells go to the ranks: a graph partitioner of the mesh made on rank 0 (from -mesh_file, or the box), "
    "or blocks: the box built on every rank at once (the box's default)", types, 4, choice, &choice, NULL));
  PetscOptionsEnd();
  PetscCheck(box || choice != IND_PARTITIONER_BLOCKS, comm, PETSC_ERR_ARG_WRONG,
    "-mesh_partitioner blocks is for the built-in box; a mesh read from -mesh_file needs ptscotch, metis or simple");
#if !defined(INDENT_HAVE_METIS)
  PetscCheck(choice != IND_PARTITIONER_METIS, comm, PETSC_ERR_SUP,
    "-mesh_partitioner metis: this indent was built without METIS (install libmetis-dev and reconfigure)");
#endif
  *type = (IndPartitionerType)choice;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndMeshSetPartitioner(DM dm, IndPartitionerType type)
{
  PetscPartitioner part;

  PetscFunctionBeginUser;
  PetscCall(DMPlexGetPartitioner(dm, &part));
  switch (type) {
  case IND_PARTITIONER_PTSCOTCH:
    PetscCall(PetscPartitionerSetType(part, PETSCPARTITIONERPTSCOTCH));
    break;
  case IND_PARTITIONER_METIS:
#if defined(INDENT_HAVE_METIS)
    PetscCall(SetMetisPartition(dm, part));
#endif
    break;
  case IND_PARTITIONER_SIMPLE:
    PetscCall(PetscPartitionerSetType(part, PETSCPARTITIONERSIMPLE));
    break;
  default:
    SETERRQ(PetscObjectComm((PetscObject)dm), PETSC_ERR_PLIB, "a box built in blocks is not partitioned again");
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}
