static const char help[] =
  "Cost of the quadrature-point kernels that a Jacobian and a residual spend their arithmetic in (doc/performance.md):\n"
  "each kinematics' stiffness (with the cell's mirroring, or for hexahedra its completion by the partition of\n"
  "unity, as the cell loop does) and stress, on random gradients and displacements, for an elastic point, a\n"
  "plastic one and a plastic one with a plastic history. Cells of a linear tetrahedron (one point) and of a\n"
  "linear hexahedron (8 points). Gathering, gradients and the insertion into the matrix are not included.\n"
  "Prints one table (ns per point, the fastest of the repeats); not a test.\n"
  "  -repeat r    timed passes over 4096 points (the fastest is reported; default 7)\n";

#include <string.h>
#include <petsctime.h>
#include "assembly_impl.h"
#include "point_material.h"

enum { NP = 4096, MAXNB = 8, MAXND = 24 };

static PetscReal G[NP][3 * MAXNB], U[NP][MAXND], Hist[NP][IND_HISTORY_NVAL];

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

/* ns per point of the stiffness (cells of nq points, each point with its own gradients) and of the stress. */
static PetscErrorCode Time(const IndKinematics *kin, const IndMaterial *m, PetscInt nb, PetscInt nq, PetscInt repeat,
                           PetscReal *stiffness, PetscReal *stress, PetscInt *plastic)
{
  const PetscInt nd = 3 * nb, nt = nq > 1 ? nb - 1 : nb;
  PetscReal      Ke[MAXND * MAXND], B[6 * MAXND], DB[6 * MAXND], sink = 0;
  PetscLogDouble t0, t1;

  PetscFunctionBeginUser;
  *stiffness = *stress = PETSC_MAX_REAL;
  *plastic             = 0;
  for (int p = 0; p < NP; ++p) {
    PetscReal P[9], dp;
    (void)kin->stress(m, IND_TANGENT_CONSISTENT, nb, G[p], NULL, U[p], Hist[p], NULL, P, &dp);
    if (dp > 0) ++*plastic;
  }
  for (PetscInt r = 0; r < repeat; ++r) {
    PetscCall(PetscTime(&t0));
    for (int c = 0; c < NP; c += nq) {
      memset(Ke, 0, sizeof(PetscReal) * nd * nd);
      for (int q = c; q < c + nq; ++q)
        (void)kin->stiffness(m, IND_TANGENT_CONSISTENT, nb, nt, G[q], NULL, U[c], Hist[q], 0.7, B, DB, Ke);
      if (nt < nb) IndCellMatrixCompleteLastNode(nb, Ke);
      else
        for (PetscInt i = 1; i < nd; ++i)
          for (PetscInt j = 0; j < i; ++j) Ke[i * nd + j] = Ke[j * nd + i];
      sink += Ke[nd * nd - 1];
    }
    PetscCall(PetscTime(&t1));
    *stiffness = PetscMin(*stiffness, (t1 - t0) / NP * 1e9);
    PetscCall(PetscTime(&t0));
    for (int p = 0; p < NP; ++p) {
      PetscReal P[9], dp;
      (void)kin->stress(m, IND_TANGENT_CONSISTENT, nb, G[p], NULL, U[p], Hist[p], NULL, P, &dp);
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
                                          "finite: stiffness, stress (ns) | finite / small stiffness |\n"
                                          "|---|---|---|---|---|---|\n"));
  for (int cell = 0; cell < 2; ++cell)
    for (int state = 0; state < 3; ++state) {
      const PetscInt nb = cell ? 8 : 4, nq = cell ? 8 : 1;
      PetscReal      ks, ss, kf, sf;
      PetscInt       np_small, np_finite;
      Points(nb, state == 0 ? 1e-3 : 0.05, (PetscBool)(state == 2));
      PetscCall(Time(IndKinematicsSmall(), &m, nb, nq, repeat, &ks, &ss, &np_small));
      PetscCall(Time(IndKinematicsFinite(), &m, nb, nq, repeat, &kf, &sf, &np_finite));
      PetscCall(PetscPrintf(PETSC_COMM_WORLD, "| %s | %s | %d%%, %d%% | %.0f, %.0f | %.0f, %.0f | %.2f |\n",
                            cell ? "hexahedron, 8 points" : "tetrahedron, 1 point",
                            state == 0 ? "elastic (strain 1e-3)" : state == 1 ? "plastic (0.05)" : "plastic history",
                            (int)(100 * np_small / NP), (int)(100 * np_finite / NP), (double)ks, (double)ss,
                            (double)kf, (double)sf, (double)(kf / ks)));
    }
  PetscCall(PetscFinalize());
  return 0;
}
