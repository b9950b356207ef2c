static const char help[] = "The residual at the start of a load step is evaluated once: Newton's first iterate takes\n"
                           "the one IndSolverSolve computed for its tolerance, and that one is the residual at the\n"
                           "iterate.\n"
                           "Runs the command line's indentation (it must have an indenter).\n";

#include "ind_app.h"

typedef struct {
  Vec       F;           /* the residual evaluated again at the first iterate */
  PetscInt  solves;      /* Newton solves begun */
  PetscInt  reevaluated; /* of which SNES evaluated its first residual itself */
  PetscReal worst;       /* largest |F_offered - F_again| / |F_again| */
} Watch;

static PetscErrorCode FirstIterate(SNES snes, PetscInt it, PetscReal fnorm, void *ctx)
{
  Watch    *w = (Watch *)ctx;
  PetscInt  nfuncs;
  Vec       X, F;
  PetscReal diff, norm;

  PetscFunctionBeginUser;
  (void)fnorm;
  if (it) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(SNESGetNumberFunctionEvals(snes, &nfuncs)); /* zero at each SNESSolve's start */
  w->solves++;
  if (nfuncs) w->reevaluated++;
  PetscCall(SNESGetSolution(snes, &X));
  PetscCall(SNESGetFunction(snes, &F, NULL, NULL));
  if (!w->F) PetscCall(VecDuplicate(F, &w->F));
  PetscCall(SNESComputeFunction(snes, X, w->F));
  PetscCall(VecNorm(w->F, NORM_2, &norm));
  PetscCall(VecAXPY(w->F, -1.0, F));
  PetscCall(VecNorm(w->F, NORM_2, &diff));
  w->worst = PetscMax(w->worst, norm > 0 ? diff / norm : diff);
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  IndApp app;
  Watch  w = {NULL, 0, 0, 0.0};

  PetscFunctionBeginUser;
  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  PetscCall(IndAppCreate(PETSC_COMM_WORLD, &app));
  PetscCheck(IndAppGetContact(app), PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "Needs an indenter (-indenter_type)");
  PetscCall(SNESMonitorSet(IndSolverGetSNES(IndAppGetSolver(app)), FirstIterate, &w, NULL));
  PetscCall(IndAppRun(app));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%" PetscInt_FMT " Newton solves, %" PetscInt_FMT
    " of which evaluated their first residual again; the residual offered against the one at the iterate: %.1e\n",
    w.solves, w.reevaluated, (double)w.worst));
  /* Every solve of a step begins with the offered residual: this case has one outer iteration per step. The
     residual at the same displacement is the same computation, so equal in every bit. */
  PetscCheck(w.solves > 0 && w.reevaluated == 0 && w.worst == 0.0, PETSC_COMM_WORLD, PETSC_ERR_PLIB,
    "The first residual of a step: %" PetscInt_FMT " of %" PetscInt_FMT " solves evaluated it again, difference %g",
    w.reevaluated, w.solves, (double)w.worst);
  PetscCall(VecDestroy(&w.F));
  PetscCall(IndAppDestroy(&app));
  PetscCall(PetscFinalize());
  return 0;
}
