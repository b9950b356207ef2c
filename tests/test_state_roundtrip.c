#define _POSIX_C_SOURCE 200809L /* strtok_r */
static const char help[] = "Every object's state survives a save and a load. A run (the options of indent) takes\n"
  "-roundtrip_steps steps; its state is saved (A), loaded into a second application made from the same options and\n"
  "saved again (B). Every dataset of B must equal A's, bit for bit. The first application then loads A too (which\n"
  "changes nothing in it but the solver's cache, rebuilt by both), and both must take the same -roundtrip_more\n"
  "steps to the same displacement, bit for bit: an object whose state the parts leave out (or restore wrongly)\n"
  "changes the second run only. Files in -roundtrip_dir.\n";

#include "ind_app.h"

/* The datasets a state file lists (its attribute "datasets", one group/name per line), allocated. */
static PetscErrorCode Datasets(PetscViewer v, char **list)
{
  PetscFunctionBeginUser;
  PetscCall(PetscViewerHDF5ReadAttribute(v, "/", "datasets", PETSC_STRING, NULL, list));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Whether dataset group/name holds the same values in the two files. */
static PetscErrorCode SameDataset(PetscViewer va, PetscViewer vb, const char group[], const char name[],
                                  PetscBool *same)
{
  Vec         x[2];
  PetscViewer v[2] = {va, vb};

  PetscFunctionBeginUser;
  for (int k = 0; k < 2; ++k) {
    PetscCall(PetscViewerHDF5PushGroup(v[k], group));
    PetscCall(VecCreate(PetscObjectComm((PetscObject)va), &x[k]));
    PetscCall(PetscObjectSetName((PetscObject)x[k], name));
    PetscCall(VecLoad(x[k], v[k]));
    PetscCall(PetscViewerHDF5PopGroup(v[k]));
  }
  PetscCall(VecEqual(x[0], x[1], same));
  PetscCall(VecDestroy(&x[0]));
  PetscCall(VecDestroy(&x[1]));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Saves the application's parts into path (FILE_MODE_WRITE) or loads them from it. */
static PetscErrorCode Transfer(IndApp app, const char path[], PetscFileMode mode)
{
  IndStatePart parts[IND_APP_MAX_STATE_PARTS];
  IndStateFile f;
  PetscInt     n;

  PetscFunctionBeginUser;
  PetscCall(IndAppGetStateParts(app, &n, parts));
  PetscCall(IndStateFileOpen(IndAppGetComm(app), IndAppGetDisc(app), path, mode, path, &f));
  PetscCall(IndStateTransfer(f, n, parts));
  PetscCall(IndStateFileClose(&f));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Steps(IndApp app, PetscInt n)
{
  IndStepResult r;

  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < n; ++k) {
    PetscCall(IndAppStep(app, &r));
    PetscCheck(r.converged, PETSC_COMM_WORLD, PETSC_ERR_NOT_CONVERGED, "step %" PetscInt_FMT " failed: %s", k, r.why);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  IndApp       a, b;
  IndStatePart parts[IND_APP_MAX_STATE_PARTS];
  PetscViewer  va, vb;
  PetscInt     n, steps = 3, more = 2, failures = 0, checked = 0;
  char         dir[PETSC_MAX_PATH_LEN] = ".", pa[PETSC_MAX_PATH_LEN + 8], pb[PETSC_MAX_PATH_LEN + 8];
  char        *la = NULL, *lb = NULL, *line, *save = NULL;
  PetscBool    same;

  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  PetscCall(PetscOptionsGetInt(NULL, NULL, "-roundtrip_steps", &steps, NULL));
  PetscCall(PetscOptionsGetInt(NULL, NULL, "-roundtrip_more", &more, NULL));
  PetscCall(PetscOptionsGetString(NULL, NULL, "-roundtrip_dir", dir, sizeof(dir), NULL));
  PetscCall(PetscSNPrintf(pa, sizeof(pa), "%s/A.h5", dir));
  PetscCall(PetscSNPrintf(pb, sizeof(pb), "%s/B.h5", dir));

  PetscCall(IndAppCreate(PETSC_COMM_WORLD, &a));
  PetscCall(Steps(a, steps));
  PetscCall(Transfer(a, pa, FILE_MODE_WRITE));
  PetscCall(IndAppCreate(PETSC_COMM_WORLD, &b));
  PetscCall(Transfer(b, pa, FILE_MODE_READ));
  PetscCall(Transfer(b, pb, FILE_MODE_WRITE));
  PetscCall(IndAppGetStateParts(b, &n, parts));

  PetscCall(PetscViewerHDF5Open(PETSC_COMM_WORLD, pa, FILE_MODE_READ, &va));
  PetscCall(PetscViewerHDF5Open(PETSC_COMM_WORLD, pb, FILE_MODE_READ, &vb));
  PetscCall(Datasets(va, &la));
  PetscCall(Datasets(vb, &lb));
  PetscCall(PetscStrcmp(la, lb, &same));
  if (!same) failures++;
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s: the two files list the same datasets\n", same ? "ok" : "FAIL"));
  for (line = strtok_r(la, "\n", &save); line; line = strtok_r(NULL, "\n", &save)) {
    char *name = strrchr(line, '/');
    *name++    = 0;
    PetscCall(SameDataset(va, vb, line, name, &same));
    if (!same) failures++;
    checked++;
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s: %s/%s saved, loaded and saved again unchanged\n",
                          same ? "ok" : "FAIL", line, name));
  }
  PetscCall(PetscFree(la));
  PetscCall(PetscFree(lb));
  PetscCall(PetscViewerDestroy(&va));
  PetscCall(PetscViewerDestroy(&vb));

  PetscCall(Transfer(a, pa, FILE_MODE_READ));
  PetscCall(Steps(a, more));
  PetscCall(Steps(b, more));
  PetscCall(VecEqual(IndAppGetSolution(a), IndAppGetSolution(b), &same));
  if (!same) failures++;
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s: %" PetscInt_FMT " more steps from the loaded state reach the same "
                        "displacement, bit for bit (%" PetscInt_FMT " parts, %" PetscInt_FMT " datasets)\n",
                        same ? "ok" : "FAIL", more, n, checked));
  PetscCall(IndAppDestroy(&b));
  PetscCall(IndAppDestroy(&a));
  PetscCall(PetscFinalize());
  return failures ? 1 : 0;
}
