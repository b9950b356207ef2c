static const char help[] = "The mesh renumbered for locality (-mesh_reorder) holds no more memory than the mesh as\n"
                           "read: the renumbering's copy must not keep the mesh it was made from alive. Run with\n"
                           "-malloc_debug, so that PETSc counts what is held.\n";

#include "ind_mesh.h"

/* The bytes PETSc holds on this rank once a mesh is made with -mesh_reorder reorder (the mesh kept alive). */
static PetscErrorCode HeldByMesh(PetscBool reorder, PetscLogDouble *held)
{
  IndMesh        mesh;
  PetscLogDouble before, after;

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsSetValue(NULL, "-mesh_reorder", reorder ? "1" : "0"));
  PetscCall(PetscMallocGetCurrentUsage(&before));
  PetscCall(IndMeshCreate(PETSC_COMM_WORLD, &mesh));
  PetscCall(PetscMallocGetCurrentUsage(&after));
  PetscCall(IndMeshDestroy(&mesh));
  *held = after - before;
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  PetscLogDouble asread, reordered, warm;
  PetscBool      counted;
  PetscMPIInt    bad;

  PetscFunctionBeginUser;
  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  PetscCall(PetscMallocGetDebug(&counted, NULL, NULL));
  PetscCheck(counted, PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONGSTATE, "run with -malloc_debug: nothing is counted");
  /* the first mesh also registers what every later one shares (types, events, options) */
  PetscCall(HeldByMesh(PETSC_FALSE, &warm));
  PetscCall(HeldByMesh(PETSC_FALSE, &asread));
  PetscCall(HeldByMesh(PETSC_TRUE, &reordered));
  PetscCall(PetscSynchronizedPrintf(PETSC_COMM_WORLD, "held by the mesh: as read %.0f B, renumbered %.0f B (%.3f)\n",
    asread, reordered, reordered / asread));
  PetscCall(PetscSynchronizedFlush(PETSC_COMM_WORLD, PETSC_STDOUT));
  /* the renumbered mesh has the same points, cones and labels, and a permutation's few more sections; a mesh kept
     alive beside it would double what is held */
  bad = !(asread > 0 && reordered < 1.1 * asread);
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &bad, 1, MPI_INT, MPI_MAX, PETSC_COMM_WORLD));
  PetscCall(PetscFinalize());
  return bad;
}
