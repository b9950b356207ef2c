#include "ind_app.h"

PetscErrorCode IndAppCreate(MPI_Comm comm, IndApp *out)
{
  IndApp   app;
  PetscInt ndof, ncell;

  PetscFunctionBeginUser;
  PetscCall(IndLogRegister());
  PetscCall(PetscCalloc1(1, &app));
  app->comm  = comm;
  app->steps = 1;
  PetscOptionsBegin(comm, NULL, "Load program", "Load");
  PetscCall(PetscOptionsInt("-load_steps", "Number of equal load steps", "", app->steps, &app->steps, NULL));
  PetscCall(PetscOptionsBool("-quiet", "Print nothing but errors", "", app->quiet, &app->quiet, NULL));
  PetscOptionsEnd();
  PetscCheck(app->steps >= 1, comm, PETSC_ERR_ARG_OUTOFRANGE, "-load_steps must be >= 1, got %" PetscInt_FMT, app->steps);

  PetscCall(PetscLogStagePush(IndLog.setup));
  PetscCall(IndMeshCreate(comm, &app->mesh));
  PetscCall(IndDiscCreate(app->mesh, &app->disc));
  PetscCall(IndMaterialsCreate(app->mesh, app->disc, &app->mats));
  PetscCall(IndBCCreate(app->mesh, app->disc, &app->bc));
  PetscCall(IndAssemblyCreate(app->disc, app->mats, &app->assembly));
  PetscCall(IndSolverCreate(app->disc->dm, app->assembly, app->bc, &app->solver));
  PetscCall(IndOutputCreate(app->mesh, app->disc, &app->output));
  PetscCall(DMCreateGlobalVector(app->disc->dm, &app->U));
  PetscCall(PetscObjectSetName((PetscObject)app->U, "displacement"));
  PetscCall(VecZeroEntries(app->U));
  PetscCall(PetscLogStagePop());
  PetscCall(IndOptionsCheckUnused(comm));

  PetscCall(VecGetSize(app->U, &ndof));
  ncell = app->disc->ncell;
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &ncell, 1, MPIU_INT, MPI_SUM, comm));
  if (!app->quiet) {
    PetscMPIInt size;
    PetscCallMPI(MPI_Comm_size(comm, &size));
    PetscCall(PetscPrintf(comm, "indent: mesh %s, %" PetscInt_FMT " %s, %s%" PetscInt_FMT " elements, %" PetscInt_FMT " dofs, %d rank%s\n", app->mesh->source, ncell, app->mesh->simplex ? "tetrahedra" : "hexahedra",
                          app->mesh->simplex ? "P" : "Q", app->disc->degree, ndof, size, size > 1 ? "s" : ""));
  }
  *out = app;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndAppSetBodyForce(IndApp app, IndVectorFn fn, void *ctx)
{
  PetscFunctionBeginUser;
  app->assembly->body_force = fn;
  app->assembly->body_ctx   = ctx;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndAppAddBoundaryFunction(IndApp app, const char surface[], PetscInt mask, IndVectorFn fn, void *ctx)
{
  PetscFunctionBeginUser;
  PetscCall(IndBCAddFunction(app->bc, surface, mask, fn, ctx));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndAppRun(IndApp app)
{
  PetscFunctionBeginUser;
  for (PetscInt k = 1; k <= app->steps; ++k) {
    const PetscReal     lf = (PetscReal)k / app->steps;
    SNESConvergedReason reason;
    PetscInt            its, lits;
    PetscLogDouble      t0, t1;

    PetscCall(PetscTime(&t0));
    PetscCall(PetscLogStagePush(IndLog.solve));
    PetscCall(IndSolverSolve(app->solver, lf, app->U, &reason));
    PetscCall(PetscLogStagePop());
    PetscCall(PetscTime(&t1));
    PetscCall(SNESGetIterationNumber(app->solver->snes, &its));
    PetscCall(SNESGetLinearSolveIterations(app->solver->snes, &lits));
    PetscCheck(reason > 0, app->comm, PETSC_ERR_NOT_CONVERGED, "Load step %" PetscInt_FMT " (load factor %g): Newton did not converge (%s)", k, (double)lf, SNESConvergedReasons[reason]);
    if (!app->quiet) PetscCall(PetscPrintf(app->comm, "step %3" PetscInt_FMT "  load %.4f  newton %2" PetscInt_FMT "  linear %4" PetscInt_FMT "  time %.3f s\n", k, (double)lf, its, lits, t1 - t0));
    PetscCall(IndOutputWriteStep(app->output, lf, app->U, app->assembly));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndAppDestroy(IndApp *app)
{
  PetscFunctionBeginUser;
  if (!*app) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(VecDestroy(&(*app)->U));
  PetscCall(IndOutputDestroy(&(*app)->output));
  PetscCall(IndSolverDestroy(&(*app)->solver));
  PetscCall(IndAssemblyDestroy(&(*app)->assembly));
  PetscCall(IndBCDestroy(&(*app)->bc));
  PetscCall(IndMaterialsDestroy(&(*app)->mats));
  PetscCall(IndDiscDestroy(&(*app)->disc));
  PetscCall(IndMeshDestroy(&(*app)->mesh));
  PetscCall(PetscFree(*app));
  PetscFunctionReturn(PETSC_SUCCESS);
}
