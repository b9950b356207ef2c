#include "ind_disc.h"

static PetscErrorCode CacheReferenceTabulation(IndDisc disc)
{
  PetscTabulation T;
  PetscInt        Nb, Nc;

  PetscFunctionBeginUser;
  PetscCall(PetscFEGetCellTabulation(disc->fe, 1, &T));
  Nb = T->Nb;
  Nc = T->Nc;
  PetscCheck(Nc == 3 && Nb % 3 == 0, PETSC_COMM_SELF, PETSC_ERR_PLIB,
    "Unexpected vector basis layout (Nb %" PetscInt_FMT ", Nc %" PetscInt_FMT ")", Nb, Nc);
  disc->nb   = Nb / 3;
  disc->ndof = Nb;
  PetscCall(PetscMalloc2(disc->nq * disc->nb, &disc->N, disc->nq * disc->nb * 3, &disc->dN));
  /* The vector Lagrange basis is node-major with the component fastest: function 3a+c is N_a e_c.
     The scalar N_a is read off function 3a, component 0; the layout is checked, not assumed. */
  for (PetscInt q = 0; q < disc->nq; ++q)
    for (PetscInt b = 0; b < Nb; ++b)
      for (PetscInt c = 0; c < Nc; ++c) {
        PetscReal v = T->T[0][(q * Nb + b) * Nc + c];
        if (c != b % 3) PetscCheck(PetscAbsReal(v) < 1e-12, PETSC_COMM_SELF, PETSC_ERR_PLIB,
          "Vector basis is not node-major with interleaved components");
        else if (c == 0) {
          disc->N[q * disc->nb + b / 3] = v;
          for (PetscInt d = 0; d < 3; ++d) disc->dN[(q * disc->nb + b / 3) * 3 + d] = T->T[1][((q * Nb + b) * Nc + c)
            * 3 + d];
        }
      }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Values (nq x nn) of the scalar Lagrange basis of the coordinate field: degree 1, or 2 for
   second-order gmsh meshes, chosen by the number nn of coordinate nodes per cell. */
static PetscErrorCode CoordinateBasis(PetscBool simplex, PetscQuadrature quad, PetscInt nq, PetscInt nn, PetscReal **Nx)
{
  PetscFunctionBeginUser;
  for (PetscInt k = 1; k <= 2; ++k) {
    PetscFE         fe;
    PetscTabulation T;
    PetscInt        nb;
    PetscCall(PetscFECreateLagrange(PETSC_COMM_SELF, 3, 1, simplex, k, PETSC_DETERMINE, &fe));
    PetscCall(PetscFESetQuadrature(fe, quad));
    PetscCall(PetscFEGetDimension(fe, &nb));
    if (nb == nn) {
      PetscCall(PetscFEGetCellTabulation(fe, 0, &T));
      PetscCall(PetscMalloc1(nq * nn, Nx));
      PetscCall(PetscArraycpy(*Nx, T->T[0], nq * nn));
      PetscCall(PetscFEDestroy(&fe));
      PetscFunctionReturn(PETSC_SUCCESS);
    }
    PetscCall(PetscFEDestroy(&fe));
  }
  SETERRQ(PETSC_COMM_SELF, PETSC_ERR_SUP,
    "Cells with %" PetscInt_FMT " coordinate nodes are not supported (first- or second-order meshes only)", nn);
}

static PetscErrorCode CacheCells(IndDisc disc, PetscBool simplex, PetscQuadrature quad)
{
  DM                     dm = disc->dm;
  PetscSection           s;
  ISLocalToGlobalMapping ltog;
  DM                     cdm;
  PetscSection           cs;
  Vec                    X;
  PetscReal             *v, *J, *detJ, *Nx = NULL;
  PetscInt               nn = 0;
  PetscInt               cEnd;

  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(IndLog.geometry, 0, 0, 0, 0));
  PetscCall(DMPlexGetHeightStratum(dm, 0, &disc->cStart, &cEnd));
  disc->ncell = cEnd - disc->cStart;
  PetscCall(DMGetLocalSection(dm, &s));
  PetscCall(DMGetLocalToGlobalMapping(dm, &ltog));
  PetscCall(PetscMalloc5(disc->ncell * disc->ndof, &disc->lidx, disc->ncell * disc->ndof, &disc->gidx,
    disc->ncell * disc->nq, &disc->wdetJ, disc->ncell * disc->nq * 9, &disc->invJ, disc->ncell * disc->nq * 3,
    &disc->xq));
  PetscCall(PetscMalloc3(disc->nq * 3, &v, disc->nq * 9, &J, disc->nq, &detJ));
  PetscCall(DMGetCoordinateDM(dm, &cdm));
  PetscCall(DMGetLocalSection(cdm, &cs));
  PetscCall(DMGetCoordinatesLocal(dm, &X));
  for (PetscInt i = 0; i < disc->ncell; ++i) {
    PetscInt  c = disc->cStart + i, n, *idx = NULL;
    PetscReal *iJ = disc->invJ + i * disc->nq * 9;

    PetscCall(DMPlexGetClosureIndices(dm, s, s, c, PETSC_TRUE, &n, &idx, NULL, NULL));
    PetscCheck(n == disc->ndof, PETSC_COMM_SELF, PETSC_ERR_PLIB,
      "Cell %" PetscInt_FMT " has %" PetscInt_FMT " closure dofs, expected %" PetscInt_FMT, c, n, disc->ndof);
    PetscCall(PetscArraycpy(disc->lidx + i * n, idx, n));
    PetscCall(DMPlexRestoreClosureIndices(dm, s, s, c, PETSC_TRUE, &n, &idx, NULL, NULL));

    for (PetscInt q = 0; q < disc->nq; ++q) detJ[q] = -1.0;
    PetscCall(DMPlexComputeCellGeometryFEM(dm, c, quad, v, J, iJ, detJ));
    /* Affine cells may get their (constant) geometry at the first point only. */
    for (PetscInt q = 1; q < disc->nq; ++q)
      if (detJ[q] == -1.0) {
        detJ[q] = detJ[0];
        PetscCall(PetscArraycpy(iJ + q * 9, iJ, 9));
      }
    for (PetscInt q = 0; q < disc->nq; ++q) {
      PetscCheck(detJ[q] > 0, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG,
        "Cell %" PetscInt_FMT " is inverted or degenerate (det J = %g at quadrature point %" PetscInt_FMT ")", c,
        (double)detJ[q], q);
      disc->wdetJ[i * disc->nq + q] = disc->w[q] * detJ[q];
    }
    /* Not DMPlexReferenceToCoordinates: in PETSc 3.18 it re-sorts a mesh label on every call, which
       made this loop quadratic in the number of cells. */
    {
      PetscScalar *xc = NULL;
      PetscInt     nc;
      PetscReal   *xq = disc->xq + i * disc->nq * 3;
      PetscCall(DMPlexVecGetClosure(cdm, cs, X, c, &nc, &xc));
      if (!Nx) {
        nn = nc / 3;
        PetscCall(CoordinateBasis(simplex, quad, disc->nq, nn, &Nx));
      }
      PetscCheck(nc == 3 * nn, PETSC_COMM_SELF, PETSC_ERR_SUP,
        "Cell %" PetscInt_FMT " has %" PetscInt_FMT " coordinate values, expected %" PetscInt_FMT, c, nc, 3 * nn);
      for (PetscInt q = 0; q < disc->nq; ++q)
        for (int d = 0; d < 3; ++d) {
          xq[q * 3 + d] = 0.0;
          for (PetscInt a = 0; a < nn; ++a) xq[q * 3 + d] += Nx[q * nn + a] * PetscRealPart(xc[3 * a + d]);
        }
      PetscCall(DMPlexVecRestoreClosure(cdm, cs, X, c, &nc, &xc));
    }
  }
  PetscCall(PetscFree(Nx));
  PetscCall(ISLocalToGlobalMappingApply(ltog, disc->ncell * disc->ndof, disc->lidx, disc->gidx));
  PetscCall(PetscFree3(v, J, detJ));
  PetscCall(PetscLogEventEnd(IndLog.geometry, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndDiscCreate(IndMesh mesh, IndDisc *out)
{
  IndDisc         disc;
  MPI_Comm        comm = PetscObjectComm((PetscObject)mesh->dm);
  PetscInt        qorder = PETSC_DETERMINE;
  PetscQuadrature quad;

  PetscFunctionBeginUser;
  PetscCall(PetscCalloc1(1, &disc));
  disc->dm     = mesh->dm;
  disc->degree = 1;
  PetscOptionsBegin(comm, NULL, IND_TITLE "Discretisation (-disc_*)", "Disc");
  PetscCall(IndOptionsInt("-disc_degree", "Polynomial degree of the displacement: 1 (P1/Q1) or 2 (P2/Q2)", NULL,
    disc->degree, &disc->degree, NULL));
  PetscCall(IndOptionsInt("-disc_quadrature_order", "Order of the quadrature rule",
    "0 for P1 tetrahedra, else PETSc's choice for the degree", qorder, &qorder, NULL));
  PetscOptionsEnd();
  /* The strain of a P1 tetrahedron is constant, so one point integrates its stiffness, stress and
     history exactly; PETSc's default rule has 8, all in the same state, at 8 times the cost of
     every residual, Jacobian and history update. */
  if (qorder == PETSC_DETERMINE && mesh->simplex && disc->degree == 1) qorder = 0;
  PetscCheck(disc->degree == 1 || disc->degree == 2, comm, PETSC_ERR_ARG_OUTOFRANGE,
    "-disc_degree must be 1 or 2, got %" PetscInt_FMT, disc->degree);
  PetscCheck(qorder == PETSC_DETERMINE || (qorder >= 0 && qorder <= 12), comm, PETSC_ERR_ARG_OUTOFRANGE,
    "-disc_quadrature_order must lie in [0, 12], got %" PetscInt_FMT, qorder);

  PetscCall(PetscFECreateLagrange(comm, 3, 3, mesh->simplex, disc->degree, qorder, &disc->fe));
  PetscCall(PetscObjectSetName((PetscObject)disc->fe, "displacement"));
  PetscCall(DMSetField(disc->dm, 0, NULL, (PetscObject)disc->fe));
  PetscCall(DMCreateDS(disc->dm));
  PetscCall(PetscFEGetQuadrature(disc->fe, &quad));
  PetscCall(PetscQuadratureGetData(quad, NULL, NULL, &disc->nq, NULL, &disc->w));
  PetscCall(CacheReferenceTabulation(disc));
  disc->simplex = mesh->simplex;
  PetscCall(CacheCells(disc, disc->simplex, quad));
  *out = disc;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndDiscNodeCoordinates(IndDisc disc, Vec *coords)
{
  DM              dm = disc->dm, cdm;
  PetscSection    cs;
  PetscDualSpace  sp;
  PetscQuadrature nodes;
  PetscReal      *ref, *Nx = NULL;
  PetscInt        nn = 0;
  Vec             X, loc;
  PetscScalar    *x;

  PetscFunctionBeginUser;
  /* Each Lagrange node is the point of its evaluation functional; functional 3a is node a's. */
  PetscCall(PetscFEGetDualSpace(disc->fe, &sp));
  PetscCall(PetscMalloc1(disc->nb * 3, &ref));
  for (PetscInt a = 0; a < disc->nb; ++a) {
    PetscQuadrature  f;
    PetscInt         np;
    const PetscReal *pt;
    PetscCall(PetscDualSpaceGetFunctional(sp, 3 * a, &f));
    PetscCall(PetscQuadratureGetData(f, NULL, NULL, &np, &pt, NULL));
    PetscCheck(np == 1, PETSC_COMM_SELF, PETSC_ERR_SUP, "Node %" PetscInt_FMT " is not a point evaluation", a);
    for (int d = 0; d < 3; ++d) ref[3 * a + d] = pt[d];
  }
  PetscCall(PetscQuadratureCreate(PETSC_COMM_SELF, &nodes));
  PetscCall(PetscQuadratureSetData(nodes, 3, 1, disc->nb, ref, NULL));
  PetscCall(DMGetCoordinateDM(dm, &cdm));
  PetscCall(DMGetLocalSection(cdm, &cs));
  PetscCall(DMGetCoordinatesLocal(dm, &X));
  PetscCall(DMCreateLocalVector(dm, &loc));
  PetscCall(VecGetArray(loc, &x));
  for (PetscInt i = 0; i < disc->ncell; ++i) {
    PetscScalar    *xc = NULL;
    PetscInt        nc;
    const PetscInt *idx = disc->lidx + i * disc->ndof;
    PetscCall(DMPlexVecGetClosure(cdm, cs, X, disc->cStart + i, &nc, &xc));
    if (!Nx) {
      nn = nc / 3;
      PetscCall(CoordinateBasis(disc->simplex, nodes, disc->nb, nn, &Nx));
    }
    for (PetscInt a = 0; a < disc->nb; ++a)
      for (int d = 0; d < 3; ++d) {
        PetscReal v = 0.0;
        for (PetscInt k = 0; k < nn; ++k) v += Nx[a * nn + k] * PetscRealPart(xc[3 * k + d]);
        x[idx[3 * a + d]] = v;
      }
    PetscCall(DMPlexVecRestoreClosure(cdm, cs, X, disc->cStart + i, &nc, &xc));
  }
  PetscCall(VecRestoreArray(loc, &x));
  PetscCall(PetscFree(Nx));
  PetscCall(PetscQuadratureDestroy(&nodes));
  PetscCall(DMCreateGlobalVector(dm, coords));
  PetscCall(DMLocalToGlobal(dm, loc, INSERT_VALUES, *coords));
  PetscCall(VecDestroy(&loc));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndDiscDestroy(IndDisc *disc)
{
  PetscFunctionBeginUser;
  if (!*disc) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscFree2((*disc)->N, (*disc)->dN));
  PetscCall(PetscFree5((*disc)->lidx, (*disc)->gidx, (*disc)->wdetJ, (*disc)->invJ, (*disc)->xq));
  PetscCall(PetscFEDestroy(&(*disc)->fe));
  PetscCall(PetscFree(*disc));
  PetscFunctionReturn(PETSC_SUCCESS);
}
