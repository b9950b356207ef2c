#include "ind_common.h"

/* PETSc reads these only at solve, factorisation, view or finalize time, so at the end of setup
   they are legitimately still unused. Everything else unused by then is a typo or an option that
   does not apply, and running hours on a misspelled setting is worse than stopping now. */
static const char *lazy_prefixes[] = {"log", "options_", "malloc", "memory_view", "info", "help", "version", "history",
                                      "on_error", "mat_mumps_", "mat_superlu", "mat_view", "vec_view", "ksp_view", "snes_view",
                                      "pc_view", "dm_view", "check_pointer", "fp_trap", "viewer_", "mpi_", "use_gpu", "skip_petscrc",
                                      "objects_dump", "display", "nox", "x_", "draw_", "petscpartitioner_view",
                                      "ksp_converged_reason", "snes_converged_reason", "snes_test_", "mg_levels_", "mg_coarse_", "pc_hypre_boomeramg_print", NULL};

PetscErrorCode IndOptionsCheckUnused(MPI_Comm comm)
{
  PetscInt   n, bad = 0;
  char     **names, **values;
  PetscBool  check = PETSC_TRUE;
  char       list[4096] = "";

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsGetBool(NULL, NULL, "-options_check_unused", &check, NULL));
  if (!check) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscOptionsLeftGet(NULL, &n, &names, &values));
  for (PetscInt i = 0; i < n; ++i) {
    PetscBool lazy = PETSC_FALSE;
    for (const char **p = lazy_prefixes; *p && !lazy; ++p) {
      size_t len;
      PetscCall(PetscStrlen(*p, &len));
      PetscCall(PetscStrncmp(names[i], *p, len, &lazy));
    }
    if (lazy) continue;
    ++bad;
    PetscCall(PetscStrlcat(list, " -", sizeof(list)));
    PetscCall(PetscStrlcat(list, names[i], sizeof(list)));
  }
  PetscCall(PetscOptionsLeftRestore(NULL, &n, &names, &values));
  PetscCheck(!bad, comm, PETSC_ERR_ARG_WRONG,
             "Unknown or unused option(s):%s. Check the spelling (-help lists every option), or pass -options_check_unused 0 to run anyway", list);
  PetscFunctionReturn(PETSC_SUCCESS);
}
