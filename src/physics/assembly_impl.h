#pragma once
/* Private to the assembly (assembly.c: small strain and the shared loops' entry points;
   assembly_finite.c: total Lagrangian finite strain): cell gathering and the material point. */
#include "ind_assembly.h"
#include "ind_elasticity.h"
#include "ind_mat3.h"

/* The displacements (ue) and the node positions (xe, from xn, the array of the discretisation's
   Xloc) of local cell i. */
static inline void GatherCell(IndAssembly a, PetscInt i, const PetscScalar *u, const PetscScalar *xn)
{
  const PetscInt *idx = a->disc->lidx + i * a->disc->ndof;
  for (PetscInt k = 0; k < a->disc->ndof; ++k) {
    a->ue[k] = PetscRealPart(u[idx[k]]);
    a->xe[k] = PetscRealPart(xn[idx[k]]);
  }
}

/* The constitutive update of one quadrature point from its committed history old (IND_HISTORY_NVAL
   values); writes the trial history to trial when not NULL and the tangent to D when not NULL. */
static inline IndPlasticStatus MaterialResponse(const IndMaterial *m, IndTangent tangent, const PetscReal eps[6],
                                                const PetscReal *old, PetscReal *trial, PetscReal sigma[6],
                                                PetscReal *D, PetscReal *dp)
{
  IndPlasticState  scratch;
  IndPlasticStatus status;

  *dp = 0.0;
  if (m->model == IND_MODEL_ELASTIC) {
    IndElasticStress(m->kappa, m->mu, eps, sigma);
    if (D) IndElasticTangent(m->kappa, m->mu, D);
    return IND_PLASTIC_OK;
  }
  status = IndPlasticUpdate(&m->plastic, eps, (const IndPlasticState *)old, trial ? (IndPlasticState *)trial : &scratch,
                            sigma, tangent == IND_TANGENT_CONSISTENT ? D : NULL, dp);
  if (trial) trial[IND_HISTORY_DP] = *dp;
  if (D && tangent == IND_TANGENT_ELASTIC) IndElasticTangent(m->kappa, m->mu, D);
  return status;
}

/* The displacement gradient H = sum_a u_a (x) G_a and F = I + H, row-major (finite strain, and the
   check for inverted cells). */
static inline void IndDeformationGradient(PetscInt nb, const PetscReal *G, const PetscReal *u, PetscReal H[9],
                                          PetscReal F[9])
{
  for (int k = 0; k < 9; ++k) H[k] = 0.0;
  for (PetscInt a = 0; a < nb; ++a)
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) H[3 * i + j] += u[3 * a + i] * G[3 * a + j];
  for (int k = 0; k < 9; ++k) F[k] = H[k] + (k % 4 == 0 ? 1.0 : 0.0);
}

/* Finite strain at one quadrature point (assembly_finite.c), from the physical gradients G (nb x 3)
   and the cell displacements ue: the first Piola-Kirchhoff stress P (3x3, row-major), writing the
   trial history when trial is not NULL; and Ke += w (B^T dS/dE_GL B + geometric stiffness), B and DB
   workspaces of 6 nd. */
IndPlasticStatus IndFinitePointStress(const IndMaterial *m, IndTangent tangent, PetscInt nb, const PetscReal *G,
                                      const PetscReal *ue, const PetscReal *old, PetscReal *trial, PetscReal P[9],
                                      PetscReal *dp);
IndPlasticStatus IndFinitePointStiffness(const IndMaterial *m, IndTangent tangent, PetscInt nb, const PetscReal *G,
                                         const PetscReal *ue, const PetscReal *old, PetscReal w, PetscReal *B,
                                         PetscReal *DB, PetscReal *Ke);
/* Cauchy stress and spatial Hencky strain of a quadrature point of cell i (committed history h), from
   the cell's displacements and gradients in the assembly's ue and G; w holds the reference weight
   and becomes that of the current volume. */
void IndAssemblyFinitePointFields(IndAssembly assembly, PetscInt i, const PetscReal *h, PetscReal sigma[6],
                                  PetscReal e[6], PetscReal *w);
