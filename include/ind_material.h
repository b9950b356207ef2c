#pragma once
/* A material per volume region, read from options prefixed by the region's name (-film_young). */
#include "ind_mesh.h"
#include "ind_disc.h"

typedef struct {
  char      region[IND_NAME_LEN];
  PetscReal young;   /* GPa */
  PetscReal poisson;
  PetscReal kappa, mu; /* derived: bulk and shear moduli, GPa */
} IndMaterial;

typedef struct _p_IndMaterials *IndMaterials;
struct _p_IndMaterials {
  PetscInt    n;
  IndMaterial mat[IND_MAX_REGIONS];
  PetscInt   *cell_material; /* per local cell of the discretisation: index into mat */
};

PetscErrorCode IndMaterialsCreate(IndMesh mesh, IndDisc disc, IndMaterials *mats);
PetscErrorCode IndMaterialsDestroy(IndMaterials *mats);
