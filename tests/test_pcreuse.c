static const char help[] = "When Newton's multigrid is rebuilt (src/solvers/pcreuse.c): the rule's decisions on small\n"
                           "sequences, its cost against every fixed lag in hindsight, and the rule on a real KSP,\n"
                           "with its hook on each multigrid built afresh.\n";

#include "pcreuse.h"
#include "unit_report.h"

static PetscMPIInt rank;

static void Check(const char *what, PetscReal worst, PetscReal tol)
{
  if (!rank) Report(what, worst, tol);
  else if (!(worst <= tol)) failures++;
}

/* Krylov iterations of a solve whose preconditioner was built `age` solves before, in a model where staleness
   costs extra(age) = slope * age (a drifting operator) or step * (age > 0) (one change, then steady). */
static PetscInt ModelIterations(PetscInt age, PetscReal slope, PetscReal step)
{
  return 20 + (PetscInt)PetscFloorReal(slope * (PetscReal)age + (age > 0 ? step : 0.0));
}

/* Total cost in Krylov iterations of n solves (iterations, plus cost per build) under the rule, or with a
   rebuild every lag solves when lag > 0. */
static PetscReal ModelCost(PetscInt n, PetscReal cost, PetscReal slope, PetscReal step, PetscInt lag)
{
  IndRebuildCount c;
  PetscReal       total = 0;
  PetscInt        age   = 0;

  IndRebuildCountInit(&c, cost);
  for (PetscInt k = 0; k < n; ++k) {
    const PetscBool fresh = lag > 0 ? (PetscBool)(k % lag == 0) : IndRebuildDue(&c);
    PetscInt        its;
    if (fresh) {
      age = 0;
      total += cost;
    }
    its = ModelIterations(age++, slope, step);
    total += (PetscReal)its;
    IndRebuildCountRecord(&c, fresh, its, PETSC_TRUE);
  }
  return total;
}

static void DecisionChecks(void)
{
  IndRebuildCount c;
  PetscReal       worst = 0;

  IndRebuildCountInit(&c, 15);
  Check("nothing built yet: due", IndRebuildDue(&c) ? 0 : 1, 0);
  IndRebuildCountRecord(&c, PETSC_TRUE, 20, PETSC_TRUE);
  Check("just built (20 iterations): not due", IndRebuildDue(&c) ? 1 : 0, 0);
  IndRebuildCountRecord(&c, PETSC_FALSE, 22, PETSC_TRUE);
  IndRebuildCountRecord(&c, PETSC_FALSE, 23, PETSC_TRUE);
  Check("kept, 22 and 23 (5 beyond): not due", IndRebuildDue(&c) ? 1 : 0, 0);
  Check("kept, 22 and 23: 5 counted", PetscAbsReal(c.excess - 5), 0);
  IndRebuildCountRecord(&c, PETSC_FALSE, 18, PETSC_TRUE);
  Check("kept, 18: the bar lowers to 18, nothing counted", PetscAbsReal(c.excess - 5) + PetscAbsInt(c.fewest - 18), 0);
  IndRebuildCountRecord(&c, PETSC_FALSE, 28, PETSC_TRUE);
  Check("kept, 28 (10 beyond 18): 15 counted, due", PetscAbsReal(c.excess - 15) + (IndRebuildDue(&c) ? 0 : 1), 0);
  IndRebuildCountRecord(&c, PETSC_TRUE, 21, PETSC_TRUE);
  Check("built again: not due, the count starts over", (IndRebuildDue(&c) ? 1 : 0) + c.excess, 0);
  IndRebuildCountRecord(&c, PETSC_FALSE, 21, PETSC_FALSE);
  Check("a kept solve that failed: due", IndRebuildDue(&c) ? 0 : 1, 0);
  IndRebuildCountInit(&c, 0);
  IndRebuildCountRecord(&c, PETSC_TRUE, 20, PETSC_TRUE);
  Check("cost 0: due after every solve", IndRebuildDue(&c) ? 0 : 1, 0);

  /* rent or buy: never more than twice the cheapest fixed lag chosen in hindsight, on drifting operators (the
     extra iterations grow with the age) and on one change (a constant extra); and no worse than rebuilding
     every time or never where those are best */
  {
    const PetscReal slopes[] = {0, 0.05, 0.5, 2, 8}, steps[] = {0, 0.5, 3, 30};
    for (size_t i = 0; i < sizeof(slopes) / sizeof(slopes[0]); ++i)
      for (size_t j = 0; j < sizeof(steps) / sizeof(steps[0]); ++j) {
        const PetscReal rule = ModelCost(400, 15, slopes[i], steps[j], 0);
        PetscReal       best = PETSC_MAX_REAL;
        for (PetscInt lag = 1; lag <= 400; ++lag) best = PetscMin(best, ModelCost(400, 15, slopes[i], steps[j], lag));
        /* the rule's cost beyond the 20 iterations every solve needs, against the best lag's */
        worst = PetscMax(worst, (rule - 400 * 20) / PetscMax(best - 400 * 20, 1.0));
      }
  }
  Check("extra cost, rule / best fixed lag, worst of 20 models", worst, 2.0);
}

/* A 1D Laplacian plus shift times the identity, assembled in place (the state of the matrix changes). */
static PetscErrorCode Assemble(Mat A, PetscReal shift)
{
  PetscInt lo, hi, N;

  PetscFunctionBeginUser;
  PetscCall(MatGetOwnershipRange(A, &lo, &hi));
  PetscCall(MatGetSize(A, &N, NULL));
  for (PetscInt i = lo; i < hi; ++i) {
    PetscScalar v[3] = {-1, 2 + shift, -1};
    PetscInt    c[3] = {i - 1, i, i + 1};
    if (i == 0) PetscCall(MatSetValues(A, 1, &i, 2, c + 1, v + 1, INSERT_VALUES));
    else if (i == N - 1) PetscCall(MatSetValues(A, 1, &i, 2, c, v, INSERT_VALUES));
    else PetscCall(MatSetValues(A, 1, &i, 3, c, v, INSERT_VALUES));
  }
  PetscCall(MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Calls of the fresh-hierarchy hook, and those that found the multigrid set up */
typedef struct {
  PetscInt calls, ready;
} FreshCount;

static PetscErrorCode CountFresh(KSP ksp, void *ctx)
{
  FreshCount *f      = (FreshCount *)ctx;
  PetscInt    levels = 0;
  PC          pc;
  PetscBool   mg;

  PetscFunctionBeginUser;
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PetscObjectTypeCompareAny((PetscObject)pc, &mg, PCMG, PCGAMG, ""));
  if (mg) PetscCall(PCMGGetLevels(pc, &levels)); /* GAMG has none before its set-up */
  f->calls++;
  if (levels > 0) f->ready++;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* n solves, each after the matrix was assembled again with a slowly drifting shift; the rule's counts, whether
   every solve converged, and the hook's calls. */
static PetscErrorCode Sequence(PCType pctype, PetscBool active, PetscReal cost, PetscInt n, PetscInt *solves,
                               PetscInt *builds, PetscBool *converged, FreshCount *fresh)
{
  Mat        A;
  Vec        x, b;
  KSP        ksp;
  PC         pc;
  IndPCReuse r;
  char       value[32];

  PetscFunctionBeginUser;
  PetscCall(PetscSNPrintf(value, sizeof(value), "%g", (double)cost));
  PetscCall(PetscOptionsSetValue(NULL, "-newton_pc_rebuild_cost", value));
  PetscCall(MatCreateAIJ(PETSC_COMM_WORLD, PETSC_DECIDE, PETSC_DECIDE, 400, 400, 3, NULL, 2, NULL, &A));
  PetscCall(MatCreateVecs(A, &x, &b));
  PetscCall(VecSet(b, 1.0));
  PetscCall(KSPCreate(PETSC_COMM_WORLD, &ksp));
  PetscCall(KSPSetType(ksp, KSPGMRES));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PCSetType(pc, pctype));
  PetscCall(KSPSetTolerances(ksp, 1e-8, PETSC_DEFAULT, PETSC_DEFAULT, 2000));
  PetscCall(IndPCReuseCreate(ksp, active, &r));
  fresh->calls = fresh->ready = 0;
  PetscCall(IndPCReuseSetFreshHook(r, CountFresh, fresh));
  *converged = PETSC_TRUE;
  for (PetscInt k = 0; k < n; ++k) {
    KSPConvergedReason reason;
    PetscCall(Assemble(A, 1e-4 * (PetscReal)(k + 1)));
    PetscCall(KSPSetOperators(ksp, A, A));
    PetscCall(VecZeroEntries(x));
    PetscCall(KSPSolve(ksp, b, x));
    PetscCall(KSPGetConvergedReason(ksp, &reason));
    if (reason <= 0) *converged = PETSC_FALSE;
  }
  IndPCReuseGetCounts(r, solves, builds);
  PetscCall(IndPCReuseDestroy(&r));
  PetscCall(KSPDestroy(&ksp));
  PetscCall(VecDestroy(&x));
  PetscCall(VecDestroy(&b));
  PetscCall(MatDestroy(&A));
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  PetscInt   solves, builds;
  PetscBool  converged;
  FreshCount fresh;

  PetscFunctionBeginUser;
  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  PetscCallMPI(MPI_Comm_rank(PETSC_COMM_WORLD, &rank));
  DecisionChecks();

  PetscCall(Sequence(PCGAMG, PETSC_TRUE, 15, 8, &solves, &builds, &converged, &fresh));
  if (!rank) printf("GAMG, cost 15: %d solves, %d builds\n", (int)solves, (int)builds);
  Check("GAMG, cost 15: every solve converged", converged ? 0 : 1, 0);
  Check("GAMG, cost 15, drift 1e-4: 8 solves, built at the first only",
        (PetscReal)(PetscAbsInt(solves - 8) + PetscAbsInt(builds - 1)), 0);
  Check("GAMG, cost 15: the hook once, on a multigrid set up", (PetscReal)(PetscAbsInt(fresh.calls - 1) +
        PetscAbsInt(fresh.ready - 1)), 0);
  PetscCall(Sequence(PCGAMG, PETSC_TRUE, 0, 8, &solves, &builds, &converged, &fresh));
  Check("GAMG, cost 0: built for every solve, converged",
        (PetscReal)(PetscAbsInt(solves - 8) + PetscAbsInt(builds - 8) + (converged ? 0 : 1)), 0);
  Check("GAMG, cost 0: the hook at every build, on a multigrid set up",
        (PetscReal)(PetscAbsInt(fresh.calls - 8) + PetscAbsInt(fresh.ready - 8)), 0);
  PetscCall(Sequence(PCBJACOBI, PETSC_TRUE, 15, 4, &solves, &builds, &converged, &fresh));
  Check("block Jacobi: not a multigrid, left to its caller",
        (PetscReal)(solves + builds + fresh.calls + (converged ? 0 : 1)), 0);
  PetscCall(Sequence(PCGAMG, PETSC_FALSE, 15, 4, &solves, &builds, &converged, &fresh));
  Check("GAMG, inactive (SNES's lag chosen): left to its caller",
        (PetscReal)(solves + builds + fresh.calls + (converged ? 0 : 1)), 0);
  PetscCall(PetscFinalize());
  return failures ? 1 : 0;
}
