#include "contact_node.h"

const char *const IndUzawaTypes[] = {"fixed_point", "newton", "IndUzawa", "IND_UZAWA_", NULL};

static const PetscReal deg = PETSC_PI / 180.0;

/* 1D quadratic Lagrange basis on the nodes -1, 0, 1. */
static inline PetscReal L2(int node, PetscReal s)
{
  return node == 0 ? 0.5 * s * (s - 1) : node == 1 ? 1 - s * s : 0.5 * s * (s + 1);
}

/* Adds to a[] (indexed like the local vector, z slot of each node) the projected tributary area
   int_face N_a |n_z| dA of every node of one face: the consistent nodal force of a unit pressure on
   a flat face, for its own Lagrange basis (Q1/Q2 quads, P1/P2 triangles). The vertices are in the
   cyclic order of the face's closure; edge nodes are identified by their two vertices. */
static PetscErrorCode FaceAreas(DM dm, PetscSection s, PetscInt face, const PetscReal *vx, PetscInt nv, PetscInt degree, PetscScalar *a)
{
  PetscInt *closure = NULL, ncl, vpt[4], nvv = 0, vStart, vEnd, eStart, eEnd;
  PetscInt  off[9], nn = 0;
  PetscReal ref[9][2];

  PetscFunctionBeginUser;
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
  PetscCall(DMPlexGetDepthStratum(dm, 1, &eStart, &eEnd));
  PetscCall(DMPlexGetTransitiveClosure(dm, face, PETSC_TRUE, &ncl, &closure));
  for (PetscInt j = 0; j < ncl; ++j)
    if (closure[2 * j] >= vStart && closure[2 * j] < vEnd) vpt[nvv++] = closure[2 * j];
  PetscCheck(nvv == nv, PETSC_COMM_SELF, PETSC_ERR_PLIB, "Face %" PetscInt_FMT " has %" PetscInt_FMT " vertices, expected %" PetscInt_FMT, face, nvv, nv);
  /* reference positions of the face's nodes */
  for (PetscInt j = 0; j < ncl; ++j) {
    const PetscInt p = closure[2 * j];
    PetscInt       dof, o;
    PetscCall(PetscSectionGetDof(s, p, &dof));
    if (dof < 3) continue;
    PetscCall(PetscSectionGetOffset(s, p, &o));
    if (p >= vStart && p < vEnd) {
      PetscInt k = 0;
      while (vpt[k] != p) ++k;
      if (nv == 4) {
        const PetscReal c[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
        ref[nn][0] = c[k][0], ref[nn][1] = c[k][1];
      } else {
        const PetscReal c[3][2] = {{0, 0}, {1, 0}, {0, 1}};
        ref[nn][0] = c[k][0], ref[nn][1] = c[k][1];
      }
    } else if (p >= eStart && p < eEnd) {
      const PetscInt *cone;
      PetscInt        k0 = 0, k1 = 0;
      PetscReal       c0[2], c1[2];
      PetscCall(DMPlexGetCone(dm, p, &cone));
      while (vpt[k0] != cone[0]) ++k0;
      while (vpt[k1] != cone[1]) ++k1;
      if (nv == 4) {
        const PetscReal c[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
        c0[0] = c[k0][0], c0[1] = c[k0][1], c1[0] = c[k1][0], c1[1] = c[k1][1];
      } else {
        const PetscReal c[3][2] = {{0, 0}, {1, 0}, {0, 1}};
        c0[0] = c[k0][0], c0[1] = c[k0][1], c1[0] = c[k1][0], c1[1] = c[k1][1];
      }
      ref[nn][0] = 0.5 * (c0[0] + c1[0]);
      ref[nn][1] = 0.5 * (c0[1] + c1[1]);
    } else { /* the face's own node: the centre of a Q2 quad */
      ref[nn][0] = ref[nn][1] = 0;
    }
    off[nn++] = o;
  }
  PetscCall(DMPlexRestoreTransitiveClosure(dm, face, PETSC_TRUE, &ncl, &closure));

  if (nv == 4) {
    const PetscReal g[3] = {-0.7745966692414834, 0.0, 0.7745966692414834}, w[3] = {5.0 / 9, 8.0 / 9, 5.0 / 9};
    const PetscReal c[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const PetscReal xi = g[i], eta = g[j];
        PetscReal       dxi[3] = {0, 0, 0}, deta[3] = {0, 0, 0}, jz;
        for (int k = 0; k < 4; ++k)
          for (int d = 0; d < 3; ++d) {
            dxi[d] += 0.25 * c[k][0] * (1 + c[k][1] * eta) * vx[3 * k + d];
            deta[d] += 0.25 * c[k][1] * (1 + c[k][0] * xi) * vx[3 * k + d];
          }
        jz = PetscAbsReal(dxi[0] * deta[1] - dxi[1] * deta[0]);
        for (PetscInt b = 0; b < nn; ++b) {
          PetscReal N;
          if (degree == 1) N = 0.25 * (1 + ref[b][0] * xi) * (1 + ref[b][1] * eta);
          else N = L2((int)PetscFloorReal(ref[b][0] + 1.5), xi) * L2((int)PetscFloorReal(ref[b][1] + 1.5), eta);
          a[off[b] + 2] += w[i] * w[j] * jz * N;
        }
      }
  } else {
    /* edge midpoints: exact for the degree-2 integrands of a flat triangle */
    const PetscReal qp[3][2] = {{0.5, 0}, {0.5, 0.5}, {0, 0.5}};
    PetscReal       e1[3], e2[3], jz;
    for (int d = 0; d < 3; ++d) {
      e1[d] = vx[3 + d] - vx[d];
      e2[d] = vx[6 + d] - vx[d];
    }
    jz = PetscAbsReal(e1[0] * e2[1] - e1[1] * e2[0]);
    for (int q = 0; q < 3; ++q) {
      const PetscReal l[3] = {1 - qp[q][0] - qp[q][1], qp[q][0], qp[q][1]};
      for (PetscInt b = 0; b < nn; ++b) {
        /* P1 only (contact on P2 tetrahedra is refused): N is the barycentric coordinate of the node's vertex */
        const PetscReal lb[3] = {1 - ref[b][0] - ref[b][1], ref[b][0], ref[b][1]};
        const PetscReal N     = l[0] * lb[0] + l[1] * lb[1] + l[2] * lb[2];
        a[off[b] + 2] += jz / 6.0 * N;
      }
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Marks the nodes of the contact surface and sums their tributary areas, in a global vector laid out
   like the displacement: slot 0 counts faces, slot 2 holds the area. With Uloc (a local displacement)
   the faces are taken through their vertices' current positions X + u. */
static PetscErrorCode SurfaceNodes(IndMesh mesh, IndDisc disc, const char surface[], Vec Uloc, Vec G)
{
  DM                 dm = disc->dm, cdm;
  PetscSection       s, cs;
  DMLabel            label;
  IS                 faces;
  Vec                loc, X;
  PetscScalar       *a;
  const PetscScalar *u = NULL;
  PetscInt           vStart, vEnd;

  PetscFunctionBeginUser;
  PetscCall(IndMeshGetRegionLabel(mesh, surface, 2, "-contact_surface", &label));
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
  if (Uloc) PetscCall(VecGetArrayRead(Uloc, &u));
  PetscCall(DMGetLocalSection(dm, &s));
  PetscCall(DMGetCoordinateDM(dm, &cdm));
  PetscCall(DMGetLocalSection(cdm, &cs));
  PetscCall(DMGetCoordinatesLocal(dm, &X));
  PetscCall(DMGetLocalVector(dm, &loc));
  PetscCall(VecZeroEntries(loc));
  PetscCall(VecGetArray(loc, &a));
  PetscCall(DMLabelGetStratumIS(label, 1, &faces));
  if (faces) {
    const PetscInt *f;
    PetscInt        nf;
    PetscCall(ISGetLocalSize(faces, &nf));
    PetscCall(ISGetIndices(faces, &f));
    for (PetscInt i = 0; i < nf; ++i) {
      PetscInt    *closure = NULL, ncl, nc, nv = 0;
      PetscScalar *xc = NULL;
      PetscReal    vx[12], uv[12];
      PetscCall(DMPlexGetTransitiveClosure(dm, f[i], PETSC_TRUE, &ncl, &closure));
      for (PetscInt j = 0; j < ncl; ++j) {
        PetscInt dof, o;
        PetscCall(PetscSectionGetDof(s, closure[2 * j], &dof));
        if (dof < 3) continue;
        PetscCall(PetscSectionGetOffset(s, closure[2 * j], &o));
        a[o] += 1.0;
        /* vertices come in the closure's order, as in the coordinate closure below */
        if (closure[2 * j] >= vStart && closure[2 * j] < vEnd && nv < 4) {
          for (int d = 0; d < 3; ++d) uv[3 * nv + d] = u ? PetscRealPart(u[o + d]) : 0.0;
          nv++;
        }
      }
      PetscCall(DMPlexRestoreTransitiveClosure(dm, f[i], PETSC_TRUE, &ncl, &closure));
      PetscCall(DMPlexVecGetClosure(cdm, cs, X, f[i], &nc, &xc));
      PetscCheck(nc == 9 || nc == 12, PETSC_COMM_SELF, PETSC_ERR_SUP, "Contact surface '%s': faces must be flat triangles or quadrilaterals with straight edges", surface);
      PetscCheck(3 * nv == nc, PETSC_COMM_SELF, PETSC_ERR_PLIB,
                 "Contact surface '%s': face with %" PetscInt_FMT " vertices and %" PetscInt_FMT " coordinates",
                 surface, nv, nc);
      for (PetscInt k = 0; k < nc; ++k) vx[k] = PetscRealPart(xc[k]) + uv[k];
      PetscCall(DMPlexVecRestoreClosure(cdm, cs, X, f[i], &nc, &xc));
      PetscCall(FaceAreas(dm, s, f[i], vx, nc / 3, disc->degree, a));
    }
    PetscCall(ISRestoreIndices(faces, &f));
    PetscCall(ISDestroy(&faces));
  }
  PetscCall(VecRestoreArray(loc, &a));
  if (Uloc) PetscCall(VecRestoreArrayRead(Uloc, &u));
  PetscCall(VecZeroEntries(G));
  PetscCall(DMLocalToGlobal(dm, loc, ADD_VALUES, G));
  PetscCall(DMRestoreLocalVector(dm, &loc));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A symmetry plane through the indenter's axis halves the model: each doubles the load. */
static PetscReal SymmetryFactor(IndBC bc, const IndIndenter *ind)
{
  PetscReal f = 1;
  for (PetscInt k = 0; k < bc->nspec; ++k) {
    PetscBool sym;
    PetscStrcmp(bc->spec[k].option, "-bc_symmetry", &sym);
    if (!sym) continue;
    for (int c = 0; c < 2; ++c)
      if (bc->spec[k].mask == (1 << c) && PetscAbsReal(bc->spec[k].plane - ind->axis[c]) <= 1e-9 * (1 + PetscAbsReal(ind->axis[c]))) f *= 2;
  }
  return f;
}

PetscErrorCode IndContactCreate(IndMesh mesh, IndDisc disc, IndBC bc, IndContact *out)
{
  IndContact         c;
  MPI_Comm           comm = PetscObjectComm((PetscObject)mesh->dm);
  IndIndenter        ind;
  PetscBool          has_type, has_radius, has_surface, has_sym, has_axis, has_rounding;
  PetscReal          angle = 0, rotation = 0, radius = 0, symmetry = 0;
  PetscInt           naxis = 2;
  char               surface[IND_NAME_LEN] = "top";
  Vec                G, nodes;
  const PetscScalar *g, *x;
  PetscInt           n, rstart;

  PetscFunctionBeginUser;
  *out = NULL;
  PetscCall(PetscMemzero(&ind, sizeof(ind)));
  PetscOptionsBegin(comm, NULL, "Rigid indenter", "Contact");
  PetscCall(PetscOptionsEnum("-indenter_type", "Rigid indenter shape", "", IndIndenterTypes, (PetscEnum)ind.type, (PetscEnum *)&ind.type, &has_type));
  PetscOptionsEnd();
  if (!has_type) PetscFunctionReturn(PETSC_SUCCESS);

  PetscCall(PetscCalloc1(1, &c));
  c->comm      = comm;
  c->variant   = IND_UZAWA_NEWTON;
  c->rtol      = 1e-6;
  c->pen_rtol  = 1e-4;
  c->monitor   = PETSC_FALSE;
  PetscOptionsBegin(comm, NULL, "Rigid indenter and contact", "Contact");
  PetscCall(PetscOptionsReal("-indenter_sharp_rounding", "Sharp cones and pyramids: the contact sees them rounded by this radius (nm; default 1e-4 of -load_depth; 0: exactly sharp)", "", c->rounding, &c->rounding, &has_rounding));
  PetscCall(PetscOptionsReal("-indenter_radius", "Sphere, tip (cone, pyramids; 0 sharp) or punch radius (nm)", "", radius, &radius, &has_radius));
  PetscCall(PetscOptionsReal("-indenter_angle", "Cone half-angle or pyramid face-to-axis angle (degrees; 0: the standard one)", "", angle, &angle, NULL));
  PetscCall(PetscOptionsReal("-indenter_rotation", "Pyramids: azimuth of the first face's normal (degrees)", "", rotation, &rotation, NULL));
  PetscCall(PetscOptionsRealArray("-indenter_axis", "x,y of the indenter's axis (nm)", "", ind.axis, &naxis, &has_axis));
  PetscCall(PetscOptionsReal("-indenter_surface", "z of the undeformed surface where depth 0 touches (nm; default: highest contact node)", "", ind.surface, &ind.surface, &has_surface));
  PetscCall(PetscOptionsString("-contact_surface", "Surface whose nodes may touch the indenter", "", surface, surface, sizeof(surface), NULL));
  PetscCall(PetscOptionsReal("-contact_friction", "Coulomb friction coefficient", "", c->mu, &c->mu, NULL));
  PetscCall(PetscOptionsEnum("-contact_uzawa", "Contact algorithm: newton (semi-smooth Newton, reactions from the residual) or fixed_point (reactions frozen in each Newton solve, updated between them)", "", IndUzawaTypes, (PetscEnum)c->variant, (PetscEnum *)&c->variant, NULL));
  /* Newton: rho sets which nodes are tried active and scales their rows, not the solution; the
     stiffness diagonal keeps those rows as well conditioned as the rest. The fixed point diverges
     once rho exceeds 2 / (largest eigenvalue of the contact compliance), about the diagonal. */
  c->rho_scale = c->variant == IND_UZAWA_NEWTON ? 1.0 : 0.3;
  c->max_outer = c->variant == IND_UZAWA_NEWTON ? 20 : 200;
  PetscCall(PetscOptionsReal("-contact_rho_scale", "rho = scale * mean stiffness diagonal of each contact node (default 1 newton, 0.3 fixed_point)", "", c->rho_scale, &c->rho_scale, NULL));
  PetscCall(PetscOptionsReal("-contact_uzawa_rtol", "Outer loop: relative change of the reactions", "", c->rtol, &c->rtol, NULL));
  PetscCall(PetscOptionsReal("-contact_penetration_rtol", "Outer loop: largest penetration relative to the largest depth", "", c->pen_rtol, &c->pen_rtol, NULL));
  {
    PetscInt gap = 0;
    const char *const gaps[] = {"current", "reference", "IndGap", "IND_GAP_", NULL};
    PetscCall(PetscOptionsEnum("-contact_gap", "Gap at the current position of the node, or at its undeformed horizontal position (small-deformation contact)", "", gaps, (PetscEnum)gap, (PetscEnum *)&gap, NULL));
    c->gap_current = gap == 0 ? PETSC_TRUE : PETSC_FALSE;
  }
  PetscCall(PetscOptionsInt("-contact_uzawa_max_it", "Outer iterations before the step fails (default 20 newton, 200 fixed_point)", "", c->max_outer, &c->max_outer, NULL));
  PetscCall(PetscOptionsBool("-contact_monitor", "Print a line per outer iteration", "", c->monitor, &c->monitor, NULL));
  PetscCall(PetscOptionsReal("-contact_symmetry_factor", "Load multiplier of a symmetric part model (default: 2 per symmetry plane through the axis)", "", symmetry, &symmetry, &has_sym));
  PetscOptionsEnd();
  ind.radius   = radius;
  ind.angle    = angle * deg;
  ind.rotation = rotation * deg;
  PetscCheck(has_radius || (ind.type != IND_INDENTER_SPHERE && ind.type != IND_INDENTER_FLAT), comm, PETSC_ERR_ARG_WRONG, "-indenter_type %s needs -indenter_radius (nm)", IndIndenterTypes[ind.type]);
  PetscCheck(radius >= 0 && (radius > 0 || (ind.type != IND_INDENTER_SPHERE && ind.type != IND_INDENTER_FLAT)), comm, PETSC_ERR_ARG_OUTOFRANGE, "-indenter_radius must be %s, got %g", ind.type == IND_INDENTER_SPHERE || ind.type == IND_INDENTER_FLAT ? "> 0" : ">= 0", (double)radius);
  PetscCheck(angle >= 0 && angle < 90, comm, PETSC_ERR_ARG_OUTOFRANGE, "-indenter_angle must lie in (0, 90) degrees (0: the standard angle), got %g", (double)angle);
  PetscCheck(!IndIndenterSetUp(&ind), comm, PETSC_ERR_ARG_OUTOFRANGE, "-indenter_type %s: bad -indenter_radius or -indenter_angle", IndIndenterTypes[ind.type]);
  PetscCheck(!has_axis || naxis == 2, comm, PETSC_ERR_ARG_WRONG, "-indenter_axis needs two values x,y");
  PetscCheck(!has_rounding || c->rounding >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-indenter_sharp_rounding must be >= 0 (nm), got %g", (double)c->rounding);
  if (!has_rounding) c->rounding = -1; /* set from the depth at setup */
  PetscCheck(c->mu >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-contact_friction must be >= 0, got %g", (double)c->mu);
  PetscCheck(c->rho_scale > 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-contact_rho_scale must be > 0, got %g", (double)c->rho_scale);
  PetscCheck(c->rtol > 0 && c->pen_rtol > 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-contact_uzawa_rtol and -contact_penetration_rtol must be > 0");
  PetscCheck(c->max_outer >= 1, comm, PETSC_ERR_ARG_OUTOFRANGE, "-contact_uzawa_max_it must be >= 1, got %" PetscInt_FMT, c->max_outer);
  PetscCheck(!has_sym || symmetry >= 1, comm, PETSC_ERR_ARG_OUTOFRANGE, "-contact_symmetry_factor must be >= 1, got %g", (double)symmetry);
  /* Consistent nodal forces of a pressure vanish at the corner nodes of a 6-node triangle, so a
     node-to-surface contact cannot represent a smooth pressure there (and negative ones would be
     needed by 20-node serendipity faces). Q2 Lagrange faces have positive weights. */
  PetscCheck(!(disc->simplex && disc->degree == 2), comm, PETSC_ERR_SUP, "Contact on P2 tetrahedra is not supported: the consistent nodal forces of a pressure are zero at the corners of their 6-node faces. Use P1 tetrahedra or Q1/Q2 hexahedra for the contact region");

  /* The owned nodes of the contact surface, their positions and tributary areas. */
  PetscCall(DMCreateGlobalVector(disc->dm, &G));
  PetscCall(SurfaceNodes(mesh, disc, surface, NULL, G));
  PetscCall(IndDiscNodeCoordinates(disc, &nodes));
  PetscCall(VecGetLocalSize(G, &n));
  PetscCall(VecGetOwnershipRange(G, &rstart, NULL));
  PetscCall(VecGetArrayRead(G, &g));
  PetscCall(VecGetArrayRead(nodes, &x));
  for (PetscInt k = 0; k < n; k += 3)
    if (PetscRealPart(g[k]) > 0.5) c->n++;
  PetscCall(PetscMalloc5(c->n, &c->row, c->n, &c->grow, 3 * c->n, &c->X, c->n, &c->kdiag, c->n, &c->A));
  PetscCall(PetscCalloc5(3 * c->n, &c->R, 3 * c->n, &c->Rc, 3 * c->n, &c->L, 3 * c->n, &c->Uc, c->n, &c->status));
  PetscCall(PetscCalloc2(3 * c->n, &c->Lu, c->n, &c->fixed));
  c->n = 0;
  {
    PetscReal top = -PETSC_MAX_REAL;
    for (PetscInt k = 0; k < n; k += 3)
      if (PetscRealPart(g[k]) > 0.5) {
        c->row[c->n]  = k;
        c->grow[c->n] = rstart + k;
        for (int d = 0; d < 3; ++d) c->X[3 * c->n + d] = PetscRealPart(x[k + d]);
        c->A[c->n] = PetscRealPart(g[k + 2]);
        top        = PetscMax(top, c->X[3 * c->n + 2]);
        c->n++;
      }
    PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &top, 1, MPIU_REAL, MPIU_MAX, comm));
    PetscCheck(top > -PETSC_MAX_REAL, comm, PETSC_ERR_ARG_WRONG, "-contact_surface '%s' has no nodes", surface);
    if (!has_surface) ind.surface = top;
  }
  PetscCall(VecRestoreArrayRead(G, &g));
  PetscCall(VecRestoreArrayRead(nodes, &x));
  PetscCall(VecDestroy(&nodes));
  PetscCall(VecDestroy(&G));
  c->indenter = ind;
  c->symmetry = has_sym ? symmetry : SymmetryFactor(bc, &ind);
  c->mesh     = mesh;
  c->disc     = disc;
  PetscCall(PetscStrncpy(c->surface, surface, sizeof(c->surface)));
  *out        = c;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndContactDestroy(IndContact *c)
{
  PetscFunctionBeginUser;
  if (!*c) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscFree5((*c)->row, (*c)->grow, (*c)->X, (*c)->kdiag, (*c)->A));
  PetscCall(PetscFree5((*c)->R, (*c)->Rc, (*c)->L, (*c)->Uc, (*c)->status));
  PetscCall(PetscFree2((*c)->Lu, (*c)->fixed));
  PetscCall(PetscFree(*c));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndContactSetUp(IndContact c, IndBC bc, Mat K, PetscReal depth_max)
{
  Vec                d;
  const PetscScalar *v;
  PetscScalar       *m;

  PetscFunctionBeginUser;
  PetscCall(MatCreateVecs(K, &d, NULL));
  PetscCall(MatGetDiagonal(K, d));
  PetscCall(VecGetArrayRead(d, &v));
  for (PetscInt i = 0; i < c->n; ++i) c->kdiag[i] = PetscRealPart(v[c->row[i]] + v[c->row[i] + 1] + v[c->row[i] + 2]) / 3.0;
  PetscCall(VecRestoreArrayRead(d, &v));
  PetscCall(VecZeroEntries(d));
  PetscCall(VecGetArray(d, &m));
  for (PetscInt k = 0; k < bc->nrows; ++k) m[bc->lrows[k]] = 1.0;
  for (PetscInt i = 0; i < c->n; ++i) {
    c->fixed[i] = 0;
    for (int dd = 0; dd < 3; ++dd)
      if (PetscRealPart(m[c->row[i] + dd]) > 0.5) c->fixed[i] |= 1 << dd;
  }
  PetscCall(VecRestoreArray(d, &m));
  PetscCall(VecDestroy(&d));
  c->pen_atol = c->pen_rtol * depth_max;
  c->indenter.rounding = c->rounding >= 0 ? c->rounding : 1e-4 * depth_max;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndContactResidual(IndContact c, Vec U, Vec F)
{
  PetscScalar *f;

  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(IndLog.contact, 0, 0, 0, 0));
  if (c->variant == IND_UZAWA_NEWTON) PetscCall(IndContactNewtonResidual(c, U, F));
  else {
    PetscCall(VecGetArray(F, &f));
    for (PetscInt i = 0; i < c->n; ++i)
      for (int d = 0; d < 3; ++d) f[c->row[i] + d] -= c->R[3 * i + d];
    PetscCall(VecRestoreArray(F, &f));
  }
  PetscCall(PetscLogEventEnd(IndLog.contact, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndContactJacobian(IndContact c, Vec U, Mat J)
{
  PetscFunctionBeginUser;
  if (c->variant == IND_UZAWA_NEWTON) PetscCall(IndContactNewtonJacobian(c, U, J));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The reaction the projection starts from: the multiplier of the last residual (Newton) or the
   frozen reaction of the last outer update (fixed point). */
static const PetscReal *Multiplier(IndContact c, PetscInt i)
{
  return (c->variant == IND_UZAWA_NEWTON ? c->L : c->R) + 3 * i;
}

PetscErrorCode IndContactSetCurrentAreas(IndContact c, PetscBool current)
{
  PetscFunctionBeginUser;
  c->areas_current = current;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The tributary areas of the nodes projected on the plane normal to z, through the current positions
   of the surface's vertices (finite strain: the area that carries the load is the deformed one). */
static PetscErrorCode CurrentAreas(IndContact c, Vec U)
{
  DM                 dm = c->disc->dm;
  Vec                Uloc, G;
  const PetscScalar *g;

  PetscFunctionBeginUser;
  PetscCall(DMGetLocalVector(dm, &Uloc));
  PetscCall(DMGetGlobalVector(dm, &G));
  PetscCall(DMGlobalToLocal(dm, U, INSERT_VALUES, Uloc));
  PetscCall(SurfaceNodes(c->mesh, c->disc, c->surface, Uloc, G));
  PetscCall(VecGetArrayRead(G, &g));
  for (PetscInt i = 0; i < c->n; ++i) c->A[i] = PetscRealPart(g[c->row[i] + 2]);
  PetscCall(VecRestoreArrayRead(G, &g));
  PetscCall(DMRestoreGlobalVector(dm, &G));
  PetscCall(DMRestoreLocalVector(dm, &Uloc));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndContactUpdate(IndContact c, Vec U, IndContactSummary *sum)
{
  const PetscScalar *u;
  PetscReal          red[7] = {0, 0, 0, 0, 0, -PETSC_MAX_REAL, -PETSC_MAX_REAL}; /* |dR|^2, |R|^2, -Fz, area; maxima: penetration, height, depth */
  PetscInt           cnt[3] = {0, 0, 0};

  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(IndLog.contact, 0, 0, 0, 0));
  if (c->areas_current) PetscCall(CurrentAreas(c, U));
  PetscCall(VecGetArrayRead(U, &u));
  for (PetscInt i = 0; i < c->n; ++i) {
    IndContactNode ns;
    IndContactNodeSolve(c, i, u + c->row[i], Multiplier(c, i), &ns);
    for (int d = 0; d < 3; ++d) {
      /* A component held by a boundary condition is the support's (Newton leaves its multiplier 0) */
      if (!(c->variant == IND_UZAWA_NEWTON && c->fixed[i] & (1 << d))) {
        red[0] += PetscSqr(ns.f[d] - Multiplier(c, i)[d]);
        red[1] += PetscSqr(ns.f[d]);
      }
      c->R[3 * i + d] = ns.f[d];
    }
    red[2] -= ns.f[2];
    c->status[i] = ns.status;
    cnt[ns.status]++;
    if (ns.status != IND_CONTACT_OPEN) red[3] += c->A[i];
    red[4] = PetscMax(red[4], -ns.gap);
    red[5] = PetscMax(red[5], c->X[3 * i + 2] + PetscRealPart(u[c->row[i] + 2]) - c->indenter.surface);
    red[6] = PetscMax(red[6], c->indenter.surface - c->X[3 * i + 2] - PetscRealPart(u[c->row[i] + 2]));
  }
  PetscCall(VecRestoreArrayRead(U, &u));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, red, 4, MPIU_REAL, MPIU_SUM, c->comm));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, red + 4, 3, MPIU_REAL, MPIU_MAX, c->comm));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, cnt, 3, MPIU_INT, MPI_SUM, c->comm));
  sum->stick       = cnt[IND_CONTACT_STICK];
  sum->slip        = cnt[IND_CONTACT_SLIP];
  sum->contact     = sum->stick + sum->slip;
  sum->change      = red[1] > 0 ? PetscSqrtReal(red[0] / red[1]) : (red[0] > 0 ? 1.0 : 0.0);
  sum->mismatch    = PetscSqrtReal(red[0]);
  sum->load        = c->symmetry * red[2];
  sum->area        = c->symmetry * red[3];
  sum->penetration = PetscMax(red[4], 0.0);
  sum->pileup      = PetscMax(red[5], 0.0);
  sum->deepest     = PetscMax(red[6], 0.0);
  PetscCall(PetscLogEventEnd(IndLog.contact, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndContactCommit(IndContact c, Vec U)
{
  const PetscScalar *u;

  PetscFunctionBeginUser;
  PetscCall(VecGetArrayRead(U, &u));
  for (PetscInt i = 0; i < c->n; ++i)
    for (int d = 0; d < 3; ++d) {
      c->Rc[3 * i + d] = c->R[3 * i + d];
      c->Uc[3 * i + d] = PetscRealPart(u[c->row[i] + d]);
    }
  PetscCall(VecRestoreArrayRead(U, &u));
  c->depth_c = c->indenter.depth;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndContactRollback(IndContact c)
{
  PetscFunctionBeginUser;
  PetscCall(PetscArraycpy(c->R, c->Rc, 3 * c->n));
  c->indenter.depth = c->depth_c;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndContactNodalFields(IndContact c, Vec U, Vec G)
{
  const PetscScalar *u;
  PetscScalar       *g;

  PetscFunctionBeginUser;
  PetscCall(VecZeroEntries(G));
  PetscCall(VecGetArrayRead(U, &u));
  PetscCall(VecGetArray(G, &g));
  for (PetscInt i = 0; i < c->n; ++i) {
    IndContactNode ns;
    IndContactNodeSolve(c, i, u + c->row[i], Multiplier(c, i), &ns);
    g[c->row[i]]     = c->A[i] > 0 ? ns.r[0] / c->A[i] : 0.0;
    g[c->row[i] + 1] = (PetscReal)ns.status;
  }
  PetscCall(VecRestoreArray(G, &g));
  PetscCall(VecRestoreArrayRead(U, &u));
  PetscFunctionReturn(PETSC_SUCCESS);
}
