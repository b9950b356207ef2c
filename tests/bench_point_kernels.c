static const char help[] =
  "Cost of the quadrature-point kernels that a Jacobian and a residual spend their arithmetic in (doc/performance.md):\n"
  "each kinematics' stiffness (with the cell's mirroring, or for hexahedra its completion by the partition of\n"
  "unity, as the cell loop does), the same stiffness from what the residual's stress kept at the point (finite\n"
  "strain: the decomposition of C), and stress, on random gradients and displacements, for an elastic point, a\n"
  "plastic one and a plastic one with a plastic history. Cells of a linear tetrahedron (one point) and of a\n"
  "linear hexahedron (8 points). Gathering, gradients and the insertion into the matrix are not included.\n"
  "Prints one table (ns per point, the fastest of the repeats); not a test.\n"
  "  -repeat r    timed passes over 4096 points (the fastest is reported; default 7)\n";

#include <string.h>
#include <petsctime.h>
#include "assembly_impl.h"
#include "point_material.h"
#include "ind_logstrain.h"

enum { NP = 4096, MAXNB = 8, MAXND = 24 };

static PetscReal G[NP][3 * MAXNB], U[NP][MAXND], Hist[NP][IND_HISTORY_NVAL], Kept[NP][IND_LOGSTRAIN_NKEEP];

static PetscReal Rand(unsigned long long *s)
{
  *s = *s * 6364136223846793005ULL + 1442695040888963407ULL;
  return (PetscReal)((*s >> 11) * (1.0 / 9007199254740992.0)) * 2.0 - 1.0;
}

/* Gradients summing to zero (a partition of unity), displacements of amplitude amp, optionally a plastic history. */
static void Points(PetscInt nb, PetscReal amp, PetscBool history)
{
  unsigned long long s = 12345;
  for (int p = 0; p < NP; ++p) {
    for (int j = 0; j < 3; ++j) {
      PetscReal sum = 0;
      for (PetscInt a = 0; a < nb - 1; ++a) sum += (G[p][3 * a + j] = Rand(&s));
      G[p][3 * (nb - 1) + j] = -sum;
    }
    for (PetscInt k = 0; k < 3 * nb; ++k) U[p][k] = amp * Rand(&s);
    memset(Hist[p], 0, sizeof(Hist[p]));
    if (history) {
      for (int k = 0; k < 6; ++k) Hist[p][k] = 0.01 * Rand(&s);
      Hist[p][2] = -(Hist[p][0] + Hist[p][1]);
      Hist[p][12] = 0.02; /* the accumulated plastic strain */
    }
  }
}

/* ns per point of the cells' stiffness (cells of nq points, each point with its own gradients), from the points'
   kept values or without them. */
static PetscErrorCode TimeStiffness(const IndKinematics *kin, const IndMaterial *m, PetscInt nb, PetscInt nq,
                                    PetscBool kept, PetscReal *ns, PetscReal *sink)
{
  const PetscInt nd = 3 * nb, nt = nq > 1 ? nb - 1 : nb;
  PetscReal      Ke[MAXND * MAXND], B[6 * MAXND], DB[6 * MAXND];
  PetscLogDouble t0, t1;

  PetscFunctionBeginUser;
  PetscCall(PetscTime(&t0));
  for (int c = 0; c < NP; c += nq) {
    memset(Ke, 0, sizeof(PetscReal) * nd * nd);
    for (int q = c; q < c + nq; ++q)
      (void)kin->stiffness(m, IND_TANGENT_CONSISTENT, nb, nt, G[q], NULL, U[c], Hist[q], 0.7, B, DB, Ke,
                           kept ? Kept[q] : NULL);
    if (nt < nb) IndCellMatrixCompleteLastNode(nb, Ke);
    else
      for (PetscInt i = 1; i < nd; ++i)
        for (PetscInt j = 0; j < i; ++j) Ke[i * nd + j] = Ke[j * nd + i];
    *sink += Ke[nd * nd - 1];
  }
  PetscCall(PetscTime(&t1));
  *ns = PetscMin(*ns, (t1 - t0) / NP * 1e9);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* ns per point of the stiffness, of the stiffness from the residual's kept values (PETSC_MAX_REAL for a kinematics
   that keeps none) and of the stress. */
static PetscErrorCode Time(const IndKinematics *kin, const IndMaterial *m, PetscInt nb, PetscInt nq, PetscInt repeat,
                           PetscReal *stiffness, PetscReal *stiffness_kept, PetscReal *stress, PetscInt *plastic)
{
  PetscReal      sink = 0;
  PetscLogDouble t0, t1;

  PetscFunctionBeginUser;
  *stiffness = *stiffness_kept = *stress = PETSC_MAX_REAL;
  *plastic                               = 0;
  for (int p = 0; p < NP; ++p) {
    PetscReal P[9], dp;
    /* the cells' points take the displacements of the cell's first point (U[c] above): so do the kept values */
    (void)kin->stress(m, IND_TANGENT_CONSISTENT, nb, G[p], NULL, U[p - p % nq], Hist[p], NULL, P, &dp,
                      kin->nkeep ? Kept[p] : NULL);
    if (dp > 0) ++*plastic;
  }
  for (PetscInt r = 0; r < repeat; ++r) {
    PetscCall(TimeStiffness(kin, m, nb, nq, PETSC_FALSE, stiffness, &sink));
    if (kin->nkeep) PetscCall(TimeStiffness(kin, m, nb, nq, PETSC_TRUE, stiffness_kept, &sink));
    PetscCall(PetscTime(&t0));
    for (int p = 0; p < NP; ++p) {
      PetscReal P[9], dp;
      (void)kin->stress(m, IND_TANGENT_CONSISTENT, nb, G[p], NULL, U[p], Hist[p], NULL, P, &dp, NULL);
      sink += P[0];
    }
    PetscCall(PetscTime(&t1));
    *stress = PetscMin(*stress, (t1 - t0) / NP * 1e9);
  }
  PetscCheck(PetscIsNormalReal(sink) || sink == 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "non-finite kernel output");
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  PetscInt    repeat = 7;
  IndMaterial m      = PointTestMaterial();

  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  PetscCall(PetscOptionsGetInt(NULL, NULL, "-repeat", &repeat, NULL));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "| cell | point | plastic points | small: stiffness, stress (ns) | "
                                          "finite: stiffness, from kept, stress (ns) | finite / small stiffness, "
                                          "from kept |\n|---|---|---|---|---|---|\n"));
  for (int cell = 0; cell < 2; ++cell)
    for (int state = 0; state < 3; ++state) {
      const PetscInt nb = cell ? 8 : 4, nq = cell ? 8 : 1;
      PetscReal      ks, ss, kf, kk, sf, unused;
      PetscInt       np_small, np_finite;
      Points(nb, state == 0 ? 1e-3 : 0.05, (PetscBool)(state == 2));
      PetscCall(Time(IndKinematicsSmall(), &m, nb, nq, repeat, &ks, &unused, &ss, &np_small));
      PetscCall(Time(IndKinematicsFinite(), &m, nb, nq, repeat, &kf, &kk, &sf, &np_finite));
      PetscCall(PetscPrintf(PETSC_COMM_WORLD, "| %s | %s | %d%%, %d%% | %.0f, %.0f | %.0f, %.0f, %.0f | %.2f, %.2f |\n",
                            cell ? "hexahedron, 8 points" : "tetrahedron, 1 point",
                            state == 0 ? "elastic (strain 1e-3)" : state == 1 ? "plastic (0.05)" : "plastic history",
                            (int)(100 * np_small / NP), (int)(100 * np_finite / NP), (double)ks, (double)ss,
                            (double)kf, (double)kk, (double)sf, (double)(kf / ks), (double)(kk / ks)));
    }
  PetscCall(PetscFinalize());
  return 0;
}
