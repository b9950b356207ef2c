#pragma once
/* Private to src/mesh/: the fields of IndBC. Other groups use the accessors of
   ind_bc.h. */
#include "ind_bc.h"

struct _p_IndBC {
  IndMesh    mesh;
  IndDisc    disc;
  PetscInt   nspec;
  IndBCSpec  spec[IND_MAX_BC];
  PetscBool  setup;
  PetscInt   nrows;   /* constrained rows owned by this rank */
  PetscInt  *rows;    /* global row numbers */
  PetscInt  *lrows;   /* the same rows, local to the owned part of a global vector */
  PetscReal *values;  /* value of each row at full load */
};
