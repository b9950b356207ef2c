#pragma once
/* Finite-strain kinematics of plasticity in the logarithmic strain space (Miehe, Apel & Lambrecht,
   CMAME 191 (2002) 5383): the geometric pre- and post-processors around the small-strain kernel.

   Total Lagrangian: F = I + Grad u, C = F^T F, the Hencky strain E = (1/2) ln C plays the small-strain
   kernel's total strain; its stress T (conjugate to E) and tangent dT/dE come back from it unchanged;
   here S = T : 2 dE/dC (second Piola-Kirchhoff) and dS/dE_GL (E_GL = (C - I)/2, Green-Lagrange).
   Depending on C only, E, T and the history are objective by construction.

   Derivatives of the isotropic tensor function (1/2) ln C use divided differences of the eigenvalues
   (the Daleckii-Krein formulas), which stay exact and continuous when eigenvalues coincide:
     dE~_ij = f1(l_i, l_j) dC~_ij,
     d2E[A, B]~_ik = sum_j f2(l_i, l_j, l_k) (A~_ij B~_jk + B~_ij A~_jk),
   with ~ the components in the eigenbasis of C and f1, f2 the first and second divided differences of
   f = (1/2) ln. Pure: petscsys.h only, no PETSc objects.

   Voigt order [xx, yy, zz, xy, yz, xz]: strains (E, E_GL) with engineering shears, stresses with
   tensor components, 6x6 tangents row-major mapping an engineering strain to a stress, as in
   ind_plasticity.h. F and H are row-major, F[3 i + j] = dx_i / dX_j. */
#include <petscsys.h>

typedef struct {
  PetscReal lm1[3]; /* eigenvalues of C minus 1 (kept apart from 1 for small strains) */
  PetscReal N[9];   /* eigenvectors of C as columns: N[3 i + k] is component i of vector k */
  PetscReal L[3];   /* ln l_k */
  PetscReal f1[9];  /* f1(l_i, l_j) */
  PetscReal J;      /* det F */
} IndLogStrain;

/* Eigen-decomposition of a symmetric 3x3 matrix (Voigt, tensor components) by a fixed count of operations (no
   loop to convergence), accurate for coincident eigenvalues: lambda[k] with unit eigenvector column k of V
   (V[3 i + k]). */
void IndSymEigen(const PetscReal A[6], PetscReal lambda[3], PetscReal V[9]);

/* From the displacement gradient H = F - I (not F: stored as I + H, a strain of 1e-6 would keep only
   10 digits, and Newton's residual would stall there): the decomposition of C and the Hencky strain E
   (engineering shears). Returns 1 (and leaves E unset) when det F <= 0: an inverted element, which
   the caller treats as a failed point. E may be NULL: the strain in the eigenbasis is diag(L) / 2. */
int IndLogStrainFromGradient(const PetscReal H[9], IndLogStrain *ls, PetscReal E[6]);
/* The part of the decomposition worth keeping for a second use at the same gradient (the residual's for the
   Jacobian's: the eigen-decomposition is a third of a finite-strain stiffness), in 7 values (the eigenvalues and the
   eigenvectors as a unit quaternion: 56 bytes a point), and the decomposition rebuilt from them and H: what
   IndLogStrainFromGradient gives, its eigenvectors to round-off, at a tenth of its cost. */
#define IND_LOGSTRAIN_NKEEP 7
void IndLogStrainKeep(const IndLogStrain *ls, PetscReal kept[IND_LOGSTRAIN_NKEEP]);
void IndLogStrainFromKept(const PetscReal H[9], const PetscReal kept[IND_LOGSTRAIN_NKEEP], IndLogStrain *ls,
                          PetscReal E[6]);
/* S = T : 2 dE/dC, both tensor components. */
void IndLogStrainStress(const IndLogStrain *ls, const PetscReal T[6], PetscReal S[6]);
/* The same from T~ = N^T T N (IndLogStrainIntoBasis), when the caller needs T~ too. */
void IndLogStrainStressFromBasis(const IndLogStrain *ls, const PetscReal Tt[9], PetscReal S[6]);
/* DS = dS/dE_GL (6x6) from the stress T and the symmetric tangent DT = dT/dE (6x6) of the small-strain
   kernel; isotropic: DT is an isotropic tensor (elastic), the same in every basis, which saves its
   rotation into the eigenbasis of C. */
void IndLogStrainTangent(const IndLogStrain *ls, const PetscReal T[6], const PetscReal DT[36], PetscBool isotropic,
                         PetscReal DS[36]);
/* At = N^T A N: a symmetric tensor A (Voigt, tensor components) in the eigenbasis of C, as a 3x3 matrix. */
void IndLogStrainIntoBasis(const IndLogStrain *ls, const PetscReal A[6], PetscReal At[9]);
/* The tangent of IndLogStrainTangent in the eigenbasis of C: M = dS~/dE~_GL (6x6, engineering shears in,
   tensor components out, both components in that basis), from T~ = N^T T N (3x3). A finite-strain
   stiffness B^T DS B equals B~^T M B~ with B~ the strain columns in that basis, which spares rotating the
   6x6 tangent back. isotropic: DT is not rotated, being the same in every basis (elastic) or given in the
   eigenbasis already. */
void IndLogStrainTangentEigen(const IndLogStrain *ls, const PetscReal Tt[9], const PetscReal DT[36],
                              PetscBool isotropic, PetscReal M[36]);
/* The same when T is coaxial with C (T~ diagonal: a point that never yielded, whose stress is an isotropic function
   of E) and DT is isotropic: M is then a 3 x 3 block on the normal pairs and a diagonal on the shear pairs, zero
   elsewhere, and T~'s off-diagonal (round-off) is not read. */
void IndLogStrainTangentCoaxial(const IndLogStrain *ls, const PetscReal Tt[9], const PetscReal DT[36], PetscReal M[36]);
/* Cauchy stress sigma = F S F^T / J (tensor components). */
void IndLogStrainCauchy(const PetscReal F[9], PetscReal J, const PetscReal S[6], PetscReal sigma[6]);
/* The Eulerian (spatial) Hencky strain (1/2) ln(F F^T) = R E R^T, engineering shears. */
void IndLogStrainSpatial(const PetscReal F[9], const IndLogStrain *ls, PetscReal e[6]);
