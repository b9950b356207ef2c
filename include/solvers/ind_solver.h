#pragma once
/* One load step: Newton (SNES) on the assembled residual with Dirichlet rows, CG + GAMG with the
   rigid-body near-null space by default (every choice can be changed by PETSc options), inside the
   outer Uzawa loop of the contact when there is an indenter. */
#include <petscsnes.h>
#include "ind_assembly.h"
#include "ind_bc.h"
#include "ind_contact.h"
#include "ind_state.h"

/* What one load step's solve did. */
typedef struct {
  PetscBool           converged;
  SNESConvergedReason reason; /* of the last Newton solve */
  PetscInt            newton, linear, outer; /* summed over the outer iterations */
  IndContactSummary   contact;              /* after the last outer update */
  char                why[256];             /* why it failed */
} IndSolveResult;

/* Load control's bordered Newton (bordered.c): the indenter's depth is an unknown beside U. */
typedef struct _p_IndBordered *IndBordered;

typedef struct _p_IndSolver *IndSolver;

/* depth_max sets the contact loop's penetration tolerance. */
PetscErrorCode IndSolverCreate(DM dm, IndAssembly assembly, IndBC bc, IndContact contact, PetscReal depth_max,
  IndSolver *solver);
PetscErrorCode IndSolverDestroy(IndSolver *solver);
/* Quadrature points, all ranks, yielding in the last residual, and those whose return map failed there. */
PetscInt       IndSolverPlasticPoints(IndSolver solver);
PetscInt       IndSolverFailedPoints(IndSolver solver);
/* The Newton solver (borrowed), for drivers and tests that inspect or tune it. */
SNES           IndSolverGetSNES(IndSolver solver);
/* Its part of the state (ind_state.h). The solver keeps no state between steps but its preconditioner: the
   multigrid hierarchy (GAMG's aggregates and interpolation), built at the first Jacobian it meets and kept, and its
   Galerkin products, rebuilt when keeping them costs more Krylov iterations than a rebuild (src/solvers/pcreuse.h);
   it changes the answers only within the linear solver's tolerance. Saving writes nothing; loading drops it, so
   that a run continued from a state builds it at its next solve, as a restarted run does. */
PetscErrorCode IndSolverState(void *solver, IndStateFile file);
/* The Jacobian matrix (borrowed). */
Mat            IndSolverGetJacobian(IndSolver solver);
/* A new matrix of the Jacobian's layout and near-null space holding the elastic tangent at U (global), without
   boundary conditions or contact: the stiffness of an elastic unloading. */
PetscErrorCode IndSolverElasticStiffness(IndSolver solver, Vec U, Mat *K);
/* Tangent predictor for a step from load factor t_old (U converged there) to t_new: adds the
   prescribed-value increment and the response of the tangent at U to it, so that an elastic step
   converges in one Newton iteration instead of starting from a strained boundary layer of cells. */
PetscErrorCode IndSolverPredict(IndSolver solver, PetscReal t_old, PetscReal t_new, Vec U);
/* Predictor for a step that lifts the indenter by rise (nm) from the accepted state U: the elastic response with
   every node in contact rising with it (wholly with friction, vertically without), added to U. A reversal turns
   the sliding of the loading into sticking; started from U alone, Newton spent 14 damped iterations there finding
   which nodes stick (19 in all against 5 on the paper's case at h_tip 15). */
PetscErrorCode IndSolverPredictUnloading(IndSolver solver, PetscReal rise, Vec U);
/* Evaluates the residual at U (load factor of the last solve): its counts of yielding and failed
   points (nplastic, nfailed) and the contact's multipliers are U's, whatever iterate SNES evaluated
   last. */
PetscErrorCode IndSolverEvaluate(IndSolver solver, Vec U);
/* Accepts U (load factor of the last solve): every quadrature point's update there becomes its
   committed history (IndAssemblyCommit); nplastic counts the points that yielded. */
PetscErrorCode IndSolverCommit(IndSolver solver, Vec U);
/* Solves for U at the given load factor (and the indenter's current depth); U holds the initial guess. */
PetscErrorCode IndSolverSolve(IndSolver solver, PetscReal load_factor, Vec U, IndSolveResult *result);
/* Load control: from now on the indenter's depth is an unknown of Newton's, with the load equation
   P(U) = P* beside the equilibrium (a bordered system: one more Krylov solve with the same operator per
   Newton iteration). depth_max (nm) bounds the depth; load_tol (nN, whole model) is the |P - P*|
   accepted. Needs the Newton contact variant. */
PetscErrorCode IndSolverSetLoadControl(IndSolver solver, PetscReal depth_max, PetscReal load_tol);
/* The load P* (nN, whole model) of the steps solved from now on. */
PetscErrorCode IndSolverSetLoadTarget(IndSolver solver, PetscReal load);
/* Whether the last failed solve ended at the largest depth with a load short of its target, and that
   load (nN, whole model). */
PetscBool      IndSolverLoadOutOfReach(IndSolver solver, PetscReal *load);
/* Makes the finest smoother of a multigrid preconditioner (PCMG, PCGAMG; nothing for other types or
   before the first setup) set itself up again on its operator at its next use: after the operator
   changed in place while the preconditioner is reused, as on lagged Newton iterations. */
PetscErrorCode IndSolverRefreshFineSmoother(KSP ksp);
/* Frees the basis a GMRES ksp keeps at the size its longest solve grew it to (nothing for other Krylov methods); its
   preconditioner is kept, and the next solve allocates what it needs. IndSolverSolve does it after each load step. */
PetscErrorCode IndSolverReleaseKrylovBasis(KSP ksp);
/* Makes every coarse operator and interpolation of a set-up multigrid (nothing for other preconditioners or before
   the first setup) multiply row by row, without PETSc's inode kernel, as the Jacobian does (-jac_inodes); with
   blocks, by their block rows (IndBlockMultInstall, -jac_block_products). With single (blocks only: a shell of
   IndBlockMultCreateSingleOperator on the finest operator, or NULL), the coarse operators and interpolations read
   their values in single precision and the finest smoother and residual multiply by single (-newton_pc_single). */
PetscErrorCode IndSolverMultigridRowProducts(KSP ksp, PetscBool blocks, Mat single);
