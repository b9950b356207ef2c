#pragma once
/* Private to the output module: continuing a field file and the curve's text format. */
#include <stdio.h>
#include "ind_output.h"

/* The curve's CSV header and one line of it. */
void           IndOutputCurveHeader(FILE *fp);
void           IndOutputCurveLine(FILE *fp, const IndCurvePoint *p);
/* A new field file: the cells' keys beside the topology, so that a restarted run can continue it. */
PetscErrorCode IndOutputWriteCellKeys(IndOutput out);
/* Opens indent.h5 of the earlier part for appending and locates this run's vertices and cells in it. */
PetscErrorCode IndOutputOpenResumed(IndOutput out);
/* VecView of a vertex (cells false) or cell field, in the file's order when the file was resumed. */
PetscErrorCode IndOutputViewField(IndOutput out, Vec x, PetscBool cells);
PetscErrorCode IndOutputPermDestroy(IndOutput out);
