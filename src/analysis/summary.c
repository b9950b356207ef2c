#include "summary_impl.h"
#include <stdio.h>
#include "ind_summary.h"
#include "ind_rundir.h"
#include "ind_version.h"
#include "ind_options.h"

PetscErrorCode IndOPParamsSetFromOptions(MPI_Comm comm, IndIndenterType shape, IndOPParams *p)
{
  PetscFunctionBeginUser;
  IndOPParamsDefault(p);
  IndIndenterOPConstants(shape, &p->epsilon, &p->beta);
  PetscOptionsBegin(comm, NULL, IND_TITLE "Oliver-Pharr analysis (-op_*)", "OP");
  PetscCall(IndOptionsReal("-op_fraction", "Fit the unloading points with P >= (1 - fraction) P_max", "", NULL,
    p->fraction,
                           &p->fraction, NULL));
  PetscCall(IndOptionsReal("-op_epsilon",
    "Contact-depth factor: h_c = h_max - epsilon P_max / S (default by the indenter: cone 0.72, flat 1, others 0.75)",
    "", NULL, p->epsilon, &p->epsilon, NULL));
  PetscCall(IndOptionsReal("-op_beta",
    "Shape factor: E_r = sqrt(pi) / (2 beta) S / sqrt(A) (default by the indenter: berkovich and cube_corner 1.034, "
    "vickers 1.012, shapes of revolution 1)", "", NULL, p->beta, &p->beta, NULL));
  PetscCall(IndOptionsReal("-op_indenter_modulus", "Indenter's Young's modulus (0 rigid, diamond 1141)", "GPa", NULL,
                           p->E_indenter, &p->E_indenter, NULL));
  PetscCall(IndOptionsReal("-op_indenter_poisson", "Indenter's Poisson's ratio", "", NULL, p->nu_indenter,
    &p->nu_indenter,
                           NULL));
  PetscCall(IndOptionsReal("-op_poisson", "Sample's Poisson's ratio, for its modulus from E_r", "", NULL, p->nu_sample,
                           &p->nu_sample, NULL));
  PetscOptionsEnd();
  PetscCheck(p->fraction > 0 && p->fraction <= 1, comm, PETSC_ERR_ARG_OUTOFRANGE,
    "-op_fraction must lie in (0, 1], got %g", (double)p->fraction);
  PetscCheck(p->epsilon > 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-op_epsilon must be > 0, got %g", (double)p->epsilon);
  PetscCheck(p->beta > 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-op_beta must be > 0, got %g", (double)p->beta);
  PetscCheck(p->E_indenter >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE,
    "-op_indenter_modulus must be >= 0 (GPa; 0 rigid), got %g", (double)p->E_indenter);
  PetscCheck(p->nu_indenter > -1 && p->nu_indenter < 0.5, comm, PETSC_ERR_ARG_OUTOFRANGE,
    "-op_indenter_poisson must lie in (-1, 0.5), got %g", (double)p->nu_indenter);
  PetscCheck(p->nu_sample > -1 && p->nu_sample < 0.5, comm, PETSC_ERR_ARG_OUTOFRANGE,
    "-op_poisson must lie in (-1, 0.5), got %g", (double)p->nu_sample);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndSummaryCreate(MPI_Comm comm, IndIndenterType shape, IndSummary *out)
{
  IndSummary s;

  PetscFunctionBeginUser;
  PetscCall(PetscCalloc1(1, &s));
  s->comm = comm;
  s->cap  = 256;
  PetscCall(PetscMalloc1(s->cap, &s->pts));
  PetscCall(IndOPParamsSetFromOptions(comm, shape, &s->op));
  s->min_contact_nodes = 50;
  PetscOptionsBegin(comm, NULL, IND_TITLE "Oliver-Pharr analysis of a run", "OP");
  PetscCall(IndOptionsInt("-op_min_contact_nodes",
                          "Nodes in contact at P_max (whole indent) below which H and E_r are withheld", NULL,
                          s->min_contact_nodes, &s->min_contact_nodes, NULL));
  PetscOptionsEnd();
  PetscCheck(s->min_contact_nodes >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-op_min_contact_nodes must be >= 0, got %" PetscInt_FMT, s->min_contact_nodes);
  *out = s;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndSummaryDestroy(IndSummary *s)
{
  PetscFunctionBeginUser;
  if (!*s) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscFree((*s)->pts));
  PetscCall(PetscFree(*s));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndSummaryAddPoint(IndSummary s, const IndCurvePoint *p)
{
  PetscFunctionBeginUser;
  if (s->n == s->cap) {
    IndCurvePoint *more;
    PetscCall(PetscMalloc1(2 * s->cap, &more));
    PetscCall(PetscArraycpy(more, s->pts, s->n));
    PetscCall(PetscFree(s->pts));
    s->pts = more;
    s->cap *= 2;
  }
  s->pts[s->n++] = *p;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndSummaryGetPoints(IndSummary s, PetscInt *n, const IndCurvePoint **pts)
{
  PetscFunctionBeginUser;
  *n   = s->n;
  *pts = s->pts;
  PetscFunctionReturn(PETSC_SUCCESS);
}

IND_GETTER(const IndOPParams *, IndSummaryGetOPParams, IndSummary, &o->op)
IND_GETTER(PetscInt, IndSummaryGetMinContactNodes, IndSummary, o->min_contact_nodes)

#define CURVE_WIDTH 16 /* reals per IndCurvePoint in the state */

static void PackPoint(const IndCurvePoint *p, PetscReal *r)
{
  const PetscReal v[CURVE_WIDTH] = {(PetscReal)p->step,    p->t,        p->depth,          p->load,
                                    (PetscReal)p->contact, (PetscReal)p->stick, (PetscReal)p->slip,
                                    (PetscReal)p->newton,  (PetscReal)p->outer, (PetscReal)p->linear,
                                    (PetscReal)p->cutbacks, p->penetration, p->area, p->pileup, p->deepest,
                                    (PetscReal)p->seconds};
  for (int k = 0; k < CURVE_WIDTH; ++k) r[k] = v[k];
}

static void UnpackPoint(const PetscReal *r, IndCurvePoint *p)
{
  p->step        = (PetscInt)r[0];
  p->t           = r[1];
  p->depth       = r[2];
  p->load        = r[3];
  p->contact     = (PetscInt)r[4];
  p->stick       = (PetscInt)r[5];
  p->slip        = (PetscInt)r[6];
  p->newton      = (PetscInt)r[7];
  p->outer       = (PetscInt)r[8];
  p->linear      = (PetscInt)r[9];
  p->cutbacks    = (PetscInt)r[10];
  p->penetration = r[11];
  p->area        = r[12];
  p->pileup      = r[13];
  p->deepest     = r[14];
  p->seconds     = r[15];
}

PetscErrorCode IndSummaryState(void *obj, IndStateFile f)
{
  IndSummary s = (IndSummary)obj;
  PetscReal *curve = NULL;
  PetscInt   n     = CURVE_WIDTH * s->n;

  PetscFunctionBeginUser;
  if (!IndStateReading(f)) {
    PetscCall(PetscMalloc1(n + 1, &curve));
    for (PetscInt i = 0; i < s->n; ++i) PackPoint(&s->pts[i], curve + CURVE_WIDTH * i);
  }
  PetscCall(IndStateRealArray(f, "curve", &n, &curve));
  if (IndStateReading(f)) {
    PetscCheck(n % CURVE_WIDTH == 0, s->comm, PETSC_ERR_FILE_UNEXPECTED, "The state's curve holds %" PetscInt_FMT
               " values, not %d per point", n, CURVE_WIDTH);
    s->n = 0;
    for (PetscInt i = 0; i < n / CURVE_WIDTH; ++i) {
      IndCurvePoint p;
      UnpackPoint(curve + CURVE_WIDTH * i, &p);
      PetscCall(IndSummaryAddPoint(s, &p));
    }
  }
  PetscCall(PetscFree(curve));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscReal Area(PetscReal hc, void *ctx)
{
  return IndIndenterArea((const IndIndenter *)ctx, hc);
}

/* The summary's numbers, in the order of its text and JSON. */
typedef struct {
  const char *key, *label, *unit;
  PetscReal   value;
  PetscBool   integer;
} Entry;

static void Put(Entry *e, PetscInt *n, const char *key, const char *label, const char *unit, PetscReal v,
  PetscBool integer)
{
  e[*n].key = key, e[*n].label = label, e[*n].unit = unit, e[*n].value = v, e[*n].integer = integer;
  (*n)++;
}

/* A JSON string literal of text (quotes, backslashes and control characters escaped). */
static void JsonString(FILE *fp, const char *text)
{
  fputc('"', fp);
  for (const char *c = text; *c; ++c) {
    if (*c == '"' || *c == '\\') fprintf(fp, "\\%c", *c);
    else if ((unsigned char)*c < 0x20) fprintf(fp, "\\u%04x", (unsigned)*c);
    else fputc(*c, fp);
  }
  fputc('"', fp);
}

static PetscErrorCode WriteProvenance(FILE *fp, const IndRunInfo *info)
{
  char       *opts, petsc[256];
  PetscMPIInt size;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(PETSC_COMM_WORLD, &size));
  PetscCall(PetscGetVersion(petsc, sizeof(petsc)));
  PetscCall(PetscOptionsGetAll(NULL, &opts));
  fprintf(fp, "  \"status\": \"finished\",\n  \"indent_version\": ");
  JsonString(fp, INDENT_VERSION);
  fprintf(fp, ",\n  \"git_commit\": ");
  JsonString(fp, INDENT_GIT_COMMIT);
  fprintf(fp, ",\n  \"petsc_version\": ");
  JsonString(fp, petsc);
  fprintf(fp, ",\n  \"ranks\": %d,\n  \"start_time\": ", size);
  JsonString(fp, info->start_time);
  fprintf(fp, ",\n  \"warnings\": [");
  for (PetscInt k = 0; k < info->warnings->n; ++k) {
    fprintf(fp, "%s", k ? ", " : "");
    JsonString(fp, info->warnings->text[k]);
  }
  fprintf(fp, "]");
  fprintf(fp, ",\n  \"wall_seconds\": %.3f,\n  \"restarted\": %s,\n  \"options\": ", (double)info->wall,
    info->restarted ? "true" : "false");
  JsonString(fp, opts);
  fprintf(fp, ",\n");
  PetscCall(PetscFree(opts));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndSummaryFinish(IndSummary s, const IndIndenter *ind, const IndRunInfo *info, const char dir[],
  PetscBool write, PetscBool print)
{
  PetscReal     *h, *P, Hs = 0, Ers = 0, Es = 0;
  IndOPResult    r;
  const IndCurvePoint *pmax, *last;
  PetscInt       imax = 0, ne = 0, newton = 0, outer = 0, linear = 0, code;
  Entry          e[40];
  char           why[512] = "", why_E[256] = "";
  PetscMPIInt    rank;

  PetscFunctionBeginUser;
  if (!s->n) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscMalloc2(s->n, &h, s->n, &P));
  for (PetscInt i = 0; i < s->n; ++i) {
    h[i] = s->pts[i].depth;
    P[i] = s->pts[i].load;
    if (P[i] > P[imax]) imax = i;
    newton += s->pts[i].newton;
    outer += s->pts[i].outer;
    linear += s->pts[i].linear;
  }
  pmax = &s->pts[imax];
  last = &s->pts[s->n - 1];
  /* Oliver-Pharr's elastic unloading is that of a static indent from the largest load: after a slide
     the contact is lopsided and the largest load may lie anywhere on the path. */
  code = info->slid ? 3 : IndOliverPharr(h, P, s->n, &s->op, Area, (void *)ind, &r);
  if (code == 3)
    PetscCall(PetscSNPrintf(why, sizeof(why), "the indenter slid (-scratch_length); it applies to a static indent"));
  else if (code == 1) PetscCall(PetscSNPrintf(why, sizeof(why),
    "fewer than 3 unloading points with P >= %g P_max: raise -load_unload_steps", (double)(1 - s->op.fraction)));
  else if (code == 4) PetscCall(PetscSNPrintf(why, sizeof(why),
    "H and E_r withheld: the contact depth h_c = h_max - epsilon P_max / S = %.6g nm (h_max %.6g nm, -op_epsilon "
    "%g, S %.6g uN/nm) is at or below the tip, where the indenter has no area; check -op_epsilon for this indenter",
    (double)r.h_c, (double)r.h_max, (double)s->op.epsilon, (double)r.S));
  else if (code) PetscCall(PetscSNPrintf(why, sizeof(why), "the unloading branch is not a power law"));
  else IndOPFromArea(&s->op, &r, pmax->area, &Hs, &Ers, &Es);
  if (!code && info->contact) {
    /* A contact of a few nodes leaves the unloading a staircase of nodes letting go: its fit is noise. */
    IndContactCheckResolved(info->contact, pmax->contact, s->min_contact_nodes, why, sizeof(why));
    if (why[0]) code = 4;
  }
  if (!code && info->contact) { /* resolved: does A(h_c) fit on the modelled surface? Else H and E_r are not a
                                    half-space's, nor the block's */
    PetscCall(IndContactCheckArea(info->contact, r.A, why, sizeof(why)));
    if (why[0]) code = 4;
  }
  PetscCall(PetscFree2(h, P));

  Put(e, &ne, "P_max_uN", "largest load P_max", "uN", pmax->load, PETSC_FALSE);
  Put(e, &ne, "h_max_nm", "depth at P_max, h_max", "nm", pmax->depth, PETSC_FALSE);
  Put(e, &ne, "final_depth_nm", "indenter depth at the end", "nm", last->depth, PETSC_FALSE);
  Put(e, &ne, "final_load_uN", "load at the end", "uN", last->load, PETSC_FALSE);
  Put(e, &ne, "residual_depth_nm", "residual depth (deepest point of the imprint at the end)", "nm", last->deepest,
    PETSC_FALSE);
  Put(e, &ne, "pileup_final_nm", "largest pile-up at the end", "nm", last->pileup, PETSC_FALSE);
  Put(e, &ne, "pileup_at_P_max_nm", "largest pile-up at P_max", "nm", pmax->pileup, PETSC_FALSE);
  Put(e, &ne, "true_area_nm2", "true (projected) contact area at P_max", "nm^2", pmax->area, PETSC_FALSE);
  Put(e, &ne, "mean_pressure_GPa", "P_max / true area (GPa)", "GPa",
    pmax->area > 0 ? 1e3 * pmax->load / pmax->area : 0, PETSC_FALSE);
  if (!code) {
    Put(e, &ne, "op_points", "Oliver-Pharr: unloading points fitted", "", (PetscReal)r.npoints, PETSC_TRUE);
    Put(e, &ne, "op_alpha", "fit P = alpha (h - h_f)^m: alpha", "uN/nm^m", r.alpha, PETSC_FALSE);
    Put(e, &ne, "h_f_nm", "fit: h_f (residual depth of the fit)", "nm", r.h_f, PETSC_FALSE);
    Put(e, &ne, "op_m", "fit: m", "", r.m, PETSC_FALSE);
    Put(e, &ne, "op_rms_uN", "fit: rms misfit", "uN", r.rms, PETSC_FALSE);
    Put(e, &ne, "S_uN_per_nm", "contact stiffness S", "uN/nm", r.S, PETSC_FALSE);
    Put(e, &ne, "h_c_nm", "contact depth h_c", "nm", r.h_c, PETSC_FALSE);
    Put(e, &ne, "A_nm2", "projected area A(h_c)", "nm^2", r.A, PETSC_FALSE);
    Put(e, &ne, "H_GPa", "hardness H", "GPa", r.H, PETSC_FALSE);
    Put(e, &ne, "E_r_GPa", "reduced modulus E_r", "GPa", r.E_r, PETSC_FALSE);
    Put(e, &ne, "E_GPa", "sample modulus E (from E_r, -op_poisson)", "GPa", r.E, PETSC_FALSE);
    Put(e, &ne, "area_ratio", "true area / A(h_c) (> 1 pile-up, < 1 sink-in)", "", r.A > 0 ? pmax->area / r.A : 0,
      PETSC_FALSE);
    Put(e, &ne, "H_true_GPa", "hardness from the true area", "GPa", Hs, PETSC_FALSE);
    Put(e, &ne, "E_r_true_GPa", "reduced modulus from the true area", "GPa", Ers, PETSC_FALSE);
  }
  if (info->contact) {
    /* the load-step error grows with how far the contact's edge moves in one step (doc/load-steps.md) */
    PetscReal adv = 0, d0 = 0;
    for (PetscInt i = 0; i < s->n && s->pts[i].t <= 1.0 + 1e-12; ++i) {
      adv = PetscMax(adv, IndContactEdgeAdvance(info->contact, d0, s->pts[i].depth));
      d0  = s->pts[i].depth;
    }
    Put(e, &ne, "edge_advance_max", "largest advance of the contact's edge in a loading step", "node spacings", adv,
      PETSC_FALSE);
  }
  Put(e, &ne, "steps", "accepted steps", "", (PetscReal)s->n, PETSC_TRUE);
  Put(e, &ne, "cutbacks", "cut-back attempts", "", (PetscReal)last->cutbacks, PETSC_TRUE);
  Put(e, &ne, "newton", "Newton iterations", "", (PetscReal)newton, PETSC_TRUE);
  Put(e, &ne, "uzawa", "outer (Uzawa) iterations", "", (PetscReal)outer, PETSC_TRUE);
  Put(e, &ne, "linear", "linear iterations", "", (PetscReal)linear, PETSC_TRUE);
  /* the counts above are the accepted attempts'; what the cut-back ones cost is work the run did too */
  Put(e, &ne, "newton_rejected", "Newton iterations of the attempts cut back", "", (PetscReal)info->rejected_newton,
    PETSC_TRUE);
  Put(e, &ne, "linear_rejected", "linear iterations of the attempts cut back", "", (PetscReal)info->rejected_linear,
    PETSC_TRUE);
  Put(e, &ne, "wall_time_s", "wall time of the run", "s", (PetscReal)info->wall, PETSC_FALSE);

  if (!code && PetscIsInfOrNanReal(r.E))
    PetscCall(PetscSNPrintf(why_E, sizeof(why_E),
      "sample modulus E withheld: E_r %.6g GPa is stiffer than the indenter allows (-op_indenter_modulus %g GPa, "
      "-op_indenter_poisson %g: 1 / E_r must exceed (1 - nu_i^2) / E_i)", (double)r.E_r, (double)s->op.E_indenter,
      (double)s->op.nu_indenter));
  if (print) {
    PetscCall(PetscPrintf(s->comm, "summary (%s indenter%s):\n", IndIndenterTypes[ind->type],
      write ? "; also in summary.txt and summary.json" : ""));
    for (PetscInt k = 0; k < ne; ++k) {
      if (e[k].integer) PetscCall(PetscPrintf(s->comm, "  %-58s %12.0f\n", e[k].label, (double)e[k].value));
      else if (PetscIsInfOrNanReal(e[k].value))
        PetscCall(PetscPrintf(s->comm, "  %-58s %12s\n", e[k].label, "withheld"));
      else PetscCall(PetscPrintf(s->comm, "  %-58s %12.6g %s\n", e[k].label, (double)e[k].value, e[k].unit));
    }
    if (code) PetscCall(PetscPrintf(s->comm, "  no Oliver-Pharr analysis: %s\n", why));
    if (why_E[0]) PetscCall(PetscPrintf(s->comm, "  %s\n", why_E));
  } else if (code == 4) PetscCall(PetscPrintf(s->comm, "indent: warning: %s\n", why));

  PetscCallMPI(MPI_Comm_rank(s->comm, &rank));
  if (write && !rank) {
    char  path[PETSC_MAX_PATH_LEN], tmp[PETSC_MAX_PATH_LEN];
    FILE *fp;
    PetscCall(PetscSNPrintf(path, sizeof(path), "%s/summary.txt", dir));
    PetscCall(PetscSNPrintf(tmp, sizeof(tmp), "%s.tmp", path));
    fp = fopen(tmp, "w");
    PetscCheck(fp, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "Cannot write '%s' (-output_dir)", tmp);
    for (PetscInt k = 0; k < ne; ++k) {
      if (PetscIsInfOrNanReal(e[k].value)) fprintf(fp, "%-58s withheld\n", e[k].label);
      else fprintf(fp, "%-58s %.10g %s\n", e[k].label, (double)e[k].value, e[k].unit);
    }
    if (code) fprintf(fp, "no Oliver-Pharr analysis: %s\n", why);
    if (why_E[0]) fprintf(fp, "%s\n", why_E);
    for (PetscInt k = 0; k < info->warnings->n; ++k) fprintf(fp, "warning: %s\n", info->warnings->text[k]);
    PetscCheck(fclose(fp) == 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "Error writing '%s'", tmp);
    PetscCall(IndRenameInto(tmp, path));
    PetscCall(PetscSNPrintf(path, sizeof(path), "%s/summary.json", dir));
    PetscCall(PetscSNPrintf(tmp, sizeof(tmp), "%s.tmp", path));
    fp = fopen(tmp, "w");
    PetscCheck(fp, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "Cannot write '%s' (-output_dir)", tmp);
    fprintf(fp, "{\n");
    PetscCall(WriteProvenance(fp, info));
    fprintf(fp, "  \"indenter\": \"%s\",\n  \"op_fraction\": %.10g,\n  \"op_epsilon\": %.10g,\n  \"op_beta\": %.10g",
      IndIndenterTypes[ind->type], (double)s->op.fraction, (double)s->op.epsilon, (double)s->op.beta);
    /* what E came from: the sample's Poisson's ratio and the indenter's elasticity (0: rigid) */
    fprintf(fp, ",\n  \"op_poisson\": %.10g,\n  \"op_indenter_modulus\": %.10g,\n  \"op_indenter_poisson\": %.10g",
      (double)s->op.nu_sample, (double)s->op.E_indenter, (double)s->op.nu_indenter);
    /* JSON has no inf or nan (E is NaN when E_r exceeds what the indenter allows): null */
    for (PetscInt k = 0; k < ne; ++k) {
      if (PetscIsInfOrNanReal(e[k].value)) fprintf(fp, ",\n  \"%s\": null", e[k].key);
      else fprintf(fp, ",\n  \"%s\": %.12g", e[k].key, (double)e[k].value);
    }
    if (why_E[0]) {
      fprintf(fp, ",\n  \"E_withheld\": ");
      JsonString(fp, why_E);
    }
    if (code) {
      /* the results a reader looks for are there, empty, with the reason */
      const char *const withheld[] = {"H_GPa", "E_r_GPa", "E_GPa", "H_true_GPa", "E_r_true_GPa"};
      for (size_t k = 0; k < sizeof(withheld) / sizeof(withheld[0]); ++k) fprintf(fp, ",\n  \"%s\": null", withheld[k]);
      fprintf(fp, ",\n  \"op_withheld\": ");
      JsonString(fp, why);
    }
    fprintf(fp, "\n}\n");
    PetscCheck(fclose(fp) == 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "Error writing '%s'", tmp);
    PetscCall(IndRenameInto(tmp, path));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}
