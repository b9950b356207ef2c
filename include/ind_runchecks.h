#pragma once
/* Checks of a run that can only be made while it runs (run_checks.c): the indenter has not touched the
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
/* warning[0] = 0, or the text: nodes on the edge of the modelled surface touch the indenter. */
PetscErrorCode IndRunCheckContactEdge(IndContact contact, PetscReal depth, char warning[], size_t len);
/* warning[0] = 0, or the text: cells of the accepted state app->U are inverted (det F <= 0 at a
   quadrature point; IndAssemblyCountInverted). label says where (e.g. "at depth 60 nm"). */
PetscErrorCode IndRunCheckInverted(IndApp app, const char label[], char warning[], size_t len);
/* warning[0] = 0, or the text: A(h_c) of the Oliver-Pharr analysis exceeds the surface's projected area. */
PetscErrorCode IndRunCheckContactArea(IndContact contact, PetscReal area_hc, char warning[], size_t len);
/* Whether the contact at the largest load, nodes of the modelled part in contact, resolves the contact
   area for Oliver-Pharr: at least min_nodes over the whole indent (the modelled part times the model's
   symmetry), about sqrt(min_nodes / pi) node spacings across its radius; why says otherwise. */
void           IndRunCheckContactResolved(IndContact contact, PetscInt nodes, PetscInt min_nodes, char why[],
                                          size_t len);

/* All of a step's checks, for IndAppRun after each accepted step r: the loading-contact error, then the
   edge and inversion warnings into warnings (printed when print is true). */
PetscErrorCode IndRunCheckStep(IndApp app, const IndStepResult *r, IndWarnings *warnings, PetscBool print);
