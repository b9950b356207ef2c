#pragma once
/* A material per volume region, read from options prefixed by the region's name (-film_young):
   linear elastic, or elasto-plastic (von Mises, Voce or linear isotropic + Prager kinematic hardening)
   with -<region>_model plastic, or densifying (a pressure-dependent ellipse for glasses, ind_densification.h). */
#include "ind_mesh.h"
#include "ind_disc.h"
#include "ind_plasticity.h"

typedef enum { IND_MODEL_ELASTIC, IND_MODEL_PLASTIC, IND_MODEL_DENSIFYING } IndModel;
extern const char *const IndModelTypes[];

typedef struct {
  char             region[IND_NAME_LEN];
  IndModel         model;
  PetscReal        young;   /* GPa */
  PetscReal        poisson;
  PetscReal        kappa, mu; /* derived: bulk and shear moduli, GPa */
  IndPlasticParams plastic; /* moduli copied in; elastic_only set for elastic regions */
} IndMaterial;

typedef struct _p_IndMaterials *IndMaterials;

/* Whether any region is elasto-plastic (collective-free: every rank reads the same options). */
PetscBool      IndMaterialsArePlastic(IndMaterials mats);
/* Whether any elasto-plastic region hardens kinematically (its points carry a back stress). */
PetscBool      IndMaterialsHaveBackStress(IndMaterials mats);
/* Whether any region is densifying (its plastic strain has a trace). */
PetscBool      IndMaterialsAreDensifying(IndMaterials mats);
PetscErrorCode IndMaterialsCreate(IndMesh mesh, IndDisc disc, IndMaterials *mats);
PetscErrorCode IndMaterialsDestroy(IndMaterials *mats);
/* The Poisson's ratio from which the elements of this degree and shape lock (0.5: they do not), and the text of the
   warning for the regions at or above it (text[0] = 0: none), naming them (locking.c). */
PetscReal      IndLockingPoisson(PetscInt degree, PetscBool simplex, PetscBool axisymmetric);
void           IndMaterialsCheckLocking(IndMaterials mats, PetscInt degree, PetscBool simplex, PetscBool axisymmetric,
                                        char text[], size_t len);
/* The regions' materials, in the mesh's order of volume regions. */
PetscInt       IndMaterialsGetCount(IndMaterials mats);
const IndMaterial *IndMaterialsGet(IndMaterials mats, PetscInt k);
