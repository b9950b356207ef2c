#include "contact_impl.h"
#include "contact_node.h"

/* Semi-smooth Newton for the contact (doc/theory.md section 2): the reaction of a contact node is not a
   separate unknown but the force the body needs there, lambda = r_i(u), the node's rows of the
   residual without contact; its three equilibrium rows are replaced by the bi-potential fixed
   point written as a complementarity function,

     C_i(u) = lambda - Q proj(Q^T lambda - rho (g + mu |du_t|, du_t)),

   whose generalized derivative (I - Q D Q^T) dlambda/du + rho Q D G is exact up to the rotation
   of the frame. An open node keeps its equilibrium rows (lambda = 0), a sticking node becomes a
   Dirichlet-like row on its gap and slip, a sliding node a mix: a primal-dual active set whose
   set follows from the projection, so rho only scales the rows and sets which nodes are tried
   active; the solution does not depend on it. Components held by a boundary condition carry the
   support's reaction, not the indenter's, and are left out of lambda. */

static PetscErrorCode Residual(IndContact c, Vec U, Vec F)
{
  const PetscScalar *u;
  PetscScalar       *f;

  PetscFunctionBeginUser;
  PetscCall(VecGetArrayRead(U, &u));
  PetscCall(VecGetArray(F, &f));
  for (PetscInt i = 0; i < c->n; ++i) {
    const PetscInt k = c->row[i];
    PetscReal     *L = c->L + 3 * i;
    IndContactNode ns;
    for (int d = 0; d < 3; ++d) {
      L[d]                = c->fixed[i] & (1 << d) ? 0.0 : PetscRealPart(f[k + d]);
      c->Lu[3 * i + d]    = PetscRealPart(u[k + d]);
    }
    IndContactNodeSolve(c, i, u + k, L, &ns);
    for (int d = 0; d < 3; ++d)
      if (!(c->fixed[i] & (1 << d))) f[k + d] = L[d] - ns.f[d];
  }
  PetscCall(VecRestoreArray(F, &f));
  PetscCall(VecRestoreArrayRead(U, &u));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Whether this rank's multipliers were computed at the displacement u (the owned part of a vector). */
static PetscBool LocalCurrent(IndContact c, const PetscScalar *u)
{
  for (PetscInt i = 0; i < c->n; ++i)
    for (int d = 0; d < 3; ++d)
      if (PetscRealPart(u[c->row[i] + d]) != c->Lu[3 * i + d]) return PETSC_FALSE;
  return PETSC_TRUE;
}

PetscErrorCode IndContactMultipliersCurrent(IndContact c, Vec U, PetscBool *current)
{
  const PetscScalar *u;
  PetscMPIInt        same;

  PetscFunctionBeginUser;
  *current = PETSC_TRUE;
  if (!c->ops.residual_multipliers) PetscFunctionReturn(PETSC_SUCCESS); /* frozen between solves */
  PetscCall(VecGetArrayRead(U, &u));
  same = LocalCurrent(c, u) ? 1 : 0;
  PetscCall(VecRestoreArrayRead(U, &u));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &same, 1, MPI_INT, MPI_MIN, c->comm));
  *current = same ? PETSC_TRUE : PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

void IndContactNewtonRows(const PetscReal P[9], const PetscReal B[9], PetscInt mask, PetscInt ncols,
                          const PetscInt diag[3], const PetscReal *K, PetscReal *out)
{
  for (int a = 0; a < 3; ++a)
    for (PetscInt j = 0; j < ncols; ++j) {
      PetscReal v = 0;
      for (int b = 0; b < 3; ++b)
        if (!(mask & (1 << b))) v += ((a == b ? 1.0 : 0.0) - P[3 * a + b]) * K[b * ncols + j];
      out[a * ncols + j] = v;
    }
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) out[a * ncols + diag[b]] += B[3 * a + b];
}

/* P = Q D Q^T: the derivative of the contact force with respect to the multiplier, global axes. */
static void Projector(const IndContactNode *ns, PetscReal P[9])
{
  PetscReal QD[3][3];

  IndContactNodeQD(ns, QD);
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      const PetscReal q[3] = {ns->n[b], ns->t1[b], ns->t2[b]};
      P[3 * a + b] = QD[a][0] * q[0] + QD[a][1] * q[1] + QD[a][2] * q[2];
    }
}

PetscErrorCode IndContactModelLoad(IndContact c, PetscReal *load)
{
  PetscReal sum = 0;

  PetscFunctionBeginUser;
  PetscCheck(c->ops.residual_multipliers, c->comm, PETSC_ERR_SUP,
             "The load of the residual needs -contact_uzawa newton");
  for (PetscInt i = 0; i < c->n; ++i)
    if (!(c->fixed[i] & 4)) sum -= c->L[3 * i + 2];
  PetscCallMPI(MPI_Allreduce(&sum, load, 1, MPIU_REAL, MPIU_SUM, c->comm));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndContactLoadRows(IndContact c, Vec e)
{
  PetscScalar *v;

  PetscFunctionBeginUser;
  PetscCall(VecZeroEntries(e));
  PetscCall(VecGetArray(e, &v));
  for (PetscInt i = 0; i < c->n; ++i)
    if (!(c->fixed[i] & 4)) v[c->row[i] + 2] = 1.0;
  PetscCall(VecRestoreArray(e, &v));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Jacobian(IndContact c, Vec U, Mat J, Vec Fd)
{
  const PetscScalar *u;
  PetscScalar       *fd = NULL;
  PetscInt           nact = 0, cap = 0, used = 0;
  PetscInt          *node, *start, *len, *cols = NULL;
  PetscReal         *vals = NULL, K[3 * 1024];

  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(IndLog.contact, 0, 0, 0, 0));
  PetscCall(PetscMalloc3(c->n, &node, c->n, &start, c->n, &len));
  PetscCall(VecGetArrayRead(U, &u));
  if (Fd) PetscCall(VecGetArray(Fd, &fd));
  PetscCheck(LocalCurrent(c, u), PETSC_COMM_SELF, PETSC_ERR_PLIB,
             "Contact Jacobian at a displacement other than the last residual's (see IndContactNewtonCurrent)");
  /* All rows are read before any is written: the matrix must stay assembled for MatGetRow. */
  for (PetscInt i = 0; i < c->n; ++i) {
    IndContactNode     ns;
    PetscReal          P[9], B[9];
    PetscInt           ncols = 0, nc, diag[3] = {-1, -1, -1};
    const PetscInt    *rc;
    const PetscScalar *rv;

    IndContactNodeSolve(c, i, u + c->row[i], c->L + 3 * i, &ns);
    if (ns.status == IND_CONTACT_OPEN) continue; /* D = 0: the equilibrium rows stand */
    Projector(&ns, P);
    (void)IndContactNodeStiffness(c, i, u + c->row[i], c->L + 3 * i, B);
    if (fd) /* F_i = L - f(u + depth e_z): dF_i/d depth = -df/du_z = B e_z */
      for (int a = 0; a < 3; ++a)
        if (!(c->fixed[i] & (1 << a))) fd[c->row[i] + a] = B[3 * a + 2];
    /* The three rows of a node share their columns (every component of a node couples to every
       component of its neighbours). */
    for (int a = 0; a < 3; ++a) {
      PetscCall(MatGetRow(J, c->grow[i] + a, &nc, &rc, &rv));
      if (a == 0) {
        ncols = nc;
        PetscCheck(ncols <= 1024, PETSC_COMM_SELF, PETSC_ERR_SUP,
                   "Contact node %" PetscInt_FMT " couples to %" PetscInt_FMT " dofs, more than 1024", c->grow[i],
                   ncols);
        if (used + ncols > cap) {
          PetscInt  *nc2;
          PetscReal *nv2;
          cap = PetscMax(2 * cap, used + ncols + 1024);
          PetscCall(PetscMalloc2(cap, &nc2, 3 * cap, &nv2));
          PetscCall(PetscArraycpy(nc2, cols, used));
          PetscCall(PetscArraycpy(nv2, vals, 3 * used));
          PetscCall(PetscFree2(cols, vals));
          cols = nc2;
          vals = nv2;
        }
        PetscCall(PetscArraycpy(cols + used, rc, ncols));
        for (PetscInt j = 0; j < ncols; ++j)
          for (int b = 0; b < 3; ++b)
            if (rc[j] == c->grow[i] + b) diag[b] = j;
      }
      PetscCheck(nc == ncols, PETSC_COMM_SELF, PETSC_ERR_PLIB,
                 "Rows of contact node %" PetscInt_FMT " differ in their columns", c->grow[i]);
      for (PetscInt j = 0; j < ncols; ++j) {
        PetscCheck(rc[j] == cols[used + j], PETSC_COMM_SELF, PETSC_ERR_PLIB,
                   "Rows of contact node %" PetscInt_FMT " differ in their columns", c->grow[i]);
        K[a * ncols + j] = PetscRealPart(rv[j]);
      }
      PetscCall(MatRestoreRow(J, c->grow[i] + a, &nc, &rc, &rv));
    }
    PetscCheck(diag[0] >= 0 && diag[1] >= 0 && diag[2] >= 0, PETSC_COMM_SELF, PETSC_ERR_PLIB,
               "Contact node %" PetscInt_FMT " has no diagonal block", c->grow[i]);
    IndContactNewtonRows(P, B, c->fixed[i], ncols, diag, K, vals + 3 * used);
    node[nact]  = i;
    start[nact] = used;
    len[nact++] = ncols;
    used += ncols;
  }
  PetscCall(VecRestoreArrayRead(U, &u));
  if (Fd) PetscCall(VecRestoreArray(Fd, &fd));
  for (PetscInt k = 0; k < nact; ++k) {
    const PetscInt rows[3] = {c->grow[node[k]], c->grow[node[k]] + 1, c->grow[node[k]] + 2};
    PetscCall(MatSetValues(J, 3, rows, len[k], cols + start[k], vals + 3 * start[k], INSERT_VALUES));
  }
  PetscCall(PetscFree2(cols, vals));
  PetscCall(PetscFree3(node, start, len));
  /* On every rank, even one with no node changed: assembly is collective. Only owned rows changed. */
  PetscCall(MatAssemblyBegin(J, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(J, MAT_FINAL_ASSEMBLY));
  PetscCall(PetscLogEventEnd(IndLog.contact, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Newton met its tolerances without a step: another outer iteration would change nothing. */
static PetscErrorCode AfterOuter(IndContact c, PetscInt its, const IndContactSummary *r, PetscBool *stuck,
                                 char why[], size_t len)
{
  PetscFunctionBeginUser;
  *stuck = its == 0 ? PETSC_TRUE : PETSC_FALSE;
  if (*stuck)
    PetscCall(PetscSNPrintf(why, len,
      "contact: reaction change %.2e (-contact_uzawa_rtol %.1e), penetration %.2e nm (limit %.2e) at Newton's "
      "tolerances: tighten -snes_rtol or -snes_atol", (double)r->change, (double)c->rtol, (double)r->penetration,
      (double)c->pen_atol));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndContactCreate_Newton(IndContact c)
{
  PetscFunctionBeginUser;
  c->ops.residual             = Residual;
  c->ops.jacobian             = Jacobian;
  c->ops.after_outer          = AfterOuter;
  c->ops.residual_multipliers = PETSC_TRUE;
  /* rho sets which nodes are tried active and scales their rows, not the solution. Half the stiffness diagonal:
     with friction on a yielding film the full diagonal cost 2 to 9% more Newton iterations, a tenth of it left
     the rows too weak for the multigrid (doc/performance.md, "rho of the contact rows"). */
  c->rho_scale = 0.5;
  c->max_outer = 20;
  PetscFunctionReturn(PETSC_SUCCESS);
}
