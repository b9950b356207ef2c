#pragma once
/* HDF5 output through PETSc viewers, with an XDMF index that ParaView opens:
   /geometry/vertices and /topology/cells once, then per output step /fields/displacement (vertices),
   /fields/stress, /fields/strain, /fields/von_mises, /fields/plastic_strain, /fields/back_stress,
   /fields/yielding (cell averages), and with an indenter /fields/contact_pressure and
   /fields/contact_status (vertices); /fields/step holds the accepted step of each output step.
   Provenance as attributes of "/". */
#include "ind_warnings.h"
#include <petscviewerhdf5.h>
#include "ind_mesh.h"
#include "ind_disc.h"
#include "ind_assembly.h"
#include "ind_contact.h"
#include "ind_state.h"

#define IND_MAX_OUTPUT_STEPS 100000
/* Values recorded per output step for the XDMF index: accepted step, load factor, depth (nm), load (uN). */
#define IND_OUTPUT_INFO 4

/* One line of the load-displacement curve, <output_dir>/load_displacement.csv. */
typedef struct {
  PetscInt       step;
  PetscReal      t, depth, load; /* pseudo-time, nm, uN */
  PetscInt       contact, stick, slip, newton, outer, linear, cutbacks;
  PetscReal      penetration, area; /* nm, nm^2 */
  PetscReal      pileup, deepest;   /* nm: highest and lowest point of the contact surface vs the undeformed one */
  PetscLogDouble seconds;
} IndCurvePoint;

typedef struct _p_IndOutput *IndOutput;

PetscErrorCode IndOutputCreate(IndMesh mesh, IndDisc disc, IndOutput *out);
/* Adds the vertex fields contact_pressure (GPa) and contact_status (0 open, 1 stick, 2 slip). */
PetscErrorCode IndOutputSetContact(IndOutput out, IndContact contact);
/* With a densifying region the fields add the cells' plastic compaction (before the first write). */
PetscErrorCode IndOutputSetDensifying(IndOutput out, PetscBool densifying);
PetscErrorCode IndOutputDestroy(IndOutput *out);
/* Collective: the bytes of field values one written step adds to indent.h5 (0 without field output). */
PetscErrorCode IndOutputBytesPerStep(IndOutput out, PetscReal *bytes);
/* Collective, before the first step: steps_left more written steps must fit indent.h5 (an error
   otherwise), and a warning (into w, printed) gives the estimate when they would exceed
   -output_size_warning or the free space of the output directory's file system. */
PetscErrorCode IndOutputCheckSize(IndOutput out, PetscInt steps_left, IndWarnings *w);
/* A restarted run continues the earlier part's files: the curve is rewritten with the checkpoint's npts
   points (the lines of steps after the checkpoint go), and indent.h5 is extended from the checkpoint's
   output step, in the file's vertex and cell order whatever the rank count (output_resume.c). */
/* The output directory, the field file (indent.h5 in it), and whether fields and the curve are written. */
const char    *IndOutputGetDir(IndOutput out);
const char    *IndOutputGetFieldFile(IndOutput out);
PetscBool      IndOutputFieldsEnabled(IndOutput out);
PetscBool      IndOutputCurveEnabled(IndOutput out);
/* -output_fields_every N: a load program writes the fields of every N-th accepted step, of each segment's end
   and of its last step (IndLoadPathFieldStep); 1: every step. */
PetscInt       IndOutputFieldsEvery(IndOutput out);
/* Its part of the state (ind_state.h): the output steps written so far, their times and values. */
PetscErrorCode IndOutputState(void *output, IndStateFile file);
PetscErrorCode IndOutputResume(IndOutput out, PetscInt npts, const IndCurvePoint *pts);
/* Appends a line to the curve (rank 0 writes; flushed at once, so a killed run keeps its curve). */
PetscErrorCode IndOutputCurvePoint(IndOutput out, const IndCurvePoint *point);
/* Records what the XDMF index says of the coming output step: the accepted step number, the load program's
   pseudo-time t (the time value: it increases through loading, hold and unloading), the load factor and,
   with an indenter, its depth (nm) and load (uN). Call it before each IndOutputWriteStep. */
PetscErrorCode IndOutputSetStepInfo(IndOutput out, PetscInt step, PetscReal t, PetscReal lambda, PetscReal depth,
                                    PetscReal load);
/* Appends one step to the HDF5 file and rewrites the XDMF index; time is its time value only when
   IndOutputSetStepInfo was not called for it (nothing else is then known of the step). */
PetscErrorCode IndOutputWriteStep(IndOutput out, PetscReal time, Vec U, IndAssembly assembly);
