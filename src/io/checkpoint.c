#define _POSIX_C_SOURCE 200809L /* sigaction, gmtime_r, strtok_r */
#include <stdio.h>
#include <string.h>
#include <petscviewerhdf5.h>
#include "ind_checkpoint.h"
#include "ind_keyedio.h"
#include "ind_rundir.h"
#include "ind_version.h"

/* 3: a checksum on every dataset; 4: each object writes its own part; 5: the load path keeps the iterations of
   the attempts it cut back */
#define FORMAT "indent checkpoint 5"

/* Options that do not change the answer, only how it is computed, shown or stored: a restart may
   change them (a tighter tolerance to get past a hard step, another output directory layout...). */
static const char *const RunControl[] = {
  "ksp_",    "snes_",    "pc_",       "mg_",         "log",           "malloc",          "options_",      "help",
  "quiet",   "restart",  "output_",   "checkpoint_", "op_",           "info",            "on_error",      "viewer",
  "vec_view", "mat_",    "mesh_view", "dm_view",     "contact_monitor", "history",       "check_pointer", "fp_trap",
  "memory_view", "objects_dump", "newton_stall_its", "load_max_cutbacks", "version", "matptap_", "matmatmult_"};

static PetscBool IsRunControl(const char *name)
{
  for (size_t k = 0; k < sizeof(RunControl) / sizeof(RunControl[0]); ++k)
    if (!strncmp(name, RunControl[k], strlen(RunControl[k]))) return PETSC_TRUE;
  return PETSC_FALSE;
}

static int LineCompare(const void *a, const void *b)
{
  return strcmp(*(char *const *)a, *(char *const *)b);
}

PetscErrorCode IndCheckpointModelOptions(char **text)
{
  char  *all, *tok, *save = NULL, **lines;
  size_t len, n = 0, cap;

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsGetAll(NULL, &all));
  PetscCall(PetscStrlen(all, &len));
  cap = len / 2 + 2;
  PetscCall(PetscCalloc1(cap, &lines));
  /* "-a 1 -b -c x": a token starting with '-' and a letter names an option, others are its value */
  for (tok = strtok_r(all, " ", &save); tok; tok = strtok_r(NULL, " ", &save)) {
    const PetscBool name = tok[0] == '-' && ((tok[1] >= 'a' && tok[1] <= 'z') || (tok[1] >= 'A' && tok[1] <= 'Z'));
    if (name) {
      PetscCall(PetscStrallocpy(tok, &lines[n++]));
    } else if (n) {
      char  *joined;
      size_t l0, l1;
      PetscCall(PetscStrlen(lines[n - 1], &l0));
      PetscCall(PetscStrlen(tok, &l1));
      PetscCall(PetscMalloc1(l0 + l1 + 2, &joined));
      PetscCall(PetscSNPrintf(joined, l0 + l1 + 2, "%s %s", lines[n - 1], tok));
      PetscCall(PetscFree(lines[n - 1]));
      lines[n - 1] = joined;
    }
  }
  qsort(lines, n, sizeof(char *), LineCompare);
  PetscCall(PetscCalloc1(len + n + 2, text));
  for (size_t i = 0; i < n; ++i) {
    if (!IsRunControl(lines[i] + 1)) {
      PetscCall(PetscStrlcat(*text, lines[i], len + n + 2));
      PetscCall(PetscStrlcat(*text, "\n", len + n + 2));
    }
    PetscCall(PetscFree(lines[i]));
  }
  PetscCall(PetscFree(lines));
  PetscCall(PetscFree(all));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Copies the line of text starting at s (without its newline) into out. */
static void Line(const char *s, char *out, size_t len)
{
  size_t k = 0;
  for (; s && s[k] && s[k] != '\n' && k + 1 < len; ++k) out[k] = s[k];
  out[k] = 0;
}

void IndCheckpointOptionsDiffer(const char *saved, const char *here, char *what, size_t len)
{
  const char *a = saved, *b = here;

  what[0] = 0;
  while (*a || *b) {
    char la[256], lb[256], na[256], nb[256];
    Line(a, la, sizeof(la));
    Line(b, lb, sizeof(lb));
    if (strcmp(la, lb)) {
      int c;
      Line(a, na, sizeof(na));
      Line(b, nb, sizeof(nb));
      strtok(na, " ");
      strtok(nb, " ");
      c = !*a ? 1 : !*b ? -1 : strcmp(na, nb);
      if (c < 0) snprintf(what, len, "the checkpoint was made with %s, which this run does not give", la);
      else if (c > 0) snprintf(what, len, "this run gives %s, which the checkpoint was made without", lb);
      else snprintf(what, len, "the checkpoint was made with %s, this run gives %s", la, lb);
      return;
    }
    a += strlen(la) + (a[strlen(la)] == '\n');
    b += strlen(lb) + (b[strlen(lb)] == '\n');
  }
}

PetscErrorCode IndCheckpointWrite(MPI_Comm comm, IndDisc disc, const char path[], PetscInt step, PetscInt nparts,
                                  const IndStatePart parts[])
{
  IndStateFile f;
  PetscViewer  v;
  char         tmp[PETSC_MAX_PATH_LEN], petsc[256], *model;
  PetscMPIInt  rank, size;
  PetscInt     ranks;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  ranks = size;
  PetscCall(PetscSNPrintf(tmp, sizeof(tmp), "%s.tmp", path));
  PetscCall(IndStateFileOpen(comm, disc, tmp, FILE_MODE_WRITE, path, &f));
  PetscCall(IndStateFileGetViewer(f, &v));
  PetscCall(PetscGetVersion(petsc, sizeof(petsc)));
  PetscCall(IndCheckpointModelOptions(&model));
  PetscCall(PetscViewerHDF5WriteAttribute(v, "/", "format", PETSC_STRING, FORMAT));
  PetscCall(PetscViewerHDF5WriteAttribute(v, "/", "indent_version", PETSC_STRING, INDENT_VERSION));
  PetscCall(PetscViewerHDF5WriteAttribute(v, "/", "git_commit", PETSC_STRING, INDENT_GIT_COMMIT));
  PetscCall(PetscViewerHDF5WriteAttribute(v, "/", "petsc_version", PETSC_STRING, petsc));
  PetscCall(PetscViewerHDF5WriteAttribute(v, "/", "mpi_ranks", PETSC_INT, &ranks));
  PetscCall(PetscViewerHDF5WriteAttribute(v, "/", "model_options", PETSC_STRING, model[0] ? model : "(none)"));
  PetscCall(PetscViewerHDF5WriteAttribute(v, "/", "accepted_steps", PETSC_INT, &step));
  PetscCall(PetscFree(model));
  PetscCall(IndStateTransfer(f, nparts, parts));
  PetscCall(IndStateFileClose(&f));

  PetscCallMPI(MPI_Barrier(comm));
  if (!rank) {
    char      previous[PETSC_MAX_PATH_LEN];
    PetscBool exists;
    IndRunDirPreviousCheckpoint(path, previous, sizeof(previous));
    PetscCall(PetscTestFile(path, 'r', &exists));
    if (exists) PetscCall(IndRenameInto(path, previous));
    PetscCall(IndRenameInto(tmp, path));
  }
  PetscCallMPI(MPI_Barrier(comm));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A damaged checkpoint is refused in one line that names what is wrong and, when the one it replaced
   is whole, how to continue from that one. */
static PetscErrorCode CheckWhole(MPI_Comm comm, const char path[])
{
  char     why[256], previous[PETSC_MAX_PATH_LEN], why_previous[256], advice[PETSC_MAX_PATH_LEN + 128] = "";
  PetscInt step = -1;

  PetscFunctionBeginUser;
  PetscCall(IndCheckpointVerify(comm, path, NULL, why, sizeof(why)));
  if (!why[0]) PetscFunctionReturn(PETSC_SUCCESS);
  IndRunDirPreviousCheckpoint(path, previous, sizeof(previous));
  {
    PetscBool exists;
    PetscCall(PetscTestFile(previous, 'r', &exists));
    if (exists) PetscCall(IndCheckpointVerify(comm, previous, &step, why_previous, sizeof(why_previous)));
    if (exists && !why_previous[0])
      PetscCall(PetscSNPrintf(advice, sizeof(advice), "; the checkpoint before it, after step %" PetscInt_FMT
                              ", is whole: continue from it with -restart %s", step, previous));
    else if (exists)
      PetscCall(PetscSNPrintf(advice, sizeof(advice), "; the one before it, %s, is damaged too: %s", previous,
                              why_previous));
  }
  SETERRQ(comm, PETSC_ERR_FILE_UNEXPECTED, "-restart: checkpoint '%s' is damaged: %s%s", path, why, advice);
}

PetscErrorCode IndCheckpointCheck(MPI_Comm comm, const char path[])
{
  PetscViewer v;
  PetscBool   has, same = PETSC_FALSE;
  char       *format = NULL, *saved = NULL, *here = NULL, differ[600];

  PetscFunctionBeginUser;
  PetscCall(CheckWhole(comm, path));
  PetscCall(PetscViewerHDF5Open(comm, path, FILE_MODE_READ, &v));
  PetscCall(PetscViewerHDF5HasAttribute(v, "/", "format", &has));
  if (has) PetscCall(PetscViewerHDF5ReadAttribute(v, "/", "format", PETSC_STRING, NULL, &format));
  if (has) PetscCall(PetscStrcmp(format, FORMAT, &same));
  PetscCheck(same, comm, PETSC_ERR_FILE_UNEXPECTED, "-restart: '%s' is %s", path,
             has ? "a checkpoint of another indent version (its format differs)" : "not an indent checkpoint");
  PetscCall(PetscViewerHDF5ReadAttribute(v, "/", "model_options", PETSC_STRING, NULL, &saved));
  PetscCall(IndCheckpointModelOptions(&here));
  IndCheckpointOptionsDiffer(strcmp(saved, "(none)") ? saved : "", here, differ, sizeof(differ));
  PetscCheck(!differ[0], comm, PETSC_ERR_ARG_INCOMP,
    "-restart %s: %s (model options must match; solver and output options may differ)", path, differ);
  PetscCall(PetscViewerDestroy(&v));
  PetscCall(PetscFree(format));
  PetscCall(PetscFree(saved));
  PetscCall(PetscFree(here));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndCheckpointRead(MPI_Comm comm, IndDisc disc, const char path[], PetscInt nparts,
                                 const IndStatePart parts[])
{
  IndStateFile f;
  char         what[PETSC_MAX_PATH_LEN + 32];

  PetscFunctionBeginUser;
  PetscCall(PetscSNPrintf(what, sizeof(what), "-restart: checkpoint '%s'", path));
  PetscCall(IndStateFileOpen(comm, disc, path, FILE_MODE_READ, what, &f));
  PetscCall(IndStateTransfer(f, nparts, parts));
  PetscCall(IndStateFileClose(&f));
  PetscFunctionReturn(PETSC_SUCCESS);
}
