#pragma once
/* A densifying (pressure-dependent) plasticity at one quadrature point, for glasses such as fused silica, which
   compact permanently under an indenter where J2 plasticity conserves volume (doc/theory.md, "Densifying
   plasticity"). The yield surface is an ellipse in the plane of the pressure p = -tr(sigma) / 3 and the von Mises
   stress q (the family of criteria used for silica's densification, e.g. Kermouche et al., Acta Mater. 56 (2008)
   3222):

     f = sqrt(q^2 + (sigma_s p / p_c)^2) - sigma_s,   p_c = p_c0 + H_v max(c, 0),   c = -tr(eps_p) (compaction)

   sigma_s is the von Mises stress at which it yields without pressure (-<region>_yield), p_c0 the hydrostatic
   pressure at which it yields without shear (-<region>_yield_pressure) and H_v how p_c grows with compaction
   (-<region>_densification_modulus); a dilated glass (c < 0, from hydrostatic tension) does not weaken below
   p_c0. The ellipse is symmetric in p: it yields in hydrostatic tension at -p_c, where a real glass would
   crack first (indent has no fracture). The flow is associated: compaction under pressure, the deviatoric flow of J2
   without it; as p_c0 grows without bound the model becomes J2 perfect plasticity.
   Pure, like ind_plasticity.h, whose conventions (Voigt order, engineering shears, units) and history it uses:
   eps_p holds the whole plastic strain, x stays zero and p accumulates sqrt(2/3 d eps_p : d eps_p). */
#include "ind_plasticity.h"

/* The yield pressure at compaction c: p_c0 + H_v max(c, 0). */
PetscReal IndDensifyingYieldPressure(const IndPlasticParams *m, PetscReal c);

/* Rejects non-physical parameters, naming the option by the region's prefix ("film_"). */
PetscErrorCode IndDensifyingParamsCheck(const IndPlasticParams *m, const char prefix[], MPI_Comm comm);

/* The stress update and consistent tangent, as IndPlasticUpdate (same arguments, same failure contract). The
   tangent is symmetric without densification hardening (H_v = 0). With H_v > 0 it is not: the cap's motion
   depends on the pressure (the algorithmic tangent of any such hardening, as in Cam-clay's), while the cell
   loops assemble symmetric element matrices, so the material point passes on its symmetric part
   (IndDensifyingSymmetrize): Newton then converges linearly, at a rate set by that asymmetry. */
void IndDensifyingSymmetrize(PetscReal D[36]);
IndPlasticStatus IndDensifyingUpdate(const IndPlasticParams *m, const PetscReal eps[6], const IndPlasticState *old,
  IndPlasticState *new_state, PetscReal sigma[6], PetscReal D[36], PetscReal *dp_out);
