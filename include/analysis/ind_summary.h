#pragma once
/* The record of an indentation run and its summary: every accepted step's point of the curve, kept
   in memory, and at the end the Oliver-Pharr analysis of the unloading branch, the residual imprint's
   depth and pile-up, the true contact area at the largest load, iteration counts and wall time, printed
   and written to <output_dir>/summary.txt (for people) and summary.json (for scripts). */
#include "ind_oliverpharr.h"
#include "ind_indenter.h"
#include "ind_output.h"
#include "ind_contact.h"
#include "ind_warnings.h"
#include "ind_state.h"

typedef struct _p_IndSummary *IndSummary;

/* Reads the -op_* options of the analysis (shared with indent-op), checking each; epsilon and beta default to the
   indenter shape's (IndIndenterOPConstants). */
PetscErrorCode IndOPParamsSetFromOptions(MPI_Comm comm, IndIndenterType shape, IndOPParams *params);
PetscErrorCode IndSummaryCreate(MPI_Comm comm, IndIndenterType shape, IndSummary *summary);
PetscErrorCode IndSummaryDestroy(IndSummary *summary);
PetscErrorCode IndSummaryAddPoint(IndSummary summary, const IndCurvePoint *point);
/* The points so far (borrowed), and the Oliver-Pharr constants of -op_*. */
PetscErrorCode IndSummaryGetPoints(IndSummary summary, PetscInt *n, const IndCurvePoint **points);
const IndOPParams *IndSummaryGetOPParams(IndSummary summary);
/* -op_min_contact_nodes: nodes in contact (whole indent) below which H and E_r are withheld. */
PetscInt           IndSummaryGetMinContactNodes(IndSummary summary);
/* Its part of the state (ind_state.h): the curve so far. */
PetscErrorCode IndSummaryState(void *summary, IndStateFile file);
/* Where and how the run was made, for the summary's provenance. */
typedef struct {
  const char    *start_time; /* UTC, ISO 8601, of the run's first part */
  PetscLogDouble wall;       /* seconds, over all parts of a restarted run */
  PetscBool      restarted;  /* this part continued from a checkpoint */
  IndContact     contact;    /* for the check of the Oliver-Pharr area against the surface */
  IndWarnings   *warnings;   /* the run's; the summary's own are added */
  PetscBool      slid;       /* the indenter slid (a scratch): no Oliver-Pharr analysis */
  PetscInt       rejected_newton, rejected_linear; /* iterations of the attempts cut back, whole run */
} IndRunInfo;

/* Prints the summary (when print is true); rank 0 writes the two files into dir when write is true,
   each under a temporary name renamed into place. summary.json also records the options, versions,
   rank count, start and wall time, and the warnings of the run. */
PetscErrorCode IndSummaryFinish(IndSummary summary, const IndIndenter *indenter, const IndRunInfo *info,
  const char dir[],
                                PetscBool write, PetscBool print);
