#pragma once
/* The bi-potential local solve of one contact node (doc/theory.md section 2), in the node's local frame:
   component 0 along the indenter's normal n (compression positive), 1 and 2 along the tangents.
   Pure: no PETSc objects. */
#include <petscsys.h>

typedef enum { IND_CONTACT_OPEN, IND_CONTACT_STICK, IND_CONTACT_SLIP } IndContactStatus;
extern const char *const IndContactStatusNames[];

/* Predictor tau = r - rho (du_t + (g + mu |du_t|) n): r the reaction of the last outer iteration, g
   the current gap (nm, positive open), du_t the tangential slip of the node relative to the indenter
   over the load step (nm), rho the penalty-like parameter (nN/nm). */
void IndBipotentialPredictor(PetscReal mu, PetscReal rho, const PetscReal r[3], PetscReal gap,
  const PetscReal du_t[2], PetscReal tau[3]);

/* Corrector: r = projection of tau on the Coulomb cone |r_t| <= mu r_n (separating, sticking or
   sliding). When D is not NULL it receives dr/dtau (3x3, row-major; symmetric). */
IndContactStatus IndBipotentialProject(PetscReal mu, const PetscReal tau[3], PetscReal r[3], PetscReal D[9]);
