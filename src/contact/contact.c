#include "contact_impl.h"
#include "ind_indenter_profile.h"
#include "contact_node.h"


static const PetscReal deg = PETSC_PI / 180.0;

/* 1D quadratic Lagrange basis on the nodes -1, 0, 1. */
static inline PetscReal L2(int node, PetscReal s)
{
  return node == 0 ? 0.5 * s * (s - 1) : node == 1 ? 1 - s * s : 0.5 * s * (s + 1);
}

/* Adds to a[] (indexed like the local vector, z slot of each node) the projected tributary area
   int_face N_a |n_z| dA of every node of one face: the consistent nodal force of a unit pressure on
   a flat face, for its own Lagrange basis (Q1/Q2 quads, P1/P2 triangles, and on an axisymmetric section
   2- and 3-node edges, whose surface of revolution has dA = 2 pi r ds). The vertices are in the
   cyclic order of the face's closure; edge nodes are identified by their two vertices. */
static PetscErrorCode FaceAreas(DM dm, PetscSection s, PetscInt face, const PetscReal *vx, PetscInt nv,
  PetscInt degree, PetscScalar *a)
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
  PetscCheck(nvv == nv, PETSC_COMM_SELF, PETSC_ERR_PLIB,
    "Face %" PetscInt_FMT " has %" PetscInt_FMT " vertices, expected %" PetscInt_FMT, face, nvv, nv);
  /* reference positions of the face's nodes */
  for (PetscInt j = 0; j < ncl; ++j) {
    const PetscInt p = closure[2 * j];
    PetscInt       dof, o;
    PetscCall(IndDiscPointDof(s, p, &dof));
    if (dof < 3) continue;
    PetscCall(PetscSectionGetOffset(s, p, &o));
    if (p >= vStart && p < vEnd) {
      PetscInt k = 0;
      while (vpt[k] != p) ++k;
      if (nv == 4) {
        const PetscReal c[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
        ref[nn][0] = c[k][0], ref[nn][1] = c[k][1];
      } else if (nv == 2) {
        ref[nn][0] = (PetscReal)k, ref[nn][1] = 0;
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
      } else if (nv == 2) {
        c0[0] = (PetscReal)k0, c1[0] = (PetscReal)k1, c0[1] = c1[1] = 0;
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

  if (nv == 2) {
    /* the edge s in [0, 1] from vertex 0 to vertex 1: 3 Gauss points integrate N_a r exactly */
    const PetscReal g[3] = {0.1127016653792583, 0.5, 0.8872983346207417}, w[3] = {5.0 / 18, 8.0 / 18, 5.0 / 18};
    const PetscReal dr = PetscAbsReal(vx[3] - vx[0]);
    for (int q = 0; q < 3; ++q) {
      const PetscReal r = (1 - g[q]) * vx[0] + g[q] * vx[3];
      for (PetscInt b = 0; b < nn; ++b) {
        PetscReal N;
        if (degree == 1) N = ref[b][0] > 0.5 ? g[q] : 1 - g[q];
        else N = L2((int)PetscFloorReal(2 * ref[b][0] + 0.5), 2 * g[q] - 1);
        a[off[b] + 2] += w[q] * 2 * PETSC_PI * r * dr * N;
      }
    }
  } else if (nv == 4) {
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

/* Adds to slot 1 of each node of one face (vertices in cyclic order, vx their coordinates) the face's
   interior angle at the node: at a corner the angle between its edges, pi at an edge node, 2 pi at a
   face's centre node. Summed over the surface, a node inside it gets 2 pi, one on its boundary less.
   An edge of an axisymmetric section gives pi to each end: its inner vertices get 2 pi too. */
static void FaceAngles(const PetscInt *voff, PetscInt nv, const PetscReal *vx, PetscScalar *a)
{
  if (nv == 2) {
    a[voff[0] + 1] += PETSC_PI;
    a[voff[1] + 1] += PETSC_PI;
    return;
  }
  for (PetscInt k = 0; k < nv; ++k) {
    const PetscReal *p = vx + 3 * k, *prev = vx + 3 * ((k + nv - 1) % nv), *next = vx + 3 * ((k + 1) % nv);
    PetscReal        e1[3], e2[3], d = 0, l1 = 0, l2 = 0;
    for (int i = 0; i < 3; ++i) {
      e1[i] = prev[i] - p[i];
      e2[i] = next[i] - p[i];
      d += e1[i] * e2[i];
      l1 += e1[i] * e1[i];
      l2 += e2[i] * e2[i];
    }
    a[voff[k] + 1] += l1 > 0 && l2 > 0 ? PetscAcosReal(PetscMax(-1.0, PetscMin(1.0, d / PetscSqrtReal(l1 * l2)))) : 0.0;
  }
}

/* Marks the nodes of the contact surface and sums their tributary areas, in a global vector laid out
   like the displacement: slot 0 counts faces, slot 1 sums the faces' angles at the node (FaceAngles),
   slot 2 holds the area. With Uloc (a local displacement) the faces are taken through their vertices'
   current positions X + u. */
static PetscErrorCode SurfaceNodes(IndMesh mesh, IndDisc disc, const char surface[], Vec Uloc, Vec G)
{
  DM                 dm, cdm;
  PetscInt           degree;
  PetscSection       s, cs;
  DMLabel            label;
  IS                 faces;
  Vec                loc, X;
  PetscScalar       *a;
  const PetscScalar *u = NULL;
  PetscInt           vStart, vEnd, eStart, eEnd;

  PetscFunctionBeginUser;
  PetscCall(IndDiscGetDM(disc, &dm));
  {
    const IndDiscLayout *L;
    PetscCall(IndDiscGetLayout(disc, &L));
    degree = L->degree;
  }
  PetscCall(IndMeshGetRegionLabel(mesh, surface, 2, "-contact_surface", &label));
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
  PetscCall(DMPlexGetDepthStratum(dm, 1, &eStart, &eEnd));
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
      PetscInt    *closure = NULL, ncl, nc, nv = 0, voff[4];
      PetscScalar *xc = NULL;
      PetscReal    vx[12], uv[12];
      PetscCall(DMPlexGetTransitiveClosure(dm, f[i], PETSC_TRUE, &ncl, &closure));
      for (PetscInt j = 0; j < ncl; ++j) {
        PetscInt dof, o;
        PetscCall(IndDiscPointDof(s, closure[2 * j], &dof));
        if (dof < 3) continue;
        PetscCall(PetscSectionGetOffset(s, closure[2 * j], &o));
        a[o] += 1.0;
        /* vertices come in the closure's order, as in the coordinate closure below */
        if (closure[2 * j] >= vStart && closure[2 * j] < vEnd && nv < 4) {
          for (int d = 0; d < 3; ++d) uv[3 * nv + d] = u ? PetscRealPart(u[o + d]) : 0.0;
          voff[nv++] = o;
        } else a[o + 1] += closure[2 * j] >= eStart && closure[2 * j] < eEnd && closure[2 * j] != f[i] ? PETSC_PI
                                                                                                      : 2 * PETSC_PI;
      }
      PetscCall(DMPlexRestoreTransitiveClosure(dm, f[i], PETSC_TRUE, &ncl, &closure));
      PetscCall(DMPlexVecGetClosure(cdm, cs, X, f[i], &nc, &xc));
      PetscCheck(nc == 6 || nc == 9 || nc == 12, PETSC_COMM_SELF, PETSC_ERR_SUP,
        "Contact surface '%s': faces must be flat triangles or quadrilaterals (straight edges on an axisymmetric "
        "section)", surface);
      PetscCheck(3 * nv == nc, PETSC_COMM_SELF, PETSC_ERR_PLIB,
                 "Contact surface '%s': face with %" PetscInt_FMT " vertices and %" PetscInt_FMT " coordinates",
                 surface, nv, nc);
      for (PetscInt k = 0; k < nc; ++k) vx[k] = PetscRealPart(xc[k]) + uv[k];
      PetscCall(DMPlexVecRestoreClosure(cdm, cs, X, f[i], &nc, &xc));
      FaceAngles(voff, nv, vx, a);
      PetscCall(FaceAreas(dm, s, f[i], vx, nc / 3, degree, a));
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
static PetscReal SymmetryFactor(PetscInt nspec, const IndBCSpec *spec, const IndIndenter *ind)
{
  PetscReal f = 1;
  for (PetscInt k = 0; k < nspec; ++k)
    if (IndContactPlaneThroughAxis(&spec[k], ind)) f *= 2;
  return f;
}

/* Bit c set when a symmetry plane normal to axis c passes through the indenter's axis. */
static PetscInt MirrorPlanes(PetscInt nspec, const IndBCSpec *spec, const IndIndenter *ind)
{
  PetscInt mask = 0;
  for (PetscInt k = 0; k < nspec; ++k) {
    const int c = IndContactPlaneThroughAxis(&spec[k], ind);
    if (c) mask |= 1 << (c - 1);
  }
  return mask;
}

int IndContactPlaneThroughAxis(const IndBCSpec *spec, const IndIndenter *ind)
{
  PetscBool sym;
  PetscStrcmp(spec->option, "-bc_symmetry", &sym);
  if (!sym) return 0;
  for (int c = 0; c < 2; ++c)
    if (spec->mask == (1 << c) && PetscAbsReal(spec->plane - ind->axis[c]) <= 1e-9 * (1 + PetscAbsReal(ind->axis[c])))
      return c + 1;
  return 0;
}

/* A symmetry plane through the axis halves the indenter too: it must be one of the pyramid's mirror
   planes, which contain its axis at the azimuths rotation + k 180/nfaces degrees. A plane normal to y
   runs along azimuth 0, one normal to x along 90. */
static PetscErrorCode CheckRotation(MPI_Comm comm, PetscInt nspec, const IndBCSpec *spec, const IndIndenter *ind,
  PetscReal rotation)
{
  const PetscReal period = ind->nfaces ? 180.0 / ind->nfaces : 0;
  PetscInt        planes = 0;

  PetscFunctionBeginUser;
  if (!ind->nfaces) PetscFunctionReturn(PETSC_SUCCESS); /* axisymmetric */
  for (PetscInt k = 0; k < nspec; ++k) planes += IndContactPlaneThroughAxis(&spec[k], ind) ? 1 : 0;
  for (PetscInt k = 0; k < nspec; ++k) {
    const int       c     = IndContactPlaneThroughAxis(&spec[k], ind);
    const PetscReal along = c == 2 ? 0.0 : 90.0;
    const char     *hint;
    PetscReal       r;
    if (!c) continue;
    r = PetscFmodReal(PetscFmodReal(along - rotation, period) + period, period);
    if (planes > 1 && ind->nfaces == 3)
      hint = "a three-sided pyramid has no two perpendicular mirror planes: mesh a half or a full model";
    else if (ind->nfaces == 4) hint = "use a rotation of 0, 45, 90, ... degrees, or a full model";
    else if (PetscFmodReal(along, period) == 0) hint = "use a rotation of 0, 60, 120, ... degrees, or a full model";
    else hint = "use a rotation of 30, 90, 150, ... degrees, or a full model";
    PetscCheck(r < 1e-6 || period - r < 1e-6, comm, PETSC_ERR_ARG_INCOMP,
               "-indenter_rotation %.6g degrees: the %s indenter is not mirror-symmetric about the symmetry plane "
               "'%s' (%c = %.6g nm, through its axis), so this %s model does not represent it; %s",
               (double)rotation, IndIndenterTypes[ind->type], spec[k].label, c == 2 ? 'y' : 'x',
               (double)spec[k].plane, planes > 1 ? "quarter" : "half", hint);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The axisymmetric model represents indenters of revolution on the axis r = 0, and the whole ring. */
static PetscErrorCode CheckAxisymmetric(MPI_Comm comm, const IndIndenter *ind, PetscBool has_sym)
{
  PetscFunctionBeginUser;
  PetscCheck(!ind->nfaces, comm, PETSC_ERR_SUP,
    "-indenter_type %s is a pyramid, which the axisymmetric model (a 2D mesh) cannot represent; the cone of the same "
    "projected area is -indenter_type cone -indenter_angle %s, or use a 3D mesh", IndIndenterTypes[ind->type],
    ind->type == IND_INDENTER_CUBE_CORNER ? "42.28" : "70.3");
  PetscCheck(ind->axis[0] == 0 && ind->axis[1] == 0, comm, PETSC_ERR_SUP,
    "-indenter_axis %g,%g: on the axisymmetric model (a 2D mesh) the indenter's axis is the mesh's axis r = 0; an "
    "indenter off the axis needs a 3D mesh", (double)ind->axis[0], (double)ind->axis[1]);
  PetscCheck(!has_sym, comm, PETSC_ERR_ARG_WRONG,
    "-contact_symmetry_factor does not apply to the axisymmetric model (a 2D mesh): its loads are the whole ring's");
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Which contact nodes lie on the edge of the modelled surface (its boundary, less the parts on
   symmetry planes, where the body goes on in the mirror image), the lowest point of the mesh and the
   surface's projected area (times the symmetry factor): what the run's checks compare with
   (run_checks.c). */
static PetscErrorCode SurfaceEdgeAndSize(IndContact c, PetscInt nspec, const IndBCSpec *spec)
{
  DM                 dm;
  Vec                X;
  const PetscScalar *x;
  PetscInt           n, counts[2] = {0, 0};
  PetscReal          zmin = PETSC_MAX_REAL, scale = 0, area = 0;

  PetscFunctionBeginUser;
  PetscCall(IndDiscGetDM(c->disc, &dm));
  PetscCall(DMGetCoordinatesLocal(dm, &X));
  PetscCall(VecGetLocalSize(X, &n));
  PetscCall(VecGetArrayRead(X, &x));
  for (PetscInt k = 0; k < n; k += 3) {
    zmin = PetscMin(zmin, PetscRealPart(x[k + 2]));
    for (int d = 0; d < 3; ++d) scale = PetscMax(scale, PetscAbsReal(PetscRealPart(x[k + d])));
  }
  PetscCall(VecRestoreArrayRead(X, &x));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &zmin, 1, MPIU_REAL, MPIU_MIN, c->comm));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &scale, 1, MPIU_REAL, MPIU_MAX, c->comm));
  c->zmin = zmin;
  c->extent[0] = c->extent[2] = PETSC_MAX_REAL;
  c->extent[1] = c->extent[3] = -PETSC_MAX_REAL;
  for (PetscInt i = 0; i < c->n; ++i) {
    for (int d = 0; d < 2; ++d) {
      c->extent[2 * d]     = PetscMin(c->extent[2 * d], c->X[3 * i + d]);
      c->extent[2 * d + 1] = PetscMax(c->extent[2 * d + 1], c->X[3 * i + d]);
    }
    area += c->A[i];
    /* the axis is no edge of a section: the surface goes on round it */
    if (c->axisymmetric && PetscAbsReal(c->X[3 * i]) <= 1e-10 * (1 + scale)) c->edge[i] = PETSC_FALSE;
    for (PetscInt k = 0; k < nspec && c->edge[i]; ++k) {
      PetscBool sym;
      PetscCall(PetscStrcmp(spec[k].option, "-bc_symmetry", &sym));
      for (int d = 0; d < 3 && sym; ++d)
        if (spec[k].mask == (1 << d) && PetscAbsReal(c->X[3 * i + d] - spec[k].plane) <= 1e-9 * (1 + scale))
          c->edge[i] = PETSC_FALSE;
    }
    counts[0] += c->edge[i] ? 1 : 0;
  }
  {
    PetscReal lo[2] = {-c->extent[0], -c->extent[2]}, hi[2] = {c->extent[1], c->extent[3]};
    PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, lo, 2, MPIU_REAL, MPIU_MAX, c->comm));
    PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, hi, 2, MPIU_REAL, MPIU_MAX, c->comm));
    c->extent[0] = -lo[0], c->extent[1] = hi[0], c->extent[2] = -lo[1], c->extent[3] = hi[1];
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &area, 1, MPIU_REAL, MPIU_SUM, c->comm));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, counts, 1, MPIU_INT, MPI_SUM, c->comm));
  c->surface_area = c->symmetry * area;
  c->nedge        = counts[0];
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndContactCreate(IndMesh mesh, IndDisc disc, IndBC bc, IndContact *out)
{
  IndContact           c;
  DM                   dm;
  MPI_Comm             comm;
  const IndDiscLayout *L;
  PetscInt             nspec;
  const IndBCSpec     *spec;
  IndIndenter          ind;
  PetscBool          has_type, has_radius, has_surface, has_sym, has_axis, has_rounding, has_profile;
  PetscReal          angle = 0, rotation = 0, radius = 0, symmetry = 0;
  PetscInt           naxis = 2;
  char               surface[IND_NAME_LEN] = "top", profile[PETSC_MAX_PATH_LEN] = "";
  Vec                G, nodes;
  const PetscScalar *g, *x;
  PetscInt           n, rstart;

  PetscFunctionBeginUser;
  *out = NULL;
  PetscCall(IndDiscGetDM(disc, &dm));
  PetscCall(IndDiscGetLayout(disc, &L));
  PetscCall(IndBCGetSpecs(bc, &nspec, &spec));
  comm = PetscObjectComm((PetscObject)dm);
  PetscCall(PetscMemzero(&ind, sizeof(ind)));
  PetscOptionsBegin(comm, NULL, IND_TITLE "Indenter (-indenter_type)", "Contact");
  PetscCall(IndOptionsEnum("-indenter_type",
    "Rigid indenter shape; without it, no indenter (a run of prescribed displacements)", IndIndenterTypes,
    (PetscEnum)ind.type, (PetscEnum *)&ind.type, &has_type));
  PetscOptionsEnd();
  if (!has_type) PetscFunctionReturn(PETSC_SUCCESS);

  PetscCall(PetscCalloc1(1, &c));
  c->comm      = comm;
  c->rtol      = 1e-6;
  c->pen_rtol  = 1e-4;
  c->monitor   = PETSC_FALSE;
  PetscOptionsBegin(comm, NULL, IND_TITLE "Indenter and contact (-indenter_*, -contact_*)", "Contact");
  PetscCall(IndOptionsReal("-indenter_sharp_rounding",
    "Sharp cones and pyramids: the contact sees them rounded by this radius (0: exactly sharp)", "nm",
    "1e-4 of -load_depth", c->rounding, &c->rounding, &has_rounding));
  PetscCall(IndOptionsReal("-indenter_radius", "Sphere, tip (cone, pyramids; 0 sharp) or punch radius", "nm",
    "required for sphere and flat; 0 (sharp) for the others", radius, &radius, &has_radius));
  PetscCall(IndOptionsReal("-indenter_angle", "Cone half-angle or pyramid face-to-axis angle (0: the standard one)",
    "degrees", NULL, angle, &angle, NULL));
  PetscCall(IndOptionsString("-indenter_profile",
    "-indenter_type table: a file of the indenter's height above its tip against the radius, r,height per line (nm)",
    "file", NULL, profile, profile, sizeof(profile), &has_profile));
  PetscCall(IndOptionsReal("-indenter_rotation",
    "Pyramids: azimuth of the first face's normal; on a half or quarter model it must keep the symmetry planes mirror "
    "planes of the pyramid", "degrees", NULL, rotation, &rotation, NULL));
  PetscCall(IndOptionsRealArray("-indenter_axis", "Position of the indenter's (vertical) axis", "x,y in nm", NULL,
    ind.axis, &naxis, &has_axis));
  PetscCall(IndOptionsReal("-indenter_surface", "z of the undeformed surface, where depth 0 touches", "nm",
    "the highest node of -contact_surface", ind.surface, &ind.surface, &has_surface));
  PetscCall(IndOptionsString("-contact_surface", "Surface whose nodes may touch the indenter", "surface", NULL, surface,
    surface, sizeof(surface), NULL));
  PetscCall(IndOptionsReal("-contact_friction", "Coulomb friction coefficient", "", NULL, c->mu, &c->mu, NULL));
  {
    char coupling[IND_NAME_LEN];
    PetscCall(IndOptionsType("-contact_uzawa",
      "Contact algorithm: newton (semi-smooth Newton, reactions from the residual) or fixed_point (reactions frozen in "
      "each Newton solve, updated between them)", &IndContactCouplingRegistry, "newton", coupling, sizeof(coupling),
      NULL));
    PetscCall(IndContactSetCoupling(c, coupling)); /* and its defaults of rho and of the outer iterations */
  }
  PetscCall(IndOptionsReal("-contact_rho_scale", "rho = scale * mean stiffness diagonal of each contact node", "",
    "0.5 newton, 0.3 fixed_point", c->rho_scale, &c->rho_scale, NULL));
  PetscCall(IndOptionsReal("-contact_uzawa_rtol", "Outer loop: relative change of the reactions", "", NULL, c->rtol,
    &c->rtol, NULL));
  PetscCall(IndOptionsReal("-contact_penetration_rtol", "Outer loop: largest penetration relative to the largest depth",
    "", NULL, c->pen_rtol, &c->pen_rtol, NULL));
  {
    PetscInt gap = 0;
    const char *const gaps[] = {"current", "reference", "IndGap", "IND_GAP_", NULL};
    PetscCall(IndOptionsEnum("-contact_gap",
      "Gap at the current position of the node, or at its undeformed horizontal position (small-deformation contact)",
      gaps, (PetscEnum)gap, (PetscEnum *)&gap, NULL));
    c->gap_current = gap == 0 ? PETSC_TRUE : PETSC_FALSE;
  }
  PetscCall(IndOptionsInt("-contact_uzawa_max_it", "Outer iterations before the step fails",
    "20 newton, 200 fixed_point", c->max_outer, &c->max_outer, NULL));
  PetscCall(IndOptionsBool("-contact_monitor", "Print a line per outer iteration", c->monitor, &c->monitor, NULL));
  PetscCall(IndOptionsReal("-contact_symmetry_factor", "Load multiplier of a symmetric part model", "",
    "2 per symmetry plane through the axis", symmetry, &symmetry, &has_sym));
  PetscOptionsEnd();
  ind.radius   = radius;
  ind.angle    = angle * deg;
  ind.rotation = rotation * deg;
  PetscCheck(has_radius || (ind.type != IND_INDENTER_SPHERE && ind.type != IND_INDENTER_FLAT), comm,
    PETSC_ERR_ARG_WRONG, "-indenter_type %s needs -indenter_radius (nm)", IndIndenterTypes[ind.type]);
  PetscCheck(radius >= 0 && (radius > 0 || (ind.type != IND_INDENTER_SPHERE && ind.type != IND_INDENTER_FLAT)), comm,
    PETSC_ERR_ARG_OUTOFRANGE, "-indenter_radius must be %s, got %g",
    ind.type == IND_INDENTER_SPHERE || ind.type == IND_INDENTER_FLAT ? "> 0" : ">= 0", (double)radius);
  PetscCheck(angle >= 0 && angle < 90, comm, PETSC_ERR_ARG_OUTOFRANGE,
    "-indenter_angle must lie in (0, 90) degrees (0: the standard angle), got %g", (double)angle);
  PetscCheck(has_profile == (ind.type == IND_INDENTER_TABLE ? PETSC_TRUE : PETSC_FALSE), comm, PETSC_ERR_ARG_WRONG,
    has_profile ? "-indenter_profile is the table of -indenter_type table, not of %s"
                : "-indenter_type %s needs -indenter_profile FILE (r,height per line, nm)", IndIndenterTypes[ind.type]);
  if (has_profile && !IndHelpListing()) {
    PetscCall(IndIndenterReadProfile(comm, profile, &c->profile, &ind.nprofile));
    ind.profile = c->profile;
  }
  PetscCheck(!IndIndenterSetUp(&ind) || (ind.type == IND_INDENTER_TABLE && IndHelpListing()), comm,
    PETSC_ERR_ARG_OUTOFRANGE,
    "-indenter_type %s: bad -indenter_radius or -indenter_angle", IndIndenterTypes[ind.type]);
  PetscCheck(!has_axis || naxis == 2, comm, PETSC_ERR_ARG_SIZ,
    "-indenter_axis needs two values x,y (nm), got %" PetscInt_FMT, naxis);
  PetscCheck(!has_rounding || c->rounding >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE,
    "-indenter_sharp_rounding must be >= 0 (nm), got %g", (double)c->rounding);
  if (!has_rounding) c->rounding = -1; /* set from the depth at setup */
  PetscCheck(c->mu >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-contact_friction must be >= 0, got %g", (double)c->mu);
  PetscCheck(c->rho_scale > 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-contact_rho_scale must be > 0, got %g",
    (double)c->rho_scale);
  PetscCheck(c->rtol > 0 && c->pen_rtol > 0, comm, PETSC_ERR_ARG_OUTOFRANGE,
    "-contact_uzawa_rtol and -contact_penetration_rtol must be > 0");
  PetscCheck(c->max_outer >= 1, comm, PETSC_ERR_ARG_OUTOFRANGE,
    "-contact_uzawa_max_it must be >= 1, got %" PetscInt_FMT, c->max_outer);
  PetscCheck(!has_sym || symmetry >= 1, comm, PETSC_ERR_ARG_OUTOFRANGE,
    "-contact_symmetry_factor must be >= 1, got %g", (double)symmetry);
  /* Consistent nodal forces of a pressure vanish at the corner nodes of a 6-node triangle, so a
     node-to-surface contact cannot represent a smooth pressure there (and negative ones would be
     needed by 20-node serendipity faces). Q2 Lagrange faces have positive weights. */
  PetscCheck(!(L->simplex && L->degree == 2 && !L->axisymmetric), comm, PETSC_ERR_SUP,
    "Contact on P2 tetrahedra is not supported: the consistent nodal forces of a pressure are zero at the corners of "
    "their 6-node faces. Use P1 tetrahedra or Q1/Q2 hexahedra for the contact region");

  if (L->axisymmetric) PetscCall(CheckAxisymmetric(comm, &ind, has_sym));

  /* The owned nodes of the contact surface, their positions and tributary areas. */
  {
    DMLabel label;
    PetscCall(IndMeshGetRegionLabel(mesh, surface, 2, "-contact_surface", &label));
    if (!IndHelpListing()) PetscCall(IndMeshCheckRegionNotEmpty(mesh, surface, 2, "-contact_surface"));
  }
  PetscCall(DMCreateGlobalVector(dm, &G));
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
  PetscCall(PetscCalloc3(3 * c->n, &c->Lu, c->n, &c->fixed, c->n, &c->Rn));
  PetscCall(PetscCalloc1(c->n, &c->edge));
  c->n = 0;
  {
    PetscReal top = -PETSC_MAX_REAL;
    for (PetscInt k = 0; k < n; k += 3)
      if (PetscRealPart(g[k]) > 0.5) {
        c->row[c->n]  = k;
        c->grow[c->n] = rstart + k;
        for (int d = 0; d < 3; ++d) c->X[3 * c->n + d] = PetscRealPart(x[k + d]);
        c->A[c->n]    = PetscRealPart(g[k + 2]);
        c->edge[c->n] = PetscRealPart(g[k + 1]) < 2 * PETSC_PI * (1 - 1e-6) ? PETSC_TRUE : PETSC_FALSE;
        top           = PetscMax(top, c->X[3 * c->n + 2]);
        c->n++;
      }
    PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &top, 1, MPIU_REAL, MPIU_MAX, comm));
    PetscCheck(top > -PETSC_MAX_REAL, comm, PETSC_ERR_USER_INPUT,
      "-contact_surface '%s' has no nodes (the surface is empty)", surface);
    if (!has_surface) ind.surface = top;
    c->top = top;
  }
  PetscCall(VecRestoreArrayRead(G, &g));
  PetscCall(VecRestoreArrayRead(nodes, &x));
  PetscCall(VecDestroy(&nodes));
  PetscCall(VecDestroy(&G));
  c->indenter = ind;
  /* a section's residual is already that of the whole ring: its radial forces cancel round the axis */
  c->symmetry = has_sym ? symmetry : L->axisymmetric ? 1.0 : SymmetryFactor(nspec, spec, &ind);
  c->mirror   = L->axisymmetric ? 3 : MirrorPlanes(nspec, spec, &ind);
  c->axisymmetric = L->axisymmetric;
  c->axis_c[0] = ind.axis[0];
  c->axis_c[1] = ind.axis[1];
  if (!IndHelpListing()) PetscCall(CheckRotation(comm, nspec, spec, &ind, rotation));
  c->mesh     = mesh;
  c->disc     = disc;
  PetscCall(SurfaceEdgeAndSize(c, nspec, spec));
  PetscCall(IndContactSpacingSetUp(c));
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
  PetscCall(PetscFree3((*c)->Lu, (*c)->fixed, (*c)->Rn));
  PetscCall(PetscFree((*c)->edge));
  PetscCall(PetscFree((*c)->spacing));
  PetscCall(PetscFree((*c)->profile));
  PetscCall(PetscFree(*c));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Before solving: the depth must stay inside the body, and the indenter must reach the surface. The
   body moves only where something pushes it; with no boundary displacement prescribed, a surface the
   rigid indenter does not reach at full depth in its undeformed position is never touched. */
static PetscErrorCode CheckReach(IndContact c, PetscInt nspec, const IndBCSpec *spec, PetscReal depth_max)
{
  const IndIndenter *ind    = &c->indenter;
  const PetscReal    lowest = ind->surface - depth_max;
  PetscBool          moves  = PETSC_FALSE;
  PetscReal          gmin   = PETSC_MAX_REAL;

  PetscFunctionBeginUser;
  PetscCheck(lowest > c->zmin, c->comm, PETSC_ERR_USER_INPUT,
             "-load_depth %.6g nm goes through the body: the indenter's lowest point would reach z = %.6g nm, at or "
             "below the mesh's bottom at z = %.6g nm (the body is %.6g nm thick under the contact surface '%s' at "
             "z = %.6g nm)",
             (double)depth_max, (double)lowest, (double)c->zmin, (double)(ind->surface - c->zmin), c->surface,
             (double)ind->surface);
  {
    /* At depth 0 the indenter touches the undeformed surface at most: a start inside the body would
       load it before the first step and report loads from a depth that is not the indentation's. */
    IndIndenter at = *ind;
    PetscReal   g0 = PETSC_MAX_REAL, tol = 1e-9 * PetscMax(1.0, PetscAbsReal(c->top) + PetscAbsReal(c->zmin));
    at.depth       = 0;
    for (PetscInt i = 0; i < c->n; ++i) {
      PetscReal gap, nrm[3];
      IndIndenterGap(&at, c->X + 3 * i, &gap, nrm);
      g0 = PetscMin(g0, gap);
    }
    PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &g0, 1, MPIU_REAL, MPIU_MIN, c->comm));
    PetscCheck(g0 >= -tol, c->comm, PETSC_ERR_USER_INPUT,
               "The indenter starts inside the body: at depth 0 it reaches %.6g nm below the contact surface '%s' "
               "(-indenter_surface %.6g nm, the surface's highest node at z = %.6g nm); give -indenter_surface at or "
               "above the surface (its default is the highest node)",
               (double)-g0, c->surface, (double)ind->surface, (double)c->top);
  }
  for (PetscInt k = 0; k < nspec; ++k)
    if (spec[k].fn || spec[k].value[0] != 0 || spec[k].value[1] != 0 || spec[k].value[2] != 0)
      moves = PETSC_TRUE;
  if (moves) PetscFunctionReturn(PETSC_SUCCESS); /* decided after loading instead (run_checks.c) */
  {
    IndIndenter at = *ind;
    at.depth       = depth_max;
    for (PetscInt i = 0; i < c->n; ++i) {
      PetscReal gap, nrm[3];
      IndIndenterGap(&at, c->X + 3 * i, &gap, nrm);
      gmin = PetscMin(gmin, gap);
    }
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &gmin, 1, MPIU_REAL, MPIU_MIN, c->comm));
  PetscCheck(gmin <= 0, c->comm, PETSC_ERR_USER_INPUT,
             "The indenter never touches the contact surface '%s': at the full depth (-load_depth %.6g nm) its lowest "
             "point is at z = %.6g nm and it stays %.6g nm away from the nearest node (surface's highest node at "
             "z = %.6g nm; -indenter_surface %.6g nm, -indenter_axis %.6g,%.6g nm)",
             c->surface, (double)depth_max, (double)lowest, (double)gmin, (double)c->top, (double)ind->surface,
             (double)ind->axis[0], (double)ind->axis[1]);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndContactSetUp(IndContact c, IndBC bc, Mat K, PetscReal depth_max)
{
  Vec                d;
  const PetscScalar *v;
  PetscScalar       *m;
  PetscInt           nrows, nspec;
  const PetscInt    *lrows;
  const IndBCSpec   *spec;

  PetscFunctionBeginUser;
  PetscCall(IndBCGetRows(bc, &nrows, NULL, &lrows));
  PetscCall(IndBCGetSpecs(bc, &nspec, &spec));
  PetscCall(MatCreateVecs(K, &d, NULL));
  PetscCall(MatGetDiagonal(K, d));
  PetscCall(VecGetArrayRead(d, &v));
  for (PetscInt i = 0; i < c->n; ++i) c->kdiag[i] = PetscRealPart(v[c->row[i]] + v[c->row[i] + 1] + v[c->row[i] + 2])
    / 3.0;
  PetscCall(VecRestoreArrayRead(d, &v));
  PetscCall(VecZeroEntries(d));
  PetscCall(VecGetArray(d, &m));
  for (PetscInt k = 0; k < nrows; ++k) m[lrows[k]] = 1.0;
  for (PetscInt i = 0; i < c->n; ++i) {
    c->fixed[i] = 0;
    for (int dd = 0; dd < 3; ++dd)
      if (PetscRealPart(m[c->row[i] + dd]) > 0.5) c->fixed[i] |= 1 << dd;
  }
  PetscCall(VecRestoreArray(d, &m));
  PetscCall(VecDestroy(&d));
  c->pen_atol = c->pen_rtol * depth_max;
  c->indenter.rounding = c->rounding >= 0 ? c->rounding : 1e-4 * depth_max;
  if (!IndHelpListing()) PetscCall(CheckReach(c, nspec, spec, depth_max));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndContactResidual(IndContact c, Vec U, Vec F)
{
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(IndLog.contact, 0, 0, 0, 0));
  PetscCall(c->ops.residual(c, U, F));
  PetscCall(PetscLogEventEnd(IndLog.contact, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndContactJacobian(IndContact c, Vec U, Mat J, Vec Fd)
{
  PetscFunctionBeginUser;
  if (c->ops.jacobian) PetscCall(c->ops.jacobian(c, U, J, Fd));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The reaction the projection starts from: the multiplier of the last residual (Newton) or the
   frozen reaction of the last outer update (fixed point). */
static const PetscReal *Multiplier(IndContact c, PetscInt i)
{
  return (c->ops.residual_multipliers ? c->L : c->R) + 3 * i;
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
  DM                 dm;
  Vec                Uloc, G;
  const PetscScalar *g;

  PetscFunctionBeginUser;
  PetscCall(IndDiscGetDM(c->disc, &dm));
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
  /* sums: |dR|^2, |R|^2, -Fz, area, Fx, Fy; maxima: penetration, height, depth */
  PetscReal          red[9] = {0, 0, 0, 0, 0, 0, -PETSC_MAX_REAL, -PETSC_MAX_REAL, -PETSC_MAX_REAL};
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
      if (!(c->ops.residual_multipliers && c->fixed[i] & (1 << d))) {
        red[0] += PetscSqr(ns.f[d] - Multiplier(c, i)[d]);
        red[1] += PetscSqr(ns.f[d]);
      }
      c->R[3 * i + d] = ns.f[d];
    }
    red[2] -= ns.f[2];
    red[4] += ns.f[0];
    red[5] += ns.f[1];
    c->status[i] = ns.status;
    c->Rn[i]     = ns.r[0];
    cnt[ns.status]++;
    if (ns.status != IND_CONTACT_OPEN) red[3] += c->A[i];
    red[6] = PetscMax(red[6], -ns.gap);
    red[7] = PetscMax(red[7], c->X[3 * i + 2] + PetscRealPart(u[c->row[i] + 2]) - c->indenter.surface);
    red[8] = PetscMax(red[8], c->indenter.surface - c->X[3 * i + 2] - PetscRealPart(u[c->row[i] + 2]));
  }
  PetscCall(VecRestoreArrayRead(U, &u));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, red, 6, MPIU_REAL, MPIU_SUM, c->comm));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, red + 6, 3, MPIU_REAL, MPIU_MAX, c->comm));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, cnt, 3, MPIU_INT, MPI_SUM, c->comm));
  sum->stick       = cnt[IND_CONTACT_STICK];
  sum->slip        = cnt[IND_CONTACT_SLIP];
  sum->contact     = sum->stick + sum->slip;
  sum->change      = red[1] > 0 ? PetscSqrtReal(red[0] / red[1]) : (red[0] > 0 ? 1.0 : 0.0);
  /* Newton with every node open: their rows were the equilibrium rows, which Newton has solved, so the
     contact is converged (a body strained by its boundary, which the indenter does not touch, left the
     relative change at 1 for ever). */
  if (c->ops.residual_multipliers && red[1] == 0 && cnt[IND_CONTACT_STICK] + cnt[IND_CONTACT_SLIP] == 0)
    sum->change = 0;
  sum->mismatch    = PetscSqrtReal(red[0]);
  sum->load        = c->symmetry * red[2];
  sum->area        = c->symmetry * red[3];
  sum->penetration = PetscMax(red[6], 0.0);
  sum->pileup      = PetscMax(red[7], 0.0);
  sum->deepest     = PetscMax(red[8], 0.0);
  /* The mirror image doubles the components in a symmetry plane and cancels the one normal to it. */
  sum->force[0]    = c->mirror & 1 ? 0.0 : c->symmetry * red[4];
  sum->force[1]    = c->mirror & 2 ? 0.0 : c->symmetry * red[5];
  sum->force[2]    = -sum->load;
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
  c->depth_c   = c->indenter.depth;
  c->axis_c[0] = c->indenter.axis[0];
  c->axis_c[1] = c->indenter.axis[1];
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndContactRollback(IndContact c)
{
  PetscFunctionBeginUser;
  PetscCall(PetscArraycpy(c->R, c->Rc, 3 * c->n));
  c->indenter.depth   = c->depth_c;
  c->indenter.axis[0] = c->axis_c[0];
  c->indenter.axis[1] = c->axis_c[1];
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndContactSetIndenterPosition(IndContact c, PetscReal depth, const PetscReal axis[2])
{
  PetscFunctionBeginUser;
  c->indenter.depth   = depth;
  c->indenter.axis[0] = axis[0];
  c->indenter.axis[1] = axis[1];
  PetscFunctionReturn(PETSC_SUCCESS);
}

IND_GETTER(PetscReal, IndContactGetDepth, IndContact, o->indenter.depth)

PetscErrorCode IndContactSetDepth(IndContact c, PetscReal depth)
{
  PetscFunctionBeginUser;
  c->indenter.depth = depth;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndContactSmallestGap(IndContact c, Vec U, PetscReal *gap)
{
  const PetscScalar *u;
  PetscReal          g = PETSC_MAX_REAL;

  PetscFunctionBeginUser;
  PetscCall(VecGetArrayRead(U, &u));
  for (PetscInt i = 0; i < c->n; ++i) {
    IndContactNode ns;
    IndContactNodeSolve(c, i, u + c->row[i], Multiplier(c, i), &ns);
    g = PetscMin(g, ns.gap);
  }
  PetscCall(VecRestoreArrayRead(U, &u));
  PetscCallMPI(MPI_Allreduce(&g, gap, 1, MPIU_REAL, MPIU_MIN, c->comm));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndContactNodalFields(IndContact c, Vec G)
{
  PetscScalar *g;

  PetscFunctionBeginUser;
  /* Not solved again at the committed state: there the slip increment is zero and every node in
     contact would read as sticking. */
  PetscCall(VecZeroEntries(G));
  PetscCall(VecGetArray(G, &g));
  for (PetscInt i = 0; i < c->n; ++i) {
    g[c->row[i]]     = c->A[i] > 0 ? c->Rn[i] / c->A[i] : 0.0;
    g[c->row[i] + 1] = (PetscReal)c->status[i];
  }
  PetscCall(VecRestoreArray(G, &g));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The rows of the nodes the indenter holds as it rises, from the last update's status (a sticking node wholly, a
   slipping one vertically) or, with committed, from the committed reactions (every node that carries one, wholly
   with friction, vertically without). */
static PetscErrorCode HeldRows(IndContact c, PetscBool committed, Vec X, PetscInt *n, PetscInt rows[])
{
  PetscScalar *x;

  PetscFunctionBeginUser;
  PetscCall(VecGetArray(X, &x));
  for (PetscInt i = 0; i < c->n; ++i) {
    const PetscReal *r        = c->Rc + 3 * i;
    const PetscBool  touching = committed ? r[0] != 0 || r[1] != 0 || r[2] != 0 : c->status[i] != IND_CONTACT_OPEN;
    const PetscBool  wholly   = committed ? c->mu > 0 : c->status[i] == IND_CONTACT_STICK;
    if (!touching) continue;
    for (int d = 0; d < 3; ++d) {
      if (c->fixed[i] & (1 << d) || (d < 2 && !wholly)) continue;
      rows[(*n)++]     = c->grow[i] + d;
      x[c->row[i] + d] = d == 2 ? 1.0 : 0.0;
    }
  }
  PetscCall(VecRestoreArray(X, &x));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndContactUnloadingRows(IndContact c, Vec X, PetscInt *n, PetscInt rows[])
{
  PetscFunctionBeginUser;
  PetscCall(HeldRows(c, PETSC_FALSE, X, n, rows));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndContactReversalRows(IndContact c, Vec X, PetscInt *n, PetscInt rows[])
{
  PetscFunctionBeginUser;
  PetscCall(HeldRows(c, PETSC_TRUE, X, n, rows));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndContactActiveForce(IndContact c, Vec F, PetscReal *Fz)
{
  const PetscScalar *f;
  PetscReal          sum = 0;

  PetscFunctionBeginUser;
  PetscCall(VecGetArrayRead(F, &f));
  for (PetscInt i = 0; i < c->n; ++i)
    if (c->status[i] != IND_CONTACT_OPEN) sum += PetscRealPart(f[c->row[i] + 2]);
  PetscCall(VecRestoreArrayRead(F, &f));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &sum, 1, MPIU_REAL, MPIU_SUM, c->comm));
  *Fz = c->symmetry * sum;
  PetscFunctionReturn(PETSC_SUCCESS);
}

IND_GETTER(PetscInt, IndContactGetSize, IndContact, o->n)
IND_GETTER(PetscReal, IndContactGetSymmetry, IndContact, o->symmetry)
IND_GETTER(const IndIndenter *, IndContactGetIndenter, IndContact, &o->indenter)
IND_GETTER(PetscReal, IndContactGetCommittedDepth, IndContact, o->depth_c)
IND_GETTER(MPI_Comm, IndContactGetComm, IndContact, o->comm)

PetscErrorCode IndContactGetSurface(IndContact c, const char **name, PetscReal extent[4])
{
  PetscFunctionBeginUser;
  if (name) *name = c->surface;
  if (extent) PetscCall(PetscArraycpy(extent, c->extent, 4));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndContactGetNodes(IndContact c, IndContactNodes *v)
{
  PetscFunctionBeginUser;
  v->n      = c->n;
  v->X      = c->X;
  v->R      = c->R;
  v->A      = c->A;
  v->status = c->status;
  PetscFunctionReturn(PETSC_SUCCESS);
}

IND_GETTER(PetscReal, IndContactGetSurfaceArea, IndContact, o->surface_area)
