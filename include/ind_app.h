#pragma once
/* The application: owns every object and the order in which they are made and destroyed. */
#include "ind_mesh.h"
#include "ind_disc.h"
#include "ind_material.h"
#include "ind_assembly.h"
#include "ind_bc.h"
#include "ind_solver.h"
#include "ind_output.h"

typedef struct _p_IndApp *IndApp;
struct _p_IndApp {
  MPI_Comm     comm;
  IndMesh      mesh;
  IndDisc      disc;
  IndMaterials mats;
  IndBC        bc;
  IndAssembly  assembly;
  IndSolver    solver;
  IndOutput    output;
  Vec          U;     /* displacement (nm), global */
  PetscInt     steps; /* load steps */
  PetscBool    quiet;
};

PetscErrorCode IndAppCreate(MPI_Comm comm, IndApp *app);
PetscErrorCode IndAppDestroy(IndApp *app);
/* Hooks for verification problems (manufactured solutions, patch tests), set before IndAppRun. */
PetscErrorCode IndAppSetBodyForce(IndApp app, IndVectorFn fn, void *ctx);
PetscErrorCode IndAppAddBoundaryFunction(IndApp app, const char surface[], PetscInt mask, IndVectorFn fn, void *ctx);
/* Applies the load in -load_steps equal steps, writing output after each. */
PetscErrorCode IndAppRun(IndApp app);
