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

  PetscCall(PetscLogStagePush(IndLog.setup));
  PetscCall(IndMeshCreate(comm, &app->mesh));
  PetscCall(IndDiscCreate(app->mesh, &app->disc));
  PetscCall(IndMaterialsCreate(app->mesh, app->disc, &app->mats));
  PetscCall(IndBCCreate(app->mesh, app->disc, &app->bc));
  PetscCall(IndContactCreate(app->mesh, app->disc, app->bc, &app->contact));
  /* An indentation unloads by default; a run of prescribed displacements only loads. */
  PetscCall(IndLoadPathSetFromOptions(comm, app->contact ? PETSC_TRUE : PETSC_FALSE, &app->path));
  PetscCheck(!app->contact || app->path.depth_max > 0, comm, PETSC_ERR_ARG_WRONG, "-indenter_type needs the largest depth -load_depth (nm) > 0");
  PetscCheck(app->contact || app->path.depth_max == 0, comm, PETSC_ERR_ARG_WRONG, "-load_depth needs an indenter: -indenter_type");
  PetscCall(IndHistoryCreate(app->disc, &app->history));
  PetscCall(IndAssemblyCreate(app->disc, app->mats, app->history, &app->assembly));
  if (app->contact)
    PetscCall(IndContactSetCurrentAreas(app->contact, app->assembly->formulation == IND_FORMULATION_FINITE));
  PetscCall(IndSolverCreate(app->disc->dm, app->assembly, app->bc, app->contact, app->path.depth_max, &app->solver));
  PetscCall(IndOutputCreate(app->mesh, app->disc, &app->output));
  PetscCall(IndOutputSetContact(app->output, app->contact));
  if (app->contact) PetscCall(IndSummaryCreate(comm, &app->summary));
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
  IndSolver       s          = app->solver;
  const PetscReal lambda_old = IndLoadPathFactor(&app->path, app->path.t);
  IndSolveResult  sr;
  PetscLogDouble  t0, t1;

  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(r, sizeof(*r)));
  r->t      = t;
  r->lambda = IndLoadPathFactor(&app->path, t);
  r->depth  = app->path.depth_max * r->lambda;
  PetscCall(PetscTime(&t0));
  PetscCall(PetscLogStagePush(IndLog.solve));
  PetscCall(VecCopy(app->U, app->Uprev));
  if (app->contact) app->contact->indenter.depth = r->depth;
  /* The prescribed values alone would strain only the boundary layer of cells, which then yields in
     the first iterate and sends Newton astray; either predictor starts it near the answer. The last
     increment is scaled by the change of load factor; a hold or a reversal takes the tangent
     response instead (for an indenter alone, the last state). */
  /* Not across a reversal: unloading from a plastic state is nothing like the loading increment
     reversed (that guess made Newton diverge 9 times in a row on a Vickers indentation). */
  if (app->predictor == IND_PREDICTOR_EXTRAPOLATE && (r->lambda - lambda_old) * app->dlambda_last > 0) PetscCall(VecAXPY(app->U, (r->lambda - lambda_old) / app->dlambda_last, app->dU));
  else if (app->predictor != IND_PREDICTOR_NONE) PetscCall(IndSolverPredict(s, lambda_old, r->lambda, app->U));
  PetscCall(IndSolverSolve(s, r->lambda, app->U, &sr));
  r->reason    = sr.reason;
  r->newton    = sr.newton;
  r->linear    = sr.linear;
  r->outer     = sr.outer;
  r->contact   = sr.contact;
  r->failed    = s->nfailed;
  r->converged = sr.converged;
  PetscCall(PetscStrncpy(r->why, sr.why, sizeof(r->why)));
  if (r->converged) {
    /* SNES may have evaluated the residual last at a line-search trial point, not at U. */
    PetscCall(IndSolverEvaluate(s, app->U));
    r->plastic = s->nplastic;
    PetscCall(IndHistoryCommit(app->history));
    if (app->contact) PetscCall(IndContactCommit(app->contact, app->U));
    PetscCall(VecWAXPY(app->dU, -1.0, app->Uprev, app->U));
    app->dlambda_last = r->lambda - lambda_old;
  } else {
    PetscCall(VecCopy(app->Uprev, app->U));
    if (app->contact) PetscCall(IndContactRollback(app->contact));
  }
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
      if (!app->quiet) PetscCall(PetscPrintf(app->comm, "  step to t = %.6f rejected (%s): cutting the increment\n", (double)t, r.why));
      PetscCall(IndLoadPathReject(lp, app->comm, r.why));
      continue;
    }
    /* With contact, Newton runs once per outer iteration: judge the step by its average. */
    IndLoadPathAccept(lp, r.outer > 1 ? (r.newton + r.outer - 1) / r.outer : r.newton);
    if (!app->quiet) {
      if (app->contact)
        PetscCall(PetscPrintf(app->comm, "step %3" PetscInt_FMT "  depth %9.4f nm  load %11.5f uN  contact %5" PetscInt_FMT " (slip %5" PetscInt_FMT ")  uzawa %2" PetscInt_FMT "  newton %3" PetscInt_FMT "  linear %5" PetscInt_FMT "  plastic %7" PetscInt_FMT "  cutbacks %2" PetscInt_FMT "  %.2f s\n", lp->accepted, (double)r.depth,
                              (double)(r.contact.load * 1e-3), r.contact.contact, r.contact.slip, r.outer, r.newton, r.linear, r.plastic, lp->cutbacks, r.seconds));
      else
        PetscCall(PetscPrintf(app->comm, "step %3" PetscInt_FMT "  load %.6f  newton %2" PetscInt_FMT "  linear %4" PetscInt_FMT "  plastic points %7" PetscInt_FMT "  cutbacks %2" PetscInt_FMT "  time %.3f s\n", lp->accepted, (double)r.lambda, r.newton, r.linear, r.plastic, lp->cutbacks, r.seconds));
    }
    PetscCall(IndOutputWriteStep(app->output, app->contact ? r.depth : r.lambda, app->U, app->assembly));
    if (app->contact) {
      IndCurvePoint p = {lp->accepted, r.t, r.depth, r.contact.load * 1e-3, r.contact.contact, r.contact.stick, r.contact.slip, r.newton, r.outer, r.linear, lp->cutbacks, r.contact.penetration, r.contact.area, r.contact.pileup, r.contact.deepest, r.seconds};
      PetscCall(IndOutputCurvePoint(app->output, &p));
      PetscCall(IndSummaryAddPoint(app->summary, &p));
    }
    if (app->monitor) PetscCall(app->monitor(app, &r, app->monitor_ctx));
    /* Unloading ends once the indenter has left the surface. */
    if (app->contact && IndLoadPathUnloading(lp, t) && r.contact.contact == 0) IndLoadPathFinish(lp);
  }
  if (app->summary) PetscCall(IndSummaryFinish(app->summary, &app->contact->indenter, app->output->dir, app->output->curve, app->quiet ? PETSC_FALSE : PETSC_TRUE));
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
  PetscCall(IndSummaryDestroy(&(*app)->summary));
  PetscCall(IndContactDestroy(&(*app)->contact));
  PetscCall(IndBCDestroy(&(*app)->bc));
  PetscCall(IndMaterialsDestroy(&(*app)->mats));
  PetscCall(IndDiscDestroy(&(*app)->disc));
  PetscCall(IndMeshDestroy(&(*app)->mesh));
  PetscCall(PetscFree(*app));
  PetscFunctionReturn(PETSC_SUCCESS);
}
