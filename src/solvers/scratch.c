#include "ind_scratch.h"
#include "ind_options.h"
#include "ind_stepcsv.h"

#define SCRATCH_HEADER "step,t,distance_nm,x_nm,y_nm,depth_nm,normal_uN,lateral_uN,side_uN,friction,contact,stick,slip"

PetscErrorCode IndScratchSetFromOptions(MPI_Comm comm, PetscBool indenter, IndScratch *s)
{
  PetscInt  ndir = 2;
  PetscBool has_length, has_dir, has_steps;
  PetscReal norm;

  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(s, sizeof(*s)));
  s->dir[0] = 1.0;
  s->steps  = 20;
  PetscOptionsBegin(comm, NULL, IND_TITLE "Scratch (-scratch_*)", "Scratch");
  PetscCall(IndOptionsReal("-scratch_length",
    "Scratch test: after loading (and the hold), the indenter slides this far "
    "at its depth (or load, under -load_force), then unloads", "nm", "0: no scratch", s->length, &s->length,
    &has_length));
  PetscCall(IndOptionsRealArray("-scratch_direction", "Direction of the slide in the surface's plane", "x,y", "1,0",
    s->dir, &ndir, &has_dir));
  PetscCall(IndOptionsInt("-scratch_steps", "Number of steps of the slide when none is cut back", NULL, s->steps,
    &s->steps, &has_steps));
  PetscOptionsEnd();
  PetscCheck(s->length >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-scratch_length must be >= 0 (nm), got %.6g",
             (double)s->length);
  PetscCheck(s->length == 0 || indenter, comm, PETSC_ERR_ARG_WRONG,
    "-scratch_length needs an indenter: -indenter_type");
  PetscCheck(s->length > 0 || !(has_dir || has_steps), comm, PETSC_ERR_ARG_WRONG,
             "-scratch_%s needs a scratch: -scratch_length > 0 (nm)", has_dir ? "direction" : "steps");
  PetscCheck(!has_dir || ndir == 2, comm, PETSC_ERR_ARG_SIZ,
    "-scratch_direction needs two values x,y, got %" PetscInt_FMT,
             ndir);
  norm = PetscSqrtReal(s->dir[0] * s->dir[0] + s->dir[1] * s->dir[1]);
  PetscCheck(norm > 0 && !PetscIsInfOrNanReal(norm), comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-scratch_direction %.6g,%.6g has no direction", (double)s->dir[0], (double)s->dir[1]);
  s->dir[0] /= norm;
  s->dir[1] /= norm;
  PetscCheck(s->steps >= 1, comm, PETSC_ERR_ARG_OUTOFRANGE, "-scratch_steps must be >= 1, got %" PetscInt_FMT,
    s->steps);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndScratchSetUp(IndScratch *s, IndContact c, IndBC bc)
{
  const IndIndenter *ind  = IndContactGetIndenter(c);
  MPI_Comm           comm = IndContactGetComm(c);
  PetscReal          end[2], extent[4];
  PetscInt           nspec;
  const IndBCSpec   *spec;
  const char        *surface;

  PetscFunctionBeginUser;
  PetscCall(IndBCGetSpecs(bc, &nspec, &spec));
  PetscCall(IndContactGetSurface(c, &surface, extent));
  s->origin[0] = ind->axis[0];
  s->origin[1] = ind->axis[1];
  if (s->length == 0) PetscFunctionReturn(PETSC_SUCCESS);
  for (PetscInt k = 0; k < nspec; ++k) {
    const int n = IndContactPlaneThroughAxis(&spec[k], ind);
    /* The mirror image of the indenter slides with it only along the plane. */
    PetscCheck(!n || PetscAbsReal(s->dir[n - 1]) <= 1e-12, comm, PETSC_ERR_ARG_INCOMP,
               "-scratch_direction %.6g,%.6g leaves the symmetry plane '%s' (%c = %.6g nm) through the indenter's "
                 "axis: slide "
               "along it (%s) or use a full model",
               (double)s->dir[0], (double)s->dir[1], spec[k].label, n == 1 ? 'x' : 'y', (double)spec[k].plane,
               n == 1 ? "0,1 or 0,-1" : "1,0 or -1,0");
  }
  IndScratchAxis(s, 1.0, end);
  PetscCheck(end[0] >= extent[0] && end[0] <= extent[1] && end[1] >= extent[2] && end[1] <= extent[3],
             comm, PETSC_ERR_USER_INPUT,
             "-scratch_length %.6g nm takes the indenter's axis from (%.6g, %.6g) to (%.6g, %.6g) nm, off the contact "
               "surface "
             "'%s' (x from %.6g to %.6g, y from %.6g to %.6g nm)",
             (double)s->length, (double)s->origin[0], (double)s->origin[1], (double)end[0], (double)end[1], surface,
             (double)extent[0], (double)extent[1], (double)extent[2], (double)extent[3]);
  PetscFunctionReturn(PETSC_SUCCESS);
}

void IndScratchAxis(const IndScratch *s, PetscReal f, PetscReal axis[2])
{
  for (int d = 0; d < 2; ++d) axis[d] = s->origin[d] + f * s->length * s->dir[d];
}

void IndScratchForces(const IndScratch *s, const IndContactSummary *cs, PetscReal *normal, PetscReal *lateral,
                      PetscReal *side)
{
  *normal  = 1e-3 * cs->load;
  *lateral = 1e-3 * (cs->force[0] * s->dir[0] + cs->force[1] * s->dir[1]);
  *side    = 1e-3 * (-cs->force[0] * s->dir[1] + cs->force[1] * s->dir[0]);
}

PetscErrorCode IndScratchWrite(MPI_Comm comm, const char dir[], const IndScratch *s, PetscInt step, PetscReal t,
                               PetscReal f, PetscReal depth, const IndContactSummary *cs)
{
  PetscReal normal, lateral, side, axis[2];
  char      line[512];

  PetscFunctionBeginUser;
  IndScratchForces(s, cs, &normal, &lateral, &side);
  IndScratchAxis(s, f, axis);
  PetscCall(PetscSNPrintf(line, sizeof(line),
                          "%" PetscInt_FMT ",%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%.10g,%" PetscInt_FMT
                          ",%" PetscInt_FMT ",%" PetscInt_FMT,
                          step, (double)t, (double)(f * s->length), (double)axis[0], (double)axis[1], (double)depth,
                          (double)normal, (double)lateral, (double)side, normal > 0 ? (double)(lateral / normal) : 0.0,
                          cs->contact, cs->stick, cs->slip));
  PetscCall(IndStepCSVAppend(comm, dir, IND_SCRATCH_FILE, SCRATCH_HEADER, line));
  PetscFunctionReturn(PETSC_SUCCESS);
}
