#define _POSIX_C_SOURCE 200809L /* setenv */
static const char help[] = "indent: finite-element nanoindentation of elasto-plastic films (PETSc).\n"
                           "With -help, lists every option the given inputs read (with the values given) and exits\n"
                           "without solving, meshing a .geo or writing a file; see doc/options.md for a guide.\n";

#include <stdlib.h>
#include <string.h>
#include "ind_app.h"
#include "ind_optionsfile.h"
#include "ind_parentwatch.h"
#include "ind_signals.h"
#include "ind_iofault.h"
#include "ind_runlock.h"
#include "ind_files.h"
#include "ind_options.h"

static int stopped; /* the signal that stopped the run after its checkpoint (0: none) */

/* gmsh meshes a .geo -mesh_file for minutes on a fine mesh: a misspelt option is found before that, by a
   set-up that reads every option as -help's listing does (the .geo's regions without its mesh, no file
   written), whose last act is the unknown-option check. Not for a .geo that declares no physical volume:
   its regions are known only from gmsh's mesh. */
static PetscErrorCode CheckOptionsFirst(void)
{
  char        file[PETSC_MAX_PATH_LEN] = "";
  PetscBool   set;
  size_t      len;
  IndApp      app;
  IndGeoInfo *info;
  PetscInt    nvolumes;

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsGetString(NULL, NULL, "-mesh_file", file, sizeof(file), &set));
  len = strlen(file);
  if (!set || len < 4 || strcmp(file + len - 4, ".geo") || IndHelpListing()) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscNew(&info));
  PetscCall(IndGeoRead(PETSC_COMM_WORLD, file, info));
  nvolumes = info->nvolumes;
  PetscCall(PetscFree(info));
  if (!nvolumes) PetscFunctionReturn(PETSC_SUCCESS);
  IndHelpSetChecking(PETSC_TRUE);
  PetscCall(IndAppCreate(PETSC_COMM_WORLD, &app));
  PetscCall(IndAppDestroy(&app));
  IndHelpSetChecking(PETSC_FALSE);
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Run(void)
{
  IndApp app;

  PetscFunctionBeginUser;
  PetscCall(IndOptionsCheckSpelling(PETSC_COMM_WORLD));
  PetscCall(CheckOptionsFirst());
  PetscCall(IndAppCreate(PETSC_COMM_WORLD, &app));
  /* the set-up has read (and listed) every option; a user asking for the list does not want the run */
  if (!IndHelpListing()) PetscCall(IndAppRun(app));
  stopped = IndAppStoppedBy(app);
  PetscCall(IndAppDestroy(&app));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* "-help intro" prints PETSc's introduction and exits inside PetscInitialize: it keeps PETSc's printing. */
static PetscBool HelpIntro(int argc, char **argv)
{
  for (int k = 1; k + 1 < argc; ++k)
    if (!strcmp(argv[k], "-help") && !strcmp(argv[k + 1], "intro")) return PETSC_TRUE;
  return PETSC_FALSE;
}

int main(int argc, char **argv)
{
  PetscErrorCode       ierr;
  PetscBool            intro = HelpIntro(argc, argv);
  IndOptionsFileCopies copies;

  if (IndArgsCheckStray("indent", argc, argv) || IndOptionsFilesPrepare("indent", argc, argv, &copies)) return 1;
  /* a rank left running by a killed launcher would write on unseen */
  (void)IndParentWatchStart(IndSignalsReceived);
  /* PT-Scotch (the default partitioner) runs threads whose race draws a different partition each run,
     and the answer then differs in its last digits: one thread, unless the user asks otherwise. */
  (void)setenv("SCOTCH_PTHREAD_NUMBER", "1", 0);
  if (!intro) IndHelpCaptureBegin();
  ierr = PetscInitialize(&argc, &argv, NULL, intro ? help : NULL);
  IndOptionsFilesRemoveCopies(&copies);
  if (ierr) return (int)ierr;
  ierr = IndErrorSetUp("indent");
  if (!ierr) ierr = IndIOFaultSetUp();
  if (!ierr) ierr = IndHelpCaptureEnd();
  if (!ierr) ierr = Run();
  /* a listing stopped by a bad input still shows what it read, then the error */
  if (IndHelpListing()) (void)IndHelpPrint(help);
  IndRunLockRelease();
  {
    const int status = IndErrorFinish(ierr);
    /* A batch script resubmits on IND_EXIT_CHECKPOINTED: the checkpoint is written, the run not finished. */
    return status ? status : stopped ? IND_EXIT_CHECKPOINTED : 0;
  }
}
