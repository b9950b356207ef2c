#include "assembly_impl.h"
#include "ind_pattern.h"
#include "ind_blockmult.h"

const char *const IndTangentTypes[]     = {"consistent", "elastic", "IndTangent", "IND_TANGENT_", NULL};
IndRegistry IndKinematicsRegistry = {
  .builtin = (const IndRegistryEntry[]){{"small", (IndRegistryFn)IndKinematicsSmall},
                                        {"finite", (IndRegistryFn)IndKinematicsFinite},
                                        {NULL, NULL}}
};

PetscErrorCode IndAssemblyCreate(IndDisc disc, IndMaterials mats, IndHistory history, IndAssembly *out)
{
  IndAssembly a;
  PetscInt    nd;

  PetscFunctionBeginUser;
  PetscCall(PetscCalloc1(1, &a));
  a->disc    = disc;
  PetscCall(IndDiscGetLayout(disc, &a->layout));
  PetscCall(IndDiscGetDM(disc, &a->dm));
  PetscCall(IndDiscGetNodePositions(disc, &a->Xloc));
  nd = a->layout->ndof;
  a->mats    = mats;
  a->history = history;
  a->tangent     = IND_TANGENT_CONSISTENT;
  PetscOptionsBegin(PetscObjectComm((PetscObject)a->dm), NULL, IND_TITLE "Kinematics and assembly", "Assembly");
  {
    IndRegistryFn fn;
    char          name[IND_NAME_LEN];
    /* finite by default: it agrees with large-deformation references (doc/finite-strain.md) */
    PetscCall(IndOptionsType("-formulation",
                             "Kinematics: finite strain (total Lagrangian, plasticity in logarithmic strain) or small "
                             "strain (the paper's model)", &IndKinematicsRegistry, "finite", name, sizeof(name), NULL));
    PetscCall(IndRegistryGet(&IndKinematicsRegistry, PetscObjectComm((PetscObject)a->dm), "-formulation", name, &fn));
    a->kin = ((const IndKinematics *(*)(void))fn)();
  }
  PetscCall(IndOptionsEnum("-plastic_tangent", "Tangent of plastic points: consistent (quadratic Newton) or elastic",
    IndTangentTypes, (PetscEnum)a->tangent, (PetscEnum *)&a->tangent, NULL));
  PetscOptionsEnd();
  PetscCall(PetscMalloc7(nd, &a->ue, nd, &a->xe, nd, &a->fe, nd * nd, &a->Ke, a->layout->nb * 3, &a->G, 6 * nd, &a->DB,
                         6 * nd, &a->B));
  PetscCall(PetscCalloc1(a->layout->nb, &a->hoop));
  a->khoop = a->layout->axisymmetric ? a->hoop : NULL;
  *out = a;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The decomposition a residual keeps for the Jacobian lives from one to the other, while the memory around it comes
   and goes (the Krylov basis, the multigrid's set-up). In one block it needs a hole as large as itself, which a heap
   that gives nothing back (doc/performance.md) did not have on 2 ranks: it went on top, into memory not used before.
   In pieces of about 1 MiB it fills the holes the solve left: sphere_800k 3,243 -> 3,078 B/dof on 2 ranks. */
#define KEPT_PIECE_BYTES (1 << 20)

static PetscErrorCode AllocateKept(IndAssembly a, PetscInt nu)
{
  const IndDiscLayout *disc = a->layout;
  const PetscInt       per_cell = disc->nq * a->kin->nkeep;

  PetscFunctionBeginUser;
  a->kept_cells  = PetscMax(1, KEPT_PIECE_BYTES / (PetscInt)(per_cell * sizeof(PetscReal)));
  a->kept_pieces = (disc->ncell + a->kept_cells - 1) / a->kept_cells;
  PetscCall(PetscMalloc1(a->kept_pieces, &a->kept));
  for (PetscInt k = 0; k < a->kept_pieces; ++k)
    PetscCall(PetscMalloc1(PetscMin(a->kept_cells, disc->ncell - k * a->kept_cells) * per_cell, &a->kept[k]));
  PetscCall(PetscMalloc1(nu, &a->kept_u));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode FreeKept(IndAssembly a)
{
  PetscFunctionBeginUser;
  for (PetscInt k = 0; a->kept && k < a->kept_pieces; ++k) PetscCall(PetscFree(a->kept[k]));
  PetscCall(PetscFree(a->kept));
  PetscCall(PetscFree(a->kept_u));
  a->kept_pieces = a->kept_n = 0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* What the residual kept at point q of local cell i */
static inline PetscReal *KeptAt(IndAssembly a, PetscInt i, PetscInt q)
{
  return a->kept[i / a->kept_cells] + ((i % a->kept_cells) * a->layout->nq + q) * a->kin->nkeep;
}

PetscErrorCode IndAssemblyDestroy(IndAssembly *a)
{
  PetscFunctionBeginUser;
  if (!*a) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscFree7((*a)->ue, (*a)->xe, (*a)->fe, (*a)->Ke, (*a)->G, (*a)->DB, (*a)->B));
  PetscCall(PetscFree((*a)->hoop));
  PetscCall(PetscFree((*a)->xq));
  PetscCall(FreeKept(*a));
  PetscCall(IndMatInsertDestroy(&(*a)->insert));
  PetscCall(PetscFree(*a));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndAssemblySetBodyForce(IndAssembly a, IndVectorFn fn, void *ctx)
{
  PetscFunctionBeginUser;
  a->body_force = fn;
  a->body_ctx   = ctx;
  /* only the manufactured-solution tests have one: the points are not kept otherwise */
  PetscCall(PetscFree(a->xq));
  if (fn) PetscCall(IndDiscQuadraturePoints(a->disc, &a->xq));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The cell loop of the residual (Floc) or of the commit (Floc NULL): the constitutive update of every
   quadrature point from its committed state at the displacement Uloc; the residual only reads the
   history, the commit writes the update over it. */
static PetscErrorCode PointLoop(IndAssembly a, Vec Uloc, Vec Floc)
{
  const IndDiscLayout *disc = a->layout;
  const PetscInt     nb = disc->nb, nq = disc->nq, nkeep = Floc ? a->kin->nkeep : 0;
  const PetscInt     stride = a->history->stride, nval = a->history->nval;
  const PetscScalar *u;
  PetscScalar       *f = NULL, *hist;
  const PetscScalar *hist_read, *xn;
  PetscInt           nu;

  PetscFunctionBeginUser;
  a->nfailed = a->nplastic = 0;
  if (Floc) PetscCall(VecZeroEntries(Floc));
  PetscCall(VecGetLocalSize(Uloc, &nu));
  if (nkeep) {
    /* the Jacobian that follows a residual is nearly always at its displacement (Newton's accepted iterate) */
    if (!a->kept && !a->kept_u) PetscCall(AllocateKept(a, nu));
    a->kept_n = 0; /* until the loop is through */
  }
  PetscCall(VecGetArrayRead(Uloc, &u));
  PetscCall(VecGetArrayRead(a->Xloc, &xn));
  if (Floc) PetscCall(VecGetArray(Floc, &f));
  if (Floc) {
    PetscCall(VecGetArrayRead(a->history->committed, &hist_read));
    hist = (PetscScalar *)hist_read; /* read only: the residual writes nothing back */
  } else PetscCall(VecGetArray(a->history->committed, &hist));
  for (PetscInt i = 0; i < disc->ncell; ++i) {
    const IndMaterial *m   = &a->mats->mat[a->mats->cell_material[i]];
    const PetscInt    *node = disc->lnode + i * nb;

    GatherCell(a, i, u, xn);
    PetscCall(PetscArrayzero(a->fe, disc->ndof));
    for (PetscInt q = 0; q < nq; ++q) {
      const PetscReal  w   = IndDiscGradients(disc, i, a->xe, q, a->G, a->hoop);
      PetscReal       *h   = hist + i * stride + q * nval;
      /* P: first Piola-Kirchhoff stress; at small strain the stress */
      PetscReal        P[9], dp, old[IND_HISTORY_NVAL], upd[IND_HISTORY_NVAL];
      IndPlasticStatus status;

      IndHistoryUnpack(nval, h, old);
      if (!Floc) PetscCall(PetscArraycpy(upd, old, IND_HISTORY_NVAL)); /* an elastic material's update writes none */
      status = a->kin->stress(m, a->tangent, nb, a->G, a->khoop, a->ue, old, Floc ? NULL : upd, P, &dp,
                              nkeep ? KeptAt(a, i, q) : NULL);
      if (status != IND_PLASTIC_OK) {
        a->nfailed++;
        continue;
      }
      if (dp > 0) a->nplastic++;
      if (!Floc) {
        IndHistoryPack(nval, upd, h);
        continue;
      }
      for (PetscInt b = 0; b < nb; ++b) {
        const PetscReal gx = a->G[3 * b], gy = a->G[3 * b + 1], gz = a->G[3 * b + 2];
        for (int r = 0; r < 3; ++r) a->fe[3 * b + r] += w * (gx * P[3 * r] + gy * P[3 * r + 1] + gz * P[3 * r + 2]);
        if (a->khoop) a->fe[3 * b] += w * a->khoop[b] * P[4]; /* the hoop stress against u_r / r */
      }
      if (a->body_force) {
        PetscReal bf[3];
        PetscCall(a->body_force(a->xq + (i * nq + q) * 3, bf, a->body_ctx));
        for (PetscInt b = 0; b < nb; ++b)
          for (int c = 0; c < 3; ++c) a->fe[3 * b + c] -= w * disc->N[q * nb + b] * bf[c];
      }
    }
    if (Floc)
      for (PetscInt b = 0; b < nb; ++b)
        for (int c = 0; c < 3; ++c) f[3 * node[b] + c] += a->fe[3 * b + c];
  }
  if (Floc) PetscCall(VecRestoreArrayRead(a->history->committed, &hist_read));
  else PetscCall(VecRestoreArray(a->history->committed, &hist));
  PetscCall(VecRestoreArrayRead(a->Xloc, &xn));
  /* a failed point kept nothing, and its residual ends the Newton iteration anyway */
  if (nkeep && !a->nfailed) {
    PetscCall(PetscArraycpy(a->kept_u, u, nu));
    a->kept_n = nu;
  }
  PetscCall(VecRestoreArrayRead(Uloc, &u));
  if (Floc) PetscCall(VecRestoreArray(Floc, &f));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndAssemblyResidual(IndAssembly a, Vec Uloc, Vec Floc)
{
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(IndLog.residual, 0, 0, 0, 0));
  PetscCall(PointLoop(a, Uloc, Floc));
  PetscCall(PetscLogFlops(a->layout->ncell * a->layout->nq * (30.0 * a->layout->nb)));
  PetscCall(PetscLogEventEnd(IndLog.residual, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndAssemblyCommit(IndAssembly a, Vec Uloc)
{
  PetscFunctionBeginUser;
  PetscCall(PointLoop(a, Uloc, NULL));
  PetscCheck(!a->nfailed, PETSC_COMM_SELF, PETSC_ERR_PLIB,
    "The return map failed at %" PetscInt_FMT " points of an accepted state", a->nfailed);
  PetscFunctionReturn(PETSC_SUCCESS);
}

void IndCellMatrixCompleteLastNode(PetscInt nb, PetscReal *Ke)
{
  const PetscInt nd = 3 * nb, nr = nd - 3;

  for (PetscInt r = 1; r < nr; ++r)
    for (PetscInt c = 0; c < r; ++c) Ke[r * nd + c] = Ke[c * nd + r];
  for (PetscInt r = 0; r < nr; ++r) {
    PetscReal *Kr = Ke + r * nd;
    for (int j = 0; j < 3; ++j) {
      PetscReal s = 0;
      for (PetscInt b = 0; b < nb - 1; ++b) s += Kr[3 * b + j];
      Kr[nr + j] = -s;
    }
  }
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j) {
      PetscReal s = 0;
      for (PetscInt b = 0; b < nb - 1; ++b) s += Ke[(3 * b + i) * nd + nr + j];
      Ke[(nr + i) * nd + nr + j] = Ke[(nr + j) * nd + nr + i] = -s;
    }
  for (int i = 0; i < 3; ++i)
    for (PetscInt c = 0; c < nr; ++c) Ke[(nr + i) * nd + c] = Ke[c * nd + nr + i];
}

PetscErrorCode IndAssemblyJacobian(IndAssembly a, Vec Uloc, Mat J)
{
  const IndDiscLayout *disc = a->layout;
  const PetscInt     nb = disc->nb, nq = disc->nq, nd = disc->ndof, stride = a->history->stride;
  const PetscInt     nval = a->history->nval;
  /* the last node's rows and columns follow from the others' (an eighth of a hexahedron's), but on an axisymmetric
     section; with one point a cell the completion costs more than it saves (a small-strain P1 cell: 154 to 198 ns) */
  const PetscInt     nt = a->khoop || nq == 1 ? nb : nb - 1;
  const PetscScalar *u, *xn, *hold;
  IndMatInsert       ins = J == a->J ? a->insert : NULL; /* cached positions are the matrix's own */
  PetscInt          *g   = NULL;                           /* a cell's global dofs, for MatSetValues */
  PetscBool          kept = PETSC_FALSE;
  PetscInt           nu;

  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(IndLog.jacobian, 0, 0, 0, 0));
  if (ins) PetscCall(IndMatInsertBegin(ins, J));
  else {
    PetscCall(PetscMalloc1(nd, &g));
    /* a copy of the Jacobian (MatDuplicate keeps its options) sends rows of other ranks through the stash */
    PetscCall(MatSetOption(J, MAT_NO_OFF_PROC_ENTRIES, PETSC_FALSE));
    PetscCall(MatZeroEntries(J));
  }
  PetscCall(VecGetArrayRead(Uloc, &u));
  PetscCall(VecGetLocalSize(Uloc, &nu));
  if (a->kept_n && a->kept_n == nu) {
    PetscBool same;
    PetscCall(PetscArraycmp(u, a->kept_u, nu, &same)); /* byte by byte */
    if (same) kept = PETSC_TRUE, a->kept_uses++;
  }
  if (a->kin->nkeep && !kept) PetscCall(PetscInfo(a->dm, "No residual kept at this displacement: C decomposed\n"));
  PetscCall(VecGetArrayRead(a->Xloc, &xn));
  PetscCall(VecGetArrayRead(a->history->committed, &hold));
  for (PetscInt i = 0; i < disc->ncell; ++i) {
    const IndMaterial *m = &a->mats->mat[a->mats->cell_material[i]];

    /* its entries arrive while the cell's matrix is computed: a finite-strain one's arithmetic covers the loads
       (1-rank Jacobians of plastic steps 0.91 times as long); a small-strain P1 cell's is too short, and with the
       prefetch its Jacobian took 2 to 7% longer (doc/performance.md) */
    if (ins && a->kin->large) IndMatInsertPrefetch(ins, i);
    GatherCell(a, i, u, xn);
    PetscCall(PetscArrayzero(a->Ke, nd * nd));
    for (PetscInt q = 0; q < nq; ++q) {
      const PetscReal  w   = IndDiscGradients(disc, i, a->xe, q, a->G, a->hoop);
      PetscReal        old[IND_HISTORY_NVAL];
      IndHistoryUnpack(nval, hold + i * stride + q * nval, old);
      /* A failed point was already reported by the residual at this displacement, which stops the
         Newton iteration before any Jacobian; its NaN tangent cannot go unnoticed either. */
      (void)a->kin->stiffness(m, a->tangent, nb, nt, a->G, a->khoop, a->ue, old, w, a->B, a->DB, a->Ke,
                              kept ? KeptAt(a, i, q) : NULL);
    }
    if (nt < nb) IndCellMatrixCompleteLastNode(nb, a->Ke);
    else
      for (PetscInt r = 1; r < nd; ++r)
        for (PetscInt c = 0; c < r; ++c) a->Ke[r * nd + c] = a->Ke[c * nd + r];
    if (ins) PetscCall(IndMatInsertCell(ins, i, a->Ke));
    else {
      IndDiscCellDofs(disc, i, PETSC_TRUE, g);
      PetscCall(MatSetValues(J, nd, g, nd, g, a->Ke, ADD_VALUES));
    }
  }
  PetscCall(PetscFree(g));
  /* Nothing reads the decomposition again before the next residual remakes it: the Krylov solve that follows
     reuses its memory for its basis, which it gives back in turn (src/solvers/solver.c, SolveDone), and the pieces
     of the next decomposition go where the basis was (doc/performance.md). */
  PetscCall(FreeKept(a));
  PetscCall(VecRestoreArrayRead(a->history->committed, &hold));
  PetscCall(VecRestoreArrayRead(a->Xloc, &xn));
  PetscCall(VecRestoreArrayRead(Uloc, &u));
  if (ins) PetscCall(IndMatInsertEnd(ins, J));
  else {
    PetscCall(MatAssemblyBegin(J, MAT_FINAL_ASSEMBLY));
    PetscCall(MatAssemblyEnd(J, MAT_FINAL_ASSEMBLY));
  }
  PetscCall(PetscLogFlops(disc->ncell * nq * (6.0 * nd * nd + 36.0 * nd)));
  PetscCall(PetscLogEventEnd(IndLog.jacobian, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndAssemblyCreateMatrix(IndAssembly a, Mat *J)
{
  const IndDiscLayout *disc = a->layout;
  MPI_Comm     comm = PetscObjectComm((PetscObject)a->dm);
  PetscSection gs;
  PetscInt     nlocal;
  PetscBool    aij;

  PetscFunctionBeginUser;
  PetscCall(DMGetGlobalSection(a->dm, &gs));
  PetscCall(PetscSectionGetConstrainedStorageSize(gs, &nlocal));
  PetscCall(MatCreate(comm, J));
  PetscCall(MatSetType(*J, MATAIJ));
  PetscCall(MatSetSizes(*J, nlocal, nlocal, PETSC_DETERMINE, PETSC_DETERMINE));
  PetscCall(MatSetBlockSize(*J, 3));
  PetscCall(MatSetOptionsPrefix(*J, "jac_"));
  PetscCall(MatSetFromOptions(*J));
  PetscCall(PetscObjectBaseTypeCompareAny((PetscObject)*J, &aij, MATSEQAIJ, MATMPIAIJ, ""));
  if (aij) PetscCall(IndPatternFromCells(a->disc, *J));
  else {
    /* another type (-jac_mat_type): a dry run of the cell loop */
    Mat          P;
    PetscScalar *zeros;
    PetscInt    *g;
    PetscCall(MatCreate(comm, &P));
    PetscCall(MatSetType(P, MATPREALLOCATOR));
    PetscCall(MatSetSizes(P, nlocal, nlocal, PETSC_DETERMINE, PETSC_DETERMINE));
    PetscCall(MatSetBlockSize(P, 3));
    PetscCall(MatSetUp(P));
    PetscCall(PetscCalloc1(disc->ndof * disc->ndof, &zeros));
    PetscCall(PetscMalloc1(disc->ndof, &g));
    for (PetscInt i = 0; i < disc->ncell; ++i) {
      IndDiscCellDofs(disc, i, PETSC_TRUE, g);
      PetscCall(MatSetValues(P, disc->ndof, g, disc->ndof, g, zeros, INSERT_VALUES));
    }
    PetscCall(PetscFree(g));
    PetscCall(PetscFree(zeros));
    PetscCall(MatAssemblyBegin(P, MAT_FINAL_ASSEMBLY));
    PetscCall(MatAssemblyEnd(P, MAT_FINAL_ASSEMBLY));
    PetscCall(MatPreallocatorPreallocate(P, PETSC_TRUE, *J));
    PetscCall(MatDestroy(&P));
  }
  PetscCall(MatSetOption(*J, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_TRUE));
  /* Every assembly sends the same (subset of) off-process entries, and conditions and contact only
     touch owned rows: the communication pattern is built once. */
  PetscCall(MatSetOption(*J, MAT_SUBSET_OFF_PROC_ENTRIES, PETSC_TRUE));
  PetscCall(MatSetOption(*J, MAT_NO_OFF_PROC_ZERO_ROWS, PETSC_TRUE));
  {
    PetscBool cached = PETSC_TRUE, inodes = PETSC_FALSE, blocks = PETSC_TRUE;
    PetscOptionsBegin(comm, NULL, IND_TITLE "Jacobian assembly", "Assembly");
    PetscCall(IndOptionsBool("-jac_cached_insert", "Add element matrices at cached positions (false: MatSetValues)",
      cached, &cached, NULL));
    PetscCall(IndOptionsBool("-jac_inodes",
      "AIJ products by groups of rows sharing their columns (PETSc's inodes), Jacobian and multigrid levels", inodes,
      &inodes, NULL));
    PetscCall(IndOptionsBool("-jac_block_products",
      "Products by block rows: a node's three rows of the Jacobian together, one column index per 3 x 3 block "
      "(GAMG's coarse operators and interpolations by their 6 x 6 and 3 x 6 blocks)", blocks, &blocks, NULL));
    PetscOptionsEnd();
    /* PETSc's inode product reads a node's three rows side by side, in short runs the memory prefetch
       does not follow: on the machines measured (doc/performance.md) the plain row-by-row product was
       2.3 times faster, and the Krylov iterations are mostly products with this matrix. */
    if (aij) PetscCall(MatSetOption(*J, MAT_USE_INODES, inodes));
    a->inodes = inodes;
    a->blocks = (PetscBool)(aij && !inodes && blocks);
    if (a->blocks) PetscCall(IndBlockMultInstall(*J, &a->blocks));
    PetscCall(IndMatInsertDestroy(&a->insert));
    a->J = *J;
    if (cached) PetscCall(IndMatInsertCreate(a->disc, *J, &a->insert));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndAssemblyCellAverages(IndAssembly a, Vec Uloc, IndCellFields *out)
{
  const IndDiscLayout *disc = a->layout;
  const PetscInt     nq = disc->nq, stride = a->history->stride, nval = a->history->nval;
  const PetscScalar *u, *xn, *hist;

  PetscFunctionBeginUser;
  PetscCall(VecGetArrayRead(Uloc, &u));
  PetscCall(VecGetArrayRead(a->Xloc, &xn));
  PetscCall(VecGetArrayRead(a->history->committed, &hist));
  for (PetscInt i = 0; i < disc->ncell; ++i) {
    const IndMaterial *m   = &a->mats->mat[a->mats->cell_material[i]];
    PetscReal          vol = 0, vol0 = 0, savg[6] = {0}, eavg[6] = {0}, pavg = 0, xavg = 0, yavg = 0, cavg = 0;
    GatherCell(a, i, u, xn);
    for (PetscInt q = 0; q < nq; ++q) {
      PetscReal              h[IND_HISTORY_NVAL];
      const IndPlasticState *st = (const IndPlasticState *)h;
      const PetscReal  w0 = IndDiscGradients(disc, i, a->xe, q, a->G, a->hoop);
      PetscReal        eps[6], s[6], w = w0;
      IndHistoryUnpack(nval, hist + i * stride + q * nval, h);
      a->kin->fields(m, disc->nb, a->G, a->khoop, a->ue, h, s, eps, &w);
      /* stress and strain over the current volume (w: at finite strain w0 J); the material's own
         state (p, back stress, yielding) over the material, i.e. the reference volume */
      vol += w;
      vol0 += w0;
      for (int k = 0; k < 6; ++k) {
        savg[k] += w * s[k];
        eavg[k] += w * eps[k];
      }
      pavg += w0 * st->p;
      xavg += w0 * IndVonMises(st->x);
      yavg += h[IND_HISTORY_DP] > 0 ? w0 : 0.0;
      cavg -= w0 * (st->eps_p[0] + st->eps_p[1] + st->eps_p[2]);
    }
    for (int k = 0; k < 6; ++k) {
      out->stress[6 * i + k] = savg[k] / vol;
      out->strain[6 * i + k] = eavg[k] / vol;
    }
    out->plastic[i]     = pavg / vol0;
    out->back_stress[i] = xavg / vol0;
    out->yielding[i]    = yavg / vol0;
    if (out->compaction) out->compaction[i] = cavg / vol0;
  }
  PetscCall(VecRestoreArrayRead(a->history->committed, &hist));
  PetscCall(VecRestoreArrayRead(a->Xloc, &xn));
  PetscCall(VecRestoreArrayRead(Uloc, &u));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndAssemblyCountInverted(IndAssembly a, Vec Uloc, PetscInt *ncells, PetscReal *jmin)
{
  const IndDiscLayout *disc = a->layout;
  const PetscInt     nb = disc->nb, nq = disc->nq;
  const PetscScalar *u, *xn;

  PetscFunctionBeginUser;
  *ncells = 0;
  *jmin   = PETSC_MAX_REAL;
  PetscCall(VecGetArrayRead(Uloc, &u));
  PetscCall(VecGetArrayRead(a->Xloc, &xn));
  for (PetscInt i = 0; i < disc->ncell; ++i) {
    PetscBool inverted = PETSC_FALSE;
    GatherCell(a, i, u, xn);
    for (PetscInt q = 0; q < nq; ++q) {
      PetscReal H[9], F[9], J;
      (void)IndDiscGradients(disc, i, a->xe, q, a->G, a->hoop);
      IndDeformationGradient(nb, a->G, a->khoop, a->ue, H, F);
      J = IndDet3(F);
      *jmin = PetscMin(*jmin, J);
      if (!(J > 0)) inverted = PETSC_TRUE;
    }
    *ncells += inverted ? 1 : 0;
  }
  PetscCall(VecRestoreArrayRead(a->Xloc, &xn));
  PetscCall(VecRestoreArrayRead(Uloc, &u));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndAssemblyElasticJacobian(IndAssembly a, Vec Uloc, Mat K)
{
  const IndTangent tangent = a->tangent;

  PetscFunctionBeginUser;
  a->tangent = IND_TANGENT_ELASTIC;
  PetscCall(IndAssemblyJacobian(a, Uloc, K));
  a->tangent = tangent;
  PetscFunctionReturn(PETSC_SUCCESS);
}

IND_GETTER(PetscBool, IndAssemblyIsFiniteStrain, IndAssembly, o->kin->large)
IND_GETTER(PetscBool, IndAssemblyJacobianInodes, IndAssembly, o->inodes)
IND_GETTER(PetscBool, IndAssemblyJacobianBlockProducts, IndAssembly, o->blocks)
IND_GETTER(PetscBool, IndAssemblyIsAxisymmetric, IndAssembly, o->layout->axisymmetric)
IND_GETTER(IndDisc, IndAssemblyGetDisc, IndAssembly, o->disc)

IND_GETTER(PetscInt, IndAssemblyGetKeptUses, IndAssembly, o->kept_uses)

void IndAssemblyGetPointCounts(IndAssembly a, PetscInt *failed, PetscInt *plastic)
{
  if (failed) *failed = a->nfailed;
  if (plastic) *plastic = a->nplastic;
}
