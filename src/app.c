#include "ind_app.h"

const char *const IndPredictorTypes[] = {"extrapolate", "tangent", "none", "IndPredictor", "IND_PREDICTOR_", NULL};

PetscErrorCode IndAppCreate(MPI_Comm comm, IndApp *out)
{
  IndApp   app;
  PetscInt ndof, ncell;

  PetscFunctionBeginUser;
  PetscCall(IndLogRegister());
  PetscCall(PetscCalloc1(1, &app));
  app->comm      = comm;
  app->predictor = IND_PREDICTOR_EXTRAPOLATE;
  PetscOptionsBegin(comm, NULL, "Run", "Run");
  PetscCall(PetscOptionsEnum("-load_predictor", "Start of each step's Newton iteration", "", IndPredictorTypes, (PetscEnum)app->predictor, (PetscEnum *)&app->predictor, NULL));
  PetscCall(PetscOptionsBool("-quiet", "Print nothing but errors", "", app->quiet, &app->quiet, NULL));
  PetscOptionsEnd();
  PetscCall(IndLoadPathSetFromOptions(comm, &app->path));

  PetscCall(PetscLogStagePush(IndLog.setup));
  PetscCall(IndMeshCreate(comm, &app->mesh));
  PetscCall(IndDiscCreate(app->mesh, &app->disc));
  PetscCall(IndMaterialsCreate(app->mesh, app->disc, &app->mats));
  PetscCall(IndBCCreate(app->mesh, app->disc, &app->bc));
  PetscCall(IndHistoryCreate(app->disc, &app->history));
  PetscCall(IndAssemblyCreate(app->disc, app->mats, app->history, &app->assembly));
  PetscCall(IndSolverCreate(app->disc->dm, app->assembly, app->bc, &app->solver));
  PetscCall(IndOutputCreate(app->mesh, app->disc, &app->output));
  PetscCall(DMCreateGlobalVector(app->disc->dm, &app->U));
  PetscCall(PetscObjectSetName((PetscObject)app->U, "displacement"));
  PetscCall(VecZeroEntries(app->U));
  PetscCall(VecDuplicate(app->U, &app->Uprev));
  PetscCall(VecDuplicate(app->U, &app->dU));
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

PetscErrorCode IndAppSetStepMonitor(IndApp app, IndStepMonitor fn, void *ctx)
{
  PetscFunctionBeginUser;
  app->monitor     = fn;
  app->monitor_ctx = ctx;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndAppSolveStep(IndApp app, PetscReal t, IndStepResult *r)
{
  IndSolver      s = app->solver;
  PetscLogDouble t0, t1;

  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(r, sizeof(*r)));
  r->t = t;
  PetscCall(PetscTime(&t0));
  PetscCall(PetscLogStagePush(IndLog.solve));
  PetscCall(VecCopy(app->U, app->Uprev));
  /* The prescribed values alone would strain only the boundary layer of cells, which then yields in
     the first iterate and sends Newton astray; either predictor starts it near the answer. */
  if (app->predictor == IND_PREDICTOR_EXTRAPOLATE && app->dt_last > 0) PetscCall(VecAXPY(app->U, (t - app->path.t) / app->dt_last, app->dU));
  else if (app->predictor != IND_PREDICTOR_NONE) PetscCall(IndSolverPredict(s, app->path.t, t, app->U));
  PetscCall(IndSolverSolve(s, t, app->U, &r->reason));
  PetscCall(SNESGetIterationNumber(s->snes, &r->newton));
  PetscCall(SNESGetLinearSolveIterations(s->snes, &r->linear));
  r->failed    = s->nfailed;
  r->converged = r->reason > 0 ? PETSC_TRUE : PETSC_FALSE;
  if (r->converged) {
    /* SNES may have evaluated the residual last at a line-search trial point, not at U. */
    PetscCall(IndSolverEvaluate(s, app->U));
    r->plastic = s->nplastic;
    PetscCall(IndHistoryCommit(app->history));
    PetscCall(VecWAXPY(app->dU, -1.0, app->Uprev, app->U));
    app->dt_last = t - app->path.t;
  } else PetscCall(VecCopy(app->Uprev, app->U));
  PetscCall(PetscLogStagePop());
  PetscCall(PetscTime(&t1));
  r->seconds = t1 - t0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndAppRun(IndApp app)
{
  IndLoadPath *lp = &app->path;

  PetscFunctionBeginUser;
  while (!IndLoadPathDone(lp)) {
    const PetscReal t = IndLoadPathTarget(lp);
    IndStepResult   r;

    PetscCall(IndAppSolveStep(app, t, &r));
    if (!r.converged) {
      char why[256];
      if (r.reason == SNES_DIVERGED_FUNCTION_DOMAIN) PetscCall(PetscSNPrintf(why, sizeof(why), "return map failed at %" PetscInt_FMT " quadrature points", r.failed));
      else PetscCall(PetscSNPrintf(why, sizeof(why), "Newton: %s after %" PetscInt_FMT " iterations", SNESConvergedReasons[r.reason], r.newton));
      if (!app->quiet) PetscCall(PetscPrintf(app->comm, "  step to load %.6f rejected (%s): cutting the increment\n", (double)t, why));
      PetscCall(IndLoadPathReject(lp, app->comm, why));
      continue;
    }
    IndLoadPathAccept(lp, r.newton);
    if (!app->quiet)
      PetscCall(PetscPrintf(app->comm, "step %3" PetscInt_FMT "  load %.6f  newton %2" PetscInt_FMT "  linear %4" PetscInt_FMT "  plastic points %7" PetscInt_FMT "  cutbacks %2" PetscInt_FMT "  time %.3f s\n", lp->accepted, (double)t, r.newton, r.linear, r.plastic, lp->cutbacks, r.seconds));
    PetscCall(IndOutputWriteStep(app->output, t, app->U, app->assembly));
    if (app->monitor) PetscCall(app->monitor(app, &r, app->monitor_ctx));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndAppDestroy(IndApp *app)
{
  PetscFunctionBeginUser;
  if (!*app) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(VecDestroy(&(*app)->U));
  PetscCall(VecDestroy(&(*app)->Uprev));
  PetscCall(VecDestroy(&(*app)->dU));
  PetscCall(IndOutputDestroy(&(*app)->output));
  PetscCall(IndSolverDestroy(&(*app)->solver));
  PetscCall(IndAssemblyDestroy(&(*app)->assembly));
  PetscCall(IndHistoryDestroy(&(*app)->history));
  PetscCall(IndBCDestroy(&(*app)->bc));
  PetscCall(IndMaterialsDestroy(&(*app)->mats));
  PetscCall(IndDiscDestroy(&(*app)->disc));
  PetscCall(IndMeshDestroy(&(*app)->mesh));
  PetscCall(PetscFree(*app));
  PetscFunctionReturn(PETSC_SUCCESS);
}
