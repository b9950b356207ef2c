#pragma once
/* The relative tolerance of each linear solve inside a Newton solve (src/solvers/forcing.c). */
#include "ind_common.h"

/* The relative tolerance for the linear solve of a Newton iteration whose residual norm is fnorm, when the
   Newton solve stops at a residual norm of ttol: eta_min (-ksp_rtol) while the residual is far from ttol, and
   gamma * ttol / fnorm, at most 0.1, once that is looser. gamma 0 (or a ttol or fnorm that is not positive)
   gives eta_min. */
PetscReal IndForcingTerm(PetscReal eta_min, PetscReal gamma, PetscReal ttol, PetscReal fnorm);
