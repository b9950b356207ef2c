#include "disc_impl.h"
#include "mesh_impl.h"
#include "ind_disc.h"
#include "ind_common.h"

static PetscErrorCode CacheReferenceTabulation(IndDisc disc)
{
  PetscTabulation T;
  PetscInt        Nb, Nc;

  PetscFunctionBeginUser;
  PetscCall(PetscFEGetCellTabulation(disc->fe, 1, &T));
  Nb = T->Nb;
  Nc = T->Nc;
  PetscCheck(T->cdim == disc->dim, PETSC_COMM_SELF, PETSC_ERR_PLIB, "Tabulation of dimension %" PetscInt_FMT,
    T->cdim);
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
          for (PetscInt d = 0; d < 3; ++d) disc->dN[(q * disc->nb + b / 3) * 3 + d] = d < disc->dim ?
            T->T[1][((q * Nb + b) * Nc + c) * disc->dim + d] : 0.0;
        }
      }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Values (nq x nn) and reference gradients (nq x nn x 3, the third 0 on 2D cells) of the scalar Lagrange basis
   of the coordinate field at the points of quad: degree 1, or 2 for second-order gmsh meshes, chosen by the
   number nn of coordinate nodes per cell. dNx may be NULL. */
static PetscErrorCode CoordinateBasis(PetscInt dim, PetscBool simplex, PetscQuadrature quad, PetscInt nq, PetscInt nn,
                                      PetscReal **Nx, PetscReal **dNx)
{
  PetscFunctionBeginUser;
  for (PetscInt k = 1; k <= 2; ++k) {
    PetscFE         fe;
    PetscTabulation T;
    PetscInt        nb;
    PetscCall(PetscFECreateLagrange(PETSC_COMM_SELF, dim, 1, simplex, k, PETSC_DETERMINE, &fe));
    PetscCall(PetscFESetQuadrature(fe, quad));
    PetscCall(PetscFEGetDimension(fe, &nb));
    if (nb == nn) {
      PetscCall(PetscFEGetCellTabulation(fe, 1, &T));
      PetscCall(PetscMalloc1(nq * nn, Nx));
      PetscCall(PetscArraycpy(*Nx, T->T[0], nq * nn));
      if (dNx) {
        PetscCall(PetscMalloc1(nq * nn * 3, dNx));
        for (PetscInt j = 0; j < nq * nn; ++j)
          for (PetscInt d = 0; d < 3; ++d) (*dNx)[3 * j + d] = d < dim ? T->T[1][dim * j + d] : 0.0;
      }
      PetscCall(PetscFEDestroy(&fe));
      PetscFunctionReturn(PETSC_SUCCESS);
    }
    PetscCall(PetscFEDestroy(&fe));
  }
  SETERRQ(PETSC_COMM_SELF, PETSC_ERR_SUP,
    "Cells with %" PetscInt_FMT " coordinate nodes are not supported (first- or second-order meshes only)", nn);
}

/* DMPlex charts the displacement's section over every point of the mesh, though only the vertices (and, for P2, the
   edges) carry dofs: on the README's P1 mesh one point in 25 is a vertex, and the section, its field's, the global
   section made from them and its field's held 8 bytes a point each (22 MB of a rank's 276 MB there). Charted over
   the range of points that carry dofs, with the same offsets, it numbers every dof as before: PETSc's closures,
   global sections and star forests skip points outside a chart, as they do for the coordinates' section, and
   indent's own loops over closures ask IndDiscPointDof. */
static PetscErrorCode ChartOverDofs(DM dm)
{
  PetscSection s, t;
  IS           range;
  PetscInt     pStart, pEnd, lo, hi;

  PetscFunctionBeginUser;
  PetscCall(DMGetLocalSection(dm, &s));
  PetscCall(PetscSectionGetChart(s, &pStart, &pEnd));
  lo = pEnd, hi = pStart;
  for (PetscInt p = pStart; p < pEnd; ++p) {
    PetscInt dof;
    PetscCall(PetscSectionGetDof(s, p, &dof));
    if (dof) lo = PetscMin(lo, p), hi = p + 1;
  }
  /* a rank without dofs, or dofs on every point (Q2): nothing to trim */
  if (lo >= hi || (lo == pStart && hi == pEnd)) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(ISCreateStride(PETSC_COMM_SELF, hi - lo, lo, 1, &range));
  PetscCall(PetscSectionCreateSubdomainSection(s, range, &t));
  PetscCall(ISDestroy(&range));
  PetscCall(DMSetLocalSection(dm, t));
  PetscCall(PetscSectionDestroy(&t));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Every per-cell closure is a search through the mesh's cell-type label in PETSc 3.18 (10 to 15 us
   a hexahedron); the indices are taken once, and the node positions and the geometry follow from
   them and the vertex coordinates without another closure. */
static PetscErrorCode CacheIndices(IndDisc disc)
{
  DM                     dm = disc->dm;
  PetscSection           s;
  ISLocalToGlobalMapping ltog;
  PetscInt               cEnd;

  PetscFunctionBeginUser;
  PetscCall(DMPlexGetHeightStratum(dm, 0, &disc->cStart, &cEnd));
  disc->ncell = cEnd - disc->cStart;
  PetscCall(DMGetLocalSection(dm, &s));
  PetscCall(DMGetLocalToGlobalMapping(dm, &ltog));
  PetscCall(PetscMalloc2(disc->ncell * disc->nb, &disc->lnode, disc->ncell * disc->nb, &disc->gnode));
  for (PetscInt i = 0; i < disc->ncell; ++i) {
    PetscInt c = disc->cStart + i, n, *idx = NULL, g[3];
    PetscCall(DMPlexGetClosureIndices(dm, s, s, c, PETSC_TRUE, &n, &idx, NULL, NULL));
    PetscCheck(n == disc->ndof, PETSC_COMM_SELF, PETSC_ERR_PLIB,
      "Cell %" PetscInt_FMT " has %" PetscInt_FMT " closure dofs, expected %" PetscInt_FMT, c, n, disc->ndof);
    /* a node's three dofs are consecutive from a multiple of 3, locally and globally: its number is kept alone,
       a third of the indices (on the README's mesh 10 MB a rank) */
    for (PetscInt a = 0; a < disc->nb; ++a) {
      PetscCall(ISLocalToGlobalMappingApply(ltog, 3, idx + 3 * a, g));
      PetscCheck(idx[3 * a] % 3 == 0 && idx[3 * a + 1] == idx[3 * a] + 1 && idx[3 * a + 2] == idx[3 * a] + 2 &&
                   g[0] % 3 == 0 && g[1] == g[0] + 1 && g[2] == g[0] + 2, PETSC_COMM_SELF, PETSC_ERR_PLIB,
                 "The dofs of a node of cell %" PetscInt_FMT " are not three consecutive from a multiple of 3", c);
      disc->lnode[i * disc->nb + a] = idx[3 * a] / 3;
      disc->gnode[i * disc->nb + a] = g[0] / 3;
    }
    PetscCall(DMPlexRestoreClosureIndices(dm, s, s, c, PETSC_TRUE, &n, &idx, NULL, NULL));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Coordinate nodes per cell (of the first local cell; 0 without cells) and whether the coordinates
   live on the vertices alone (a first-order mesh). */
static PetscErrorCode CoordinateLayout(IndDisc disc, PetscInt *nn, PetscBool *on_vertices)
{
  DM           dm = disc->dm, cdm;
  PetscSection cs;
  PetscInt     pStart, pEnd, vStart, vEnd;

  PetscFunctionBeginUser;
  PetscCall(DMGetCoordinateDM(dm, &cdm));
  PetscCall(DMGetLocalSection(cdm, &cs));
  PetscCall(PetscSectionGetChart(cs, &pStart, &pEnd));
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
  *on_vertices = PETSC_TRUE;
  for (PetscInt p = pStart; p < pEnd && *on_vertices; ++p) {
    PetscInt dof;
    PetscCall(PetscSectionGetDof(cs, p, &dof));
    if (dof && (p < vStart || p >= vEnd)) *on_vertices = PETSC_FALSE;
  }
  *nn = 0;
  if (disc->ncell) {
    Vec          X;
    PetscScalar *xc = NULL;
    PetscInt     nc;
    PetscCall(DMGetCoordinatesLocal(dm, &X));
    PetscCall(DMPlexVecGetClosure(cdm, cs, X, disc->cStart, &nc, &xc));
    PetscCall(DMPlexVecRestoreClosure(cdm, cs, X, disc->cStart, &nc, &xc));
    *nn = nc / 3;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The position of every displacement node in a local vector of the displacement's layout: on a
   first-order mesh with P1/Q1 the nodes are the vertices; otherwise each cell's nodes are
   interpolated from its coordinate closure at their reference points. */
static PetscErrorCode NodePositions(IndDisc disc, PetscInt nn, PetscBool on_vertices)
{
  DM           dm = disc->dm, cdm;
  PetscSection s, cs;
  Vec          X;
  PetscScalar *xn;

  PetscFunctionBeginUser;
  PetscCall(DMGetLocalSection(dm, &s));
  PetscCall(DMGetCoordinateDM(dm, &cdm));
  PetscCall(DMGetLocalSection(cdm, &cs));
  PetscCall(DMGetCoordinatesLocal(dm, &X));
  PetscCall(DMCreateLocalVector(dm, &disc->Xloc));
  PetscCall(VecGetArray(disc->Xloc, &xn));
  if (on_vertices && disc->degree == 1) {
    const PetscScalar *x;
    PetscInt           vStart, vEnd;
    PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
    PetscCall(VecGetArrayRead(X, &x));
    for (PetscInt v = vStart; v < vEnd; ++v) {
      PetscInt dof, cdof, o, co;
      PetscCall(PetscSectionGetDof(s, v, &dof));
      PetscCall(PetscSectionGetDof(cs, v, &cdof));
      PetscCheck(dof == 3 && cdof == 3, PETSC_COMM_SELF, PETSC_ERR_PLIB,
        "Vertex %" PetscInt_FMT " has %" PetscInt_FMT " displacement and %" PetscInt_FMT " coordinate values", v, dof,
        cdof);
      PetscCall(PetscSectionGetOffset(s, v, &o));
      PetscCall(PetscSectionGetOffset(cs, v, &co));
      for (int d = 0; d < 3; ++d) xn[o + d] = x[co + d];
    }
    PetscCall(VecRestoreArrayRead(X, &x));
  } else {
    PetscDualSpace  sp;
    PetscQuadrature nodes;
    PetscReal      *ref, *Nx = NULL;
    /* each Lagrange node is the point of its evaluation functional; functional 3a is node a's */
    PetscCall(PetscFEGetDualSpace(disc->fe, &sp));
    PetscCall(PetscMalloc1(disc->nb * disc->dim, &ref));
    for (PetscInt a = 0; a < disc->nb; ++a) {
      PetscQuadrature  f;
      PetscInt         np;
      const PetscReal *pt;
      PetscCall(PetscDualSpaceGetFunctional(sp, 3 * a, &f));
      PetscCall(PetscQuadratureGetData(f, NULL, NULL, &np, &pt, NULL));
      PetscCheck(np == 1, PETSC_COMM_SELF, PETSC_ERR_SUP, "Node %" PetscInt_FMT " is not a point evaluation", a);
      for (PetscInt d = 0; d < disc->dim; ++d) ref[disc->dim * a + d] = pt[d];
    }
    PetscCall(PetscQuadratureCreate(PETSC_COMM_SELF, &nodes));
    PetscCall(PetscQuadratureSetData(nodes, disc->dim, 1, disc->nb, ref, NULL));
    if (disc->ncell) PetscCall(CoordinateBasis(disc->dim, disc->simplex, nodes, disc->nb, nn, &Nx, NULL));
    for (PetscInt i = 0; i < disc->ncell; ++i) {
      PetscScalar    *xc = NULL;
      PetscInt        nc;
      const PetscInt *node = disc->lnode + i * disc->nb;
      PetscCall(DMPlexVecGetClosure(cdm, cs, X, disc->cStart + i, &nc, &xc));
      PetscCheck(nc == 3 * nn, PETSC_COMM_SELF, PETSC_ERR_SUP,
        "Cell %" PetscInt_FMT " has %" PetscInt_FMT " coordinate values, expected %" PetscInt_FMT, disc->cStart + i, nc,
        3 * nn);
      for (PetscInt a = 0; a < disc->nb; ++a)
        for (int d = 0; d < 3; ++d) {
          PetscReal v = 0.0;
          for (PetscInt k = 0; k < nn; ++k) v += Nx[a * nn + k] * PetscRealPart(xc[3 * k + d]);
          xn[3 * node[a] + d] = v;
        }
      PetscCall(DMPlexVecRestoreClosure(cdm, cs, X, disc->cStart + i, &nc, &xc));
    }
    PetscCall(PetscFree(Nx));
    PetscCall(PetscQuadratureDestroy(&nodes));
  }
  PetscCall(VecRestoreArray(disc->Xloc, &xn));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Every cell must map onto its reference cell with det J > 0 at every quadrature point. When the
   displacement basis holds the coordinate map (a mesh of the same or a lower order), the assembly
   recomputes J from the node positions (IndDiscGradients) and nothing is stored; a curved mesh under
   P1/Q1 has its own coordinate basis, and its weights and inverse Jacobians are kept. */
static PetscErrorCode CheckGeometry(IndDisc disc, PetscQuadrature quad, PetscInt nn)
{
  DM                 dm = disc->dm, cdm;
  PetscSection       cs;
  Vec                X;
  const PetscScalar *xn;
  PetscReal         *dNx = NULL, *Nx = NULL, *xc;
  const PetscBool    own = nn <= disc->nb ? PETSC_TRUE : PETSC_FALSE;
  const PetscInt     n   = own ? disc->nb : nn;

  PetscFunctionBeginUser;
  PetscCall(DMGetCoordinateDM(dm, &cdm));
  PetscCall(DMGetLocalSection(cdm, &cs));
  PetscCall(DMGetCoordinatesLocal(dm, &X));
  if (!own) {
    PetscCall(CoordinateBasis(disc->dim, disc->simplex, quad, disc->nq, nn, &Nx, &dNx));
    PetscCall(PetscMalloc2(disc->ncell * disc->nq, &disc->wdetJ, disc->ncell * disc->nq * 9, &disc->invJ));
  }
  PetscCall(PetscMalloc1(3 * n, &xc));
  PetscCall(VecGetArrayRead(disc->Xloc, &xn));
  for (PetscInt i = 0; i < disc->ncell; ++i) {
    const PetscInt   c  = disc->cStart + i;
    const PetscReal *dN = own ? disc->dN : dNx;
    if (own) IndDiscCellNodes(&disc->layout, i, xn, xc);
    else {
      PetscScalar *cl = NULL;
      PetscInt     nc;
      PetscCall(DMPlexVecGetClosure(cdm, cs, X, c, &nc, &cl));
      PetscCheck(nc == 3 * nn, PETSC_COMM_SELF, PETSC_ERR_SUP,
        "Cell %" PetscInt_FMT " has %" PetscInt_FMT " coordinate values, expected %" PetscInt_FMT, c, nc, 3 * nn);
      for (PetscInt k = 0; k < nc; ++k) xc[k] = PetscRealPart(cl[k]);
      PetscCall(DMPlexVecRestoreClosure(cdm, cs, X, c, &nc, &cl));
    }
    for (PetscInt q = 0; q < disc->nq; ++q) {
      PetscReal J[9], det;
      det = IndDiscJacobian(n, disc->dim == 2, xc, dN + q * n * 3, J);
      /* a section's cells may be drawn either way round: only a degenerate one is wrong */
      PetscCheck(disc->dim == 2 ? det != 0 : det > 0, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG,
        "Cell %" PetscInt_FMT " is inverted or degenerate (det J = %g at quadrature point %" PetscInt_FMT ")", c,
        (double)det, q);
      if (!own) {
        IndInverse3(J, det, disc->invJ + (i * disc->nq + q) * 9);
        disc->wdetJ[i * disc->nq + q] = disc->w[q] * PetscAbsReal(det);
      }
    }
  }
  PetscCall(VecRestoreArrayRead(disc->Xloc, &xn));
  PetscCall(PetscFree(xc));
  PetscCall(PetscFree(Nx));
  PetscCall(PetscFree(dNx));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static void SyncLayout(IndDisc disc)
{
  disc->layout = (IndDiscLayout){disc->degree, disc->simplex, disc->dim == 2, disc->nq,    disc->nb,
                                 disc->ndof,   disc->w,       disc->N,       disc->dN,    disc->ncell,
                                 disc->cStart, disc->lnode,   disc->gnode,   disc->wdetJ, disc->invJ};
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
  PetscCall(DMGetDimension(disc->dm, &disc->dim));
  PetscOptionsBegin(comm, NULL, IND_TITLE "Discretisation (-disc_*)", "Disc");
  PetscCall(IndOptionsInt("-disc_degree", "Polynomial degree of the displacement: 1 (P1/Q1) or 2 (P2/Q2)", NULL,
    disc->degree, &disc->degree, NULL));
  PetscCall(IndOptionsInt("-disc_quadrature_order", "Order of the quadrature rule",
    "0 for P1 tetrahedra, else PETSc's choice for the degree", qorder, &qorder, NULL));
  PetscOptionsEnd();
  /* The strain of a P1 tetrahedron is constant, so one point integrates its stiffness, stress and
     history exactly; PETSc's default rule has 8, all in the same state, at 8 times the cost of
     every residual, Jacobian and history update. (Not so on an axisymmetric section: the hoop strain
     u_r / r varies over a triangle.) */
  if (qorder == PETSC_DETERMINE && mesh->simplex && disc->degree == 1 && disc->dim == 3) qorder = 0;
  PetscCheck(disc->degree == 1 || disc->degree == 2, comm, PETSC_ERR_ARG_OUTOFRANGE,
    "-disc_degree must be 1 or 2, got %" PetscInt_FMT, disc->degree);
  PetscCheck(qorder == PETSC_DETERMINE || (qorder >= 0 && qorder <= 12), comm, PETSC_ERR_ARG_OUTOFRANGE,
    "-disc_quadrature_order must lie in [0, 12], got %" PetscInt_FMT, qorder);

  PetscCall(PetscFECreateLagrange(comm, disc->dim, 3, mesh->simplex, disc->degree, qorder, &disc->fe));
  if (qorder == PETSC_DETERMINE && mesh->simplex && disc->dim == 2) {
    /* A section's triangles: the fully symmetric rule of degree 2k (3 points for P1, 6 for P2) instead of
       PETSc's conical product (4 and 9). On the film under the cone (10 nm P1 cells, 2 ranks) P_max moved by
       1.7e-7 relative and the run took 8.2 s instead of 9.2 s; P2 with 20 nm cells: 4.7e-5, 9.0 s against
       11.1 s. Every point costs the finite-strain kinematics and the return map. */
    PetscQuadrature q;
    PetscCall(PetscDTSimplexQuadrature(2, 2 * disc->degree, PETSCDTSIMPLEXQUAD_MINSYM, &q));
    PetscCall(PetscFESetQuadrature(disc->fe, q));
    PetscCall(PetscQuadratureDestroy(&q));
  }
  PetscCall(PetscObjectSetName((PetscObject)disc->fe, "displacement"));
  PetscCall(DMSetField(disc->dm, 0, NULL, (PetscObject)disc->fe));
  PetscCall(DMCreateDS(disc->dm));
  PetscCall(ChartOverDofs(disc->dm));
  PetscCall(PetscFEGetQuadrature(disc->fe, &quad));
  PetscCall(PetscQuadratureGetData(quad, NULL, NULL, &disc->nq, NULL, &disc->w));
  PetscCall(CacheReferenceTabulation(disc));
  disc->simplex = mesh->simplex;
  {
    PetscInt  nn          = 0;
    PetscBool on_vertices = PETSC_FALSE;
    PetscCall(PetscLogEventBegin(IndLog.geometry, 0, 0, 0, 0));
    PetscCall(CacheIndices(disc));
    PetscCall(CoordinateLayout(disc, &nn, &on_vertices));
    PetscCall(NodePositions(disc, nn, on_vertices));
    SyncLayout(disc);
    PetscCall(CheckGeometry(disc, quad, nn));
    PetscCall(PetscLogEventEnd(IndLog.geometry, 0, 0, 0, 0));
  }
  SyncLayout(disc);
  *out = disc;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndDiscQuadraturePoints(IndDisc disc, PetscReal **xq)
{
  DM              dm = disc->dm, cdm;
  PetscSection    cs;
  PetscQuadrature quad;
  Vec             X;
  PetscReal      *Nx = NULL;
  PetscInt        nn = 0;

  PetscFunctionBeginUser;
  PetscCall(PetscFEGetQuadrature(disc->fe, &quad));
  PetscCall(DMGetCoordinateDM(dm, &cdm));
  PetscCall(DMGetLocalSection(cdm, &cs));
  PetscCall(DMGetCoordinatesLocal(dm, &X));
  PetscCall(PetscMalloc1(disc->ncell * disc->nq * 3, xq));
  for (PetscInt i = 0; i < disc->ncell; ++i) {
    PetscScalar *xc = NULL;
    PetscInt     nc;
    PetscReal   *x = *xq + i * disc->nq * 3;
    PetscCall(DMPlexVecGetClosure(cdm, cs, X, disc->cStart + i, &nc, &xc));
    if (!Nx) {
      nn = nc / 3;
      PetscCall(CoordinateBasis(disc->dim, disc->simplex, quad, disc->nq, nn, &Nx, NULL));
    }
    for (PetscInt q = 0; q < disc->nq; ++q)
      for (int d = 0; d < 3; ++d) {
        x[q * 3 + d] = 0.0;
        for (PetscInt a = 0; a < nn; ++a) x[q * 3 + d] += Nx[q * nn + a] * PetscRealPart(xc[3 * a + d]);
      }
    PetscCall(DMPlexVecRestoreClosure(cdm, cs, X, disc->cStart + i, &nc, &xc));
  }
  PetscCall(PetscFree(Nx));
  PetscFunctionReturn(PETSC_SUCCESS);
}

IND_GETTER_OUT(const IndDiscLayout *, IndDiscGetLayout, IndDisc, &o->layout)
IND_GETTER_OUT(DM, IndDiscGetDM, IndDisc, o->dm)
IND_GETTER_OUT(Vec, IndDiscGetNodePositions, IndDisc, o->Xloc)

PetscErrorCode IndDiscNodeCoordinates(IndDisc disc, Vec *coords)
{
  PetscFunctionBeginUser;
  PetscCall(DMCreateGlobalVector(disc->dm, coords));
  PetscCall(DMLocalToGlobal(disc->dm, disc->Xloc, INSERT_VALUES, *coords));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndDiscDestroy(IndDisc *disc)
{
  PetscFunctionBeginUser;
  if (!*disc) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscFree2((*disc)->N, (*disc)->dN));
  PetscCall(PetscFree2((*disc)->lnode, (*disc)->gnode));
  PetscCall(PetscFree2((*disc)->wdetJ, (*disc)->invJ));
  PetscCall(VecDestroy(&(*disc)->Xloc));
  PetscCall(PetscFEDestroy(&(*disc)->fe));
  PetscCall(PetscFree(*disc));
  PetscFunctionReturn(PETSC_SUCCESS);
}
