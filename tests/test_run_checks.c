static const char help[] = "The checks of src/solvers/run_checks.c on small runs, driven step by step up to the end of "
  "loading:\n"
                           "  -check edge      a contact node on the edge of the modelled surface touches the indenter "
                             "(warning)\n"
                           "  -check inverted  cells of the accepted state have det F <= 0 (warning)\n"
                           "  -check area      A(h_c) against the surface's area, 1% above and below it (warning; "
                             "pure)\n"
                           "  -check loading   no node in contact at the end of loading (error)\n"
                           "  -expect 1|0      whether the check must fire (default 1)\n"
                           "plus the options of indent. Exits non-zero when the verdict differs from -expect.\n";

#include <string.h>
#include "ind_runchecks.h"

int main(int argc, char **argv)
{
  IndApp         app;
  IndWarnings    w;
  IndStepResult  r;
  char           check[32] = "", text[IND_WARNING_LEN] = "";
  PetscBool      expect = PETSC_TRUE, fired = PETSC_FALSE, isedge, isinv, isarea, isload;
  PetscInt       failures = 0;
  PetscErrorCode ierr;

  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  PetscCall(PetscOptionsGetString(NULL, NULL, "-check", check, sizeof(check), NULL));
  PetscCall(PetscOptionsGetBool(NULL, NULL, "-expect", &expect, NULL));
  PetscCall(PetscStrcmp(check, "edge", &isedge));
  PetscCall(PetscStrcmp(check, "inverted", &isinv));
  PetscCall(PetscStrcmp(check, "area", &isarea));
  PetscCall(PetscStrcmp(check, "loading", &isload));
  PetscCheck(isedge || isinv || isarea || isload, PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG,
    "-check edge|inverted|area|loading");
  PetscCall(PetscMemzero(&w, sizeof(w)));
  PetscCall(IndAppCreate(PETSC_COMM_WORLD, &app));
  PetscCheck(!(isedge || isarea || isload) || IndAppGetContact(app), PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG,
    "-check %s needs an indenter", check);

  if (isarea) { /* pure: the surface's area is known at set-up */
    const PetscReal S = IndContactGetSurfaceArea(IndAppGetContact(app));
    PetscCall(IndContactCheckArea(IndAppGetContact(app), 0.99 * S, text, sizeof(text)));
    if (text[0]) failures++;
    PetscCall(IndContactCheckArea(IndAppGetContact(app), 1.01 * S, text, sizeof(text)));
    fired = text[0] ? PETSC_TRUE : PETSC_FALSE;
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "surface area %g nm^2 (symmetry %g); at 1.01 of it: %s\n", (double)S,
      (double)IndContactGetSymmetry(IndAppGetContact(app)), text[0] ? text : "(no warning)"));
  } else {
    while (IndAppGetLoadPath(app)->t < 1 - 1e-12) {
      const PetscReal t = IndLoadPathTarget(IndAppGetLoadPath(app));
      PetscCall(IndAppStep(app, &r));
      PetscCheck(r.converged, PETSC_COMM_WORLD, PETSC_ERR_NOT_CONVERGED, "step to t = %g did not converge (%s)",
        (double)t, r.why);
      if (isedge) {
        PetscCall(IndContactCheckEdge(IndAppGetContact(app), r.depth, text, sizeof(text)));
        if (text[0]) PetscCall(IndWarningsAdd(IndAppGetComm(app), &w, "contact_edge", PETSC_TRUE, text));
      }
      if (isinv) {
        PetscCall(IndRunCheckInverted(app, "at the end of loading", text, sizeof(text)));
        if (text[0]) PetscCall(IndWarningsAdd(IndAppGetComm(app), &w, "inverted_cells", PETSC_TRUE, text));
      }
      if (isload) {
        PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
        ierr = IndRunCheckLoadingContact(app, &r);
        PetscCall(PetscPopErrorHandler());
        if (ierr) {
          char *msg = NULL;
          PetscCall(PetscErrorMessage(ierr, NULL, &msg));
          PetscCall(PetscPrintf(PETSC_COMM_WORLD, "error %d at t = %g: %s\n", (int)ierr, (double)t, msg));
          if (ierr != PETSC_ERR_USER_INPUT || !strstr(msg, "did not touch")) failures++;
          fired = PETSC_TRUE;
          break;
        }
      }
      if (IndAppGetContact(app)) PetscCall(PetscPrintf(PETSC_COMM_WORLD,
        "step to depth %g nm: %" PetscInt_FMT " contact nodes\n", (double)r.depth, r.contact.contact));
    }
    if (isedge || isinv) fired = w.n > 0 ? PETSC_TRUE : PETSC_FALSE;
    /* once per kind: the same warning again is not recorded twice */
    if (w.n) {
      PetscCall(IndWarningsAdd(IndAppGetComm(app), &w, w.key[0], PETSC_FALSE, "again"));
      if (w.n != 1) failures++;
    }
  }
  if (fired != expect) failures++;
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "check %s: %s (expected %s)%s\n", check, fired ? "fired" : "did not fire",
    expect ? "to fire" : "not to fire", failures ? "  FAIL" : ""));
  PetscCall(IndAppDestroy(&app));
  PetscCall(PetscFinalize());
  return failures ? 1 : 0;
}
