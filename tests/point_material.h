#pragma once
/* The material of the point-kernel test and benchmark (test_cell_stiffness.c, bench_point_kernels.c): aluminium-like
   elasticity (E 70 GPa, nu 0.3), yield 0.3 GPa, linear hardening of slope 1 GPa, no back stress. */
#include <string.h>
#include "ind_material.h"
#include "ind_hardening.h"
#include "ind_elasticity.h"

static inline IndMaterial PointTestMaterial(void)
{
  IndMaterial m;

  memset(&m, 0, sizeof(m));
  m.model = IND_MODEL_PLASTIC;
  IndElasticModuli(70.0, 0.3, &m.kappa, &m.mu);
  m.plastic.kappa = m.kappa;
  m.plastic.mu    = m.mu;
  m.plastic.R0    = 0.3;
  IndHardeningSetLinear(&m.plastic, 1.0);
  return m;
}
