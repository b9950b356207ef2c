#include <stdio.h>
#include <string.h>
#include "ind_material.h"

/* Linear elements lock as a material nears incompressibility: their few volumetric modes cannot follow an
   isochoric displacement, and the body comes out too stiff. The Poisson's ratio from which the excess load passed
   about 2% on an elastic Hertz contact (doc/theory.md, "Volumetric locking"): 0.4 for P1 tetrahedra (2.6%; 5.9% at
   0.45, 25% at 0.49), 0.45 for Q1 hexahedra (2.3%; 12% at 0.49), 0.49 on an axisymmetric section (P1 and Q1 2%);
   second-order elements stayed below 2% (Q2 hexahedra 1.6% at 0.49). 0.5: never. */
PetscReal IndLockingPoisson(PetscInt degree, PetscBool simplex, PetscBool axisymmetric)
{
  if (degree != 1) return 0.5;
  if (axisymmetric) return 0.49;
  return simplex ? 0.4 : 0.45;
}

void IndMaterialsCheckLocking(IndMaterials mats, PetscInt degree, PetscBool simplex, PetscBool axisymmetric,
                              char text[], size_t len)
{
  const PetscReal nu_lock = IndLockingPoisson(degree, simplex, axisymmetric);
  const char     *cells   = axisymmetric ? (simplex ? "P1 triangles" : "Q1 quadrilaterals")
                                         : (simplex ? "P1 tetrahedra" : "Q1 hexahedra");
  char            regions[256] = "";
  size_t          used         = 0;
  PetscInt        count        = 0;

  text[0] = 0;
  for (PetscInt k = 0; k < IndMaterialsGetCount(mats); ++k) {
    const IndMaterial *m = IndMaterialsGet(mats, k);
    if (m->poisson < nu_lock) continue;
    if (used < sizeof(regions))
      used += (size_t)snprintf(regions + used, sizeof(regions) - used, "%s'%s' (nu %g)", count ? ", " : "", m->region,
                               (double)m->poisson);
    count++;
  }
  if (!count) return;
  snprintf(text, len,
           "region%s %s on %s, which lock as a material nears incompressibility: the loads, hardness and moduli come "
           "out too high (on an elastic Hertz contact P1 tetrahedra by 6%% at nu 0.45 and 25%% at 0.49, Q1 hexahedra "
           "by 2%% and 12%%); second-order hexahedra (-disc_degree 2) lock far less (doc/theory.md)",
           count > 1 ? "s" : "", regions, cells);
}
