#pragma once
/* Checks of a run that can only be made while it runs (run_checks.c; the contact's own verdicts
   are IndContactCheck* in ind_contact.h): the indenter has not touched the
   surface by the end of loading (an error), the contact reaches the edge of the modelled surface,
   cells are inverted in an accepted state, the Oliver-Pharr area exceeds the surface (warnings). The
   checks that can be decided before solving are made at set-up (contact.c: depth through the body, an
   indenter that never reaches the surface, a rotation that breaks a symmetry plane).

   Warnings go into an IndWarnings list (ind_warnings.h). */
#include "ind_app.h"
#include "ind_warnings.h"

/* Verdicts on their own, for tests; each is collective on the objects' communicator. */
/* An error (PETSC_ERR_USER_INPUT) when the step r ends the loading segment (t = 1) with no node in
   contact: the indenter never touched the surface. */
PetscErrorCode IndRunCheckLoadingContact(IndApp app, const IndStepResult *r);
/* warning[0] = 0, or the text: cells of the accepted state app->U are inverted (det F <= 0 at a
   quadrature point; IndAssemblyCountInverted). label says where (e.g. "at depth 60 nm"). */
PetscErrorCode IndRunCheckInverted(IndApp app, const char label[], char warning[], size_t len);

/* All of a step's checks, for IndAppRun after each accepted step r: the loading-contact error, then the
   edge and inversion warnings into warnings (printed when print is true). */
PetscErrorCode IndRunCheckStep(IndApp app, const IndStepResult *r, IndWarnings *warnings, PetscBool print);
