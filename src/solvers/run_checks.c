#include <stdio.h>
#include <string.h>
#include <stdlib.h>
#include "app_impl.h"
#include "ind_runchecks.h"

static PetscBool HasWarning(const IndWarnings *w, const char key[])
{
  for (PetscInt k = 0; k < w->n; ++k)
    if (!strcmp(w->key[k], key)) return PETSC_TRUE;
  return PETSC_FALSE;
}

PetscErrorCode IndWarningsAdd(MPI_Comm comm, IndWarnings *w, const char key[], PetscBool print, const char text[])
{
  PetscFunctionBeginUser;
  if (HasWarning(w, key)) PetscFunctionReturn(PETSC_SUCCESS);
  if (w->n < IND_MAX_WARNINGS) {
    PetscCall(PetscStrncpy(w->key[w->n], key, sizeof(w->key[0])));
    PetscCall(PetscStrncpy(w->text[w->n], text, sizeof(w->text[0])));
    w->n++;
  }
  if (print) PetscCall(PetscFPrintf(comm, PETSC_STDERR, "indent: warning: %s\n", text));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndWarningsState(void *obj, IndStateFile f)
{
  IndWarnings *w = (IndWarnings *)obj;
  char         count[32], name[48];
  PetscInt     n = w->n;

  PetscFunctionBeginUser;
  if (IndStateReading(f)) {
    PetscViewer v;
    PetscBool   has;
    PetscCall(IndStateFileGetViewer(f, &v));
    PetscCall(PetscViewerHDF5HasAttribute(v, "/", "warning_count", &has));
    if (!has) PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(PetscSNPrintf(count, sizeof(count), "%" PetscInt_FMT, n));
  PetscCall(IndStateString(f, "warning_count", count, sizeof(count)));
  if (!IndStateReading(f)) {
    for (PetscInt k = 0; k < n; ++k) {
      PetscCall(PetscSNPrintf(name, sizeof(name), "warning_key_%" PetscInt_FMT, k));
      PetscCall(IndStateString(f, name, w->key[k], sizeof(w->key[k])));
      PetscCall(PetscSNPrintf(name, sizeof(name), "warning_text_%" PetscInt_FMT, k));
      PetscCall(IndStateString(f, name, w->text[k], sizeof(w->text[k])));
    }
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  n = (PetscInt)strtol(count, NULL, 10);
  for (PetscInt k = 0; k < n; ++k) {
    char key[sizeof(w->key[0])], text[sizeof(w->text[0])];
    PetscCall(PetscSNPrintf(name, sizeof(name), "warning_key_%" PetscInt_FMT, k));
    PetscCall(IndStateString(f, name, key, sizeof(key)));
    PetscCall(PetscSNPrintf(name, sizeof(name), "warning_text_%" PetscInt_FMT, k));
    PetscCall(IndStateString(f, name, text, sizeof(text)));
    PetscCall(IndWarningsAdd(PETSC_COMM_SELF, w, key, PETSC_FALSE, text));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndRunCheckLoadingContact(IndApp app, const IndStepResult *r)
{
  PetscFunctionBeginUser;
  if (!app->contact || PetscAbsReal(r->t - 1.0) > 1e-12) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(IndContactCheckTouched(app->contact, app->path.depth_max, r->contact.contact));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndRunCheckInverted(IndApp app, const char label[], char warning[], size_t len)
{
  DM        dm;
  Vec       Uloc;
  PetscInt  counts[2];
  PetscReal jmin;

  PetscFunctionBeginUser;
  warning[0] = 0;
  PetscCall(IndDiscGetDM(app->disc, &dm));
  PetscCall(DMGetLocalVector(dm, &Uloc));
  PetscCall(DMGlobalToLocal(dm, app->U, INSERT_VALUES, Uloc));
  PetscCall(IndAssemblyCountInverted(app->assembly, Uloc, &counts[0], &jmin));
  PetscCall(DMRestoreLocalVector(dm, &Uloc));
  {
    const IndDiscLayout *L;
    PetscCall(IndDiscGetLayout(app->disc, &L));
    counts[1] = L->ncell;
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, counts, 2, MPIU_INT, MPI_SUM, app->comm));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &jmin, 1, MPIU_REAL, MPIU_MIN, app->comm));
  if (counts[0])
    PetscCall(PetscSNPrintf(warning, len,
                            "%" PetscInt_FMT " of %" PetscInt_FMT " cells are inverted %s (det F <= 0 at a quadrature "
                            "point, smallest %.6g): the displacement there is not physical; refine the mesh, reduce "
                            "the load or depth, or use -formulation finite, which cuts such steps back",
                            counts[0], counts[1], label, (double)jmin));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndRunCheckStep(IndApp app, const IndStepResult *r, IndWarnings *w, PetscBool print)
{
  char text[IND_WARNING_LEN], label[64];

  PetscFunctionBeginUser;
  PetscCall(IndRunCheckLoadingContact(app, r));
  if (app->contact) {
    PetscCall(IndContactCheckEdge(app->contact, r->depth, text, sizeof(text)));
    if (text[0]) PetscCall(IndWarningsAdd(app->comm, w, "contact_edge", print, text));
    PetscCall(PetscSNPrintf(label, sizeof(label), "at depth %.6g nm", (double)r->depth));
  } else PetscCall(PetscSNPrintf(label, sizeof(label), "at load factor %.6g", (double)r->lambda));
  /* At finite strain an inverted point fails the step, so an accepted state has none; a warning once
     given is not given again, so the pass over every quadrature point is spared after it. */
  if (!IndAssemblyIsFiniteStrain(app->assembly) && !HasWarning(w, "inverted_cells")) {
    PetscCall(IndRunCheckInverted(app, label, text, sizeof(text)));
    if (text[0]) PetscCall(IndWarningsAdd(app->comm, w, "inverted_cells", print, text));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}
