#include "contact_impl.h"
#include "contact_node.h"

void IndContactNodeSolve(IndContact c, PetscInt i, const PetscScalar *u, const PetscReal Rv[3], IndContactNode *ns)
{
  const PetscReal *Uc = c->Uc + 3 * i;
  PetscReal        x[3], du[3], dut[2], rl[3], tau[3], slip;

  if (c->gap_current) {
    for (int d = 0; d < 3; ++d) x[d] = c->X[3 * i + d] + PetscRealPart(u[d]);
    IndIndenterGap(&c->indenter, x, &ns->gap, ns->n);
    if (c->fixed && c->fixed[i]) {
      /* A node on a symmetry plane pushes the indenter only within the plane: the mirror image of
         the indenter pushes back the other half. Where the nearest point is not unique (a node on
         the axis of a quarter model, inside a sharp tip) the distance's gradient can point out of
         the plane; its projection on the free directions is the symmetric one. */
      PetscReal nn = 0;
      for (int d = 0; d < 3; ++d) {
        if (c->fixed[i] & (1 << d)) ns->n[d] = 0;
        nn += ns->n[d] * ns->n[d];
      }
      if (nn > 0) for (int d = 0; d < 3; ++d) ns->n[d] /= PetscSqrtReal(nn);
      else IndIndenterGap(&c->indenter, x, &ns->gap, ns->n);
    }
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
  /* slip relative to the indenter, which moved down by the change of depth over the step and
     sideways by the change of its axis (a scratch) */
  for (int d = 0; d < 3; ++d) du[d] = PetscRealPart(u[d]) - Uc[d];
  du[0] -= c->indenter.axis[0] - c->axis_c[0];
  du[1] -= c->indenter.axis[1] - c->axis_c[1];
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

void IndContactNodeQD(const IndContactNode *ns, PetscReal QD[3][3])
{
  for (int a = 0; a < 3; ++a) {
    const PetscReal q[3] = {ns->n[a], ns->t1[a], ns->t2[a]};
    for (int b = 0; b < 3; ++b) QD[a][b] = q[0] * ns->D[b] + q[1] * ns->D[3 + b] + q[2] * ns->D[6 + b];
  }
}

/* rho Q D G: the derivative with the frame held fixed. */
static void FrozenFrameStiffness(PetscReal mu, PetscReal rho, const IndContactNode *ns, PetscReal B[9])
{
  PetscReal G[3][3], QD[3][3];

  for (int d = 0; d < 3; ++d) {
    G[0][d] = ns->n[d] + mu * (ns->s[0] * ns->t1[d] + ns->s[1] * ns->t2[d]);
    G[1][d] = ns->t1[d];
    G[2][d] = ns->t2[d];
  }
  IndContactNodeQD(ns, QD);
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) B[3 * a + b] = rho * (QD[a][0] * G[0][b] + QD[a][1] * G[1][b] + QD[a][2] * G[2][b]);
}

PetscBool IndContactNodeStiffness(IndContact c, PetscInt i, const PetscScalar *u, const PetscReal R[3], PetscReal B[9])
{
  const PetscReal rho = c->rho_scale * c->kdiag[i];
  PetscReal       h   = 0;
  IndContactNode  n0;

  for (int d = 0; d < 3; ++d) h = PetscMax(h, PetscAbsReal(c->X[3 * i + d] + PetscRealPart(u[d])));
  h = 1e-6 * (1 + h);
  IndContactNodeSolve(c, i, u, R, &n0);
  for (int b = 0; b < 3; ++b) {
    PetscScalar    up[3], um[3];
    IndContactNode np, nm;
    for (int d = 0; d < 3; ++d) up[d] = um[d] = u[d];
    up[b] += h;
    um[b] -= h;
    IndContactNodeSolve(c, i, up, R, &np);
    IndContactNodeSolve(c, i, um, R, &nm);
    for (int a = 0; a < 3; ++a) {
      const PetscReal fwd = (np.f[a] - n0.f[a]) / h, bwd = (n0.f[a] - nm.f[a]) / h;
      /* One-sided differences that disagree (at the scale of rho) straddle a kink: an edge or the apex
         of a sharp shape, or a change of status. There is no derivative to take; the frozen frame's
         is an element of the generalized one, and the central difference (the turning normal) would
         be 1/h large. */
      if (PetscAbsReal(fwd - bwd) > 1e-3 * rho) {
        FrozenFrameStiffness(c->mu, rho, &n0, B);
        return PETSC_FALSE;
      }
      B[3 * a + b] = -0.5 * (fwd + bwd);
    }
  }
  return PETSC_TRUE;
}
