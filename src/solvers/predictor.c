#include "ind_predictor.h"
#include "ind_options.h"

const char *const IndPredictorTypes[] = {"extrapolate", "tangent", "none", "IndPredictorType", "IND_PREDICTOR_",
                                         NULL};

struct _p_IndPredictor {
  IndPredictorType type;
  Vec              dU;      /* increment of the last accepted step */
  PetscReal        dlambda; /* its load-factor increment; 0 before the first step */
  PetscReal        ddepth;  /* its indenter-depth increment, nm */
  PetscReal        dslide;  /* its slide (scratch) increment, nm */
};

PetscErrorCode IndPredictorCreate(MPI_Comm comm, Vec U, IndPredictor *out)
{
  IndPredictor p;

  PetscFunctionBeginUser;
  PetscCall(PetscNew(&p));
  p->type = IND_PREDICTOR_EXTRAPOLATE;
  /* a title of its own: PETSc lists a (prefix, title) pair's block once */
  PetscOptionsBegin(comm, NULL, IND_TITLE "Start of the load steps", "Run");
  PetscCall(IndOptionsEnum("-load_predictor", "Start of each step's Newton iteration", IndPredictorTypes,
                           (PetscEnum)p->type, (PetscEnum *)&p->type, NULL));
  PetscOptionsEnd();
  PetscCall(VecDuplicate(U, &p->dU));
  PetscCall(VecZeroEntries(p->dU));
  *out = p;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndPredictorDestroy(IndPredictor *p)
{
  PetscFunctionBeginUser;
  if (!*p) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(VecDestroy(&(*p)->dU));
  PetscCall(PetscFree(*p));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The tangent response to the new prescribed values, and where the indenter rises the elastic unloading with the
   nodes in contact rising with it. */
static PetscErrorCode Tangent(IndSolver s, const IndPredictorStep *st, Vec U)
{
  PetscFunctionBeginUser;
  PetscCall(IndSolverPredict(s, st->lambda_old, st->lambda, U));
  if (st->depth < st->depth_old) PetscCall(IndSolverPredictUnloading(s, st->depth_old - st->depth, U));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The prescribed values alone would strain only the boundary layer of cells, which then yields in the first
   iterate and sends Newton astray; either predictor starts it near the answer. The last increment is scaled by
   the change of load factor; a hold or a reversal takes the tangent response instead (for an indenter alone,
   the last state, moved by the elastic unloading where the indenter rises). Not across a reversal: unloading
   from a plastic state is nothing like the loading increment reversed (that guess made Newton diverge 9 times
   in a row on a Vickers indentation). Under load control the
   depth drives the step: the increment is scaled by the change of depth. A slide drives it in a scratch: the
   last slide's increment, scaled (at its start, the accepted state). */
PetscErrorCode IndPredictorApply(IndPredictor p, IndSolver s, const IndPredictorStep *st, Vec U)
{
  const PetscBool extrapolate = p->type == IND_PREDICTOR_EXTRAPOLATE ? PETSC_TRUE : PETSC_FALSE;
  const PetscBool tangent     = p->type != IND_PREDICTOR_NONE ? PETSC_TRUE : PETSC_FALSE;

  PetscFunctionBeginUser;
  if (st->slide > st->slide_old) {
    if (extrapolate && p->dslide > 0) PetscCall(VecAXPY(U, (st->slide - st->slide_old) / p->dslide, p->dU));
  } else if (st->by_depth) {
    const PetscReal ratio = p->ddepth != 0 ? (st->depth - st->depth_old) / p->ddepth : 0;
    if (extrapolate && ratio > 0) PetscCall(VecAXPY(U, ratio, p->dU));
    else if (tangent) PetscCall(Tangent(s, st, U));
  } else if (extrapolate && (st->lambda - st->lambda_old) * p->dlambda > 0)
    PetscCall(VecAXPY(U, (st->lambda - st->lambda_old) / p->dlambda, p->dU));
  else if (tangent) PetscCall(Tangent(s, st, U));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndPredictorAccept(IndPredictor p, const IndPredictorStep *st, Vec U, Vec Uprev)
{
  PetscFunctionBeginUser;
  p->ddepth  = st->depth - st->depth_old;
  p->dslide  = st->slide - st->slide_old;
  p->dlambda = st->lambda - st->lambda_old;
  PetscCall(VecWAXPY(p->dU, -1.0, Uprev, U));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndPredictorState(void *obj, IndStateFile f)
{
  IndPredictor p    = (IndPredictor)obj;
  PetscReal    s[3] = {p->dlambda, p->ddepth, p->dslide};

  PetscFunctionBeginUser;
  PetscCall(IndStateReals(f, "increments", 3, s));
  PetscCall(IndStateNodes(f, "dU", p->dU));
  p->dlambda = s[0];
  p->ddepth  = s[1];
  p->dslide  = s[2];
  PetscFunctionReturn(PETSC_SUCCESS);
}
