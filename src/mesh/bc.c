#include "bc_impl.h"
#include "disc_impl.h"
#include "mesh_impl.h"
#include "ind_bc.h"

static PetscErrorCode AddSpec(IndBC bc, const char label[], const char option[], PetscInt mask,
  const PetscReal value[3], IndVectorFn fn, void *ctx)
{
  IndBCSpec *s;

  PetscFunctionBeginUser;
  PetscCheck(bc->nspec < IND_MAX_BC, PETSC_COMM_SELF, PETSC_ERR_SUP, "At most %d boundary conditions", IND_MAX_BC);
  s = &bc->spec[bc->nspec++];
  PetscCall(PetscStrncpy(s->label, label, sizeof(s->label)));
  PetscCall(PetscStrncpy(s->option, option, sizeof(s->option)));
  s->mask = mask;
  for (int c = 0; c < 3; ++c) s->value[c] = value ? value[c] : 0.0;
  s->fn  = fn;
  s->ctx = ctx;
  bc->setup = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode ParseComponents(MPI_Comm comm, const char option[], const char entry[], const char *s,
  PetscInt *mask)
{
  PetscFunctionBeginUser;
  *mask = 0;
  for (; *s && *s != '='; ++s) {
    PetscCheck(*s >= 'x' && *s <= 'z', comm, PETSC_ERR_ARG_WRONG, "%s: bad component '%c' in '%s' (use x, y, z)",
      option, *s, entry);
    *mask |= 1 << (*s - 'x');
  }
  PetscCheck(*mask, comm, PETSC_ERR_ARG_WRONG, "%s: no component given in '%s'", option, entry);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The axis normal to every face of a symmetry plane; only axis-aligned planes are supported. */
static PetscErrorCode SymmetryAxis(IndBC bc, const char label[], PetscInt *mask, PetscReal *plane)
{
  DM       dm = bc->mesh->dm;
  MPI_Comm comm = PetscObjectComm((PetscObject)dm);
  DMLabel  l;
  IS       faces;
  PetscInt axes = 0, skew = 0;
  PetscReal where = PETSC_MAX_REAL;

  PetscFunctionBeginUser;
  PetscCall(IndMeshGetRegionLabel(bc->mesh, label, 2, "-bc_symmetry", &l));
  if (!IndHelpListing()) PetscCall(IndMeshCheckRegionNotEmpty(bc->mesh, label, 2, "-bc_symmetry"));
  PetscCall(DMLabelGetStratumIS(l, 1, &faces));
  if (faces) {
    const PetscInt *f;
    PetscInt        n;
    PetscCall(ISGetLocalSize(faces, &n));
    PetscCall(ISGetIndices(faces, &f));
    for (PetscInt k = 0; k < n; ++k) {
      PetscReal area, centroid[3], normal[3], len;
      int       d = 0;
      PetscCall(DMPlexComputeCellGeometryFVM(dm, f[k], &area, centroid, normal));
      len = PetscSqrtReal(PetscSqr(normal[0]) + PetscSqr(normal[1]) + PetscSqr(normal[2]));
      for (int e = 1; e < 3; ++e)
        if (PetscAbsReal(normal[e]) > PetscAbsReal(normal[d])) d = e;
      if (PetscAbsReal(normal[d]) < (1.0 - 1e-8) * len) skew++;
      axes |= 1 << d;
      where = PetscMin(where, centroid[d]);
    }
    PetscCall(ISRestoreIndices(faces, &f));
    PetscCall(ISDestroy(&faces));
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &axes, 1, MPIU_INT, MPI_BOR, comm));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &skew, 1, MPIU_INT, MPI_SUM, comm));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &where, 1, MPIU_REAL, MPIU_MIN, comm));
  *plane = where;
  PetscCheck(axes, comm, PETSC_ERR_ARG_WRONG, "-bc_symmetry: surface '%s' has no faces", label);
  PetscCheck(!skew && (axes == 1 || axes == 2 || axes == 4), comm, PETSC_ERR_SUP,
    "-bc_symmetry: surface '%s' is not a plane normal to x, y or z", label);
  *mask = axes;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndBCCreate(IndMesh mesh, IndDisc disc, IndBC *out)
{
  IndBC     bc;
  MPI_Comm  comm = PetscObjectComm((PetscObject)mesh->dm);
  char     *fixed[IND_MAX_BC], *sym[IND_MAX_BC], *roller[IND_MAX_BC], *disp[IND_MAX_BC];
  PetscInt  nfixed = IND_MAX_BC, nsym = IND_MAX_BC, nroller = IND_MAX_BC, ndisp = IND_MAX_BC;
  PetscBool set;

  PetscFunctionBeginUser;
  PetscCall(PetscCalloc1(1, &bc));
  bc->mesh = mesh;
  bc->disc = disc;
  PetscOptionsBegin(comm, NULL, IND_TITLE "Boundary conditions on named surfaces (-bc_*)", "BC");
  PetscCall(IndOptionsStringArray("-bc_fixed", "Surfaces with all displacement components zero", "surface,...", fixed,
    &nfixed, &set));
  if (!set) nfixed = 0;
  PetscCall(IndOptionsStringArray("-bc_symmetry", "Symmetry planes (normal displacement zero; axis-aligned)",
    "surface,...", sym, &nsym, &set));
  if (!set) nsym = 0;
  PetscCall(IndOptionsStringArray("-bc_roller", "Rollers: the components held on each surface, e.g. bottom:z,left:xy",
    "surface:components,...", roller, &nroller, &set));
  if (!set) nroller = 0;
  PetscCall(IndOptionsStringArray("-bc_displacement", "Prescribed displacement at full load in nm, e.g. top:z=-10",
    "surface:components=value,...", disp, &ndisp, &set));
  if (!set) ndisp = 0;
  PetscOptionsEnd();

  for (PetscInt i = 0; i < nfixed; ++i) {
    DMLabel l;
    PetscCall(IndMeshGetRegionLabel(mesh, fixed[i], 2, "-bc_fixed", &l));
    if (!IndHelpListing()) PetscCall(IndMeshCheckRegionNotEmpty(mesh, fixed[i], 2, "-bc_fixed"));
    PetscCall(AddSpec(bc, fixed[i], "-bc_fixed", 7, NULL, NULL, NULL));
  }
  for (PetscInt i = 0; i < nsym; ++i) {
    PetscInt  mask = 0;
    PetscReal plane = 0;
    PetscCall(SymmetryAxis(bc, sym[i], &mask, &plane));
    PetscCall(AddSpec(bc, sym[i], "-bc_symmetry", mask, NULL, NULL, NULL));
    bc->spec[bc->nspec - 1].plane = plane;
  }
  for (PetscInt i = 0; i < nroller; ++i) {
    char   *colon = strchr(roller[i], ':');
    PetscInt mask;
    DMLabel  l;
    PetscCheck(colon, comm, PETSC_ERR_ARG_WRONG, "-bc_roller: '%s' is not surface:components (e.g. bottom:z)",
      roller[i]);
    *colon = 0;
    PetscCall(ParseComponents(comm, "-bc_roller", roller[i], colon + 1, &mask));
    PetscCall(IndMeshGetRegionLabel(mesh, roller[i], 2, "-bc_roller", &l));
    if (!IndHelpListing()) PetscCall(IndMeshCheckRegionNotEmpty(mesh, roller[i], 2, "-bc_roller"));
    PetscCall(AddSpec(bc, roller[i], "-bc_roller", mask, NULL, NULL, NULL));
  }
  for (PetscInt i = 0; i < ndisp; ++i) {
    char     *colon = strchr(disp[i], ':'), *eq = strchr(disp[i], '='), *end;
    PetscInt  mask;
    PetscReal value[3] = {0, 0, 0}, v;
    DMLabel   l;
    PetscCheck(colon && eq && eq > colon, comm, PETSC_ERR_ARG_WRONG,
      "-bc_displacement: '%s' is not surface:component=value (e.g. top:z=-10)", disp[i]);
    *colon = 0;
    PetscCall(ParseComponents(comm, "-bc_displacement", disp[i], colon + 1, &mask));
    v = strtod(eq + 1, &end);
    PetscCheck(end != eq + 1 && *end == 0, comm, PETSC_ERR_ARG_WRONG,
      "-bc_displacement: '%s' for surface '%s' is not a number (nm)", eq + 1, disp[i]);
    PetscCheck(!PetscIsInfOrNanReal(v), comm, PETSC_ERR_ARG_OUTOFRANGE,
      "-bc_displacement: '%s' for surface '%s' is not a finite number (nm)", eq + 1, disp[i]);
    for (int c = 0; c < 3; ++c)
      if (mask & (1 << c)) value[c] = v;
    PetscCall(IndMeshGetRegionLabel(mesh, disp[i], 2, "-bc_displacement", &l));
    if (!IndHelpListing()) PetscCall(IndMeshCheckRegionNotEmpty(mesh, disp[i], 2, "-bc_displacement"));
    PetscCall(AddSpec(bc, disp[i], "-bc_displacement", mask, value, NULL, NULL));
  }
  for (PetscInt i = 0; i < nfixed; ++i) PetscCall(PetscFree(fixed[i]));
  for (PetscInt i = 0; i < nsym; ++i) PetscCall(PetscFree(sym[i]));
  for (PetscInt i = 0; i < nroller; ++i) PetscCall(PetscFree(roller[i]));
  for (PetscInt i = 0; i < ndisp; ++i) PetscCall(PetscFree(disp[i]));
  *out = bc;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndBCAddFunction(IndBC bc, const char label[], PetscInt mask, IndVectorFn fn, void *ctx)
{
  DMLabel l;

  PetscFunctionBeginUser;
  PetscCall(IndMeshGetRegionLabel(bc->mesh, label, 2, "IndBCAddFunction", &l));
  PetscCall(AddSpec(bc, label, "IndBCAddFunction", mask, NULL, fn, ctx));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode ProjectWrapper(PetscInt dim, PetscReal t, const PetscReal x[], PetscInt Nc, PetscScalar *u,
  void *ctx)
{
  IndBCSpec *s = (IndBCSpec *)ctx;
  PetscReal  v[3];

  PetscFunctionBeginUser;
  (void)dim;
  (void)t;
  (void)Nc;
  PetscCall(s->fn(x, v, s->ctx));
  for (int c = 0; c < 3; ++c) u[c] = v[c];
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The axisymmetric model's own conditions, on top of the user's: the hoop displacement (y) is zero at every
   node (torsionless), and the radial one (x) at every node on the axis r = 0, where a ring shrinks to a point. */
static PetscErrorCode MarkAxisymmetricConditions(IndBC bc, Vec Mloc)
{
  const PetscScalar *x;
  PetscScalar       *m;
  PetscInt           n;
  PetscReal          extent = 0;

  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(Mloc, &n));
  PetscCall(VecGetArrayRead(bc->disc->Xloc, &x));
  for (PetscInt k = 0; k < n; ++k) extent = PetscMax(extent, PetscAbsReal(PetscRealPart(x[k])));
  PetscCallMPI(
    MPI_Allreduce(MPI_IN_PLACE, &extent, 1, MPIU_REAL, MPIU_MAX, PetscObjectComm((PetscObject)bc->disc->dm)));
  PetscCall(VecGetArray(Mloc, &m));
  for (PetscInt k = 0; k < n; k += 3) {
    m[k + 1] += 1.0;
    if (PetscAbsReal(PetscRealPart(x[k])) <= 1e-10 * extent) m[k] += 1.0;
  }
  PetscCall(VecRestoreArray(Mloc, &m));
  PetscCall(VecRestoreArrayRead(bc->disc->Xloc, &x));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Constrained dofs are marked in local vectors and summed into global ones, so that a rank owning a
   node of a boundary face it does not hold itself still learns of the condition. Where several
   conditions meet on one dof their values are averaged; consistent inputs give one value. */
PetscErrorCode IndBCSetUp(IndBC bc)
{
  DM                 dm = bc->disc->dm;
  PetscSection       s;
  Vec                Mloc, Vloc, Floc = NULL, M, V;
  PetscScalar       *m, *v;
  const PetscScalar *mg, *vg, *fv = NULL;
  PetscInt           rstart, n, *seen;

  PetscFunctionBeginUser;
  if (bc->setup) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscLogEventBegin(IndLog.bc, 0, 0, 0, 0));
  PetscCall(PetscFree3(bc->rows, bc->lrows, bc->values));
  PetscCall(DMGetLocalSection(dm, &s));
  PetscCall(DMGetLocalVector(dm, &Mloc));
  PetscCall(DMGetLocalVector(dm, &Vloc));
  PetscCall(VecZeroEntries(Mloc));
  PetscCall(VecZeroEntries(Vloc));
  PetscCall(VecGetLocalSize(Mloc, &n));
  PetscCall(PetscMalloc1(n, &seen));
  for (PetscInt i = 0; i < n; ++i) seen[i] = -1;
  for (PetscInt k = 0; k < bc->nspec; ++k) {
    IndBCSpec *sp = &bc->spec[k];
    DMLabel    l;
    IS         faces;

    PetscCall(DMGetLabel(dm, sp->label, &l));
    if (sp->fn) {
      PetscErrorCode (*funcs[1])(PetscInt, PetscReal, const PetscReal[], PetscInt, PetscScalar *,
        void *) = {ProjectWrapper};
      void *ctxs[1] = {sp};
      PetscCall(DMGetLocalVector(dm, &Floc));
      PetscCall(DMProjectFunctionLocal(dm, 0.0, funcs, ctxs, INSERT_ALL_VALUES, Floc));
      PetscCall(VecGetArrayRead(Floc, &fv));
    }
    PetscCall(VecGetArray(Mloc, &m));
    PetscCall(VecGetArray(Vloc, &v));
    PetscCall(DMLabelGetStratumIS(l, 1, &faces));
    if (faces) {
      const PetscInt *f;
      PetscInt        nf;
      PetscCall(ISGetLocalSize(faces, &nf));
      PetscCall(ISGetIndices(faces, &f));
      for (PetscInt i = 0; i < nf; ++i) {
        PetscInt *closure = NULL, ncl;
        PetscCall(DMPlexGetTransitiveClosure(dm, f[i], PETSC_TRUE, &ncl, &closure));
        for (PetscInt j = 0; j < ncl; ++j) {
          PetscInt dof, off;
          PetscCall(IndDiscPointDof(s, closure[2 * j], &dof));
          if (!dof) continue;
          PetscCall(PetscSectionGetOffset(s, closure[2 * j], &off));
          for (PetscInt d = 0; d < dof; ++d) {
            const PetscInt c = d % 3;
            if (!(sp->mask & (1 << c))) continue;
            /* A point in several faces is visited several times: count it once per condition. */
            if (seen[off + d] == k) continue;
            seen[off + d] = k;
            m[off + d] += 1.0;
            v[off + d] += sp->fn ? PetscRealPart(fv[off + d]) : sp->value[c];
          }
        }
        PetscCall(DMPlexRestoreTransitiveClosure(dm, f[i], PETSC_TRUE, &ncl, &closure));
      }
      PetscCall(ISRestoreIndices(faces, &f));
      PetscCall(ISDestroy(&faces));
    }
    PetscCall(VecRestoreArray(Mloc, &m));
    PetscCall(VecRestoreArray(Vloc, &v));
    if (sp->fn) {
      PetscCall(VecRestoreArrayRead(Floc, &fv));
      PetscCall(DMRestoreLocalVector(dm, &Floc));
    }
  }
  PetscCall(PetscFree(seen));
  if (bc->disc->dim == 2) PetscCall(MarkAxisymmetricConditions(bc, Mloc));

  PetscCall(DMGetGlobalVector(dm, &M));
  PetscCall(DMGetGlobalVector(dm, &V));
  PetscCall(VecZeroEntries(M));
  PetscCall(VecZeroEntries(V));
  PetscCall(DMLocalToGlobal(dm, Mloc, ADD_VALUES, M));
  PetscCall(DMLocalToGlobal(dm, Vloc, ADD_VALUES, V));
  PetscCall(VecGetOwnershipRange(M, &rstart, NULL));
  PetscCall(VecGetLocalSize(M, &n));
  PetscCall(VecGetArrayRead(M, &mg));
  PetscCall(VecGetArrayRead(V, &vg));
  bc->nrows = 0;
  for (PetscInt i = 0; i < n; ++i)
    if (PetscRealPart(mg[i]) > 0.5) bc->nrows++;
  PetscCall(PetscMalloc3(bc->nrows, &bc->rows, bc->nrows, &bc->lrows, bc->nrows, &bc->values));
  bc->nrows = 0;
  for (PetscInt i = 0; i < n; ++i)
    if (PetscRealPart(mg[i]) > 0.5) {
      bc->lrows[bc->nrows]  = i;
      bc->rows[bc->nrows]   = rstart + i;
      bc->values[bc->nrows] = PetscRealPart(vg[i]) / PetscRealPart(mg[i]);
      bc->nrows++;
    }
  PetscCall(VecRestoreArrayRead(M, &mg));
  PetscCall(VecRestoreArrayRead(V, &vg));
  PetscCall(DMRestoreGlobalVector(dm, &M));
  PetscCall(DMRestoreGlobalVector(dm, &V));
  PetscCall(DMRestoreLocalVector(dm, &Mloc));
  PetscCall(DMRestoreLocalVector(dm, &Vloc));
  bc->setup = PETSC_TRUE;
  PetscCall(PetscLogEventEnd(IndLog.bc, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndBCInvalidate(IndBC bc)
{
  PetscFunctionBeginUser;
  bc->setup = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndBCApplySolution(IndBC bc, PetscReal lf, Vec U)
{
  PetscScalar *u;

  PetscFunctionBeginUser;
  PetscCall(VecGetArray(U, &u));
  for (PetscInt i = 0; i < bc->nrows; ++i) u[bc->lrows[i]] = lf * bc->values[i];
  PetscCall(VecRestoreArray(U, &u));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndBCApplyResidual(IndBC bc, PetscReal lf, Vec U, Vec F)
{
  const PetscScalar *u;
  PetscScalar       *f;

  PetscFunctionBeginUser;
  PetscCall(VecGetArrayRead(U, &u));
  PetscCall(VecGetArray(F, &f));
  for (PetscInt i = 0; i < bc->nrows; ++i) f[bc->lrows[i]] = u[bc->lrows[i]] - lf * bc->values[i];
  PetscCall(VecRestoreArrayRead(U, &u));
  PetscCall(VecRestoreArray(F, &f));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndBCApplyJacobian(IndBC bc, Mat J)
{
  PetscFunctionBeginUser;
  PetscCall(MatZeroRowsColumns(J, bc->nrows, bc->rows, 1.0, NULL, NULL));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndBCDestroy(IndBC *bc)
{
  PetscFunctionBeginUser;
  if (!*bc) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscFree3((*bc)->rows, (*bc)->lrows, (*bc)->values));
  PetscCall(PetscFree(*bc));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndBCGetSpecs(IndBC bc, PetscInt *n, const IndBCSpec **specs)
{
  PetscFunctionBeginUser;
  *n     = bc->nspec;
  *specs = bc->spec;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndBCGetRows(IndBC bc, PetscInt *n, const PetscInt **rows, const PetscInt **local)
{
  PetscFunctionBeginUser;
  PetscCheck(bc->setup, PETSC_COMM_SELF, PETSC_ERR_ORDER, "IndBCGetRows() before IndBCSetUp()");
  *n = bc->nrows;
  if (rows) *rows = bc->rows;
  if (local) *local = bc->lrows;
  PetscFunctionReturn(PETSC_SUCCESS);
}
