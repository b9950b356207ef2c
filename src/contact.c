#include "ind_contact.h"

const char *const IndUzawaTypes[] = {"fixed_point", "augmented", "IndUzawa", "IND_UZAWA_", NULL};

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
   like the displacement: slot 0 counts faces, slot 2 holds the area. */
static PetscErrorCode SurfaceNodes(IndMesh mesh, IndDisc disc, const char surface[], Vec G)
{
  DM                 dm = disc->dm, cdm;
  PetscSection       s, cs;
  DMLabel            label;
  IS                 faces;
  Vec                loc, X;
  PetscScalar       *a;

  PetscFunctionBeginUser;
  PetscCall(IndMeshGetRegionLabel(mesh, surface, 2, "-contact_surface", &label));
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
      PetscInt    *closure = NULL, ncl, nc;
      PetscScalar *xc = NULL;
      PetscReal    vx[12];
      PetscCall(DMPlexGetTransitiveClosure(dm, f[i], PETSC_TRUE, &ncl, &closure));
      for (PetscInt j = 0; j < ncl; ++j) {
        PetscInt dof, o;
        PetscCall(PetscSectionGetDof(s, closure[2 * j], &dof));
        if (dof < 3) continue;
        PetscCall(PetscSectionGetOffset(s, closure[2 * j], &o));
        a[o] += 1.0;
      }
      PetscCall(DMPlexRestoreTransitiveClosure(dm, f[i], PETSC_TRUE, &ncl, &closure));
      PetscCall(DMPlexVecGetClosure(cdm, cs, X, f[i], &nc, &xc));
      PetscCheck(nc == 9 || nc == 12, PETSC_COMM_SELF, PETSC_ERR_SUP, "Contact surface '%s': faces must be flat triangles or quadrilaterals with straight edges", surface);
      for (PetscInt k = 0; k < nc; ++k) vx[k] = PetscRealPart(xc[k]);
      PetscCall(DMPlexVecRestoreClosure(cdm, cs, X, f[i], &nc, &xc));
      PetscCall(FaceAreas(dm, s, f[i], vx, nc / 3, disc->degree, a));
    }
    PetscCall(ISRestoreIndices(faces, &f));
    PetscCall(ISDestroy(&faces));
  }
  PetscCall(VecRestoreArray(loc, &a));
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
  PetscBool          has_type, has_radius, has_surface, has_sym, has_axis;
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
  c->variant   = IND_UZAWA_AUGMENTED;
  c->rtol      = 1e-6;
  c->pen_rtol  = 1e-4;
  c->monitor   = PETSC_FALSE;
  PetscOptionsBegin(comm, NULL, "Rigid indenter and contact", "Contact");
  PetscCall(PetscOptionsReal("-indenter_radius", "Sphere, tip (cone, pyramids; 0 sharp) or punch radius (nm)", "", radius, &radius, &has_radius));
  PetscCall(PetscOptionsReal("-indenter_angle", "Cone half-angle or pyramid face-to-axis angle (degrees; 0: the standard one)", "", angle, &angle, NULL));
  PetscCall(PetscOptionsReal("-indenter_rotation", "Pyramids: azimuth of the first face's normal (degrees)", "", rotation, &rotation, NULL));
  PetscCall(PetscOptionsRealArray("-indenter_axis", "x,y of the indenter's axis (nm)", "", ind.axis, &naxis, &has_axis));
  PetscCall(PetscOptionsReal("-indenter_surface", "z of the undeformed surface where depth 0 touches (nm; default: highest contact node)", "", ind.surface, &ind.surface, &has_surface));
  PetscCall(PetscOptionsString("-contact_surface", "Surface whose nodes may touch the indenter", "", surface, surface, sizeof(surface), NULL));
  PetscCall(PetscOptionsReal("-contact_friction", "Coulomb friction coefficient", "", c->mu, &c->mu, NULL));
  PetscCall(PetscOptionsEnum("-contact_uzawa", "Outer loop: fixed_point (frozen reactions) or augmented (projected reactions in Newton)", "", IndUzawaTypes, (PetscEnum)c->variant, (PetscEnum *)&c->variant, NULL));
  /* The augmented loop contracts faster the larger rho is, but Newton's residual then jumps by rho
     times the gap where a node's status changes, and with friction it cycled between stick and slip
     (Berkovich into a plastic film, mu = 0.1: no step past 2.5 nm at 100). So each step starts at
     rho_min, where Newton is robust, and the outer loop grows rho tenfold per iteration up to
     rho_max once the contact state has settled. The fixed point diverges once rho exceeds
     2 / (largest eigenvalue of the contact compliance), about the stiffness diagonal already. */
  c->rho_max   = c->variant == IND_UZAWA_AUGMENTED ? 100.0 : 0.3;
  c->rho_min   = c->variant == IND_UZAWA_AUGMENTED ? 1.0 : 0.3;
  c->max_outer = c->variant == IND_UZAWA_AUGMENTED ? 50 : 200;
  PetscCall(PetscOptionsReal("-contact_rho_scale", "rho = scale * mean stiffness diagonal of each contact node (augmented: the largest, default 100; fixed_point: default 0.3)", "", c->rho_max, &c->rho_max, NULL));
  if (c->variant == IND_UZAWA_AUGMENTED) {
    c->rho_min = PetscMin(c->rho_min, c->rho_max);
    PetscCall(PetscOptionsReal("-contact_rho_initial", "Augmented: the largest scale of rho at the start of a step (lower after steps whose first Newton solve needed a smaller rho), grown tenfold per outer iteration up to -contact_rho_scale", "", c->rho_min, &c->rho_min, NULL));
  } else c->rho_min = c->rho_max;
  c->rho_scale = c->rho_min;
  c->rho_start = c->rho_min;
  PetscCall(PetscOptionsReal("-contact_uzawa_rtol", "Outer loop: relative change of the reactions", "", c->rtol, &c->rtol, NULL));
  PetscCall(PetscOptionsReal("-contact_penetration_rtol", "Outer loop: largest penetration relative to the largest depth", "", c->pen_rtol, &c->pen_rtol, NULL));
  {
    PetscInt gap = 0;
    const char *const gaps[] = {"current", "reference", "IndGap", "IND_GAP_", NULL};
    PetscCall(PetscOptionsEnum("-contact_gap", "Gap at the current position of the node, or at its undeformed horizontal position (small-deformation contact)", "", gaps, (PetscEnum)gap, (PetscEnum *)&gap, NULL));
    c->gap_current = gap == 0 ? PETSC_TRUE : PETSC_FALSE;
  }
  PetscCall(PetscOptionsInt("-contact_uzawa_max_it", "Outer iterations before the step fails (default 50 augmented, 200 fixed_point)", "", c->max_outer, &c->max_outer, NULL));
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
  PetscCheck(c->mu >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-contact_friction must be >= 0, got %g", (double)c->mu);
  PetscCheck(c->rho_max > 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-contact_rho_scale must be > 0, got %g", (double)c->rho_max);
  PetscCheck(c->rho_min > 0 && c->rho_min <= c->rho_max, comm, PETSC_ERR_ARG_OUTOFRANGE, "-contact_rho_initial must lie in (0, -contact_rho_scale %g], got %g", (double)c->rho_max, (double)c->rho_min);
  PetscCheck(c->rtol > 0 && c->pen_rtol > 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-contact_uzawa_rtol and -contact_penetration_rtol must be > 0");
  PetscCheck(c->max_outer >= 1, comm, PETSC_ERR_ARG_OUTOFRANGE, "-contact_uzawa_max_it must be >= 1, got %" PetscInt_FMT, c->max_outer);
  PetscCheck(!has_sym || symmetry >= 1, comm, PETSC_ERR_ARG_OUTOFRANGE, "-contact_symmetry_factor must be >= 1, got %g", (double)symmetry);
  /* Consistent nodal forces of a pressure vanish at the corner nodes of a 6-node triangle, so a
     node-to-surface contact cannot represent a smooth pressure there (and negative ones would be
     needed by 20-node serendipity faces). Q2 Lagrange faces have positive weights. */
  PetscCheck(!(disc->simplex && disc->degree == 2), comm, PETSC_ERR_SUP, "Contact on P2 tetrahedra is not supported: the consistent nodal forces of a pressure are zero at the corners of their 6-node faces. Use P1 tetrahedra or Q1/Q2 hexahedra for the contact region");

  /* The owned nodes of the contact surface, their positions and tributary areas. */
  PetscCall(DMCreateGlobalVector(disc->dm, &G));
  PetscCall(SurfaceNodes(mesh, disc, surface, G));
  PetscCall(IndDiscNodeCoordinates(disc, &nodes));
  PetscCall(VecGetLocalSize(G, &n));
  PetscCall(VecGetOwnershipRange(G, &rstart, NULL));
  PetscCall(VecGetArrayRead(G, &g));
  PetscCall(VecGetArrayRead(nodes, &x));
  for (PetscInt k = 0; k < n; k += 3)
    if (PetscRealPart(g[k]) > 0.5) c->n++;
  PetscCall(PetscMalloc5(c->n, &c->row, c->n, &c->grow, 3 * c->n, &c->X, c->n, &c->kdiag, c->n, &c->A));
  PetscCall(PetscCalloc5(3 * c->n, &c->R, 3 * c->n, &c->Rc, 3 * c->n, &c->Rs, 3 * c->n, &c->Uc, c->n, &c->status));
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
  *out        = c;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndContactDestroy(IndContact *c)
{
  PetscFunctionBeginUser;
  if (!*c) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscFree5((*c)->row, (*c)->grow, (*c)->X, (*c)->kdiag, (*c)->A));
  PetscCall(PetscFree5((*c)->R, (*c)->Rc, (*c)->Rs, (*c)->Uc, (*c)->status));
  PetscCall(PetscFree(*c));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndContactSetUp(IndContact c, Mat K, PetscReal depth_max)
{
  Vec                d;
  const PetscScalar *v;

  PetscFunctionBeginUser;
  PetscCall(MatCreateVecs(K, &d, NULL));
  PetscCall(MatGetDiagonal(K, d));
  PetscCall(VecGetArrayRead(d, &v));
  for (PetscInt i = 0; i < c->n; ++i) c->kdiag[i] = PetscRealPart(v[c->row[i]] + v[c->row[i] + 1] + v[c->row[i] + 2]) / 3.0;
  PetscCall(VecRestoreArrayRead(d, &v));
  PetscCall(VecDestroy(&d));
  c->pen_atol = c->pen_rtol * depth_max;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The local problem of node i at displacement u (3 values): frame, predictor and projection. The
   force on the body is f = r0 n + r1 t1 + r2 t2; D = dr/dtau; s the unit slip direction (local).
   With either gap definition d gap / d u = n. */
typedef struct {
  PetscReal        gap, n[3], t1[3], t2[3], r[3], f[3], D[9], s[2];
  IndContactStatus status;
} NodeState;

static void NodeSolve(IndContact c, PetscInt i, const PetscScalar *u, NodeState *ns)
{
  const PetscReal *Rv = c->R + 3 * i, *Uc = c->Uc + 3 * i;
  PetscReal        x[3], du[3], dut[2], rl[3], tau[3], slip;

  if (c->gap_current) {
    for (int d = 0; d < 3; ++d) x[d] = c->X[3 * i + d] + PetscRealPart(u[d]);
    IndIndenterGap(&c->indenter, x, &ns->gap, ns->n);
    IndIndenterTangents(ns->n, ns->t1, ns->t2);
  } else {
    /* Small-deformation contact, as in Hertz's and Sneddon's solutions: the vertical distance from
       the node, at its undeformed horizontal position moved by u_z, up to the indenter's surface;
       the reaction is vertical and the tangents horizontal. */
    PetscReal g0, g, n[3], sv = 0;
    PetscBool hit = PETSC_FALSE;
    for (int d = 0; d < 3; ++d) x[d] = c->X[3 * i + d] + (d == 2 ? PetscRealPart(u[d]) : 0.0);
    IndIndenterGap(&c->indenter, x, &g0, n);
    g = g0;
    /* Newton along the vertical line; where it misses the indenter's underside (beside a sphere
       or a punch) the node is far from contact, and the Euclidean gap, never larger, stands in. */
    for (int it = 0; it < 50 && n[2] < -1e-3; ++it) {
      const PetscReal ds = -g / n[2];
      PetscReal       y[3] = {x[0], x[1], x[2] + sv + ds};
      sv += ds;
      IndIndenterGap(&c->indenter, y, &g, n);
      if (PetscAbsReal(ds) <= 1e-12 * (1 + PetscAbsReal(sv))) {
        hit = n[2] < -1e-3 ? PETSC_TRUE : PETSC_FALSE;
        break;
      }
    }
    if (!hit) sv = g0;
    ns->gap = sv;
    ns->n[0] = ns->n[1] = 0, ns->n[2] = -1;
    ns->t1[0] = 1, ns->t1[1] = ns->t1[2] = 0;
    ns->t2[1] = 1, ns->t2[0] = ns->t2[2] = 0;
  }
  /* slip relative to the indenter, which moved down by the change of depth over the step */
  for (int d = 0; d < 3; ++d) du[d] = PetscRealPart(u[d]) - Uc[d];
  du[2] += c->indenter.depth - c->depth_c;
  dut[0] = du[0] * ns->t1[0] + du[1] * ns->t1[1] + du[2] * ns->t1[2];
  dut[1] = du[0] * ns->t2[0] + du[1] * ns->t2[1] + du[2] * ns->t2[2];
  slip   = PetscSqrtReal(dut[0] * dut[0] + dut[1] * dut[1]);
  ns->s[0] = slip > 0 ? dut[0] / slip : 0;
  ns->s[1] = slip > 0 ? dut[1] / slip : 0;
  rl[0] = Rv[0] * ns->n[0] + Rv[1] * ns->n[1] + Rv[2] * ns->n[2];
  rl[1] = Rv[0] * ns->t1[0] + Rv[1] * ns->t1[1] + Rv[2] * ns->t1[2];
  rl[2] = Rv[0] * ns->t2[0] + Rv[1] * ns->t2[1] + Rv[2] * ns->t2[2];
  IndBipotentialPredictor(c->mu, c->rho_scale * c->kdiag[i], rl, ns->gap, dut, tau);
  ns->status = IndBipotentialProject(c->mu, tau, ns->r, ns->D);
  for (int d = 0; d < 3; ++d) ns->f[d] = ns->r[0] * ns->n[d] + ns->r[1] * ns->t1[d] + ns->r[2] * ns->t2[d];
}

PetscErrorCode IndContactResidual(IndContact c, Vec U, Vec F)
{
  const PetscScalar *u;
  PetscScalar       *f;

  PetscFunctionBeginUser;
  PetscCall(VecGetArrayRead(U, &u));
  PetscCall(VecGetArray(F, &f));
  for (PetscInt i = 0; i < c->n; ++i) {
    const PetscInt k = c->row[i];
    if (c->variant == IND_UZAWA_FIXED_POINT)
      for (int d = 0; d < 3; ++d) f[k + d] -= c->R[3 * i + d];
    else {
      NodeState ns;
      NodeSolve(c, i, u + k, &ns);
      for (int d = 0; d < 3; ++d) f[k + d] -= ns.f[d];
    }
  }
  PetscCall(VecRestoreArray(F, &f));
  PetscCall(VecRestoreArrayRead(U, &u));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndContactJacobian(IndContact c, Vec U, Mat J)
{
  const PetscScalar *u;

  PetscFunctionBeginUser;
  if (c->variant == IND_UZAWA_AUGMENTED) {
    PetscCall(VecGetArrayRead(U, &u));
    for (PetscInt i = 0; i < c->n; ++i) {
      NodeState      ns;
      PetscReal      Q[3][3], G[3][3], QD[3][3], B[9];
      const PetscInt rows[3] = {c->grow[i], c->grow[i] + 1, c->grow[i] + 2};
      NodeSolve(c, i, u + c->row[i], &ns);
      if (ns.status == IND_CONTACT_OPEN) continue;
      /* f = Q r(tau), dtau/du = -rho G: G's rows n + mu (s1 t1 + s2 t2), t1, t2 (the frame's own
         rotation is left out). The residual has -f, so J += rho Q D G. */
      for (int d = 0; d < 3; ++d) {
        Q[d][0] = ns.n[d], Q[d][1] = ns.t1[d], Q[d][2] = ns.t2[d];
        G[0][d] = ns.n[d] + c->mu * (ns.s[0] * ns.t1[d] + ns.s[1] * ns.t2[d]);
        G[1][d] = ns.t1[d];
        G[2][d] = ns.t2[d];
      }
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) {
          QD[a][b] = 0;
          for (int k = 0; k < 3; ++k) QD[a][b] += Q[a][k] * ns.D[3 * k + b];
        }
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) {
          B[3 * a + b] = 0;
          for (int k = 0; k < 3; ++k) B[3 * a + b] += c->rho_scale * c->kdiag[i] * QD[a][k] * G[k][b];
        }
      PetscCall(MatSetValues(J, 3, rows, 3, rows, B, ADD_VALUES));
    }
    PetscCall(VecRestoreArrayRead(U, &u));
  }
  PetscCall(MatAssemblyBegin(J, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(J, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndContactUpdate(IndContact c, Vec U, IndContactSummary *sum)
{
  const PetscScalar *u;
  PetscReal          red[7] = {0, 0, 0, 0, 0, -PETSC_MAX_REAL, -PETSC_MAX_REAL}; /* |dR|^2, |R|^2, -Fz, area; maxima: penetration, height, depth */
  PetscInt           cnt[3] = {0, 0, 0};

  PetscFunctionBeginUser;
  PetscCall(VecGetArrayRead(U, &u));
  for (PetscInt i = 0; i < c->n; ++i) {
    NodeState ns;
    NodeSolve(c, i, u + c->row[i], &ns);
    for (int d = 0; d < 3; ++d) {
      red[0] += PetscSqr(ns.f[d] - c->R[3 * i + d]);
      red[1] += PetscSqr(ns.f[d]);
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
  sum->load        = c->symmetry * red[2];
  sum->area        = c->symmetry * red[3];
  sum->penetration = PetscMax(red[4], 0.0);
  sum->pileup      = PetscMax(red[5], 0.0);
  sum->deepest     = PetscMax(red[6], 0.0);
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
    NodeState ns;
    NodeSolve(c, i, u + c->row[i], &ns);
    g[c->row[i]]     = c->A[i] > 0 ? ns.r[0] / c->A[i] : 0.0;
    g[c->row[i] + 1] = (PetscReal)ns.status;
  }
  PetscCall(VecRestoreArray(G, &g));
  PetscCall(VecRestoreArrayRead(U, &u));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndContactSaveReactions(IndContact c)
{
  PetscFunctionBeginUser;
  PetscCall(PetscArraycpy(c->Rs, c->R, 3 * c->n));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndContactRestoreReactions(IndContact c)
{
  PetscFunctionBeginUser;
  PetscCall(PetscArraycpy(c->R, c->Rs, 3 * c->n));
  PetscFunctionReturn(PETSC_SUCCESS);
}
