#include <math.h>
#include <stdint.h>
#include <petscsf.h>
#include "mesh_impl.h"

/* The built-in box, made on every rank at once: each rank builds the block of cells it will own, so no rank
   makes the whole mesh, no graph is partitioned and nothing is migrated. (Made on rank 0 and distributed, the
   box of 63^3 cells took 2.9 s of a 2-rank run's 6.3 s set-up: the partitioner and DMPlexDistribute.)

   The ranks form a grid px x py x pz over the cells; each axis's cells are split as evenly as integers allow.
   Each rank makes its block with PETSc's own hexahedral box on itself alone (cells in lexicographic order, x
   fastest: neighbours stay close in memory, as the reverse Cuthill-McKee order of a mesh read from a file does),
   copies it into a mesh on the communicator (on one rank the box is PETSc's box itself), and the points on the
   planes between blocks are joined by the point SF, matched by position. A point belongs to the block of the cell
   whose lowest corner it lies on (clamped to the last cell along each axis), which always holds it. (Built from a
   list of cells, the interpolation of faces and edges alone took 1.7 s a rank on the 2-rank box of 63^3 cells;
   PETSc's box makes them directly.) */

typedef struct {
  PetscInt  grid[3];        /* ranks along x, y, z */
  PetscInt  n[3];           /* cells along x, y, z */
  PetscInt *cellStart[3];   /* per axis: first cell of each block, and n[d] at the end (grid[d] + 1 entries) */
  PetscInt *planeOwner[3];  /* per axis: the block owning each of the n[d] + 1 vertex planes */
} BoxLayout;

/* The work of the busiest rank for a grid g over n cells: the cells of the largest block, plus the faces it shares
   with its neighbours (as many as an interior block has), one each: its own work and what it exchanges. */
static PetscInt64 GridCost(const PetscInt n[3], const PetscInt g[3])
{
  PetscInt64 c[3], cost;
  for (int d = 0; d < 3; ++d) c[d] = (n[d] + g[d] - 1) / g[d];
  cost = c[0] * c[1] * c[2];
  for (int d = 0; d < 3; ++d) cost += (g[d] > 2 ? 2 : g[d] - 1) * c[(d + 1) % 3] * c[(d + 2) % 3];
  return cost;
}

PetscErrorCode IndBoxChooseGrid(PetscMPIInt size, const PetscInt faces[3], PetscInt grid[3])
{
  PetscInt64 best = INT64_MAX;

  PetscFunctionBeginUser;
  PetscCheck(size > 0, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "A grid of ranks needs at least one rank");
  /* On a tie z is cut first, then y: a block of whole z layers is a contiguous range of the box's lexicographic
     order. */
  for (PetscInt pz = size; pz >= 1; --pz) {
    if (size % pz) continue;
    for (PetscInt py = size / pz; py >= 1; --py) {
      const PetscInt g[3] = {size / pz / py, py, pz};
      PetscInt64     cost;
      if ((size / pz) % py) continue;
      cost = GridCost(faces, g);
      if (cost < best) {
        best = cost;
        for (int d = 0; d < 3; ++d) grid[d] = g[d];
      }
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscInt RankOfBlock(const BoxLayout *L, const PetscInt b[3])
{
  return b[0] + L->grid[0] * (b[1] + L->grid[1] * b[2]);
}

static PetscErrorCode BoxLayoutCreate(PetscMPIInt size, const PetscInt faces[3], BoxLayout *L)
{
  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(L, sizeof(*L)));
  PetscCall(IndBoxChooseGrid(size, faces, L->grid));
  for (int d = 0; d < 3; ++d) {
    L->n[d] = faces[d];
    PetscCall(PetscMalloc2(L->grid[d] + 1, &L->cellStart[d], faces[d] + 1, &L->planeOwner[d]));
    for (PetscInt b = 0; b <= L->grid[d]; ++b) L->cellStart[d][b] = (PetscInt)((PetscInt64)b * faces[d] / L->grid[d]);
    /* plane i is the lowest of cell i, and the last plane the highest of the last cell */
    for (PetscInt b = 0; b < L->grid[d]; ++b)
      for (PetscInt c = L->cellStart[d][b]; c < L->cellStart[d][b + 1]; ++c) L->planeOwner[d][c] = b;
    L->planeOwner[d][faces[d]] = L->planeOwner[d][faces[d] - 1];
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode BoxLayoutDestroy(BoxLayout *L)
{
  PetscFunctionBeginUser;
  for (int d = 0; d < 3; ++d) PetscCall(PetscFree2(L->cellStart[d], L->planeOwner[d]));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The lattice index of every vertex of dm, on a lattice from lo with spacing h: idx[3 (v - vStart) + d]. */
static PetscErrorCode VertexLattice(DM dm, const PetscReal lo[3], const PetscReal h[3], PetscInt idx[])
{
  PetscInt           vStart, vEnd;
  Vec                X;
  PetscSection       cs;
  const PetscScalar *x;

  PetscFunctionBeginUser;
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
  PetscCall(DMGetCoordinatesLocal(dm, &X));
  PetscCall(DMGetCoordinateSection(dm, &cs));
  PetscCall(VecGetArrayRead(X, &x));
  for (PetscInt v = vStart; v < vEnd; ++v) {
    PetscInt o;
    PetscCall(PetscSectionGetOffset(cs, v, &o));
    for (int d = 0; d < 3; ++d)
      idx[3 * (v - vStart) + d] = (PetscInt)round((double)((PetscRealPart(x[o + d]) - lo[d]) / h[d]));
  }
  PetscCall(VecRestoreArrayRead(X, &x));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The block of cells [c0, c1) made by PETSc's box on this rank alone, copied into a mesh on comm (the same points,
   cones and orientations), its vertices at the whole box's lattice coordinates. On one rank the block is the box,
   made on comm at once. */
static PetscErrorCode CreateBlock(MPI_Comm comm, const PetscInt c0[3], const PetscInt c1[3], const PetscInt n[3],
  const PetscReal lower[3], const PetscReal upper[3], DM *dm)
{
  DM           blk;
  PetscMPIInt  size;
  PetscInt     numPoints[4] = {0, 0, 0, 0}, pStart = 0, pEnd = 0, vStart = 0, vEnd = 0, nb[3], off = 0;
  PetscInt    *coneSize = NULL, *cones = NULL, *orients = NULL, *lattice = NULL;
  PetscScalar *coords = NULL;
  PetscReal    lo[3], hi[3], h[3];

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  if (size == 1) {
    PetscCall(DMPlexCreateBoxMesh(comm, 3, PETSC_FALSE, n, lower, upper, NULL, PETSC_TRUE, dm));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  for (int d = 0; d < 3; ++d) {
    nb[d] = c1[d] - c0[d];
    h[d]  = (upper[d] - lower[d]) / n[d];
    lo[d] = lower[d] + h[d] * c0[d];
    hi[d] = lower[d] + h[d] * c1[d];
  }
  PetscCall(DMCreate(comm, dm));
  PetscCall(DMSetType(*dm, DMPLEX));
  PetscCall(DMSetDimension(*dm, 3));
  if (!nb[0] || !nb[1] || !nb[2]) { /* a rank without cells */
    PetscCall(DMPlexCreateFromDAG(*dm, 3, numPoints, NULL, NULL, NULL, NULL));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(DMPlexCreateBoxMesh(PETSC_COMM_SELF, 3, PETSC_FALSE, nb, lo, hi, NULL, PETSC_TRUE, &blk));
  PetscCall(DMPlexGetChart(blk, &pStart, &pEnd));
  PetscCheck(pStart == 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "PETSc's box starts its chart at %" PetscInt_FMT, pStart);
  for (PetscInt d = 0; d < 4; ++d) {
    PetscInt s, e;
    PetscCall(DMPlexGetDepthStratum(blk, d, &s, &e));
    numPoints[d] = e - s;
    if (!d) vStart = s, vEnd = e;
  }
  PetscCall(PetscMalloc1(pEnd, &coneSize));
  for (PetscInt p = 0; p < pEnd; ++p) {
    PetscCall(DMPlexGetConeSize(blk, p, &coneSize[p]));
    off += coneSize[p];
  }
  PetscCall(PetscMalloc4(off, &cones, off, &orients, 3 * (vEnd - vStart), &coords, 3 * (vEnd - vStart), &lattice));
  off = 0;
  for (PetscInt p = 0; p < pEnd; ++p) {
    const PetscInt *cone, *ornt;
    PetscCall(DMPlexGetCone(blk, p, &cone));
    PetscCall(DMPlexGetConeOrientation(blk, p, &ornt));
    for (PetscInt k = 0; k < coneSize[p]; ++k, ++off) {
      cones[off]   = cone[k];
      orients[off] = ornt[k];
    }
  }
  /* the coordinates by the formula of PETSc's box of the whole: the same to the bit */
  PetscCall(VertexLattice(blk, lo, h, lattice));
  for (PetscInt v = 0; v < vEnd - vStart; ++v)
    for (int d = 0; d < 3; ++d)
      coords[3 * v + d] = lower[d] + ((upper[d] - lower[d]) / n[d]) * (c0[d] + lattice[3 * v + d]);
  PetscCall(DMDestroy(&blk));
  PetscCall(DMPlexCreateFromDAG(*dm, 3, numPoints, coneSize, cones, orients, coords));
  PetscCall(PetscFree4(cones, orients, coords, lattice));
  PetscCall(PetscFree(coneSize));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* pos[3 p], the position of point p (but cells, -1) in half cells: a vertex (2i, 2j, 2k), an edge's midpoint one odd
   coordinate, a face's centre two. Vertices from their lattice coordinates, edges from their vertices, faces from
   their edges (the mean of four midpoints). */
static PetscErrorCode PointPositions(DM dm, const PetscInt n[3], const PetscReal lower[3], const PetscReal upper[3],
  PetscInt **pos)
{
  PetscInt  pStart, pEnd, vStart, vEnd;
  PetscReal h[3];

  PetscFunctionBeginUser;
  PetscCall(DMPlexGetChart(dm, &pStart, &pEnd));
  PetscCheck(pStart == 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "the box's chart starts at %" PetscInt_FMT, pStart);
  PetscCall(PetscMalloc1(3 * pEnd, pos));
  for (PetscInt k = 0; k < 3 * pEnd; ++k) (*pos)[k] = -1;
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
  for (int d = 0; d < 3; ++d) h[d] = (upper[d] - lower[d]) / n[d];
  PetscCall(VertexLattice(dm, lower, h, *pos + 3 * vStart));
  for (PetscInt k = 3 * vStart; k < 3 * vEnd; ++k) (*pos)[k] *= 2;
  for (PetscInt depth = 1; depth <= 2; ++depth) {
    PetscInt s, e;
    PetscCall(DMPlexGetDepthStratum(dm, depth, &s, &e));
    for (PetscInt p = s; p < e; ++p) {
      const PetscInt *cone;
      PetscInt        nc, sum[3] = {0, 0, 0};
      PetscCall(DMPlexGetConeSize(dm, p, &nc));
      PetscCall(DMPlexGetCone(dm, p, &cone));
      for (PetscInt k = 0; k < nc; ++k)
        for (int d = 0; d < 3; ++d) sum[d] += (*pos)[3 * cone[k] + d];
      for (int d = 0; d < 3; ++d) (*pos)[3 * p + d] = sum[d] / nc;
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The point SF: every point on a plane between this block and another (a vertex, edge or face there is made by
   each block that touches it) is matched by its position with the block that owns it. */
static PetscErrorCode JoinBlocks(DM dm, const BoxLayout *L, PetscMPIInt rank, const PetscInt c0[3],
  const PetscInt c1[3], const PetscInt pos[])
{
  MPI_Comm           comm = PetscObjectComm((PetscObject)dm);
  const PetscInt64   side[3] = {2 * L->n[0] + 1, 2 * L->n[1] + 1, 2 * L->n[2] + 1};
  PetscInt           pStart, pEnd, cStart, cEnd, nroots = 0, nleaves = 0, *rkey, *rpt, *lkey, *lpt, nmatched;
  const PetscInt    *ilocal;
  const PetscSFNode *iremote;
  PetscInt          *leaves;
  PetscSFNode       *remotes;
  PetscLayout        layout;
  PetscSF            matched, sf;

  PetscFunctionBeginUser;
  PetscCheck(side[0] * side[1] * side[2] <= PETSC_MAX_INT, comm, PETSC_ERR_ARG_OUTOFRANGE,
    "-dm_plex_box_faces %" PetscInt_FMT ",%" PetscInt_FMT ",%" PetscInt_FMT " is too large for this PETSc's 32-bit "
    "indices (build PETSc with --with-64-bit-indices)", L->n[0], L->n[1], L->n[2]);
  PetscCall(DMPlexGetChart(dm, &pStart, &pEnd));
  PetscCall(DMPlexGetHeightStratum(dm, 0, &cStart, &cEnd));
  PetscCall(PetscMalloc4(pEnd - pStart, &rkey, pEnd - pStart, &rpt, pEnd - pStart, &lkey, pEnd - pStart, &lpt));
  for (PetscInt p = pStart; p < pEnd; ++p) {
    const PetscInt *X = &pos[3 * p];
    PetscBool       shared = PETSC_FALSE;
    PetscInt        owner[3], key;
    if (p >= cStart && p < cEnd) continue;
    for (int d = 0; d < 3; ++d)
      if (X[d] % 2 == 0 && ((X[d] / 2 == c0[d] && c0[d] > 0) || (X[d] / 2 == c1[d] && c1[d] < L->n[d])))
        shared = PETSC_TRUE;
    if (!shared) continue;
    for (int d = 0; d < 3; ++d) owner[d] = L->planeOwner[d][X[d] / 2];
    key = (PetscInt)(X[0] + side[0] * (X[1] + side[1] * X[2]));
    if (RankOfBlock(L, owner) == rank) {
      rkey[nroots]  = key;
      rpt[nroots++] = p;
    } else {
      lkey[nleaves]  = key;
      lpt[nleaves++] = p;
    }
  }
  PetscCall(PetscLayoutCreate(comm, &layout));
  PetscCall(PetscLayoutSetSize(layout, (PetscInt)(side[0] * side[1] * side[2])));
  PetscCall(PetscLayoutSetUp(layout));
  PetscCall(PetscSFCreateByMatchingIndices(layout, nroots, rkey, rpt, 0, nleaves, lkey, lpt, 0, NULL, &matched));
  PetscCall(PetscLayoutDestroy(&layout));
  PetscCall(PetscFree4(rkey, rpt, lkey, lpt));
  /* the same graph over the whole chart (the matching's root space ends at its last root) */
  PetscCall(PetscSFGetGraph(matched, NULL, &nmatched, &ilocal, &iremote));
  PetscCall(PetscMalloc1(nmatched, &leaves));
  PetscCall(PetscMalloc1(nmatched, &remotes));
  for (PetscInt l = 0; l < nmatched; ++l) {
    leaves[l]  = ilocal ? ilocal[l] : l;
    remotes[l] = iremote[l];
  }
  PetscCall(PetscSFDestroy(&matched));
  PetscCall(PetscSFCreate(comm, &sf));
  PetscCall(PetscObjectSetName((PetscObject)sf, "point SF"));
  PetscCall(PetscSFSetGraph(sf, pEnd - pStart, nmatched, leaves, PETSC_OWN_POINTER, remotes, PETSC_OWN_POINTER));
  PetscCall(DMSetPointSF(dm, sf));
  PetscCall(PetscSFDestroy(&sf));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* "Face Sets" as PETSc's own hexahedral box marks them (bottom 1, top 2, front 3, back 4, right 5, left 6): the faces
   in the box's six planes. */
static PetscErrorCode MarkFaceSets(DM dm, const PetscInt n[3], const PetscInt pos[])
{
  const PetscInt value[3][2] = {{6, 5}, {3, 4}, {1, 2}}; /* axis, low or high side */
  DMLabel        faceSets;
  PetscInt       fStart, fEnd;

  PetscFunctionBeginUser;
  PetscCall(DMCreateLabel(dm, "Face Sets"));
  PetscCall(DMGetLabel(dm, "Face Sets", &faceSets));
  PetscCall(DMPlexGetHeightStratum(dm, 1, &fStart, &fEnd));
  for (PetscInt f = fStart; f < fEnd; ++f)
    for (int d = 0; d < 3; ++d) {
      if (pos[3 * f + d] == 0) PetscCall(DMLabelSetValue(faceSets, f, value[d][0]));
      if (pos[3 * f + d] == 2 * n[d]) PetscCall(DMLabelSetValue(faceSets, f, value[d][1]));
    }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndBoxCreateDistributed(MPI_Comm comm, const PetscInt faces[3], const PetscReal lower[3],
  const PetscReal upper[3], DM *dm)
{
  PetscMPIInt rank, size;
  BoxLayout   L;
  PetscInt    b[3], c0[3], c1[3], *pos;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCall(BoxLayoutCreate(size, faces, &L));
  b[0] = rank % L.grid[0];
  b[1] = (rank / L.grid[0]) % L.grid[1];
  b[2] = rank / (L.grid[0] * L.grid[1]);
  for (int d = 0; d < 3; ++d) {
    c0[d] = L.cellStart[d][b[d]];
    c1[d] = L.cellStart[d][b[d] + 1];
  }
  PetscCall(CreateBlock(comm, c0, c1, faces, lower, upper, dm));
  PetscCall(PointPositions(*dm, faces, lower, upper, &pos));
  PetscCall(JoinBlocks(*dm, &L, rank, c0, c1, pos));
  PetscCall(MarkFaceSets(*dm, faces, pos));
  PetscCall(PetscFree(pos));
  PetscCall(BoxLayoutDestroy(&L));
  PetscFunctionReturn(PETSC_SUCCESS);
}
