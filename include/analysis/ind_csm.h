#pragma once
/* Hardness and modulus against depth from one run, as a continuous-stiffness measurement does: at chosen
   accepted loading steps the contact stiffness S = dP/dh of a small elastic unloading of the current
   state, with the contact nodes held to the indenter (sticking nodes move with it, slipping ones follow
   it vertically; the rest of the body follows the elastic tangent at the current configuration), then
   h_c = h - epsilon P / S, A(h_c),
   H = P / A(h_c) and E_r = sqrt(pi) / (2 beta) S / sqrt(A(h_c)) with the -op_* parameters. One linear
   solve per point, on a copy of the Jacobian: the load program's solver state is not touched. */
#include "ind_solver.h"
#include "ind_contact.h"
#include "ind_bc.h"
#include "ind_oliverpharr.h"

#define IND_CSM_FILE "csm.csv" /* in the output directory; a restart truncates it (stepcsv.c) */

typedef struct {
  PetscReal S;       /* uN/nm */
  PetscReal h_c, A;  /* nm, nm^2 (A from the indenter's area function at h_c) */
  PetscReal H, E_r;  /* GPa */
  PetscReal a;       /* contact radius sqrt(true area / pi), nm */
} IndCSMPoint;

/* Collective: S and the quantities above at the accepted state U (depth h, load P in uN, true projected contact
   area area_true in nm^2, times the symmetry factor as the curve has them), with the contact's state of its last
   update and the Oliver-Pharr constants op. */
PetscErrorCode IndCSMStiffness(IndSolver solver, IndBC bc, IndContact contact, const IndOPParams *op, Vec U,
                               PetscReal h, PetscReal P, PetscReal area_true, IndCSMPoint *point);
/* Rank 0 appends the point of accepted step `step` to <dir>/csm.csv (the header first when the file is
   new). */
PetscErrorCode IndCSMWrite(MPI_Comm comm, const char dir[], PetscInt step, PetscReal h, PetscReal P,
                           const IndCSMPoint *point);
