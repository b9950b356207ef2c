/* Unit test of the cell matrix by the partition of unity (IndCellMatrixCompleteLastNode, src/physics/assembly.c):
   the kinematics' stiffness computed for the first nb - 1 nodes and the last node's rows and columns completed
   from them equals the stiffness computed for all nb nodes, for both kinematics, linear tetrahedra and
   hexahedra, elastic and plastic points, one and several quadrature points. Gradients that do not sum to zero
   (a control) must make the two differ: the comparison can fail. And at finite strain, a point that never yielded
   (whose material is evaluated in the eigenbasis of C) gives the stiffness and stress of the global frame's general
   path, elastic or yielding, J2 or densifying; a plastic history (the control) must not. */
#include <string.h>
#include "assembly_impl.h"
#include "point_material.h"
#include "unit_report.h"

enum { MAXNB = 8, MAXND = 3 * MAXNB, NQ = 3 };

/* Random gradients of nb shape functions at a point, summing to zero unless control is set. */
static void Gradients(unsigned long long *seed, PetscInt nb, PetscBool control, PetscReal *G)
{
  for (int j = 0; j < 3; ++j) {
    PetscReal s = 0;
    for (PetscInt a = 0; a < nb - 1; ++a) {
      G[3 * a + j] = 2.0 * Rand(seed) - 1.0;
      s += G[3 * a + j];
    }
    G[3 * (nb - 1) + j] = -s + (control ? 0.5 : 0.0);
  }
}

/* Max |K1 - K2| / max |K1| over the cell matrices of nq points (each with its own gradients and weight). */
static PetscReal Compare(const IndKinematics *kin, const IndMaterial *m, PetscInt nb, PetscReal amp, PetscBool hist,
                         PetscBool control, unsigned long long *seed)
{
  const PetscInt nd = 3 * nb;
  PetscReal      full[MAXND * MAXND] = {0}, part[MAXND * MAXND] = {0}, B[6 * MAXND], DB[6 * MAXND], kmax = 0, dmax = 0;

  for (int q = 0; q < NQ; ++q) {
    PetscReal G[3 * MAXNB], u[MAXND], old[IND_HISTORY_NVAL] = {0}, w = 0.5 + Rand(seed);
    Gradients(seed, nb, control, G);
    for (PetscInt k = 0; k < nd; ++k) u[k] = amp * (2.0 * Rand(seed) - 1.0);
    if (hist) {
      for (int k = 0; k < 3; ++k) old[k] = 0.01 * (2.0 * Rand(seed) - 1.0);
      old[2] = -(old[0] + old[1]);
      for (int k = 3; k < 6; ++k) old[k] = 0.01 * (2.0 * Rand(seed) - 1.0);
      old[12] = 0.02;
    }
    (void)kin->stiffness(m, IND_TANGENT_CONSISTENT, nb, nb, G, NULL, u, old, w, B, DB, full, NULL);
    (void)kin->stiffness(m, IND_TANGENT_CONSISTENT, nb, nb - 1, G, NULL, u, old, w, B, DB, part, NULL);
  }
  for (PetscInt r = 1; r < nd; ++r)
    for (PetscInt c = 0; c < r; ++c) full[r * nd + c] = full[c * nd + r];
  IndCellMatrixCompleteLastNode(nb, part);
  for (PetscInt k = 0; k < nd * nd; ++k) {
    kmax = PetscMax(kmax, PetscAbsReal(full[k]));
    dmax = PetscMax(dmax, PetscAbsReal(full[k] - part[k]));
  }
  for (PetscInt r = 0; r < nd; ++r) /* the completed matrix is exactly symmetric */
    for (PetscInt c = 0; c < r; ++c)
      if (part[r * nd + c] != part[c * nd + r]) dmax = PETSC_MAX_REAL;
  return dmax / kmax;
}

/* Max relative difference, in the stiffness and in the stress, between a finite-strain point that never yielded
   (its material evaluated in the eigenbasis of C) and the same point with a plastic strain eps in its history (the
   material in the global frame): eps = 1e-300 leaves the response as it is, which must agree; eps = 1e-3 turns the
   stress and must not. amp: the displacements' amplitude (1e-3 elastic, 0.05 yielding from the virgin state). */
static PetscReal CompareVirgin(const IndMaterial *m, PetscInt nb, PetscInt nt, PetscReal amp, PetscReal eps,
                               unsigned long long *seed)
{
  const IndKinematics *kin = IndKinematicsFinite();
  const PetscInt       nd  = 3 * nb;
  PetscReal            K1[MAXND * MAXND] = {0}, K2[MAXND * MAXND] = {0}, B[6 * MAXND], DB[6 * MAXND], P1[9], P2[9];
  PetscReal            G[3 * MAXNB], u[MAXND], old[IND_HISTORY_NVAL] = {0}, kmax = 0, dmax = 0, pmax = 0, dpmax = 0;
  PetscReal            dp;

  Gradients(seed, nb, PETSC_FALSE, G);
  for (PetscInt k = 0; k < nd; ++k) u[k] = amp * (2.0 * Rand(seed) - 1.0);
  (void)kin->stiffness(m, IND_TANGENT_CONSISTENT, nb, nt, G, NULL, u, old, 0.7, B, DB, K1, NULL);
  (void)kin->stress(m, IND_TANGENT_CONSISTENT, nb, G, NULL, u, old, NULL, P1, &dp, NULL);
  old[0] = eps;
  (void)kin->stiffness(m, IND_TANGENT_CONSISTENT, nb, nt, G, NULL, u, old, 0.7, B, DB, K2, NULL);
  (void)kin->stress(m, IND_TANGENT_CONSISTENT, nb, G, NULL, u, old, NULL, P2, &dp, NULL);
  for (PetscInt k = 0; k < nd * nd; ++k) {
    kmax = PetscMax(kmax, PetscAbsReal(K2[k]));
    dmax = PetscMax(dmax, PetscAbsReal(K1[k] - K2[k]));
  }
  for (int k = 0; k < 9; ++k) {
    pmax  = PetscMax(pmax, PetscAbsReal(P2[k]));
    dpmax = PetscMax(dpmax, PetscAbsReal(P1[k] - P2[k]));
  }
  return PetscMax(dmax / kmax, dpmax / pmax);
}

int main(int argc, char **argv)
{
  unsigned long long seed = 20261128ULL;
  IndMaterial        m    = PointTestMaterial();

  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  printf("cell stiffness completed by the partition of unity against the whole computation\n");
  for (int f = 0; f < 2; ++f) {
    const IndKinematics *kin = f ? IndKinematicsFinite() : IndKinematicsSmall();
    for (PetscInt nb = 4; nb <= 8; nb += 4)
      for (int c = 0; c < 3; ++c) { /* elastic, plastic, and plastic from a plastic history */
        const PetscReal amp  = c == 0 ? 1e-4 : 0.05;
        const PetscBool hist = c == 2 ? PETSC_TRUE : PETSC_FALSE;
        char            what[128];
        PetscReal       worst = 0;
        for (int t = 0; t < 50; ++t) worst = PetscMax(worst, Compare(kin, &m, nb, amp, hist, PETSC_FALSE, &seed));
        PetscCall(PetscSNPrintf(what, sizeof(what), "%s, %" PetscInt_FMT " nodes, %s", kin->name, nb,
                                c == 0 ? "elastic" : c == 1 ? "plastic" : "plastic history"));
        Report(what, worst, 1e-13);
      }
    {
      /* the control: gradients that do not sum to zero are not completed right */
      const PetscReal d = Compare(kin, &m, 4, 1e-3, PETSC_FALSE, PETSC_TRUE, &seed);
      Report(f ? "finite, control: gradients not summing to zero differ (1 / difference)"
               : "small, control: gradients not summing to zero differ (1 / difference)", 1.0 / d, 1e3);
    }
  }
  printf("finite strain: a point that never yielded (material in the eigenbasis of C) against the global frame's\n");
  for (int mat = 0; mat < 2; ++mat) {
    IndMaterial md = m;
    if (mat) { /* the densifying glass: its consistent tangent comes whole, not by its parts */
      md.model                         = IND_MODEL_DENSIFYING;
      md.plastic.yield_pressure        = 0.4;
      md.plastic.densification_modulus = 2.0;
    }
    for (PetscInt nb = 4; nb <= 8; nb += 4)
      for (int c = 0; c < 2; ++c) {
        const PetscReal amp = c ? 0.05 : 1e-3;
        char            what[160];
        PetscReal       worst = 0, control = PETSC_MAX_REAL;
        for (int t = 0; t < 50; ++t)
          worst = PetscMax(worst, CompareVirgin(&md, nb, nb == 4 ? 4 : 7, amp, 1e-300, &seed));
        for (int t = 0; t < 10; ++t)
          control = PetscMin(control, CompareVirgin(&md, nb, nb == 4 ? 4 : 7, amp, 1e-3, &seed));
        PetscCall(PetscSNPrintf(what, sizeof(what), "%s, %" PetscInt_FMT " nodes, %s", mat ? "densifying" : "J2", nb,
                                c ? "yielding (0.05)" : "elastic (1e-3)"));
        Report(what, worst, 1e-13);
        PetscCall(PetscSNPrintf(what, sizeof(what), "  control: a plastic strain 1e-3 (1e-5 / difference)"));
        Report(what, 1e-5 / control, 1.0);
      }
  }
  PetscCall(PetscFinalize());
  return failures ? 1 : 0;
}
