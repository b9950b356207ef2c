#pragma once
/* Private to src/physics/: the fields of IndAssembly, the kinematics' table of operations (kinematics_small.c,
   kinematics_finite.c) and the helpers of the cell loops (assembly.c): cell gathering and the material point. */
#include "ind_assembly.h"

struct _p_IndAssembly {
  IndDisc              disc;
  const IndDiscLayout *layout;  /* the discretisation's, read by the cell loops */
  DM                   dm;      /* its DM (borrowed) */
  Vec                  Xloc;    /* its node positions (borrowed) */
  IndMaterials         mats;
  IndHistory           history;
  IndTangent           tangent; /* -plastic_tangent: elastic only for comparisons, it loses quadratic Newton */
  const IndKinematics *kin;     /* -formulation */
  IndVectorFn          body_force;
  void                *body_ctx;
  PetscReal           *xq;       /* with a body force: the quadrature points, ncell x nq x 3 */
  PetscInt             nfailed;  /* local quadrature points whose return map failed, last residual */
  PetscInt             nplastic; /* local quadrature points yielding (dp > 0), last residual */
  PetscReal           *ue, *xe, *fe, *Ke, *G, *DB, *B; /* per-cell work arrays, allocated once */
  PetscReal           *hoop;     /* nb: N_a / r at the point, on an axisymmetric section */
  const PetscReal     *khoop;    /* what the kinematics get: hoop there, NULL in 3D */
  Mat                  J;        /* the matrix made by IndAssemblyCreateMatrix (borrowed) */
  IndMatInsert         insert;   /* and its cached insertion (NULL: MatSetValues) */
  PetscBool            inodes;   /* products by PETSc's inode kernel (-jac_inodes) */
  PetscBool            blocks;   /* products by block rows (-jac_block_products) */
  /* what the last residual's points kept for a Jacobian at the same displacement (kin->nkeep values a point), in
     pieces of kept_cells cells each (NULL: nothing allocated) */
  PetscReal          **kept;
  PetscInt             kept_pieces, kept_cells;
  PetscScalar         *kept_u;    /* that residual's local displacement, to the bit */
  PetscInt             kept_n;    /* its length; 0: nothing kept */
  PetscInt             kept_uses; /* Jacobians that used them */
};

#include "material_impl.h"
#include "history_impl.h"
#include "ind_elasticity.h"
#include "ind_densification.h"
#include "ind_mat3.h"

/* The displacements (ue) and the node positions (xe, from xn, the array of the discretisation's
   Xloc) of local cell i. */
static inline void GatherCell(IndAssembly a, PetscInt i, const PetscScalar *u, const PetscScalar *xn)
{
  const PetscInt *node = a->layout->lnode + i * a->layout->nb;
  for (PetscInt b = 0; b < a->layout->nb; ++b)
    for (int c = 0; c < 3; ++c) {
      a->ue[3 * b + c] = PetscRealPart(u[3 * node[b] + c]);
      a->xe[3 * b + c] = PetscRealPart(xn[3 * node[b] + c]);
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
  if (m->model == IND_MODEL_DENSIFYING) {
    status = IndDensifyingUpdate(&m->plastic, eps, (const IndPlasticState *)old,
                                 trial ? (IndPlasticState *)trial : &scratch, sigma,
                                 tangent == IND_TANGENT_CONSISTENT ? D : NULL, dp);
    /* the cell loops assemble symmetric element matrices */
    if (D && tangent == IND_TANGENT_CONSISTENT && m->plastic.densification_modulus > 0) IndDensifyingSymmetrize(D);
  } else
    status = IndPlasticUpdate(&m->plastic, eps, (const IndPlasticState *)old,
                              trial ? (IndPlasticState *)trial : &scratch, sigma,
                              tangent == IND_TANGENT_CONSISTENT ? D : NULL, dp);
  if (trial) trial[IND_HISTORY_DP] = *dp;
  if (D && tangent == IND_TANGENT_ELASTIC) IndElasticTangent(m->kappa, m->mu, D);
  return status;
}

/* MaterialResponse without a trial history, its tangent by its parts (IndPlasticTangent) where the model's has that
   form: elastic, J2 plasticity, and every model under -plastic_tangent elastic (*by_parts true, D not written). The
   densifying model's consistent tangent comes whole in D (*by_parts false). */
static inline IndPlasticStatus MaterialResponseParts(const IndMaterial *m, IndTangent tangent, const PetscReal eps[6],
                                                     const PetscReal *old, PetscReal sigma[6], IndPlasticTangent *t,
                                                     PetscBool *by_parts, PetscReal *D, PetscReal *dp)
{
  const IndPlasticState *o = (const IndPlasticState *)old;
  IndPlasticState        scratch;
  IndPlasticStatus       status;

  *by_parts = (PetscBool)(m->model != IND_MODEL_DENSIFYING || tangent == IND_TANGENT_ELASTIC);
  if (!*by_parts) return MaterialResponse(m, tangent, eps, old, NULL, sigma, D, dp);
  *dp = 0.0;
  if (m->model == IND_MODEL_ELASTIC) {
    IndElasticStress(m->kappa, m->mu, eps, sigma);
    IndPlasticTangentElastic(m->kappa, m->mu, t);
    return IND_PLASTIC_OK;
  }
  if (m->model == IND_MODEL_DENSIFYING) status = IndDensifyingUpdate(&m->plastic, eps, o, &scratch, sigma, NULL, dp);
  else
    status = IndPlasticUpdateParts(&m->plastic, eps, o, &scratch, sigma, tangent == IND_TANGENT_CONSISTENT ? t : NULL,
                                   dp);
  if (tangent == IND_TANGENT_ELASTIC) IndPlasticTangentElastic(m->kappa, m->mu, t);
  return status;
}

/* The displacement gradient H = sum_a u_a (x) G_a and F = I + H, row-major (finite strain, and the
   check for inverted cells). On an axisymmetric section (hoop not NULL) y is the hoop direction:
   H_yy = u_r / r = sum_a hoop_a u_a,x. */
static inline void IndDeformationGradient(PetscInt nb, const PetscReal *G, const PetscReal *hoop, const PetscReal *u,
                                          PetscReal H[9], PetscReal F[9])
{
  for (int k = 0; k < 9; ++k) H[k] = 0.0;
  for (PetscInt a = 0; a < nb; ++a)
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) H[3 * i + j] += u[3 * a + i] * G[3 * a + j];
  if (hoop)
    for (PetscInt a = 0; a < nb; ++a) H[4] += hoop[a] * u[3 * a];
  for (int k = 0; k < 9; ++k) F[k] = H[k] + (k % 4 == 0 ? 1.0 : 0.0);
}

/* A kinematics (-formulation): the quadrature point's operations of the cell loops (assembly.c), registered
   by name in IndKinematicsRegistry. G holds the physical gradients (nb x 3) and ue the cell's displacements;
   old the point's committed history, trial (if not NULL) receives its update. On an axisymmetric section hoop
   holds N_a / r (nb), y being the hoop direction and u_y zero: the hoop strain u_x / r adds to H_yy, and a
   test function's gradient e_x (x) G_a gains hoop_a e_y (x) e_y. hoop is NULL in 3D. */
struct _IndKinematics {
  const char *name;
  /* the stress that the residual integrates against G: first Piola-Kirchhoff P (3x3, row-major); keep (if not
     NULL) receives the point's nkeep values that spare the stiffness at the same displacement some work */
  IndPlasticStatus (*stress)(const IndMaterial *m, IndTangent tangent, PetscInt nb, const PetscReal *G,
                             const PetscReal *hoop, const PetscReal *ue, const PetscReal *old, PetscReal *trial,
                             PetscReal P[9], PetscReal *dp, PetscReal *keep);
  /* Ke (nd x nd, nd = 3 nb) += w times the point's stiffness, on and above the diagonal, in the rows and columns of
     the first nt nodes (nt = nb, or nb - 1 when the cell loop completes the last node's from the others'); B and DB
     workspaces of 6 nd; kept (if not NULL) what stress() kept at this very displacement */
  IndPlasticStatus (*stiffness)(const IndMaterial *m, IndTangent tangent, PetscInt nb, PetscInt nt, const PetscReal *G,
                                const PetscReal *hoop, const PetscReal *ue, const PetscReal *old, PetscReal w,
                                PetscReal *B, PetscReal *DB, PetscReal *Ke, const PetscReal *kept);
  /* Cauchy stress and strain of a committed point h; w holds the reference weight and becomes the current one */
  void (*fields)(const IndMaterial *m, PetscInt nb, const PetscReal *G, const PetscReal *hoop, const PetscReal *ue,
                 const PetscReal *h, PetscReal sigma[6], PetscReal e[6], PetscReal *w);
  /* large deformation: an inverted point fails the step, contact areas follow the deformed surface */
  PetscBool large;
  /* values a point keeps from the residual for the Jacobian at the same displacement (0: none) */
  PetscInt nkeep;
};

/* The last node's rows and columns of a cell matrix Ke (nd x nd, nd = 3 nb) from the others', given the upper
   triangle of the first nd - 3 rows and columns: the shape functions' gradients sum to zero at every point
   (partition of unity), and so does every row of 3 x 3 blocks of a stiffness B^T D B + geometric. On return Ke
   is whole and symmetric. Not on an axisymmetric section, whose hoop terms N_a / r do not sum to zero. */
void IndCellMatrixCompleteLastNode(PetscInt nb, PetscReal *Ke);

/* The kinematics registered by default. */
const IndKinematics *IndKinematicsSmall(void);
const IndKinematics *IndKinematicsFinite(void);
