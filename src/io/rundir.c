#define _XOPEN_SOURCE 700 /* realpath */
#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "ind_rundir.h"
#include "ind_runlock.h"
#include "ind_files.h"
#include "ind_options.h"

/* Every file a run (and scripts/plot-indent.py and export-curves.py after it) puts in its directory: a
   fresh run in the directory must not leave any of an earlier run's beside its own. */
static const char *const RunFiles[] = {"indent.h5", "indent.xdmf", "indent.xdmf.tmp", "load_displacement.csv",
                                       "summary.txt", "summary.json", "checkpoint.h5", "checkpoint.h5.tmp",
                                       "checkpoint.previous.h5", "mesh.msh", "mesh.msh.tmp", "mesh.msh.log",
                                       "imprint.csv", "imprint.png", "stress_slice.png", "load_displacement.png",
                                       "curve.niget", "curve_hysitron.txt", "imprint.xyz", "imprint.gsf",
                                       "csm.csv", "csm.csv.tmp", "csm.png", "scratch.csv", "scratch.csv.tmp",
                                       "scratch.png", "groove_along.csv", "groove_across.csv", "groove.png",
                                       IND_STOPPED_FILE};
#define NRUNFILES ((int)(sizeof(RunFiles) / sizeof(RunFiles[0])))

void IndRunDirPreviousCheckpoint(const char path[], char *previous, size_t len)
{
  const size_t n = strlen(path);

  if (n > 3 && !strcmp(path + n - 3, ".h5")) snprintf(previous, len, "%.*s.previous.h5", (int)(n - 3), path);
  else snprintf(previous, len, "%s.previous", path);
}

PetscErrorCode IndRenameInto(const char tmp[], const char path[])
{
  PetscFunctionBeginUser;
  PetscCheck(rename(tmp, path) == 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "Cannot rename '%s' to '%s': %s", tmp, path,
             strerror(errno));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* On rank 0: what the path is (0 missing, 1 directory, 2 something else) and the run files in it. */
static void Inspect(const char dir[], int *kind, char found[], size_t len)
{
  struct stat st;

  found[0] = 0;
  if (stat(dir, &st)) {
    *kind = 0;
    return;
  }
  *kind = S_ISDIR(st.st_mode) ? 1 : 2;
  if (*kind != 1) return;
  for (int k = 0; k < NRUNFILES; ++k) {
    char path[2 * PETSC_MAX_PATH_LEN];
    snprintf(path, sizeof(path), "%s/%s", dir, RunFiles[k]);
    if (access(path, F_OK)) continue;
    if (strlen(found) + strlen(RunFiles[k]) + 3 < len) {
      if (found[0]) strcat(found, ", ");
      strcat(found, RunFiles[k]);
    }
  }
}

/* -output_overwrite: the earlier run's files go, except the mesh this run reads (-mesh_file may be the
   earlier run's mesh.msh). */
static PetscErrorCode RemoveRunFiles(MPI_Comm comm, const char dir[])
{
  char        mesh[PETSC_MAX_PATH_LEN] = "", real_mesh[PETSC_MAX_PATH_LEN] = "", failed[2 * PETSC_MAX_PATH_LEN] = "";
  PetscMPIInt rank;
  int         err = 0;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCall(PetscOptionsGetString(NULL, NULL, "-mesh_file", mesh, sizeof(mesh), NULL));
  if (!rank) {
    if (mesh[0] && !realpath(mesh, real_mesh)) real_mesh[0] = 0;
    for (int k = 0; k < NRUNFILES && !err; ++k) {
      char path[2 * PETSC_MAX_PATH_LEN], real[PETSC_MAX_PATH_LEN];
      snprintf(path, sizeof(path), "%s/%s", dir, RunFiles[k]);
      if (access(path, F_OK)) continue;
      if (real_mesh[0] && realpath(path, real) && !strcmp(real, real_mesh)) continue;
      if (unlink(path)) {
        err = errno;
        snprintf(failed, sizeof(failed), "%s", path);
      }
    }
  }
  PetscCallMPI(MPI_Bcast(&err, 1, MPI_INT, 0, comm));
  PetscCallMPI(MPI_Bcast(failed, sizeof(failed), MPI_CHAR, 0, comm));
  PetscCheck(!err, comm, PETSC_ERR_FILE_WRITE, "-output_overwrite: cannot remove '%s': %s", failed, strerror(err));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The checkpoint a -restart value names: the file itself, or checkpoint.h5 in a directory. */
static PetscErrorCode RestartFile(MPI_Comm comm, const char value[], char file[], size_t len)
{
  PetscBool isdir = PETSC_FALSE, isfile = PETSC_FALSE;

  PetscFunctionBeginUser;
  PetscCall(PetscTestDirectory(value, 'r', &isdir));
  if (isdir) PetscCall(PetscSNPrintf(file, len, "%s/checkpoint.h5", value));
  else PetscCall(PetscStrncpy(file, value, len));
  PetscCall(PetscTestFile(file, 'r', &isfile));
  PetscCheck(isfile, comm, PETSC_ERR_FILE_OPEN, "-restart %s: no checkpoint %s%s", value,
    isdir ? "in that directory (" : "file '",
             isdir ? "checkpoint.h5)" : "'");
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Lock(MPI_Comm comm, const char dir[], const char option[])
{
  char warning[2 * PETSC_MAX_PATH_LEN + 256];

  PetscFunctionBeginUser;
  PetscCall(IndRunLockTake(comm, dir, option, warning, sizeof(warning)));
  if (warning[0]) PetscCall(PetscFPrintf(comm, PETSC_STDERR, "indent: warning: %s\n", warning));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndRunDirSetUp(MPI_Comm comm, PetscBool writes, IndRunDir *rd)
{
  char        restart[PETSC_MAX_PATH_LEN] = "", found[1024];
  PetscBool   has_restart = PETSC_FALSE;
  PetscMPIInt rank;
  int         kind = 0;

  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(rd, sizeof(*rd)));
  PetscCall(PetscStrncpy(rd->dir, "output", sizeof(rd->dir)));
  PetscOptionsBegin(comm, NULL, IND_TITLE "Output directory and restart", "Output");
  PetscCall(IndOptionsString("-output_dir", "Directory of the run's files (created if missing)", "dir", NULL, rd->dir,
                             rd->dir, sizeof(rd->dir), NULL));
  PetscCall(IndOptionsBool("-output_overwrite", "Replace the files of an earlier run in -output_dir", rd->overwrite,
                           &rd->overwrite, NULL));
  PetscCall(IndOptionsString("-restart", "Continue from a checkpoint: its file, or the directory holding checkpoint.h5",
                             "file or dir", "none", restart, restart, sizeof(restart), &has_restart));
  PetscOptionsEnd();
  PetscCheck(rd->dir[0], comm, PETSC_ERR_ARG_WRONG, "-output_dir must not be empty");
  PetscCall(PetscSNPrintf(rd->checkpoint, sizeof(rd->checkpoint), "%s/checkpoint.h5", rd->dir));
  PetscCheck(!has_restart || restart[0], comm, PETSC_ERR_ARG_WRONG,
    "-restart needs a checkpoint file or the directory holding one");
  PetscCheck(!(has_restart && rd->overwrite), comm, PETSC_ERR_ARG_INCOMP,
    "-restart continues a run and -output_overwrite replaces it: give one");
  /* A listing (-help, or the option check before a .geo is meshed) reads the options and touches nothing:
     no lock, no checkpoint read. */
  if (IndHelpListing() || (!writes && !has_restart)) PetscFunctionReturn(PETSC_SUCCESS);

  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (!rank) Inspect(rd->dir, &kind, found, sizeof(found));
  PetscCallMPI(MPI_Bcast(&kind, 1, MPI_INT, 0, comm));
  PetscCallMPI(MPI_Bcast(found, sizeof(found), MPI_CHAR, 0, comm));
  PetscCheck(kind != 2, comm, PETSC_ERR_FILE_OPEN, "-output_dir '%s' exists and is not a directory", rd->dir);

  if (has_restart) {
    char file[PETSC_MAX_PATH_LEN], real_ckpt[PETSC_MAX_PATH_LEN] = "", real_here[PETSC_MAX_PATH_LEN] = "";
    PetscCall(RestartFile(comm, restart, file, sizeof(file)));
    /* Output continues beside the checkpoint: the run's files there are the earlier part of this run. */
    if (!rank) {
      char previous[PETSC_MAX_PATH_LEN], real_previous[PETSC_MAX_PATH_LEN];
      if (!realpath(file, real_ckpt)) real_ckpt[0] = 0;
      if (kind != 1 || !realpath(rd->checkpoint, real_here)) real_here[0] = 0;
      /* or the checkpoint the last one replaced, kept beside it */
      IndRunDirPreviousCheckpoint(rd->checkpoint, previous, sizeof(previous));
      if (kind == 1 && real_ckpt[0] && realpath(previous, real_previous) && !strcmp(real_ckpt, real_previous))
        PetscCall(PetscStrncpy(real_here, real_previous, sizeof(real_here)));
    }
    PetscCallMPI(MPI_Bcast(real_ckpt, sizeof(real_ckpt), MPI_CHAR, 0, comm));
    PetscCallMPI(MPI_Bcast(real_here, sizeof(real_here), MPI_CHAR, 0, comm));
    {
      PetscBool same;
      PetscCall(PetscStrcmp(real_ckpt, real_here, &same));
      PetscCheck(same && real_ckpt[0], comm, PETSC_ERR_ARG_INCOMP,
                 "-restart %s: the checkpoint must lie in -output_dir '%s' (the run continues there): give "
                 "-output_dir the checkpoint's directory",
                 restart, rd->dir);
    }
    PetscCall(PetscStrncpy(rd->restart_file, file, sizeof(rd->restart_file)));
    PetscCall(Lock(comm, rd->dir, "-restart"));
    rd->restart = rd->ready = PETSC_TRUE;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  /* The directory's owner first: a live run's files are neither judged nor removed. */
  if (kind == 0) PetscCall(IndMakeDirectory(comm, rd->dir, "-output_dir"));
  PetscCall(Lock(comm, rd->dir, rd->overwrite ? "-output_overwrite" : "-output_dir"));
  if (found[0]) {
    PetscCheck(rd->overwrite, comm, PETSC_ERR_FILE_OPEN,
               "-output_dir '%s' already holds a run (%s): give -output_overwrite to replace it, -restart %s to "
               "continue it, or another -output_dir",
               rd->dir, found, rd->dir);
    PetscCall(RemoveRunFiles(comm, rd->dir));
  }
  PetscCall(IndMakeDirectory(comm, rd->dir, "-output_dir"));
  rd->ready = PETSC_TRUE;
  PetscFunctionReturn(PETSC_SUCCESS);
}
