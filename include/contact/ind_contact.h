#pragma once
/* Frictional contact of the displacement nodes of one named surface (-contact_surface) with a rigid
   analytic indenter (doc/theory.md section 2). Every contact node is owned by the rank that owns its
   dofs, like the mesh; its reaction (a nodal force on the body, nN, global axes) lives here in a
   committed copy (end of the last accepted step) and a current one (the outer Uzawa iterate).

   Two couplings with the Newton solve, by -contact_uzawa (registered by name, IndContactCouplingRegistry):
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
#include "ind_state.h"
#include "ind_registry.h"


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
/* Whether the reactions the next outer update starts from are those of U: with reactions from the residual,
   whether the last residual was at U (on every rank); frozen reactions always are. */
PetscErrorCode IndContactMultipliersCurrent(IndContact contact, Vec U, PetscBool *current);
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
/* An elastic unloading by 1 nm from the last update's state: the global rows the indenter holds (a sticking node
   moves with it, a slipping one only follows it vertically; not the components of boundary conditions), appended
   to rows[*n...] (room for 3 per owned contact node: IndContactGetSize), and X set to the indenter's motion
   there (1 in z). */
PetscErrorCode IndContactUnloadingRows(IndContact contact, Vec X, PetscInt *n, PetscInt rows[]);
/* The same as the indenter starts to rise from the committed state: every node carrying a committed reaction moves
   with it, wholly with friction (sliding turns to sticking as the load falls), vertically without. The committed
   reactions are part of the state, so a continued run holds the rows the uninterrupted one held. */
PetscErrorCode IndContactReversalRows(IndContact contact, Vec X, PetscInt *n, PetscInt rows[]);
/* The z force of F (global) on the nodes in contact at the last update, all ranks, times the symmetry factor. */
PetscErrorCode IndContactActiveForce(IndContact contact, Vec F, PetscReal *Fz);
MPI_Comm       IndContactGetComm(IndContact contact);
/* The contact surface's name and the box its nodes span: x in [extent[0], extent[1]], y in [2], [3], nm. */
PetscErrorCode IndContactGetSurface(IndContact contact, const char **name, PetscReal extent[4]);
/* The owned contact nodes as the last update left them, read-only (borrowed): for diagnostics and tests. */
typedef struct {
  PetscInt         n;
  const PetscReal *X;      /* 3n reference positions */
  const PetscReal *R;      /* 3n current reactions (force on the body, nN, global axes) */
  const PetscReal *A;      /* n tributary areas projected on z, nm^2 */
  const PetscInt  *status; /* n IndContactStatus */
} IndContactNodes;
PetscErrorCode IndContactGetNodes(IndContact contact, IndContactNodes *nodes);
/* Projected area of the contact surface times the symmetry factor, nm^2. */
PetscReal      IndContactGetSurfaceArea(IndContact contact);
/* Owned contact nodes. */
PetscInt       IndContactGetSize(IndContact contact);
/* Load multiplier of a half (2) or quarter (4) model. */
PetscReal      IndContactGetSymmetry(IndContact contact);
/* The indenter as the contact sees it (borrowed). */
const IndIndenter *IndContactGetIndenter(IndContact contact);
/* The spacing (nm) of the contact surface's nodes within radius r of the indenter's axis, the finest of the
   largest around each radius (0: no node there), from the reference tributary areas: sqrt(A) on a 3D surface,
   A / (2 pi r) on a section. */
PetscReal      IndContactSpacing(IndContact contact, PetscReal r);
/* The depth a loading step from depth0 may reach, at most depth1: the indenter's edge (IndIndenterEdgeRadius)
   advances by at most 1/per_cell of the spacing within it (per_cell <= 0: depth1). */
PetscReal      IndContactEdgeDepth(IndContact contact, PetscReal depth0, PetscReal depth1, PetscReal per_cell);
/* How far a step from depth0 to depth1 moves that edge, in the surface's spacings within it (0 when it recedes, or
   before it has passed the first spacing). */
PetscReal      IndContactEdgeAdvance(IndContact contact, PetscReal depth0, PetscReal depth1);
/* The indenter's depth at the committed state, nm. */
PetscReal      IndContactGetCommittedDepth(IndContact contact);

/* The couplings by name (contact_coupling.c): each entry's function, PetscErrorCode create(IndContact), fills the
   contact's table of operations and its defaults. */
extern IndRegistry IndContactCouplingRegistry;
PetscErrorCode IndContactSetCoupling(IndContact contact, const char name[]);
/* Whether the contact leaves the Jacobian as assembled (symmetric: CG), and whether its reactions come from the
   residual (load control needs that). */
PetscBool      IndContactJacobianIsSymmetric(IndContact contact);
PetscBool      IndContactReactionsFromResidual(IndContact contact);
/* The outer loop of a step (solver.c): at most IndContactOuterMax updates; after update k, at Newton's
   solution after its Newton iterations, whether the contact has converged (atol: Newton's absolute tolerance
   of the step; prints the -contact_monitor line); if not, the coupling's next move, which may find the step
   stuck, with why. */
PetscInt       IndContactOuterMax(IndContact contact);
PetscErrorCode IndContactOuterConverged(IndContact contact, PetscInt k, PetscInt its, PetscReal atol,
                                        const IndContactSummary *sum, PetscBool *converged);
PetscErrorCode IndContactOuterNext(IndContact contact, PetscInt its, const IndContactSummary *sum, PetscBool *stuck,
                                   char why[], size_t len);
/* Why a step ran out of outer iterations. */
PetscErrorCode IndContactOuterFailure(IndContact contact, const IndContactSummary *sum, char why[], size_t len);
PetscErrorCode IndContactRollback(IndContact contact);
/* Verdicts on a run (contact_checks.c). An error (PETSC_ERR_USER_INPUT) when no node (touching, all ranks)
   is in contact at the end of loading, at depth_max: the indenter never touched the surface. */
PetscErrorCode IndContactCheckTouched(IndContact contact, PetscReal depth_max, PetscInt touching);
/* warning[0] = 0, or the text: a vertical symmetry plane of bc misses the indenter's axis, so that the model holds
   the indenter's mirror image too (a pair of indents), and the load is one indenter's. An error (PETSC_ERR_USER_INPUT)
   when the plane cuts the indenter at depth_max (the edge of its contact with the undeformed surface): the pair
   would overlap. */
PetscErrorCode IndContactCheckMirror(IndContact contact, IndBC bc, PetscReal depth_max, char warning[], size_t len);
/* warning[0] = 0, or the text: nodes on the edge of the modelled surface touch the indenter. */
PetscErrorCode IndContactCheckEdge(IndContact contact, PetscReal depth, char warning[], size_t len);
/* why[0] = 0, or why H and E_r are withheld: A(h_c) of the Oliver-Pharr analysis exceeds the surface's projected
   area. */
PetscErrorCode IndContactCheckArea(IndContact contact, PetscReal area_hc, char why[], size_t len);
/* Whether the contact at the largest load, nodes of the modelled part in contact, resolves the contact area
   for Oliver-Pharr: at least min_nodes over the whole indent (the modelled part times the model's symmetry),
   about sqrt(min_nodes / pi) node spacings across its radius; why says otherwise. */
void           IndContactCheckResolved(IndContact contact, PetscInt nodes, PetscInt min_nodes, char why[],
                                       size_t len);
/* Its part of the state (ind_state.h, contact_state.c): the committed reactions and node displacements, the
   penalty scale and the indenter's committed position. */
PetscErrorCode IndContactState(void *contact, IndStateFile file);
