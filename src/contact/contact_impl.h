#pragma once
/* Private to src/contact/: the fields of IndContact. Other groups use the accessors of
   ind_contact.h. */
#include "ind_contact.h"

/* A coupling of the contact with the Newton solve (-contact_uzawa), registered by name with
   IndContactCouplingRegistry: its create function fills the table and the defaults below. */
typedef struct {
  /* F holds the residual without contact at U: adds the contact's part */
  PetscErrorCode (*residual)(IndContact, Vec U, Vec F);
  /* adds the contact's part to the assembled J at U, and the depth derivative to Fd (if not NULL); NULL: none,
     and J stays symmetric */
  PetscErrorCode (*jacobian)(IndContact, Vec U, Mat J, Vec Fd);
  /* after an outer update that did not converge: a step that cannot progress says why (stuck true) */
  PetscErrorCode (*after_outer)(IndContact, PetscInt newton_its, const IndContactSummary *sum, PetscBool *stuck,
                                char why[], size_t len);
  /* the reactions come from the residual (the multipliers L) rather than frozen between solves (R): the
     projection starts from L, a component held by a boundary condition carries the support's reaction, the
     residual's load is known (load control), and the complementarity residual is part of Newton's */
  PetscBool residual_multipliers;
} IndContactOps;

struct _p_IndContact {
  MPI_Comm    comm;
  IndIndenter indenter;
  IndContactOps ops;
  PetscReal     last_change; /* the reaction change of the previous outer iteration of the step */
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
  PetscBool   axisymmetric; /* a 2D section: x is the radius, loads and areas are the whole ring's */
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
  PetscInt    spacing_nbins; /* the surface's node spacing against the radius from the axis (contact_spacing.c) */
  PetscReal   spacing_width; /* width of its bins, nm */
  PetscReal  *spacing;       /* spacing_nbins values, nm (0: no node there) */
  PetscReal  *profile;       /* -indenter_profile's table, which the indenter borrows (NULL: none) */
  IndMesh     mesh;          /* borrowed, for the surface's faces */
  IndDisc     disc;          /* borrowed */
  char        surface[IND_NAME_LEN];
};

/* contact_spacing.c: the table, from the reference tributary areas (at create). */
PetscErrorCode IndContactSpacingSetUp(IndContact contact);
