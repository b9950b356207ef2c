#pragma once
/* Frictional contact of the displacement nodes of one named surface (-contact_surface) with a rigid
   analytic indenter (THEORY.md section 2). Every contact node is owned by the rank that owns its
   dofs, like the mesh; its reaction (a nodal force on the body, nN, global axes) lives here in a
   committed copy (end of the last accepted step) and a current one (the outer Uzawa iterate).

   Two couplings with the Newton solve, by -contact_uzawa:
   - fixed_point: the reactions are frozen during each SNES solve and updated after it by the
     bi-potential predictor-corrector;
   - augmented: inside SNES the contact force is the projected reaction as a function of the
     displacement, with its generalized derivative in the Jacobian; the outer loop updates the
     multipliers. */
#include <petscmat.h>
#include "ind_mesh.h"
#include "ind_disc.h"
#include "ind_bc.h"
#include "ind_indenter.h"
#include "ind_bipotential.h"

typedef enum { IND_UZAWA_FIXED_POINT, IND_UZAWA_AUGMENTED } IndUzawa;
extern const char *const IndUzawaTypes[];

/* The state of the contact after an outer iteration, summed over all ranks. */
typedef struct {
  PetscInt  contact, stick, slip; /* nodes in contact (stick + slip) */
  PetscReal load;                 /* indenter load P, nN: minus the z force on the body, times the symmetry factor */
  PetscReal penetration;          /* largest -gap, nm (0 when none penetrates) */
  PetscReal change;               /* |R_new - R| / |R_new| of the update (0 when both vanish) */
  PetscReal area;                 /* projected area of the contact nodes' tributary faces, nm^2, times symmetry */
  PetscReal pileup;               /* largest height of a contact-surface node above the undeformed surface, nm */
  PetscReal deepest;              /* largest depth of a contact-surface node below it, nm */
} IndContactSummary;

typedef struct _p_IndContact *IndContact;
struct _p_IndContact {
  MPI_Comm    comm;
  IndIndenter indenter;
  IndUzawa    variant;
  PetscReal   mu;        /* Coulomb friction coefficient */
  PetscBool   gap_current; /* gap at X + u (default), or at the undeformed horizontal position */
  PetscReal   rho_scale; /* current rho = rho_scale * mean stiffness diagonal of the node */
  PetscReal   rho_max;   /* augmented: the scale the outer loop grows to (-contact_rho_scale) */
  PetscReal   rho_min;   /* augmented: the largest scale a step starts from (-contact_rho_initial) */
  PetscReal   rho_start; /* augmented: the scale the next step starts from; evolving state (see IndSolverSolve) */
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
  PetscReal  *Rs;       /* 3n reactions saved at the start of an outer iteration */
  PetscReal  *Uc;       /* 3n displacement at the committed state */
  PetscReal  *A;        /* n horizontal tributary areas (projected on z) */
  PetscInt   *status;   /* n, IndContactStatus of the last update */
  PetscReal   depth_c;  /* indenter depth at the committed state */
};

/* Reads -indenter_* and -contact_* options; *contact is NULL when no -indenter_type is given. */
PetscErrorCode IndContactCreate(IndMesh mesh, IndDisc disc, IndBC bc, IndContact *contact);
PetscErrorCode IndContactDestroy(IndContact *contact);
/* rho per node from the diagonal of the (unconstrained) stiffness K; pen_atol from the largest depth. */
PetscErrorCode IndContactSetUp(IndContact contact, Mat K, PetscReal depth_max);
/* F -= contact forces at the displacement U (global vectors); the frozen reactions, or the projected
   ones of the augmented variant. */
PetscErrorCode IndContactResidual(IndContact contact, Vec U, Vec F);
/* Augmented variant: J += minus the derivative of the contact forces; assembles J. */
PetscErrorCode IndContactJacobian(IndContact contact, Vec U, Mat J);
/* The outer update: R <- projection of the predictor at U; fills the summary. */
PetscErrorCode IndContactUpdate(IndContact contact, Vec U, IndContactSummary *summary);
/* Contact pressure (normal reaction over tributary area, GPa) and status (0 open, 1 stick, 2 slip) of
   each contact node at U, in the first two components of its node in the global vector G (zero
   elsewhere). */
PetscErrorCode IndContactNodalFields(IndContact contact, Vec U, Vec G);
/* Save / restore the current reactions around an outer iteration that may be retried. */
PetscErrorCode IndContactSaveReactions(IndContact contact);
PetscErrorCode IndContactRestoreReactions(IndContact contact);
PetscErrorCode IndContactCommit(IndContact contact, Vec U);
PetscErrorCode IndContactRollback(IndContact contact);
