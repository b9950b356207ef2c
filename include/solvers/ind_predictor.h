#pragma once
/* Where each step's Newton iteration starts (-load_predictor): the last accepted increment extrapolated to
   the step (by its change of load factor, of depth under load control, or of slide in a scratch), the
   tangent response to the step's prescribed values, or the accepted state itself. It owns that increment,
   part of the run's state. */
#include "ind_solver.h"
#include "ind_state.h"

typedef enum { IND_PREDICTOR_EXTRAPOLATE, IND_PREDICTOR_TANGENT, IND_PREDICTOR_NONE } IndPredictorType;
extern const char *const IndPredictorTypes[];

typedef struct _p_IndPredictor *IndPredictor;

/* How the step about to be solved differs from the accepted state: the old and new load factor, depth (nm)
   and slide (nm); by_depth: load control, where the depth drives the step. */
typedef struct {
  PetscReal lambda_old, lambda;
  PetscReal depth_old, depth;
  PetscReal slide_old, slide;
  PetscBool by_depth;
} IndPredictorStep;

/* Reads -load_predictor; U gives the layout of the increment it keeps. */
PetscErrorCode IndPredictorCreate(MPI_Comm comm, Vec U, IndPredictor *predictor);
PetscErrorCode IndPredictorDestroy(IndPredictor *predictor);
/* Moves U, the accepted state, to the start of the step's Newton iteration (the tangent response through
   IndSolverPredict). */
PetscErrorCode IndPredictorApply(IndPredictor predictor, IndSolver solver, const IndPredictorStep *step, Vec U);
/* The step was accepted at U, from Uprev: its increment becomes the one to extrapolate. */
PetscErrorCode IndPredictorAccept(IndPredictor predictor, const IndPredictorStep *step, Vec U, Vec Uprev);
/* Its part of the state: the last increment and its changes of load factor, depth and slide. */
PetscErrorCode IndPredictorState(void *predictor, IndStateFile file);
