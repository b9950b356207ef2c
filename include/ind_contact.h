#pragma once
/* Frictional contact of the displacement nodes of one named surface (-contact_surface) with a rigid
   analytic indenter (doc/theory.md section 2). Every contact node is owned by the rank that owns its
   dofs, like the mesh; its reaction (a nodal force on the body, nN, global axes) lives here in a
   committed copy (end of the last accepted step) and a current one (the outer Uzawa iterate).

   Two couplings with the Newton solve, by -contact_uzawa:
   - newton (default, contact_newton.c): semi-smooth Newton; the reaction of a node is the residual
     of its rows without contact, and those rows hold the bi-potential projection's fixed point
     instead, with its generalized derivative in the Jacobian; the outer update only checks it;
   - fixed_point: the reactions are frozen during each SNES solve and updated after it by the
     bi-potential predictor-corrector (the paper's Uzawa loop). */
#include <petscmat.h>
#include "ind_mesh.h"
#include "ind_disc.h"
#include "ind_bc.h"
#include "ind_indenter.h"
#include "ind_bipotential.h"

typedef enum { IND_UZAWA_FIXED_POINT, IND_UZAWA_NEWTON } IndUzawa;
extern const char *const IndUzawaTypes[];

/* The state of the contact after an outer iteration, summed over all ranks. */
typedef struct {
  PetscInt  contact, stick, slip; /* nodes in contact (stick + slip) */
  PetscReal load;                 /* indenter load P, nN: minus the z force on the body, times the symmetry factor */
  PetscReal penetration;          /* largest -gap, nm (0 when none penetrates) */
  PetscReal change;               /* |R_new - R| / |R_new| of the update (0 when both vanish) */
  PetscReal mismatch;             /* |R_new - R|, nN: the complementarity residual of the Newton variant */
  PetscReal area;                 /* projected area of the contact nodes' tributary faces, nm^2, times symmetry */
  PetscReal pileup;               /* largest height of a contact-surface node above the undeformed surface, nm */
  PetscReal deepest;              /* largest depth of a contact-surface node below it, nm */
  PetscReal force[3];             /* force of the indenter on the body, nN, with the mirror images: the
                                     component normal to a symmetry plane through the axis cancels */
} IndContactSummary;

typedef struct _p_IndContact *IndContact;
struct _p_IndContact {
  MPI_Comm    comm;
  IndIndenter indenter;
  IndUzawa    variant;
  PetscReal   mu;        /* Coulomb friction coefficient */
  PetscBool   gap_current; /* gap at X + u (default), or at the undeformed horizontal position */
  PetscReal   rho_scale; /* rho = rho_scale * mean stiffness diagonal of the node */
  PetscReal   rounding;  /* -indenter_sharp_rounding, nm (-1: 1e-4 of the largest depth) */
  PetscReal   rtol;      /* outer loop: relative change of the reactions */
  PetscReal   pen_rtol;  /* outer loop: largest penetration, relative to the largest depth */
  PetscReal   pen_atol;  /* the same in nm, computed at setup */
  PetscInt    max_outer;
  PetscBool   monitor;
  PetscReal   symmetry; /* load multiplier of a half (2) or quarter (4) model */
  PetscInt    n;        /* owned contact nodes */
  PetscInt   *row;      /* index of each node's x dof in the owned part of a global vector */
  PetscInt   *grow;     /* its global row */
  PetscReal  *X;        /* 3n reference positions */
  PetscReal  *kdiag;    /* n mean stiffness diagonals: rho_i = rho_scale * kdiag_i */
  PetscReal  *R, *Rc;   /* 3n current and committed reactions */
  PetscReal  *L;        /* newton: 3n multipliers (residual without contact) of the last residual */
  PetscReal  *Lu;       /* newton: 3n node displacements of that residual */
  PetscInt   *fixed;    /* n masks: bit d set when component d of the node is held by a boundary condition */
  PetscReal  *Uc;       /* 3n displacement at the committed state */
  PetscReal  *A;        /* n horizontal tributary areas (projected on z), reference or current */
  PetscInt   *status;   /* n, IndContactStatus of the last update */
  PetscReal  *Rn;       /* n normal reactions of the last update */
  PetscReal   depth_c;  /* indenter depth at the committed state */
  PetscReal   axis_c[2]; /* indenter axis (x, y) at the committed state: a scratch moves it */
  PetscInt    mirror;    /* bit c set: a symmetry plane normal to axis c passes through the indenter's axis */
  PetscReal   extent[4]; /* the contact surface's nodes span x in [extent[0], extent[1]], y in [2], [3], nm */
  PetscBool   areas_current; /* A from the deformed surface at each update (finite strain) */
  PetscBool  *edge;          /* n: the node lies on the edge of the modelled surface (not on a symmetry plane) */
  PetscInt    nedge;         /* such nodes, all ranks */
  PetscReal   top;           /* z of the surface's highest node, nm */
  PetscReal   zmin;          /* z of the mesh's lowest point, nm */
  PetscReal   surface_area;  /* projected area of the contact surface times the symmetry factor, nm^2 */
  IndMesh     mesh;          /* borrowed, for the surface's faces */
  IndDisc     disc;          /* borrowed */
  char        surface[IND_NAME_LEN];
};

/* Reads -indenter_* and -contact_* options; *contact is NULL when no -indenter_type is given. */
PetscErrorCode IndContactCreate(IndMesh mesh, IndDisc disc, IndBC bc, IndContact *contact);
PetscErrorCode IndContactDestroy(IndContact *contact);
/* Whether the tributary areas (true contact area, contact pressure) follow the deformed surface. */
PetscErrorCode IndContactSetCurrentAreas(IndContact contact, PetscBool current);
/* rho per node from the diagonal of the (unconstrained) stiffness K; pen_atol from the largest depth;
   which components of the nodes the (set up) boundary conditions hold. Refuses (but not in a -help
   listing) a depth that reaches the mesh's bottom and, when no boundary displacement moves the body,
   an indenter that at full depth does not reach the surface. */
PetscErrorCode IndContactSetUp(IndContact contact, IndBC bc, Mat K, PetscReal depth_max);
/* F holds the residual without contact at U (global vectors, before boundary conditions): fixed
   point, F -= frozen reactions; newton, the contact nodes' rows become the complementarity function. */
PetscErrorCode IndContactResidual(IndContact contact, Vec U, Vec F);
/* Newton: replaces the contact nodes' rows of the assembled J by the derivative of the
   complementarity function at U, which must be the last residual's displacement. Fd (NULL: not
   wanted; else zeroed by the caller) receives the derivative of the residual in the indenter's depth:
   a node's force depends on u_z + depth alone (the gap and the slip see the indenter's motion as the
   node's), so it is the z column of the node's stiffness. */
PetscErrorCode IndContactJacobian(IndContact contact, Vec U, Mat J, Vec Fd);
/* The semi-smooth Newton strategy (contact_newton.c). */
PetscErrorCode IndContactNewtonResidual(IndContact contact, Vec U, Vec F);
PetscErrorCode IndContactNewtonJacobian(IndContact contact, Vec U, Mat J, Vec Fd);
/* Load control with the Newton variant. The load the body carries at the last residual's displacement,
   nN of the modelled part (not times the symmetry factor): minus the z rows of the residual without
   contact summed over the contact nodes whose z is free, which at convergence is the indenter's load. */
PetscErrorCode IndContactModelLoad(IndContact contact, PetscReal *load);
/* e = 1 on the z rows that IndContactModelLoad sums, 0 elsewhere (global vector): the load's
   derivative in U is -K^T e, K the tangent without contact. */
PetscErrorCode IndContactLoadRows(IndContact contact, Vec e);
/* The smallest gap (nm) between the indenter at its current depth and the contact nodes at U, all ranks. */
PetscErrorCode IndContactSmallestGap(IndContact contact, Vec U, PetscReal *gap);
PetscReal      IndContactGetDepth(IndContact contact);
PetscErrorCode IndContactSetDepth(IndContact contact, PetscReal depth);
/* Whether the multipliers are those of a residual at U (on every rank). */
PetscErrorCode IndContactNewtonCurrent(IndContact contact, Vec U, PetscBool *current);
/* Its rows for one node, pure: K the node's 3 rows of the tangent (3 x ncols, row-major), diag the
   positions of the node's own 3 dofs among the columns, P = Q D Q^T and B = rho Q D G (3x3,
   global axes), mask the components held by boundary conditions. out = (I - P) M K + B at diag. */
void IndContactNewtonRows(const PetscReal P[9], const PetscReal B[9], PetscInt mask, PetscInt ncols,
                          const PetscInt diag[3], const PetscReal *K, PetscReal *out);
/* The outer update: R <- projection of the predictor at U (from the multipliers of the last residual,
   which must be at U, or the frozen reactions); fills the summary, whose change is |R - multiplier|. */
PetscErrorCode IndContactUpdate(IndContact contact, Vec U, IndContactSummary *summary);
/* Contact pressure (normal reaction over tributary area, GPa) and status (0 open, 1 stick, 2 slip) of
   each contact node as the last update found them (an accepted step's: the state its summary counted),
   in the first two components of its node in the global vector G (zero elsewhere). */
PetscErrorCode IndContactNodalFields(IndContact contact, Vec G);
/* The indenter's depth and the position of its axis (x, y, nm) for the step being solved; the slip of
   a node is taken relative to the indenter's motion since the committed state. */
PetscErrorCode IndContactSetIndenterPosition(IndContact contact, PetscReal depth, const PetscReal axis[2]);
/* Whether the symmetry plane of spec passes through the indenter's axis: 0 no, 1 normal x, 2 normal y. */
int            IndContactPlaneThroughAxis(const IndBCSpec *spec, const IndIndenter *ind);
PetscErrorCode IndContactCommit(IndContact contact, Vec U);
PetscErrorCode IndContactRollback(IndContact contact);
