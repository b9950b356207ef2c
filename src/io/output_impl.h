#pragma once
/* Private to src/io/: the fields of IndOutput, continuing a field file, and the curve's text format. */
#include <stdio.h>
#include "ind_output.h"

struct _p_IndOutput {
  IndDisc              disc;
  DM                   dm;      /* the mesh's, which carries the displacement (borrowed) */
  PetscBool            simplex; /* tetrahedra or triangles */
  PetscBool            planar;  /* triangles or quadrilaterals: an axisymmetric section */
  const char          *source;  /* the mesh file, or "box" (the mesh's) */
  const IndDiscLayout *layout;  /* the discretisation's */
  PetscBool   enabled;
  PetscBool   curve;   /* -output_curve */
  PetscInt    every;   /* -output_fields_every: the caller writes every N-th step's fields (and others) */
  PetscReal   size_warning; /* -output_size_warning, GB: field output expected beyond it is announced */
  FILE       *csv;     /* rank 0, opened at the first point */
  char        dir[PETSC_MAX_PATH_LEN];
  char        h5name[PETSC_MAX_PATH_LEN];
  PetscViewer viewer;
  DM          vdm; /* the vertex layout (3 values a vertex); the fields are vectors of rows, without a DM */
  Vec           Uloc, vloc, disp, stress, strain, vonmises, plastic, back, yielding;
  PetscBool     densifying; /* a region is densifying: the cells' compaction is written too */
  Vec           compaction;
  IndCellFields cells; /* per local cell, filled by the assembly */
  IndContact    contact;                      /* NULL without an indenter */
  Vec           Gc, Cloc, c3, pressure, status; /* contact fields: disc layout (global, local),
    vertex rows of 3 and of 1 */
  PetscInt    nsteps;
  PetscReal  *times;    /* per output step: XDMF time value, the pseudo-time t given to IndOutputSetStepInfo */
  PetscReal  *info;     /* per output step: IND_OUTPUT_INFO values, NaN where not known */
  PetscBool   info_set; /* IndOutputSetStepInfo was called for the coming step */
  PetscBool   resume;               /* continue indent.h5 (a restarted run) rather than create it */
  struct _n_IndOutputPerm *perm;   /* resumed: where this run's vertices and cells sit in the file */
  PetscInt    nvert, ncell, corners; /* global counts */
};


/* The curve's CSV header and one line of it. */
void           IndOutputCurveHeader(FILE *fp);
void           IndOutputCurveLine(FILE *fp, const IndCurvePoint *p);
/* A new field file: the cells' keys beside the topology, so that a restarted run can continue it. */
PetscErrorCode IndOutputWriteCellKeys(IndOutput out);
/* Opens indent.h5 of the earlier part for appending and locates this run's vertices and cells in it. */
PetscErrorCode IndOutputOpenResumed(IndOutput out);
/* Writes a vertex (cells false) or cell field (the vector's name and block size) as the current step of its
   dataset, in the file's order when the file was resumed. */
PetscErrorCode IndOutputViewField(IndOutput out, Vec x, PetscBool cells);
PetscErrorCode IndOutputPermDestroy(IndOutput out);

/* Vertices per cell: tetrahedra 4, hexahedra 8, triangles 3, quadrilaterals 4. */
static inline PetscInt IndOutputCorners(IndOutput o)
{
  return o->planar ? (o->simplex ? 3 : 4) : (o->simplex ? 4 : 8);
}
