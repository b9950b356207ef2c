#pragma once
/* Private to the contact modules: the local problem of one contact node. */
#include "ind_contact.h"

/* The state of node i at displacement u (its 3 values) for the reaction R (3 values, global axes):
   gap, frame, predictor and projection. The force on the body is f = r0 n + r1 t1 + r2 t2;
   D = dr/dtau; s the unit slip direction (local). With either gap definition d gap / d u = n. */
typedef struct {
  PetscReal        gap, n[3], t1[3], t2[3], r[3], f[3], D[9], s[2];
  IndContactStatus status;
} IndContactNode;

void IndContactNodeSolve(IndContact contact, PetscInt i, const PetscScalar *u, const PetscReal R[3],
                         IndContactNode *node);

/* Q D, Q the frame's columns (n, t1, t2) in global axes: the force's derivative in the local reaction. */
void IndContactNodeQD(const IndContactNode *node, PetscReal QD[3][3]);

/* B = -d f / d u of node i at u for the fixed reaction R (3x3, row-major, global axes), by central
   differences: it carries the rotation of the frame with the node (the curvature of the indenter's
   surface), which the projection's derivative D leaves out, so that Newton stays quadratic on a
   rounded tip. Where the one-sided differences disagree (a kink: a sharp edge or apex, a change of
   status) it is rho Q D G instead, the frame held fixed (G's rows n + mu (s1 t1 + s2 t2), t1, t2),
   and the return value is PETSC_FALSE. */
PetscBool IndContactNodeStiffness(IndContact contact, PetscInt i, const PetscScalar *u, const PetscReal R[3],
                                  PetscReal B[9]);
