#pragma once
/* Shared by every indent source file: PETSc compatibility and the project's log events. */
#include <petscsys.h>

#ifndef PETSC_SUCCESS
  #define PETSC_SUCCESS 0 /* PETSc < 3.19 returns plain 0 */
#endif

#include "ind_options.h"
#include "ind_errors.h"

#define IND_NAME_LEN 128

/* An accessor that only reads its object, in the object's own file: IND_GETTER returns expr (of the object o),
   IND_GETTER_OUT gives it through *v in PETSc's way (DMGetCoordinateDM). */
#define IND_GETTER(Type, Func, Obj, expr) \
  Type Func(Obj o) \
  { \
    return expr; \
  }
#define IND_GETTER_OUT(Type, Func, Obj, expr) \
  PetscErrorCode Func(Obj o, Type *v) \
  { \
    PetscFunctionBeginUser; \
    *v = expr; \
    PetscFunctionReturn(PETSC_SUCCESS); \
  }

typedef struct {
  PetscLogStage setup, solve, output;
  PetscLogEvent mesh_create, mesh_distribute, geometry, preallocate, near_null, residual, jacobian, contact, bc,
    output_write;
} IndLogTable;

/* Registered once by IndLogRegister(); read-only afterwards. */
extern IndLogTable IndLog;

PetscErrorCode IndLogRegister(void);
