static const char help[] =
  "Takes the linear system of one Newton iteration of a run apart (doc/performance.md): with the run's Krylov\n"
  "tolerance and GAMG, it solves the Jacobian as the run does and its variants, and prints their iterations.\n"
  "  -anatomy_step s     the load step (1: the first; counted as accepted steps + 1)\n"
  "  -anatomy_newton k   its Newton iteration (0: the first)\n"
  "  -anatomy_*          options for the variants' KSP and PC (e.g. -anatomy_pc_gamg_threshold 0.01)\n"
  "The run stops after that step (a checkpoint is written into -output_dir).\n";

#include <signal.h>
#include "ind_app.h"
#include "ind_signals.h"
#include "contact_node.h"
/* A white-box diagnostic: it takes the solver, the contact and the assembly apart, so it reads their private
   fields (scripts/check-private-headers.py lists it as such). */
#include "contact_impl.h"
#include "app_impl.h"
#include "solver_impl.h"
#include "assembly_impl.h"

typedef struct {
  IndApp    app;
  PetscInt  step, newton;
  PetscBool done;
} Anatomy;

/* F = the residual at U as the Newton iteration sees it (assembly, contact rows, conditions), through
   the run's own residual callback. */
static PetscErrorCode Residual(IndApp app, Vec U, Vec F)
{
  PetscFunctionBeginUser;
  PetscCall(SNESComputeFunction(app->solver->snes, U, F));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The tangent of the material (consistent or elastic) at the last residual's displacement, with the
   contact rows when asked, and the conditions' rows and columns. */
static PetscErrorCode Tangent(IndApp app, IndTangent tangent, PetscBool contact, Mat K)
{
  IndAssembly    a = app->assembly;
  const IndTangent keep = a->tangent;

  PetscFunctionBeginUser;
  a->tangent = tangent;
  PetscCall(IndAssemblyJacobian(a, app->solver->Uloc, K));
  a->tangent = keep;
  if (contact && app->contact) PetscCall(IndContactJacobian(app->contact, app->solver->Ubc, K, NULL));
  PetscCall(IndBCApplyJacobian(app->bc, K));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The active contact nodes at U: T the block-diagonal projector on their free directions (identity
   elsewhere, I - n n^T on a sliding node, 0 on a sticking one but for components a boundary condition
   holds) and the dofs the contact constraints hold. */
static PetscErrorCode ContactProjector(IndApp app, Vec U, Mat T, IS *held, PetscInt counts[3])
{
  IndContact         c = app->contact;
  const PetscScalar *u;
  PetscInt           rstart, rend, nheld = 0, *rows;

  PetscFunctionBeginUser;
  PetscCall(MatGetOwnershipRange(T, &rstart, &rend));
  for (PetscInt r = rstart; r < rend; r += 3) {
    const PetscInt    b[3] = {r, r + 1, r + 2};
    const PetscScalar I3[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    PetscCall(MatSetValues(T, 3, b, 3, b, I3, INSERT_VALUES));
  }
  PetscCall(PetscMalloc1(c ? 3 * c->n + 1 : 1, &rows));
  counts[0] = counts[1] = counts[2] = 0;
  PetscCall(VecGetArrayRead(U, &u));
  for (PetscInt i = 0; c && i < c->n; ++i) {
    IndContactNode  ns;
    const PetscInt  b[3] = {c->grow[i], c->grow[i] + 1, c->grow[i] + 2};
    PetscScalar     P[9];
    IndContactNodeSolve(c, i, u + c->row[i], c->L + 3 * i, &ns);
    counts[ns.status]++;
    if (ns.status == IND_CONTACT_OPEN) continue;
    /* a component a boundary condition holds stays as it is (a sliding node's normal has none there) */
    for (int x = 0; x < 3; ++x)
      for (int y = 0; y < 3; ++y)
        P[3 * x + y] = ns.status == IND_CONTACT_STICK ? (x == y && c->fixed[i] & (1 << x) ? 1.0 : 0.0)
                                                      : (x == y ? 1.0 : 0.0) - ns.n[x] * ns.n[y];
    PetscCall(MatSetValues(T, 3, b, 3, b, P, INSERT_VALUES));
    for (int d = 0; d < 3; ++d)
      if (!(c->fixed[i] & (1 << d))) rows[nheld++] = b[d];
  }
  PetscCall(VecRestoreArrayRead(U, &u));
  PetscCall(MatAssemblyBegin(T, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(T, MAT_FINAL_ASSEMBLY));
  PetscCall(ISCreateGeneral(PetscObjectComm((PetscObject)T), nheld, rows, PETSC_OWN_POINTER, held));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, counts, 3, MPIU_INT, MPI_SUM, PetscObjectComm((PetscObject)T)));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* One solve of A x = b preconditioned by GAMG on P, with the run's Krylov tolerance. */
static PetscErrorCode Solve(IndApp app, const char *what, Mat A, Mat P, KSPType type, Vec b)
{
  KSP                ksp, run;
  PC                 pc;
  MatNullSpace       rigid;
  Vec                x;
  PetscReal          rtol, atol, dtol;
  PetscInt           maxit, its;
  KSPConvergedReason reason;
  PetscLogDouble     t0, t1, t2;

  PetscFunctionBeginUser;
  PetscCall(MatGetNearNullSpace(app->solver->J, &rigid));
  PetscCall(MatSetNearNullSpace(P, rigid));
  PetscCall(SNESGetKSP(app->solver->snes, &run));
  PetscCall(KSPGetTolerances(run, &rtol, &atol, &dtol, &maxit));
  PetscCall(KSPCreate(app->comm, &ksp));
  PetscCall(KSPSetOptionsPrefix(ksp, "anatomy_"));
  PetscCall(KSPSetOperators(ksp, A, P));
  PetscCall(KSPSetType(ksp, type));
  PetscCall(KSPGMRESSetRestart(ksp, 100));
  PetscCall(KSPSetTolerances(ksp, rtol, atol, dtol, 1000));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PCSetType(pc, PCGAMG));
  PetscCall(PCGAMGSetUseSAEstEig(pc, PETSC_FALSE));
  PetscCall(KSPSetFromOptions(ksp));
  PetscCall(VecDuplicate(b, &x));
  PetscCall(PetscTime(&t0));
  PetscCall(KSPSetUp(ksp));
  PetscCall(PetscTime(&t1));
  PetscCall(KSPSolve(ksp, b, x));
  PetscCall(PetscTime(&t2));
  PetscCall(KSPGetIterationNumber(ksp, &its));
  PetscCall(KSPGetConvergedReason(ksp, &reason));
  PetscCall(PetscPrintf(app->comm, "| %-44s | %-5s | %4" PetscInt_FMT " | %-26s | %6.2f | %6.2f |\n", what, type, its,
    KSPConvergedReasons[reason], (double)(t1 - t0), (double)(t2 - t1)));
  PetscCall(VecDestroy(&x));
  PetscCall(KSPDestroy(&ksp));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode TakeApart(IndApp app, PetscInt step, PetscInt it, Vec U)
{
  IndSolver s = app->solver;
  Mat       J, K, Kel, Kfix, D, T;
  Vec       F, b;
  IS        held;
  PetscInt  counts[3], n;
  PetscReal alpha;

  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(U, &F));
  PetscCall(VecDuplicate(U, &b));
  PetscCall(Residual(app, U, F));
  PetscCall(VecAXPBY(b, -1.0, 0.0, F));
  PetscCall(MatDuplicate(s->J, MAT_DO_NOT_COPY_VALUES, &J));
  PetscCall(MatDuplicate(s->J, MAT_DO_NOT_COPY_VALUES, &K));
  PetscCall(MatDuplicate(s->J, MAT_DO_NOT_COPY_VALUES, &Kel));
  PetscCall(Tangent(app, app->assembly->tangent, PETSC_TRUE, J));
  PetscCall(Tangent(app, app->assembly->tangent, PETSC_FALSE, K));
  PetscCall(Tangent(app, IND_TANGENT_ELASTIC, PETSC_FALSE, Kel));
  /* the constrained dofs of the active nodes: scaled like the rest of the diagonal */
  PetscCall(MatGetSize(K, &n, NULL));
  {
    Vec d;
    PetscCall(MatCreateVecs(K, &d, NULL));
    PetscCall(MatGetDiagonal(K, d));
    PetscCall(VecSum(d, &alpha));
    alpha /= n;
    PetscCall(VecDestroy(&d));
  }
  {
    PetscInt m;
    PetscCall(MatGetLocalSize(K, &m, NULL));
    PetscCall(MatCreateAIJ(app->comm, m, m, n, n, 3, NULL, 0, NULL, &T)); /* block diagonal */
    PetscCall(MatSetBlockSize(T, 3));
  }
  PetscCall(ContactProjector(app, s->Ubc, T, &held, counts));
  PetscCall(MatDuplicate(K, MAT_COPY_VALUES, &Kfix));
  PetscCall(MatZeroRowsColumnsIS(Kfix, held, alpha, NULL, NULL));
  /* D = T K T + alpha (I - T): the active constraints eliminated symmetrically in each node's frame */
  PetscCall(MatPtAP(K, T, MAT_INITIAL_MATRIX, 2.0, &D));
  PetscCall(MatSetBlockSize(D, 3)); /* the product forgets it, and GAMG then aggregates dofs, not nodes */
  {
    /* alpha (I - T) on the active nodes' diagonal blocks, where D has its entries already */
    const PetscInt *rows;
    PetscInt        nh;
    PetscCall(ISGetLocalSize(held, &nh));
    PetscCall(ISGetIndices(held, &rows));
    for (PetscInt k = 0; k < nh; ++k) {
      const PetscInt     r = rows[k], b[3] = {r - r % 3, r - r % 3 + 1, r - r % 3 + 2};
      PetscScalar        t[3], v[3];
      PetscCall(MatGetValues(T, 1, &r, 3, b, t));
      for (int d = 0; d < 3; ++d) v[d] = (b[d] == r ? alpha : 0.0) - alpha * t[d];
      PetscCall(MatSetValues(D, 1, &r, 3, b, v, ADD_VALUES));
    }
    PetscCall(ISRestoreIndices(held, &rows));
    PetscCall(MatAssemblyBegin(D, MAT_FINAL_ASSEMBLY));
    PetscCall(MatAssemblyEnd(D, MAT_FINAL_ASSEMBLY));
  }
  PetscCall(PetscPrintf(app->comm,
    "Newton iteration %" PetscInt_FMT " of step %" PetscInt_FMT ": %" PetscInt_FMT " dofs, contact nodes open %"
    PetscInt_FMT
    ", sticking %" PetscInt_FMT ", sliding %" PetscInt_FMT ", %" PetscInt_FMT " yielding points\n\n", it, step, n,
    counts[0], counts[1], counts[2], s->nplastic));
  PetscCall(PetscPrintf(app->comm, "| %-44s | %-5s | %4s | %-26s | %6s | %6s |\n|---|---|---|---|---|---|\n", "system",
    "KSP", "its", "reason", "setup", "solve"));
  PetscCall(Solve(app, "J: the Jacobian as the run solves it", J, J, KSPGMRES, b));
  PetscCall(Solve(app, "K: no contact rows (equilibrium rows)", K, K, KSPCG, b));
  PetscCall(Solve(app, "K_elastic: K with the elastic tangent", Kel, Kel, KSPCG, b));
  PetscCall(Solve(app, "K_fixed: K, active contact nodes held", Kfix, Kfix, KSPCG, b));
  PetscCall(Solve(app, "D: K, active constraints eliminated", D, D, KSPCG, b));
  PetscCall(Solve(app, "J preconditioned by GAMG(D)", J, D, KSPGMRES, b));
  PetscCall(Solve(app, "J preconditioned by GAMG(K_elastic)", J, Kel, KSPGMRES, b));
  PetscCall(ISDestroy(&held));
  PetscCall(MatDestroy(&J));
  PetscCall(MatDestroy(&K));
  PetscCall(MatDestroy(&Kel));
  PetscCall(MatDestroy(&Kfix));
  PetscCall(MatDestroy(&D));
  PetscCall(MatDestroy(&T));
  PetscCall(VecDestroy(&F));
  PetscCall(VecDestroy(&b));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Monitor(SNES snes, PetscInt it, PetscReal fnorm, void *ctx)
{
  Anatomy *an = (Anatomy *)ctx;
  Vec      U;

  PetscFunctionBeginUser;
  (void)fnorm;
  if (an->done || an->app->path.accepted + 1 != an->step || it != an->newton) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(SNESGetSolution(snes, &U));
  PetscCall(TakeApart(an->app, an->step, it, U));
  an->done = PETSC_TRUE;
  IndSignalsRaise(SIGTERM); /* the run stops after this step */
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  Anatomy an = {NULL, 1, 0, PETSC_FALSE};

  PetscFunctionBeginUser;
  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  PetscOptionsBegin(PETSC_COMM_WORLD, NULL, "Solver anatomy", NULL);
  PetscCall(PetscOptionsInt("-anatomy_step", "Load step (1: the first)", NULL, an.step, &an.step, NULL));
  PetscCall(
    PetscOptionsInt("-anatomy_newton", "Its Newton iteration (0: the first)", NULL, an.newton, &an.newton, NULL));
  PetscOptionsEnd();
  {
    /* the variants' KSP and PC options are read only when they are solved: not unused for the run's check */
    PetscInt n;
    char   **names, **values;
    PetscCall(PetscOptionsLeftGet(NULL, &n, &names, &values));
    for (PetscInt k = 0; k < n; ++k) {
      PetscBool anatomy, has;
      char      opt[256];
      PetscCall(PetscStrncmp(names[k], "anatomy_", 8, &anatomy));
      PetscCall(PetscSNPrintf(opt, sizeof(opt), "-%s", names[k]));
      if (anatomy) PetscCall(PetscOptionsHasName(NULL, NULL, opt, &has));
    }
    PetscCall(PetscOptionsLeftRestore(NULL, &n, &names, &values));
  }
  PetscCall(IndAppCreate(PETSC_COMM_WORLD, &an.app));
  PetscCall(SNESMonitorSet(an.app->solver->snes, Monitor, &an, NULL));
  PetscCall(IndAppRun(an.app));
  PetscCheck(an.done, PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE,
    "The run never reached Newton iteration %" PetscInt_FMT " of step %" PetscInt_FMT, an.newton, an.step);
  PetscCall(IndAppDestroy(&an.app));
  PetscCall(PetscFinalize());
  return 0;
}
