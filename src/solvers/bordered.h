#pragma once
/* Load control's bordered Newton (src/solvers/bordered.c). The indenter's depth d is an unknown beside
   the displacement U, and the load equation P(U) = P* stands beside equilibrium F(U, d) = 0:

     [ J    F_d ] [dU]     [ F      ]
     [ p^T  0   ] [dd] = - [ P - P* ],   p = dP/dU, F_d = dF/dd (the contact rows only).

   It is solved by bordering, with the operator SNES has just set up: J Y = F (SNES's own solve) and
   J b = F_d, then dd = (c - p.Y) / p.b with c = P - P*, and dU = -(Y + dd b). Newton on the whole
   system converges like depth control's, instead of a search over whole nonlinear solves; a line
   search on |F|^2 + c^2 globalizes it as backtracking does depth control's semi-smooth Newton. */
#include <petscsnes.h>
#include "ind_contact.h"
#include "ind_solver.h"

/* The depth increment of one bordered Newton step, pure: c = P - P* (nN), pY = p.Y, pb = p.b at depth
   d. -p.b is the load's stiffness along the step (nN/nm, > 0 with a node in contact). Without it (no node
   in contact) a load short of P* moves the indenter to the nearest node (gap, nm) and a little further,
   and anything else stays. The depth stays within [0, depth_max]. */
PetscReal IndBorderedDepthIncrement(PetscReal c, PetscReal pY, PetscReal pb, PetscReal gap, PetscReal depth,
                                    PetscReal depth_max);

/* The object, owned by the solver (private to src/solvers). load_tol: the accepted |P - P*|, nN of the
   whole model. Refuses the fixed-point contact, whose reactions do not depend on the depth within Newton. */
PetscErrorCode IndBorderedCreate(IndContact contact, Vec U, PetscReal depth_max, PetscReal load_tol,
                                 IndBordered *bordered);
PetscErrorCode IndBorderedDestroy(IndBordered *bordered);
/* P* (nN, whole model) of the next solves; resets the step's counters. */
PetscErrorCode IndBorderedSetTarget(IndBordered bordered, PetscReal load);
/* After the contact residual: c = P(U) - P* at its displacement. */
PetscErrorCode IndBorderedResidual(IndBordered bordered);
PetscReal      IndBorderedLoadResidual(IndBordered bordered);
PetscBool      IndBorderedLoadMet(IndBordered bordered);
/* P(U) at the last residual, nN of the whole model. */
PetscReal      IndBorderedLoad(IndBordered bordered);
/* Whether the last line search left the indenter at the largest depth with the load short of P*. */
PetscBool      IndBorderedOutOfReach(IndBordered bordered);
/* Krylov iterations of the bordering solves since the target was set. */
PetscInt       IndBorderedLinearIterations(IndBordered bordered);
/* With the tangent K without contact (before the contact's rows and the boundary conditions): p from it,
   and F_d zeroed for the contact's Jacobian to fill (IndBorderedDepthDerivative). */
PetscErrorCode IndBorderedBodyJacobian(IndBordered bordered, Mat K);
Vec            IndBorderedDepthDerivative(IndBordered bordered);
Vec            IndBorderedLoadDerivative(IndBordered bordered);
/* SNESLINESEARCHSHELL's function (ctx: the IndBordered). */
PetscErrorCode IndBorderedLineSearch(SNESLineSearch ls, void *ctx);
