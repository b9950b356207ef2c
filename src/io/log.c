#include "ind_common.h"

IndLogTable IndLog;

PetscErrorCode IndLogRegister(void)
{
  static PetscBool registered = PETSC_FALSE;
  PetscClassId     classid;

  PetscFunctionBeginUser;
  if (registered) PetscFunctionReturn(PETSC_SUCCESS);
  registered = PETSC_TRUE;
  PetscCall(PetscClassIdRegister("indent", &classid));
  PetscCall(PetscLogStageRegister("IndSetup", &IndLog.setup));
  PetscCall(PetscLogStageRegister("IndSolve", &IndLog.solve));
  PetscCall(PetscLogStageRegister("IndOutput", &IndLog.output));
  PetscCall(PetscLogEventRegister("IndMeshCreate", classid, &IndLog.mesh_create));
  PetscCall(PetscLogEventRegister("IndMeshDistrib", classid, &IndLog.mesh_distribute));
  PetscCall(PetscLogEventRegister("IndGeometry", classid, &IndLog.geometry));
  PetscCall(PetscLogEventRegister("IndPreallocate", classid, &IndLog.preallocate));
  PetscCall(PetscLogEventRegister("IndNearNull", classid, &IndLog.near_null));
  PetscCall(PetscLogEventRegister("IndResidual", classid, &IndLog.residual));
  PetscCall(PetscLogEventRegister("IndJacobian", classid, &IndLog.jacobian));
  PetscCall(PetscLogEventRegister("IndContact", classid, &IndLog.contact));
  PetscCall(PetscLogEventRegister("IndBC", classid, &IndLog.bc));
  PetscCall(PetscLogEventRegister("IndOutputWrite", classid, &IndLog.output_write));
  PetscFunctionReturn(PETSC_SUCCESS);
}
