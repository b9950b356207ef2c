#define _POSIX_C_SOURCE 200809L /* sigaction, gmtime_r, strtok_r */
#include "app_impl.h"
#include <signal.h>
#include <stdio.h>
#include <string.h>
#include <time.h>
#include <sys/stat.h>
#include "ind_app.h"
#include "ind_checkpoint.h"
#include "ind_signals.h"
#include "ind_runchecks.h"
#include "ind_options.h"
#include "ind_csm.h"
#include "ind_stepcsv.h"
#include "runwrite.h"

/* Whether -load_edge_steps limits a step ending at t: depth control, loading, an indenter. */
static PetscBool EdgeLimitApplies(IndApp app, PetscReal t)
{
  const IndLoadPath *lp = &app->path;
  return app->contact && !app->control && lp->edge_steps > 0 && t <= 1.0 && lp->depth_max > 0 ? PETSC_TRUE
                                                                                              : PETSC_FALSE;
}

/* The loading steps -load_edge_steps adds to the uniform ones still to come (at most limit): the limit
   depends on the depth alone, so it can be followed ahead without solving. */
static PetscInt ExtraEdgeSteps(IndApp app, PetscInt limit)
{
  const IndLoadPath *lp = &app->path;
  PetscReal          d;
  PetscInt           n = 0, uniform;

  if (lp->t >= 1.0 || !EdgeLimitApplies(app, lp->t)) return 0;
  d       = IndContactGetCommittedDepth(app->contact);
  uniform = (PetscInt)PetscCeilReal((1.0 - lp->t) / lp->dt_max - 1e-9);
  while (d < lp->depth_max * (1 - 1e-12) && n < limit) {
    const PetscReal next = PetscMin(d + lp->dt_max * lp->depth_max, lp->depth_max);
    d = PetscMax(IndContactEdgeDepth(app->contact, d, next, lp->edge_steps),
                 PetscMin(d + lp->dt_min * lp->depth_max, next));
    n++;
  }
  return PetscMax(n - uniform, 0);
}

PetscErrorCode IndAppCreate(MPI_Comm comm, IndApp *out)
{
  IndApp   app;
  PetscInt ndof, ncell;

  PetscFunctionBeginUser;
  PetscCall(IndLogRegister());
  PetscCall(PetscCalloc1(1, &app));
  app->comm = comm;
  /* From the start: a signal during the set-up (meshing, distribution) stops the run before its first step. */
  PetscCall(IndSignalsInstall());
  app->checkpoint_every = 10;
  app->stop_after       = -1;
  app->checkpointed     = -1;
  app->depth_start      = -1;
  PetscCall(PetscTime(&app->t_start));
  {
    time_t    now = time(NULL);
    struct tm utc;
    gmtime_r(&now, &utc);
    strftime(app->start_time, sizeof(app->start_time), "%Y-%m-%dT%H:%M:%SZ", &utc);
  }
  PetscOptionsBegin(comm, NULL, IND_TITLE "Run", "Run");
  PetscCall(IndOptionsBool("-quiet", "Print nothing but errors and warnings", app->quiet, &app->quiet, NULL));
  PetscCall(IndOptionsInt("-checkpoint_every",
    "Write <output_dir>/checkpoint.h5 every N accepted steps (0: only on SIGTERM, SIGINT, SIGUSR1)",
                          NULL, app->checkpoint_every, &app->checkpoint_every, NULL));
  PetscCall(IndOptionsInt("-checkpoint_stop_after_step",
    "Stop with a checkpoint after this accepted step, as on SIGTERM (for tests)",
                          "-1: never", app->stop_after, &app->stop_after, NULL));
  PetscCall(IndOptionsInt("-csm_every", "Hardness and modulus against depth: the contact stiffness of a small elastic "
                          "unloading every N accepted loading steps, into <output_dir>/csm.csv (0: never)", NULL,
                          app->csm_every, &app->csm_every, NULL));
  PetscOptionsEnd();
  PetscCheck(app->csm_every >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-csm_every must be >= 0 (steps), got %" PetscInt_FMT,
             app->csm_every);
  PetscCheck(app->checkpoint_every >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-checkpoint_every must be >= 0 (steps), got %" PetscInt_FMT, app->checkpoint_every);
  {
    /* Decided before the mesh, which may mesh a .geo into the output directory. */
    PetscBool fields = PETSC_TRUE, curve = PETSC_TRUE, indenter, listing;
    PetscCall(PetscOptionsGetBool(NULL, NULL, "-output_fields", &fields, NULL));
    PetscCall(PetscOptionsGetBool(NULL, NULL, "-output_curve", &curve, NULL));
    PetscCall(PetscOptionsHasName(NULL, NULL, "-indenter_type", &indenter));
    listing = IndHelpListing();
    PetscCall(IndRunDirSetUp(comm, (fields || (indenter && curve)) && !listing, &app->rundir));
    if (app->rundir.restart) PetscCall(IndCheckpointCheck(comm, app->rundir.restart_file));
  }

  PetscCall(PetscLogStagePush(IndLog.setup));
  PetscCall(IndMeshCreate(comm, &app->mesh));
  PetscCall(IndDiscCreate(app->mesh, &app->disc));
  PetscCall(IndMaterialsCreate(app->mesh, app->disc, &app->mats));
  PetscCall(IndBCCreate(app->mesh, app->disc, &app->bc));
  PetscCall(IndContactCreate(app->mesh, app->disc, app->bc, &app->contact));
  /* An indentation unloads by default; a run of prescribed displacements only loads. */
  PetscCall(IndLoadPathSetFromOptions(comm, app->contact ? PETSC_TRUE : PETSC_FALSE, &app->path));
  PetscCheck(!app->contact || app->path.depth_max > 0, comm, PETSC_ERR_ARG_WRONG,
    "-indenter_type needs the largest depth -load_depth (nm) > 0");
  PetscCheck(app->contact || app->path.force_max == 0, comm, PETSC_ERR_ARG_WRONG,
    "-load_force needs an indenter: -indenter_type");
  PetscCheck(app->contact || app->path.depth_max == 0, comm, PETSC_ERR_ARG_WRONG,
    "-load_depth needs an indenter: -indenter_type");
  PetscCall(IndScratchSetFromOptions(comm, app->contact ? PETSC_TRUE : PETSC_FALSE, &app->scratch));
  {
    PetscBool axisymmetric;
    PetscCall(IndMeshIsAxisymmetric(app->mesh, &axisymmetric));
    PetscCheck(!axisymmetric || app->scratch.length == 0, comm, PETSC_ERR_SUP,
      "-scratch_length: a scratch slides the indenter off the axis, which the axisymmetric model (a 2D mesh) cannot "
      "represent; use a 3D mesh (inputs/scratch.opts)");
  }
  if (app->contact && !IndHelpListing()) PetscCall(IndScratchSetUp(&app->scratch, app->contact, app->bc));
  if (app->scratch.length > 0) IndLoadPathSetScratch(&app->path, app->scratch.steps);
  PetscCall(IndHistoryCreate(app->disc, IndMaterialsHaveBackStress(app->mats), &app->history));
  PetscCall(IndAssemblyCreate(app->disc, app->mats, app->history, &app->assembly));
  if (app->contact) PetscCall(IndContactSetCurrentAreas(app->contact, IndAssemblyIsFiniteStrain(app->assembly)));
  {
    DM dm;
    PetscCall(IndDiscGetDM(app->disc, &dm));
    PetscCall(IndSolverCreate(dm, app->assembly, app->bc, app->contact, app->path.depth_max, &app->solver));
    PetscCall(DMCreateGlobalVector(dm, &app->U));
  }
  if (app->path.force_max > 0) {
    PetscCall(
      IndSolverSetLoadControl(app->solver, app->path.depth_max, app->path.force_rtol * app->path.force_max * 1e3));
    PetscCall(IndLoadControlCreate(&app->control));
  }
  PetscCall(IndOutputCreate(app->mesh, app->disc, &app->output));
  PetscCall(IndOutputSetContact(app->output, app->contact));
  PetscCall(IndOutputSetDensifying(app->output, IndMaterialsAreDensifying(app->mats)));
  if (app->contact) PetscCall(IndSummaryCreate(comm, IndContactGetIndenter(app->contact)->type, &app->summary));
  PetscCall(PetscObjectSetName((PetscObject)app->U, "displacement"));
  PetscCall(VecZeroEntries(app->U));
  PetscCall(VecDuplicate(app->U, &app->Uprev));
  PetscCall(IndPredictorCreate(comm, app->U, &app->predictor));
  PetscCall(PetscLogStagePop());
  PetscCall(IndOptionsCheckUnused(comm));
  if (app->rundir.restart) {
    PetscInt             npts = 0;
    const IndCurvePoint *pts  = NULL;
    PetscCall(IndAppCheckpoint(app, app->rundir.restart_file, FILE_MODE_READ));
    if (app->summary) PetscCall(IndSummaryGetPoints(app->summary, &npts, &pts));
    if (!strcmp(app->rundir.restart_file, app->rundir.checkpoint)) app->checkpointed = app->path.accepted;
    PetscCall(IndAppRemoveStopMarker(app)); /* this part may stop for its own reasons */
    PetscCall(IndStepCSVTruncate(comm, app->rundir.dir, IND_CSM_FILE, app->path.accepted));
    PetscCall(IndStepCSVTruncate(comm, app->rundir.dir, IND_SCRATCH_FILE, app->path.accepted));
    PetscCall(IndOutputResume(app->output, npts, pts));
  }

  {
    const PetscInt every = IndOutputFieldsEvery(app->output);
    PetscInt       left  = IndLoadPathStepsLeft(&app->path, every, IND_MAX_OUTPUT_STEPS + 1);
    left += ExtraEdgeSteps(app, IND_MAX_OUTPUT_STEPS + 1) / every;
    PetscCall(IndOutputCheckSize(app->output, PetscMin(left, IND_MAX_OUTPUT_STEPS + 1), &app->warnings));
  }
  if (!IndHelpListing()) { /* not on the stand-in mesh of a listing or of the options' check before meshing */
    const IndDiscLayout *L;
    char                 text[IND_WARNING_LEN];
    PetscCall(IndDiscGetLayout(app->disc, &L));
    IndMaterialsCheckLocking(app->mats, L->degree, L->simplex, L->axisymmetric, text, sizeof(text));
    if (text[0]) PetscCall(IndWarningsAdd(comm, &app->warnings, "locking", PETSC_TRUE, text));
    if (app->contact) PetscCall(IndContactCheckMirror(app->contact, app->bc, app->path.depth_max, text, sizeof(text)));
    if (app->contact && text[0]) PetscCall(IndWarningsAdd(comm, &app->warnings, "mirror", PETSC_TRUE, text));
  }
  PetscCall(VecGetSize(app->U, &ndof));
  {
    const IndDiscLayout *L;
    PetscCall(IndDiscGetLayout(app->disc, &L));
    ncell = L->ncell;
    PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &ncell, 1, MPIU_INT, MPI_SUM, comm));
    /* not for a listing (-help, or the option check before gmsh), whose mesh is a stand-in */
    if (!app->quiet && !IndHelpListing()) {
      PetscMPIInt size;
      const char *source;
      PetscCall(IndMeshGetSource(app->mesh, &source));
      PetscCallMPI(MPI_Comm_size(comm, &size));
      PetscCall(PetscPrintf(comm,
        "indent: mesh %s, %" PetscInt_FMT " %s, %s%" PetscInt_FMT " elements, %" PetscInt_FMT " dofs%s, %d rank%s\n",
        source, ncell,
        L->axisymmetric ? (L->simplex ? "triangles" : "quadrilaterals") : (L->simplex ? "tetrahedra" : "hexahedra"),
        L->simplex ? "P" : "Q", L->degree, ndof, L->axisymmetric ? " (axisymmetric: the hoop third held at zero)" : "",
        size, size > 1 ? "s" : ""));
    }
  }
  *out = app;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndAppSetBodyForce(IndApp app, IndVectorFn fn, void *ctx)
{
  PetscFunctionBeginUser;
  PetscCall(IndAssemblySetBodyForce(app->assembly, fn, ctx));
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

/* The distance slid at pseudo-time t of the load program (0 without a scratch), nm. */
static PetscReal SlideAt(IndApp app, PetscReal t)
{
  return app->scratch.length * IndLoadPathScratchFraction(&app->path, t);
}

/* The step about to be solved, against the accepted state, as the predictor sees it. */
static IndPredictorStep StepOf(IndApp app, const IndStepResult *r)
{
  IndPredictorStep st;
  st.lambda_old = IndLoadPathFactor(&app->path, app->path.t);
  st.lambda     = r->lambda;
  st.depth_old  = app->contact ? IndContactGetCommittedDepth(app->contact) : 0;
  st.depth      = r->depth;
  st.slide_old  = SlideAt(app, app->path.t);
  st.slide      = r->slide;
  st.by_depth   = app->depth_start >= 0 ? PETSC_TRUE : PETSC_FALSE;
  return st;
}

/* The converged state U becomes the accepted one. */
static PetscErrorCode AcceptStep(IndApp app, IndStepResult *r)
{
  const IndPredictorStep st = StepOf(app, r);

  PetscFunctionBeginUser;
  PetscCall(IndSolverCommit(app->solver, app->U));
  r->plastic = IndSolverPlasticPoints(app->solver);
  if (app->control) IndLoadControlAccept(app->control, r->contact.load * 1e-3, st.depth - st.depth_old);
  if (app->contact) PetscCall(IndContactCommit(app->contact, app->U));
  PetscCall(IndPredictorAccept(app->predictor, &st, app->U, app->Uprev));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Load control: the depth is an unknown of the step's Newton iteration (bordered.c), which starts from
   the depth the load control object predicts for P*. */
static PetscErrorCode SolveLoadStep(IndApp app, PetscReal t, IndStepResult *r)
{
  IndLoadPath    *lp     = &app->path;
  const PetscReal lambda = IndLoadPathFactor(lp, t);
  const PetscReal target = lp->force_max * (IndLoadPathUnloading(lp, t) ? PetscMax(lambda, lp->unload_to) : lambda);
  const PetscBool sliding = SlideAt(app, t) != SlideAt(app, lp->t) ? PETSC_TRUE : PETSC_FALSE;
  PetscReal       load    = 0;

  PetscFunctionBeginUser;
  app->depth_start = IndLoadControlStartDepth(app->control, lp, lambda, target,
                                              IndContactGetCommittedDepth(app->contact), sliding);
  PetscCall(IndSolverSetLoadTarget(app->solver, target * 1e3));
  PetscCall(IndAppSolveStep(app, t, r));
  app->depth_start = -1;
  PetscCheck(r->converged || !IndSolverLoadOutOfReach(app->solver, &load), app->comm, PETSC_ERR_USER_INPUT,
             "-load_force %g uN is out of reach: at -load_depth %g nm, the largest depth allowed, the load is %g uN; "
             "raise -load_depth (within the body) or lower -load_force",
             (double)lp->force_max, (double)lp->depth_max, (double)(load * 1e-3));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndAppSolveStep(IndApp app, PetscReal t, IndStepResult *r)
{
  IndSolver        s = app->solver;
  IndSolveResult   sr;
  IndPredictorStep st;
  PetscLogDouble   t0, t1;

  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(r, sizeof(*r)));
  r->t      = t;
  r->lambda = IndLoadPathFactor(&app->path, t);
  r->depth  = app->depth_start >= 0 ? app->depth_start : app->path.depth_max * r->lambda;
  r->slide  = SlideAt(app, t);
  PetscCall(PetscTime(&t0));
  PetscCall(PetscLogStagePush(IndLog.solve));
  PetscCall(VecCopy(app->U, app->Uprev));
  if (app->contact) {
    PetscReal axis[2];
    IndScratchAxis(&app->scratch, IndLoadPathScratchFraction(&app->path, t), axis);
    PetscCall(IndContactSetIndenterPosition(app->contact, r->depth, axis));
  }
  st = StepOf(app, r);
  PetscCall(IndPredictorApply(app->predictor, s, &st, app->U));
  PetscCall(IndSolverSolve(s, r->lambda, app->U, &sr));
  if (app->control) r->depth = IndContactGetDepth(app->contact); /* an unknown of the solve */
  r->reason    = sr.reason;
  r->newton    = sr.newton;
  r->linear    = sr.linear;
  r->outer     = sr.outer;
  r->contact   = sr.contact;
  r->failed    = IndSolverFailedPoints(s);
  r->converged = sr.converged;
  PetscCall(PetscStrncpy(r->why, sr.why, sizeof(r->why)));
  if (r->converged) {
    PetscCall(AcceptStep(app, r));
  } else {
    PetscCall(VecCopy(app->Uprev, app->U));
    if (app->contact) PetscCall(IndContactRollback(app->contact));
  }
  PetscCall(PetscLogStagePop());
  PetscCall(PetscTime(&t1));
  r->seconds = t1 - t0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Depth control, loading: the step ends where the indenter's edge has moved 1/-load_edge_steps of the
   surface's node spacing under the contact. Backward Euler integrates each step's plastic flow in one
   jump; the error it leaves in P_max grows with the step and, under fixed steps, as the mesh is refined
   (doc/load-steps.md): steps that follow the spacing keep it level. */
static void LimitByContactEdge(IndApp app)
{
  IndLoadPath    *lp = &app->path;
  const PetscReal t  = IndLoadPathTarget(lp);
  PetscReal       d0, d1;

  if (!EdgeLimitApplies(app, t)) return; /* not the hold, the scratch (after t = 1) or the unloading */
  d0 = IndContactGetCommittedDepth(app->contact);
  d1 = IndContactEdgeDepth(app->contact, d0, lp->depth_max * IndLoadPathFactor(lp, t), lp->edge_steps);
  IndLoadPathLimit(lp, d1 / lp->depth_max);
}

PetscErrorCode IndAppStep(IndApp app, IndStepResult *r)
{
  IndLoadPath *lp = &app->path;
  PetscReal    t;

  PetscFunctionBeginUser;
  LimitByContactEdge(app);
  t = IndLoadPathTarget(lp);
  if (app->control) PetscCall(SolveLoadStep(app, t, r));
  else PetscCall(IndAppSolveStep(app, t, r));
  if (!r->converged) {
    if (!app->quiet)
      PetscCall(PetscPrintf(app->comm,
        "  step to t = %.6f rejected after newton %" PetscInt_FMT " linear %" PetscInt_FMT " (%s): cutting the "
        "increment\n", (double)t, r->newton, r->linear, r->why));
    lp->rejected_newton += r->newton;
    lp->rejected_linear += r->linear;
    /* a linear solve that fails (an iterative solver's limit, met at the reversal with friction of 2 on the paper's
       mesh, where MUMPS solves every step) is not cured by smaller steps */
    PetscCall(IndLoadPathReject(lp, app->comm, r->why,
      r->reason == SNES_DIVERGED_LINEAR_SOLVE ? "the linear solves failed, which smaller steps do not cure: a direct "
      "solve (-ksp_type preonly -pc_type lu -pc_factor_mat_solver_type mumps) may" : NULL));
  } else {
    /* With contact, Newton runs once per outer iteration: judge the step by its average. */
    IndLoadPathAccept(lp, r->outer > 1 ? (r->newton + r->outer - 1) / r->outer : r->newton);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndAppRun(IndApp app)
{
  IndLoadPath *lp = &app->path;

  PetscFunctionBeginUser;
  if (app->rundir.restart && !app->quiet)
    PetscCall(PetscPrintf(app->comm, "indent: continuing from %s after step %" PetscInt_FMT " (depth %g nm)\n",
                          app->rundir.restart_file, lp->accepted,
                          app->contact ? (double)IndContactGetDepth(app->contact) : 0.0));
  while (!IndLoadPathDone(lp)) {
    const PetscReal t = IndLoadPathTarget(lp);
    IndStepResult   r;
    int             signum;

    PetscCall(IndSignalsPending(app->comm, &signum));
    if (signum) {
      PetscCall(IndAppStop(app, signum));
      break;
    }

    PetscCall(IndAppStep(app, &r));
    if (!r.converged) continue;
    if (!app->quiet) {
      if (app->contact)
        PetscCall(PetscPrintf(app->comm,
          "step %3" PetscInt_FMT "  depth %9.4f nm  load %11.5f uN  contact %5" PetscInt_FMT " (slip %5" PetscInt_FMT
            ")  uzawa %2" PetscInt_FMT "  newton %3" PetscInt_FMT "  linear %5" PetscInt_FMT
            "  plastic %7" PetscInt_FMT "  cutbacks %2" PetscInt_FMT "  %.2f s\n", lp->accepted, (double)r.depth,
                              (double)(r.contact.load * 1e-3), r.contact.contact, r.contact.slip, r.outer, r.newton,
                                r.linear, r.plastic, lp->cutbacks, r.seconds));
      else
        PetscCall(PetscPrintf(app->comm,
          "step %3" PetscInt_FMT "  load %.6f  newton %2" PetscInt_FMT "  linear %4" PetscInt_FMT
            "  plastic points %7" PetscInt_FMT "  cutbacks %2" PetscInt_FMT
            "  time %.3f s\n", lp->accepted, (double)r.lambda, r.newton, r.linear, r.plastic, lp->cutbacks, r.seconds));
    }
    PetscCall(IndRunCheckStep(app, &r, &app->warnings, PETSC_TRUE));
    /* Unloading ends once the indenter has left the surface, or (load control) at a fraction of the largest
       load: known before the writes, since the last step's fields are always written. */
    if (app->contact && IndLoadPathUnloading(lp, t) && r.contact.contact == 0) IndLoadPathFinish(lp);
    if (lp->unload_to > 0 && IndLoadPathUnloading(lp, t) && IndLoadPathFactor(lp, t) <= lp->unload_to)
      IndLoadPathFinish(lp);
    r.fields = IndLoadPathFieldStep(lp, IndOutputFieldsEvery(app->output));
    if (r.fields) PetscCall(IndOutputSetStepInfo(app->output, lp->accepted, r.t, r.lambda, r.depth,
                                                 r.contact.load * 1e-3));
    if (app->contact) {
      IndCurvePoint p = {lp->accepted, r.t, r.depth, r.contact.load * 1e-3, r.contact.contact, r.contact.stick,
        r.contact.slip, r.newton, r.outer, r.linear, lp->cutbacks, r.contact.penetration, r.contact.area,
        r.contact.pileup, r.contact.deepest, r.seconds};
      /* in the record first: a checkpoint after a failed write then carries this step's point */
      PetscCall(IndSummaryAddPoint(app->summary, &p));
      PetscCall(IndAppWriteStep(app, &r, &p));
    } else PetscCall(IndAppWriteStep(app, &r, NULL));
    if (app->scratch.length > 0) {
      if (!app->quiet && IndLoadPathScratching(lp, t)) {
        PetscReal normal, lateral, side;
        IndScratchForces(&app->scratch, &r.contact, &normal, &lateral, &side);
        PetscCall(PetscPrintf(app->comm, "  slid %.5g nm: lateral force %.6g uN, apparent friction %.4f\n",
                              (double)r.slide, (double)lateral, normal > 0 ? (double)(lateral / normal) : 0.0));
      }
    }
    if (app->csm_every && app->contact && !IndLoadPathUnloading(lp, t) && !IndLoadPathScratching(lp, t) &&
        r.contact.contact > 0 &&
        lp->accepted % app->csm_every == 0) {
      IndCSMPoint csm;
      char why[512];
      PetscCall(IndCSMStiffness(app->solver, app->bc, app->contact, IndSummaryGetOPParams(app->summary), app->U,
                                r.depth, r.contact.load * 1e-3, r.contact.area, &csm));
      /* as the summary's: a contact of a few nodes does not resolve the area H and E_r divide by */
      IndContactCheckResolved(app->contact, r.contact.contact, IndSummaryGetMinContactNodes(app->summary), why,
                              sizeof(why));
      if (why[0] || !(csm.A > 0)) {
        char text[IND_WARNING_LEN];
        csm.H = csm.E_r = NAN;
        PetscCall(PetscSNPrintf(text, sizeof(text), "csm.csv leaves H and E_r empty where fewer than "
          "-op_min_contact_nodes %" PetscInt_FMT " nodes touch the indenter over the whole indent or h_c has no area "
          "(from depth %.6g nm)", IndSummaryGetMinContactNodes(app->summary), (double)r.depth));
        PetscCall(IndWarningsAdd(app->comm, &app->warnings, "csm_withheld", PETSC_FALSE, text));
      }
      if (app->rundir.ready) PetscCall(IndCSMWrite(app->comm, app->rundir.dir, lp->accepted, r.depth,
        r.contact.load * 1e-3, &csm));
      if (!app->quiet && PetscIsInfOrNanReal(csm.H))
        PetscCall(PetscPrintf(app->comm, "  stiffness S %.6g uN/nm, h_c %.5g nm, H and E_r withheld (%" PetscInt_FMT
          " nodes in contact)\n", (double)csm.S, (double)csm.h_c, r.contact.contact));
      else if (!app->quiet)
        PetscCall(PetscPrintf(app->comm, "  stiffness S %.6g uN/nm, h_c %.5g nm, H %.5g GPa, E_r %.5g GPa\n",
          (double)csm.S, (double)csm.h_c, (double)csm.H, (double)csm.E_r));
    }
    if (app->monitor) PetscCall(app->monitor(app, &r, app->monitor_ctx));
    if (lp->accepted == app->stop_after) IndSignalsRaise(SIGTERM);
    else if (app->checkpoint_every && lp->accepted % app->checkpoint_every == 0 && !IndLoadPathDone(lp))
      PetscCall(IndAppWriteCheckpoint(app, PETSC_FALSE));
  }
  if (app->stopped) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(IndAppElapsed(app));
  if (app->summary) {
    IndRunInfo info = {app->start_time, app->elapsed_before + app->elapsed_now, app->rundir.restart, app->contact,
                       &app->warnings, app->scratch.length > 0 ? PETSC_TRUE : PETSC_FALSE, lp->rejected_newton,
                       lp->rejected_linear};
    PetscCall(IndAppWriteSummary(app, &info));
  }
  /* The run is complete: its checkpoint could only restart a finished run. */
  PetscCall(IndAppRemoveCheckpoint(app));
  PetscFunctionReturn(PETSC_SUCCESS);
}

IND_GETTER(int, IndAppStoppedBy, IndApp, o->stopped)

PetscErrorCode IndAppDestroy(IndApp *app)
{
  PetscFunctionBeginUser;
  if (!*app) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(IndSignalsRestore());
  PetscCall(VecDestroy(&(*app)->U));
  PetscCall(VecDestroy(&(*app)->Uprev));
  PetscCall(IndPredictorDestroy(&(*app)->predictor));
  PetscCall(IndLoadControlDestroy(&(*app)->control));
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

IND_GETTER(MPI_Comm, IndAppGetComm, IndApp, o->comm)
IND_GETTER(IndMesh, IndAppGetMesh, IndApp, o->mesh)
IND_GETTER(IndDisc, IndAppGetDisc, IndApp, o->disc)
IND_GETTER(IndMaterials, IndAppGetMaterials, IndApp, o->mats)
IND_GETTER(IndBC, IndAppGetBC, IndApp, o->bc)
IND_GETTER(IndContact, IndAppGetContact, IndApp, o->contact)
IND_GETTER(IndAssembly, IndAppGetAssembly, IndApp, o->assembly)
IND_GETTER(IndSolver, IndAppGetSolver, IndApp, o->solver)
IND_GETTER(const IndLoadPath *, IndAppGetLoadPath, IndApp, &o->path)
IND_GETTER(Vec, IndAppGetSolution, IndApp, o->U)

DM IndAppGetDM(IndApp app)
{
  DM dm;
  (void)IndDiscGetDM(app->disc, &dm);
  return dm;
}
