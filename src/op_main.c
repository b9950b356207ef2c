static const char help[] = "indent-op: Oliver-Pharr analysis of a load-displacement curve (CSV with columns depth_nm "
  "and load_uN,\n"
                           "as indent writes in load_displacement.csv; a contact_area_nm2 column adds the true-area "
                             "values).\n"
                           "  -op_file FILE            the curve (required)\n"
                           "  -op_fraction f           fit the unloading points with P >= (1 - f) P_max (0.5)\n"
                           "  -op_epsilon e            h_c = h_max - e P_max / S (0.75)\n"
                           "  -op_beta b               E_r = sqrt(pi) / (2 b) S / sqrt(A) (1.034)\n"
                           "  -op_indenter_modulus E   GPa; 0 for a rigid indenter (default); diamond: 1141\n"
                           "  -op_indenter_poisson nu  (0.07)\n"
                           "  -op_poisson nu           the sample's, for its modulus E (0.3)\n"
                           "  -op_area_coefficients C0,C1,...: a calibrated area function\n"
                           "                           A = C0 h^2 + C1 h + C2 h^(1/2) + ...\n"
                           "  -indenter_type, -indenter_radius (nm), -indenter_angle (degrees): the area function "
                             "A(h_c)\n";

#include "ind_optionsfile.h"
#include <string.h>
#include "ind_summary.h"
#include "ind_indenter.h"
#include "ind_indenter_profile.h"
#include "ind_common.h"

static PetscReal Area(PetscReal hc, void *ctx)
{
  return IndIndenterArea((const IndIndenter *)ctx, hc);
}

#define MAX_AREA_COEFFICIENTS 9

/* A calibrated area function (Oliver and Pharr 1992): A = C0 h^2 + C1 h + C2 h^(1/2) + C3 h^(1/4) + ... */
typedef struct {
  PetscInt  n;
  PetscReal c[MAX_AREA_COEFFICIENTS];
} AreaFit;

static PetscReal CalibratedArea(PetscReal hc, void *ctx)
{
  const AreaFit *f = (const AreaFit *)ctx;
  PetscReal      A = 0, e = 2;
  for (PetscInt k = 0; k < f->n; ++k, e /= 2) A += f->c[k] * PetscPowReal(hc, e);
  return A;
}

/* The cells of a line split at sep, empty cells kept (a column's index must not shift past one), the line's end
   removed. Returns their count, at most max. */
static int SplitCells(char line[], char sep, char *cells[], int max)
{
  int n = 0;

  line[strcspn(line, "\r\n")] = 0;
  for (char *c = line; n < max;) {
    cells[n++] = c;
    c          = strchr(c, sep);
    if (!c) break;
    *c++ = 0;
  }
  return n;
}

/* Reads the columns depth_nm, load_uN and (if present) contact_area_nm2 of a CSV file: indent's own, or the same
   saved by a spreadsheet (a UTF-8 byte-order mark; semicolons or tabs between the cells, and then decimal commas). */
static PetscErrorCode ReadCurve(const char path[], PetscInt *n, PetscReal **h, PetscReal **P, PetscReal **A)
{
  FILE    *fp = fopen(path, "r");
  char     line[4096], *cells[256], *head = line, sep;
  int      ch = -1, cP = -1, cA = -1, ncol;
  PetscInt cap = 1024, lineno = 1;

  PetscFunctionBeginUser;
  PetscCheck(fp, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "Cannot open the curve '%s' (-op_file)", path);
  PetscCheck(fgets(line, sizeof(line), fp), PETSC_COMM_SELF, PETSC_ERR_FILE_READ, "'%s' (-op_file) is empty", path);
  if (!strncmp(head, "\xef\xbb\xbf", 3)) head += 3;
  sep  = strchr(head, ';') ? ';' : strchr(head, '\t') ? '\t' : ',';
  ncol = SplitCells(head, sep, cells, 256);
  for (int col = 0; col < ncol; ++col) {
    const char *name = cells[col] + strspn(cells[col], " \"");
    const size_t len = strcspn(name, " \"");
    if (len == 8 && !strncmp(name, "depth_nm", len)) ch = col;
    if (len == 7 && !strncmp(name, "load_uN", len)) cP = col;
    if (len == 16 && !strncmp(name, "contact_area_nm2", len)) cA = col;
  }
  PetscCheck(ch >= 0 && cP >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED,
    "'%s' (-op_file) has no depth_nm and load_uN columns", path);
  PetscCall(PetscMalloc3(cap, h, cap, P, cap, A));
  *n = 0;
  while (fgets(line, sizeof(line), fp)) {
    const int cols[3] = {ch, cP, cA};
    PetscReal v[3]    = {0, 0, 0};
    ++lineno;
    ncol = SplitCells(line, sep, cells, 256);
    if (ncol == 1 && !cells[0][strspn(cells[0], " ")]) continue; /* a blank line */
    for (int k = 0; k < 3; ++k) {
      char *cell, *end;
      if (cols[k] < 0) continue;
      PetscCheck(cols[k] < ncol, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED,
        "'%s' (-op_file) line %" PetscInt_FMT ": %d cells, no column %d", path, lineno, ncol, cols[k] + 1);
      cell = cells[cols[k]];
      if (sep != ',') /* a decimal comma */
        for (char *c = cell; *c; ++c)
          if (*c == ',') *c = '.';
      v[k] = strtod(cell, &end);
      PetscCheck(end != cell && !end[strspn(end, " ")], PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED,
        "'%s' (-op_file) line %" PetscInt_FMT ": '%s' is not a number", path, lineno, cell);
    }
    if (*n == cap) {
      PetscReal *h2, *P2, *A2;
      PetscCall(PetscMalloc3(2 * cap, &h2, 2 * cap, &P2, 2 * cap, &A2));
      PetscCall(PetscArraycpy(h2, *h, cap));
      PetscCall(PetscArraycpy(P2, *P, cap));
      PetscCall(PetscArraycpy(A2, *A, cap));
      PetscCall(PetscFree3(*h, *P, *A));
      *h = h2, *P = P2, *A = A2, cap *= 2;
    }
    (*h)[*n] = v[0], (*P)[*n] = v[1], (*A)[*n] = v[2];
    (*n)++;
  }
  fclose(fp);
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Analyse(void)
{
  char        path[PETSC_MAX_PATH_LEN] = "", profile[PETSC_MAX_PATH_LEN] = "";
  PetscReal  *table = NULL;
  IndOPParams p;
  IndOPResult r;
  IndIndenter ind;
  PetscReal  *h, *P, *A, angle = 0;
  PetscInt    n = 0, imax = 0;
  PetscBool   has_file, has_type, has_fit, has_profile;
  AreaFit     fit = {MAX_AREA_COEFFICIENTS, {0}};
  int         code;

  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(&ind, sizeof(ind)));
  PetscOptionsBegin(PETSC_COMM_WORLD, NULL, IND_TITLE "Curve and indenter", "OP");
  PetscCall(IndOptionsString("-op_file", "Load-displacement CSV (columns depth_nm, load_uN)", "file", IND_REQUIRED,
    path, path, sizeof(path), &has_file));
  PetscCall(IndOptionsEnum("-indenter_type", "Indenter shape, for the area function", IndIndenterTypes,
    (PetscEnum)ind.type, (PetscEnum *)&ind.type, &has_type));
  PetscCall(IndOptionsReal("-indenter_radius", "Sphere, tip or punch radius", "nm", NULL, ind.radius, &ind.radius,
    NULL));
  PetscCall(IndOptionsReal("-indenter_angle", "Cone half-angle or pyramid face angle (0: the standard one)", "degrees",
    NULL, angle, &angle, NULL));
  PetscCall(IndOptionsString("-indenter_profile", "-indenter_type table: its height above the tip against the radius",
    "file", NULL, profile, profile, sizeof(profile), &has_profile));
  PetscCall(IndOptionsRealArray("-op_area_coefficients",
    "A calibrated area function instead of the indenter's: A = C0 h_c^2 + C1 h_c + C2 h_c^(1/2) + C3 h_c^(1/4) + ...",
    "C0,C1,... (nm^2, nm, ...)", NULL, fit.c, &fit.n, &has_fit));
  PetscOptionsEnd();
  /* epsilon and beta follow the indenter; a calibrated area function is a Berkovich's unless the type is given */
  PetscCall(IndOPParamsSetFromOptions(PETSC_COMM_WORLD, has_type ? ind.type : IND_INDENTER_BERKOVICH, &p));
  if (!has_fit) fit.n = 0;
  if (IndHelpListing()) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCheck(has_file, PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "-op_file is required (a CSV with depth_nm and load_uN)");
  PetscCheck(has_type || fit.n, PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG,
    "-indenter_type or -op_area_coefficients is required for the area function");
  PetscCheck(!(has_fit && has_type), PETSC_COMM_WORLD, PETSC_ERR_ARG_INCOMP,
    "-op_area_coefficients and -indenter_type both give the area function: give one");
  PetscCheck(has_profile == (has_type && ind.type == IND_INDENTER_TABLE ? PETSC_TRUE : PETSC_FALSE), PETSC_COMM_WORLD,
    PETSC_ERR_ARG_WRONG, "-indenter_profile goes with -indenter_type table, and table needs it");
  if (has_profile) PetscCall(IndIndenterReadProfile(PETSC_COMM_WORLD, profile, &table, &ind.nprofile));
  ind.profile = table;
  if (!has_fit) {
    ind.angle = angle * PETSC_PI / 180;
    PetscCheck(!IndIndenterSetUp(&ind), PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE,
      "-indenter_type %s: bad -indenter_radius or -indenter_angle", IndIndenterTypes[ind.type]);
  }
  PetscCall(ReadCurve(path, &n, &h, &P, &A));
  code = fit.n ? IndOliverPharr(h, P, n, &p, CalibratedArea, &fit, &r) : IndOliverPharr(h, P, n, &p, Area, &ind, &r);
  PetscCheck(code != 1, PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG,
    "'%s': fewer than 3 unloading points with P >= (1 - %g) P_max: record more unloading steps or raise -op_fraction",
    path, (double)p.fraction);
  PetscCheck(code != 3, PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE,
    "-op_fraction must lie in (0, 1], -op_epsilon and -op_beta be > 0");
  PetscCheck(code != 2, PETSC_COMM_WORLD, PETSC_ERR_NOT_CONVERGED,
    "'%s': the unloading branch is not a power law (fit gave alpha %g, m %g)", path, (double)r.alpha, (double)r.m);
  PetscCheck(code != 4 || !fit.n || !(r.h_c > 0), PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE,
    "-op_area_coefficients give A(h_c) = %g nm^2 at h_c = %g nm: an area must be > 0", (double)r.A, (double)r.h_c);
  PetscCheck(code != 4, PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE,
    "'%s': the contact depth h_c = h_max - epsilon P_max / S = %g nm (h_max %g nm, -op_epsilon %g) is at or below the "
    "tip, where the indenter has no area; check -op_epsilon for this indenter", path, (double)r.h_c,
    (double)r.h_max, (double)p.epsilon);
  for (PetscInt i = 1; i < n; ++i)
    if (P[i] > P[imax]) imax = i;
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "Oliver-Pharr analysis of %s (%s)\n", path,
    fit.n ? "calibrated area function" : IndIndenterTypes[ind.type]));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "  P_max %.6g uN at h_max %.6g nm\n", (double)r.P_max, (double)r.h_max));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD,
    "  fit of %" PetscInt_FMT " unloading points: P = %.6g (h - %.6g)^%.6g, rms misfit %.3g uN\n", r.npoints,
    (double)r.alpha, (double)r.h_f, (double)r.m, (double)r.rms));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "  S %.10g uN/nm, h_c %.10g nm (h_c/h_max %.4f), A(h_c) %.10g nm^2\n",
    (double)r.S, (double)r.h_c, (double)(r.h_c / r.h_max), (double)r.A));
  if (PetscIsInfOrNanReal(r.E))
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "  H %.10g GPa, E_r %.10g GPa, E withheld: E_r is stiffer than the "
      "indenter allows (-op_indenter_modulus %g GPa, -op_indenter_poisson %g)\n", (double)r.H, (double)r.E_r,
      (double)p.E_indenter, (double)p.nu_indenter));
  else
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "  H %.10g GPa, E_r %.10g GPa, E %.10g GPa (nu %.3g, %s indenter)\n",
      (double)r.H, (double)r.E_r, (double)r.E, (double)p.nu_sample, p.E_indenter > 0 ? "elastic" : "rigid"));
  if (A[imax] > 0) {
    PetscReal H, Er, E;
    IndOPFromArea(&p, &r, A[imax], &H, &Er, &E);
    PetscCall(PetscPrintf(PETSC_COMM_WORLD,
      "  true contact area at P_max %.6g nm^2 (A_true / A(h_c) = %.4f): H %.6g GPa, E_r %.6g GPa, E %.6g GPa\n",
      (double)A[imax], (double)(A[imax] / r.A), (double)H, (double)Er, (double)E));
  }
  PetscCall(PetscFree3(h, P, A));
  PetscCall(PetscFree(table));
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  PetscErrorCode       ierr;
  IndOptionsFileCopies copies;

  if (IndArgsCheckStray("indent-op", argc, argv) || IndOptionsFilesPrepare("indent-op", argc, argv, &copies)) return 1;
  IndHelpCaptureBegin();
  ierr = PetscInitialize(&argc, &argv, NULL, NULL);
  IndOptionsFilesRemoveCopies(&copies);
  if (ierr) return (int)ierr;
  ierr = IndErrorSetUp("indent-op");
  if (!ierr) ierr = IndHelpCaptureEnd();
  if (!ierr) ierr = IndOptionsCheckSpelling(PETSC_COMM_WORLD);
  if (!ierr) ierr = Analyse();
  if (IndHelpListing()) (void)IndHelpPrint(help);
  return IndErrorFinish(ierr);
}
