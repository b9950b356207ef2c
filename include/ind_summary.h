#pragma once
/* The record of an indentation run and its summary: every accepted step's point of the curve, kept
   in memory, and at the end the Oliver-Pharr analysis of the unloading branch, the residual imprint's
   depth and pile-up, the true contact area at the largest load, iteration counts and wall time, printed
   and written to <output_dir>/summary.txt (for people) and summary.json (for scripts). */
#include "ind_oliverpharr.h"
#include "ind_indenter.h"
#include "ind_output.h"

typedef struct _p_IndSummary *IndSummary;
struct _p_IndSummary {
  MPI_Comm       comm;
  IndOPParams    op;
  IndCurvePoint *pts; /* accepted steps */
  PetscInt       n, cap;
  PetscLogDouble start; /* wall clock at creation */
};

/* Reads the -op_* options of the analysis (shared with indent-op), checking each. */
PetscErrorCode IndOPParamsSetFromOptions(MPI_Comm comm, IndOPParams *params);
PetscErrorCode IndSummaryCreate(MPI_Comm comm, IndSummary *summary);
PetscErrorCode IndSummaryDestroy(IndSummary *summary);
PetscErrorCode IndSummaryAddPoint(IndSummary summary, const IndCurvePoint *point);
/* Prints the summary (when print is true); rank 0 writes the two files into dir when write is true. */
PetscErrorCode IndSummaryFinish(IndSummary summary, const IndIndenter *indenter, const char dir[], PetscBool write, PetscBool print);
