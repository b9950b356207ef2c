static const char help[] = "The built-in box made in blocks on every rank (-mesh_partitioner blocks): the grid of\n"
                           "ranks it chooses, and a mesh PETSc's checks pass, with every cell, vertex and boundary\n"
                           "face of the box once, the six sides where PETSc's own box puts them, and its volume.\n"
                           "Takes the box's options (-dm_plex_box_faces, ...).\n";

#include <petscbt.h>
#include <petscsf.h>
#include "mesh_impl.h"

/* The grid chosen for size ranks on faces; *bad counts a grid other than the one expected. */
static PetscErrorCode ExpectGrid(PetscMPIInt size, PetscInt nx, PetscInt ny, PetscInt nz, PetscInt gx, PetscInt gy,
  PetscInt gz, PetscInt *bad)
{
  const PetscInt faces[3] = {nx, ny, nz};
  PetscInt       grid[3];

  PetscFunctionBeginUser;
  PetscCall(IndBoxChooseGrid(size, faces, grid));
  if (grid[0] != gx || grid[1] != gy || grid[2] != gz) {
    ++*bad;
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%d ranks on %" PetscInt_FMT "x%" PetscInt_FMT "x%" PetscInt_FMT
      ": grid %" PetscInt_FMT "x%" PetscInt_FMT "x%" PetscInt_FMT ", expected %" PetscInt_FMT "x%" PetscInt_FMT
      "x%" PetscInt_FMT "\n", size, nx, ny, nz, grid[0], grid[1], grid[2], gx, gy, gz));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode CheckGrids(PetscInt *bad)
{
  PetscFunctionBeginUser;
  PetscCall(ExpectGrid(1, 63, 63, 63, 1, 1, 1, bad));
  PetscCall(ExpectGrid(2, 63, 63, 63, 1, 1, 2, bad)); /* a tie: z is cut first */
  PetscCall(ExpectGrid(4, 63, 63, 63, 1, 2, 2, bad)); /* 1.6% more cells than 1x1x4, a third fewer faces shared */
  PetscCall(ExpectGrid(64, 63, 63, 63, 4, 4, 4, bad)); /* not 64 slabs of one layer (and one rank without any) */
  PetscCall(ExpectGrid(8, 64, 64, 64, 2, 2, 2, bad));
  PetscCall(ExpectGrid(2, 40, 10, 10, 2, 1, 1, bad)); /* across the long side, the smallest cut */
  PetscCall(ExpectGrid(4, 3, 3, 64, 1, 1, 4, bad));   /* 2x2x1 would leave 4 of 9 columns on the busiest rank */
  PetscCall(ExpectGrid(6, 2, 3, 1, 2, 3, 1, bad));    /* one cell a rank */
  PetscCall(ExpectGrid(7, 4, 4, 4, 1, 1, 7, bad));    /* a prime beyond every side: three ranks get no cell */
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Points of the stratum [pStart, pEnd) this rank owns (not leaves of the point SF), over all ranks. */
static PetscErrorCode CountOwned(DM dm, PetscInt pStart, PetscInt pEnd, DMLabel label, PetscInt value, PetscInt *n)
{
  PetscSF         sf;
  PetscInt        nleaves, chartStart, chartEnd;
  const PetscInt *leaves;
  PetscBT         leaf;

  PetscFunctionBeginUser;
  PetscCall(DMGetPointSF(dm, &sf));
  PetscCall(PetscSFGetGraph(sf, NULL, &nleaves, &leaves, NULL));
  PetscCall(DMPlexGetChart(dm, &chartStart, &chartEnd));
  PetscCall(PetscBTCreate(chartEnd - chartStart, &leaf));
  for (PetscInt l = 0; l < nleaves; ++l) PetscCall(PetscBTSet(leaf, (leaves ? leaves[l] : l) - chartStart));
  *n = 0;
  for (PetscInt p = pStart; p < pEnd; ++p) {
    PetscInt v = value;
    if (label) PetscCall(DMLabelGetValue(label, p, &v));
    if (v == value && !PetscBTLookup(leaf, p - chartStart)) ++*n;
  }
  PetscCall(PetscBTDestroy(&leaf));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, n, 1, MPIU_INT, MPI_SUM, PetscObjectComm((PetscObject)dm)));
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  /* PETSc's hexahedral box: bottom z-, top z+, front y-, back y+, right x+, left x- */
  const PetscInt axis[6] = {2, 2, 1, 1, 0, 0}, high[6] = {0, 1, 0, 1, 1, 0};
  PetscInt       faces[3] = {2, 2, 2}, n = 3, bad = 0, cStart, cEnd, vStart, vEnd, fStart, fEnd, count;
  PetscReal      lower[3] = {0, 0, 0}, upper[3] = {1, 1, 1}, volume = 0, side[3], perturb = 0;
  IndMesh        mesh;
  DM             dm;
  DMLabel        faceSets;

  PetscFunctionBeginUser;
  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  PetscCall(CheckGrids(&bad));
  PetscCall(PetscOptionsGetIntArray(NULL, NULL, "-dm_plex_box_faces", faces, &n, NULL));
  n = 3;
  PetscCall(PetscOptionsGetRealArray(NULL, NULL, "-dm_plex_box_lower", lower, &n, NULL));
  n = 3;
  PetscCall(PetscOptionsGetRealArray(NULL, NULL, "-dm_plex_box_upper", upper, &n, NULL));
  PetscCall(PetscOptionsGetReal(NULL, NULL, "-mesh_perturb", &perturb, NULL));
  PetscCall(IndMeshCreate(PETSC_COMM_WORLD, &mesh));
  PetscCall(IndMeshGetDM(mesh, &dm));
  PetscCall(DMPlexCheckSymmetry(dm));
  PetscCall(DMPlexCheckSkeleton(dm, 0));
  PetscCall(DMPlexCheckFaces(dm, 0));
  PetscCall(DMPlexCheckGeometry(dm));
  PetscCall(DMPlexCheckPointSF(dm, NULL, PETSC_FALSE));
  PetscCall(DMPlexCheckInterfaceCones(dm));
  PetscCall(DMPlexGetHeightStratum(dm, 0, &cStart, &cEnd));
  PetscCall(DMPlexGetHeightStratum(dm, 1, &fStart, &fEnd));
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
  PetscCall(CountOwned(dm, cStart, cEnd, NULL, 0, &count));
  if (count != faces[0] * faces[1] * faces[2]) ++bad;
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "cells %" PetscInt_FMT, count));
  PetscCall(CountOwned(dm, vStart, vEnd, NULL, 0, &count));
  if (count != (faces[0] + 1) * (faces[1] + 1) * (faces[2] + 1)) ++bad;
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, ", vertices %" PetscInt_FMT, count));
  PetscCall(DMGetLabel(dm, "Face Sets", &faceSets));
  for (PetscInt s = 0; s < 6; ++s) {
    const PetscInt a = axis[s], b = (a + 1) % 3, c = (a + 2) % 3;
    IS             pts = NULL;
    PetscInt       npts = 0;
    const PetscInt *p;
    PetscCall(CountOwned(dm, fStart, fEnd, faceSets, s + 1, &count));
    if (count != faces[b] * faces[c]) ++bad;
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, ", side %" PetscInt_FMT " %" PetscInt_FMT, s + 1, count));
    /* every face of the side lies in its plane */
    PetscCall(DMLabelGetStratumIS(faceSets, s + 1, &pts));
    if (pts) PetscCall(ISGetLocalSize(pts, &npts));
    if (pts) PetscCall(ISGetIndices(pts, &p));
    for (PetscInt k = 0; k < npts; ++k) {
      PetscReal centroid[3], normal[3];
      PetscCall(DMPlexComputeCellGeometryFVM(dm, p[k], NULL, centroid, normal));
      if (PetscAbsReal(centroid[a] - (high[s] ? upper[a] : lower[a])) > 1e-12 * (upper[a] - lower[a])) ++bad;
    }
    if (pts) PetscCall(ISRestoreIndices(pts, &p));
    PetscCall(ISDestroy(&pts));
  }
  for (PetscInt cell = cStart; cell < cEnd; ++cell) {
    PetscReal vol;
    PetscCall(DMPlexComputeCellGeometryFVM(dm, cell, &vol, NULL, NULL));
    volume += vol;
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &volume, 1, MPIU_REAL, MPI_SUM, PETSC_COMM_WORLD));
  for (int d = 0; d < 3; ++d) side[d] = upper[d] - lower[d];
  /* (a hexahedron with warped faces has its volume approximated) */
  if (perturb == 0 && PetscAbsReal(volume / (side[0] * side[1] * side[2]) - 1) > 1e-12) ++bad;
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, ", volume %.15g; %" PetscInt_FMT " failed\n", (double)volume, bad));
  PetscCall(IndMeshDestroy(&mesh));
  PetscCall(PetscFinalize());
  return bad ? 1 : 0;
}
