#include "ind_pattern.h"

/* The Jacobian couples every component of a node to every component of the nodes it shares a cell with, so its
   pattern is the node graph's with each entry a dense 3 x 3 block, and J takes its rows as rows of 3 x 3 blocks.
   A dry run of the cell loop into a MATPREALLOCATOR searched a hash table for all 24 x 24 entries of every
   hexahedron: 8.3 s at 262k hexahedra, a third of the set-up; the node graph alone through it (8 x 8 per
   hexahedron) still took 2.75 s of the 1-rank set-up of sphere_800k. A row of the node graph is the union of
   the nodes of the cells about its node: the rank's own cells give it from a list of the cells of each node, and
   only the couplings a cell makes to a node another rank owns go through a MATPREALLOCATOR, to that rank. */

/* The couplings other ranks' cells give this rank's nodes: a (nodes x nodes) AIJ matrix, the rows of the rank's
   nodes holding what other ranks sent for them. */
static PetscErrorCode RemoteCouplings(const IndDiscLayout *disc, MPI_Comm comm, PetscInt nown, PetscInt rs,
  Mat *G)
{
  Mat          P;
  PetscScalar *zeros;

  PetscFunctionBeginUser;
  PetscCall(MatCreate(comm, &P));
  PetscCall(MatSetType(P, MATPREALLOCATOR));
  PetscCall(MatSetSizes(P, nown, nown, PETSC_DETERMINE, PETSC_DETERMINE));
  PetscCall(MatSetUp(P));
  PetscCall(PetscCalloc1(disc->nb, &zeros));
  for (PetscInt i = 0; i < disc->ncell; ++i) {
    const PetscInt *g = disc->gnode + i * disc->nb;
    for (PetscInt a = 0; a < disc->nb; ++a)
      if (g[a] < rs || g[a] >= rs + nown) PetscCall(MatSetValues(P, 1, &g[a], disc->nb, g, zeros, INSERT_VALUES));
  }
  PetscCall(PetscFree(zeros));
  PetscCall(MatAssemblyBegin(P, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(P, MAT_FINAL_ASSEMBLY));
  PetscCall(MatCreate(comm, G));
  PetscCall(MatSetType(*G, MATAIJ));
  PetscCall(MatSetSizes(*G, nown, nown, PETSC_DETERMINE, PETSC_DETERMINE));
  PetscCall(MatPreallocatorPreallocate(P, PETSC_TRUE, *G));
  PetscCall(MatDestroy(&P));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The rank's own cells about each of its nodes, as CSR: the cells of node n are cell[first[n] .. first[n + 1]). */
static PetscErrorCode CellsOfNodes(const IndDiscLayout *disc, PetscInt nown, PetscInt rs, PetscInt **first,
  PetscInt **cell, PetscInt *most)
{
  PetscInt *fill;

  PetscFunctionBeginUser;
  PetscCall(PetscCalloc1(nown + 1, first));
  for (PetscInt k = 0; k < disc->ncell * disc->nb; ++k)
    if (disc->gnode[k] >= rs && disc->gnode[k] < rs + nown) (*first)[disc->gnode[k] - rs + 1]++;
  *most = 0;
  for (PetscInt n = 0; n < nown; ++n) {
    *most = PetscMax(*most, (*first)[n + 1]);
    (*first)[n + 1] += (*first)[n];
  }
  PetscCall(PetscMalloc1((*first)[nown], cell));
  PetscCall(PetscMalloc1(nown, &fill));
  PetscCall(PetscArraycpy(fill, *first, nown));
  for (PetscInt k = 0; k < disc->ncell * disc->nb; ++k)
    if (disc->gnode[k] >= rs && disc->gnode[k] < rs + nown) (*cell)[fill[disc->gnode[k] - rs]++] = k / disc->nb;
  PetscCall(PetscFree(fill));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Row rs + n of the node graph into buf (sorted, each column once). */
static PetscErrorCode NodeRow(const IndDiscLayout *disc, Mat G, PetscInt rs, PetscInt n, const PetscInt first[],
  const PetscInt cell[], PetscInt *buf, PetscInt *len)
{
  const PetscInt *cols;
  PetscInt        nc, row = rs + n;

  PetscFunctionBeginUser;
  *len = 0;
  for (PetscInt k = first[n]; k < first[n + 1]; ++k) {
    PetscCall(PetscArraycpy(buf + *len, disc->gnode + cell[k] * disc->nb, disc->nb));
    *len += disc->nb;
  }
  PetscCall(MatGetRow(G, row, &nc, &cols, NULL));
  PetscCall(PetscArraycpy(buf + *len, cols, nc));
  *len += nc;
  PetscCall(MatRestoreRow(G, row, &nc, &cols, NULL));
  PetscCall(PetscSortRemoveDupsInt(len, buf));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndPatternFromCells(IndDisc space, Mat J)
{
  const IndDiscLayout *disc;
  MPI_Comm             comm = PetscObjectComm((PetscObject)J);
  Mat                  G;
  PetscInt             nlocal, nown, rs = 0, *first, *cell, most, remote = 0, *dnnz, *onnz, *buf, len;
  PetscScalar         *zeros;

  PetscFunctionBeginUser;
  PetscCall(IndDiscGetLayout(space, &disc));
  PetscCall(MatGetLocalSize(J, &nlocal, NULL));
  PetscCheck(nlocal % 3 == 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "%" PetscInt_FMT " local rows: not nodes of 3 dofs",
    nlocal);
  nown = nlocal / 3;
  PetscCallMPI(MPI_Exscan(&nown, &rs, 1, MPIU_INT, MPI_SUM, comm));
  {
    PetscMPIInt rank;
    PetscCallMPI(MPI_Comm_rank(comm, &rank));
    if (!rank) rs = 0; /* MPI_Exscan leaves rank 0's undefined */
  }
  PetscCall(RemoteCouplings(disc, comm, nown, rs, &G));
  PetscCall(CellsOfNodes(disc, nown, rs, &first, &cell, &most));
  for (PetscInt r = rs; r < rs + nown; ++r) {
    PetscInt nc;
    PetscCall(MatGetRow(G, r, &nc, NULL, NULL));
    remote = PetscMax(remote, nc);
    PetscCall(MatRestoreRow(G, r, &nc, NULL, NULL));
  }
  PetscCall(PetscMalloc1(most * disc->nb + remote, &buf));
  /* block counts per block row, in and out of the rank's diagonal block */
  PetscCall(PetscCalloc2(nown, &dnnz, nown, &onnz));
  for (PetscInt n = 0; n < nown; ++n) {
    PetscCall(NodeRow(disc, G, rs, n, first, cell, buf, &len));
    for (PetscInt k = 0; k < len; ++k) {
      if (buf[k] >= rs && buf[k] < rs + nown) dnnz[n]++;
      else onnz[n]++;
    }
  }
  PetscCall(MatXAIJSetPreallocation(J, 3, dnnz, onnz, NULL, NULL));
  PetscCall(PetscFree2(dnnz, onnz));
  /* the pattern itself, a block row at a time (no array of the whole pattern at once) */
  PetscCall(PetscCalloc1(9 * (most * disc->nb + remote), &zeros));
  for (PetscInt n = 0; n < nown; ++n) {
    const PetscInt row = rs + n;
    PetscCall(NodeRow(disc, G, rs, n, first, cell, buf, &len));
    PetscCall(MatSetValuesBlocked(J, 1, &row, len, buf, zeros, INSERT_VALUES));
  }
  PetscCall(PetscFree(zeros));
  PetscCall(PetscFree(buf));
  PetscCall(PetscFree(first));
  PetscCall(PetscFree(cell));
  PetscCall(MatDestroy(&G));
  PetscCall(MatAssemblyBegin(J, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(J, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(PETSC_SUCCESS);
}
