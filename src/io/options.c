#define _POSIX_C_SOURCE 200809L /* strtok_r */
#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include "ind_common.h"
#include "ind_options.h"

/* PETSc reads these only at solve, factorisation, view or finalize time, so at the end of setup
   they are legitimately still unused. Everything else unused by then is a typo or an option that
   does not apply, and running hours on a misspelled setting is worse than stopping now. */
static const char *lazy_prefixes[] = {"log", "options_", "malloc", "memory_view", "info", "help", "version", "history",
                                      "on_error", "mat_mumps_", "mat_superlu", "mat_view", "vec_view", "ksp_view",
                                        "snes_view",
                                      "pc_view", "dm_view", "check_pointer", "fp_trap", "viewer_", "mpi_", "use_gpu",
                                        "skip_petscrc",
                                      "objects_dump", "display", "nox", "x_", "draw_", "petscpartitioner_view",
                                      "ksp_converged_reason", "snes_converged_reason", "snes_test_", "mg_levels_",
                                      "mg_coarse_", "pc_hypre_boomeramg_print", "matptap_", "matmatmult_",
                                      "mat_product_",
                                      NULL};

PetscErrorCode IndOptionsCheckUnused(MPI_Comm comm)
{
  PetscInt   n, bad = 0;
  char     **names, **values;
  PetscBool  check = PETSC_TRUE;
  char       list[4096] = "";

  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, NULL, IND_TITLE "Checks", "Run");
  PetscCall(IndOptionsBool("-options_check_unused",
    "Stop on options nobody read (misspelt, or not applying to this run)", check, &check, NULL));
  PetscOptionsEnd();
  if (!check) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscOptionsLeftGet(NULL, &n, &names, &values));
  for (PetscInt i = 0; i < n; ++i) {
    PetscBool lazy = PETSC_FALSE;
    for (const char **p = lazy_prefixes; *p && !lazy; ++p) {
      size_t len;
      PetscCall(PetscStrlen(*p, &len));
      PetscCall(PetscStrncmp(names[i], *p, len, &lazy));
    }
    if (lazy) continue;
    ++bad;
    PetscCall(PetscStrlcat(list, " -", sizeof(list)));
    PetscCall(PetscStrlcat(list, names[i], sizeof(list)));
  }
  PetscCall(PetscOptionsLeftRestore(NULL, &n, &names, &values));
  PetscCheck(!bad, comm, PETSC_ERR_ARG_WRONG,
             "Unknown or unused option(s):%s. Check the spelling (-help lists every option), or pass "
               "-options_check_unused 0 to run anyway", list);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndOptionsCheckSpelling(MPI_Comm comm)
{
  PetscInt n;
  char   **names, **values, bad[256] = "";

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsLeftGet(NULL, &n, &names, &values));
  for (PetscInt i = 0; i < n && !bad[0]; ++i)
    if (strchr(names[i], '=')) PetscCall(PetscStrncpy(bad, names[i], sizeof(bad)));
  PetscCall(PetscOptionsLeftRestore(NULL, &n, &names, &values));
  if (bad[0]) {
    char *eq = strchr(bad, '=');
    *eq      = 0;
    SETERRQ(comm, PETSC_ERR_ARG_WRONG, "-%s=%s: an option and its value are separated by a blank, not '=' (-%s %s)",
            bad, eq + 1, bad, eq + 1);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* ---- checked conversions ---------------------------------------------------------------------- */

static void FullName(PetscOptionItems *po, const char opt[], char name[], size_t len)
{
  snprintf(name, len, "-%s%s", po->prefix ? po->prefix : "", opt + 1);
}

/* The raw text of the option, if given. */
static PetscErrorCode Raw(PetscOptionItems *po, const char opt[], char str[], size_t len, PetscBool *given)
{
  PetscFunctionBeginUser;
  str[0] = 0;
  PetscCall(PetscOptionsGetString(po->options, po->prefix, opt, str, len, given));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscBool ParseReal(const char s[], PetscReal *v)
{
  char  *end;
  double d;

  if (!s[0]) return PETSC_FALSE;
  errno = 0;
  d     = strtod(s, &end);
  if (end == s || *end) return PETSC_FALSE;
  *v = (PetscReal)d;
  return PETSC_TRUE;
}

static PetscBool ParseInt(const char s[], PetscInt *v)
{
  char     *end;
  long long l;

  if (!s[0]) return PETSC_FALSE;
  errno = 0;
  l     = strtoll(s, &end, 10);
  if (end == s || *end || errno == ERANGE || l > PETSC_MAX_INT || l < PETSC_MIN_INT) return PETSC_FALSE;
  *v = (PetscInt)l;
  return PETSC_TRUE;
}

static PetscBool ParseBool(const char s[])
{
  const char *ok[] = {"", "1", "0", "true", "false", "yes", "no", "on", "off"};
  for (size_t k = 0; k < sizeof(ok) / sizeof(ok[0]); ++k)
    if (!strcasecmp(s, ok[k])) return PETSC_TRUE;
  return PETSC_FALSE;
}

/* " (nm)" after a message, or nothing for a dimensionless value. */
static void UnitsSuffix(const char units[], char out[], size_t len)
{
  if (units && units[0]) snprintf(out, len, " (%s)", units);
  else out[0] = 0;
}

static PetscErrorCode CheckReal(MPI_Comm comm, const char name[], const char str[], const char units[])
{
  PetscReal v;
  char      u[64];

  PetscFunctionBeginUser;
  UnitsSuffix(units, u, sizeof(u));
  PetscCheck(str[0], comm, PETSC_ERR_ARG_WRONG, "%s needs a value%s", name, u);
  PetscCheck(ParseReal(str, &v), comm, PETSC_ERR_ARG_WRONG, "%s: '%s' is not a number%s", name, str, u);
  PetscCheck(isfinite(v), comm, PETSC_ERR_ARG_OUTOFRANGE, "%s: '%s' is not a finite number%s", name, str, u);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Checks each comma-separated entry of a list of n at most. */
static PetscErrorCode CheckList(MPI_Comm comm, const char name[], const char str[], const char what[],
  PetscBool integer, PetscInt nmax)
{
  char     buf[1024], *save = NULL;
  PetscInt count = 0;

  PetscFunctionBeginUser;
  PetscCheck(str[0], comm, PETSC_ERR_ARG_WRONG, "%s needs a value (%s)", name, what);
  snprintf(buf, sizeof(buf), "%s", str);
  PetscCheck(str[strlen(str) - 1] != ',' && str[0] != ',' && !strstr(str, ",,"), comm, PETSC_ERR_ARG_WRONG,
    "%s: '%s' has an empty entry (%s)", name, str, what);
  for (char *tok = strtok_r(buf, ",", &save); tok; tok = strtok_r(NULL, ",", &save)) {
    PetscReal v;
    PetscInt  i;
    ++count;
    if (integer) PetscCheck(ParseInt(tok, &i), comm, PETSC_ERR_ARG_WRONG, "%s: '%s' in '%s' is not an integer (%s)",
      name, tok, str, what);
    else {
      PetscCheck(ParseReal(tok, &v), comm, PETSC_ERR_ARG_WRONG, "%s: '%s' in '%s' is not a number (%s)", name, tok, str,
        what);
      PetscCheck(isfinite(v), comm, PETSC_ERR_ARG_OUTOFRANGE, "%s: '%s' in '%s' is not a finite number (%s)", name, tok,
        str, what);
    }
  }
  PetscCheck(count <= nmax, comm, PETSC_ERR_ARG_SIZ,
    "%s: '%s' has %" PetscInt_FMT " values, at most %" PetscInt_FMT " expected (%s)", name, str, count, nmax, what);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* ---- help lines ------------------------------------------------------------------------------------ */

static PetscBool Listing(PetscOptionItems *po)
{
  return po->printhelp && po->count == 1 && !po->alreadyprinted ? PETSC_TRUE : PETSC_FALSE;
}

/* One line: "-name <kind>: text (default; given: value)". */
static PetscErrorCode HelpLine(PetscOptionItems *po, const char opt[], const char kind[], const char text[],
  const char dflt[], PetscBool given, const char str[])
{
  char name[256], when[512];

  PetscFunctionBeginUser;
  FullName(po, opt, name, sizeof(name));
  if (!strncmp(dflt, IND_REQUIRED, strlen(IND_REQUIRED))) snprintf(when, sizeof(when), "%s", dflt);
  else snprintf(when, sizeof(when), "default: %s", dflt[0] ? dflt : "none");
  if (given) {
    size_t l = strlen(when);
    snprintf(when + l, sizeof(when) - l, "; given: %s", str[0] ? str : "(no value)");
  }
  PetscCall((*PetscHelpPrintf)(po->comm, IND_HELP_MARK "  %s <%s>: %s (%s)\n", name, kind, text, when));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* PETSc's own help line for the option would repeat ours. */
#define WithoutHelp(po, call) \
  do { \
    const PetscBool printhelp_ = (po)->printhelp; \
    PetscErrorCode  ierr_      = PETSC_SUCCESS; \
    (po)->printhelp            = PETSC_FALSE; \
    ierr_                      = (call); \
    (po)->printhelp            = printhelp_; \
    PetscCall(ierr_); \
  } while (0)

PetscErrorCode IndOptionsReal_Private(PetscOptionItems *po, const char opt[], const char text[], const char units[],
  const char dflt[], PetscReal cur, PetscReal *value, PetscBool *set)
{
  char      str[256], name[256], def[64];
  PetscBool given;

  PetscFunctionBeginUser;
  FullName(po, opt, name, sizeof(name));
  PetscCall(Raw(po, opt, str, sizeof(str), &given));
  if (given) PetscCall(CheckReal(po->comm, name, str, units));
  if (Listing(po)) {
    snprintf(def, sizeof(def), "%g", (double)cur);
    PetscCall(HelpLine(po, opt, units && units[0] ? units : "real", text, dflt ? dflt : def, given, str));
  }
  WithoutHelp(po, PetscOptionsReal_Private(po, opt, text, "", cur, value, set));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndOptionsInt_Private(PetscOptionItems *po, const char opt[], const char text[], const char dflt[],
  PetscInt cur, PetscInt *value, PetscBool *set)
{
  char      str[256], name[256], def[64];
  PetscBool given;
  PetscInt  v;

  PetscFunctionBeginUser;
  FullName(po, opt, name, sizeof(name));
  PetscCall(Raw(po, opt, str, sizeof(str), &given));
  if (given) {
    PetscCheck(str[0], po->comm, PETSC_ERR_ARG_WRONG, "%s needs a value (an integer)", name);
    PetscCheck(ParseInt(str, &v), po->comm, PETSC_ERR_ARG_WRONG, "%s: '%s' is not an integer", name, str);
  }
  if (Listing(po)) {
    snprintf(def, sizeof(def), "%" PetscInt_FMT, cur);
    PetscCall(HelpLine(po, opt, "int", text, dflt ? dflt : def, given, str));
  }
  WithoutHelp(po, PetscOptionsInt_Private(po, opt, text, "", cur, value, set, PETSC_MIN_INT, PETSC_MAX_INT));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndOptionsBool_Private(PetscOptionItems *po, const char opt[], const char text[], PetscBool cur,
  PetscBool *value, PetscBool *set)
{
  char      str[256], name[256];
  PetscBool given;

  PetscFunctionBeginUser;
  FullName(po, opt, name, sizeof(name));
  PetscCall(Raw(po, opt, str, sizeof(str), &given));
  if (given) PetscCheck(ParseBool(str), po->comm, PETSC_ERR_ARG_WRONG,
    "%s: '%s' is not a boolean (true or false, 1 or 0)", name, str);
  if (Listing(po)) PetscCall(HelpLine(po, opt, "bool", text, cur ? "true" : "false", given,
    str[0] || !given ? str : "true"));
  WithoutHelp(po, PetscOptionsBool_Private(po, opt, text, "", cur, value, set));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The names of a choice as "a|b|c". */
static void Choices(const char *const *list, PetscInt n, char out[], size_t len)
{
  out[0] = 0;
  for (PetscInt k = 0; k < n; ++k) {
    size_t l = strlen(out);
    snprintf(out + l, len - l, "%s%s", k ? "|" : "", list[k]);
  }
}

static PetscErrorCode CheckChoice(MPI_Comm comm, const char name[], const char str[], const char *const *list,
  PetscInt n)
{
  char choices[1024];

  PetscFunctionBeginUser;
  Choices(list, n, choices, sizeof(choices));
  for (char *c = choices; *c; ++c)
    if (*c == '|') *c = ' ';
  PetscCheck(str[0], comm, PETSC_ERR_ARG_WRONG, "%s needs a value: one of %s", name, choices);
  for (PetscInt k = 0; k < n; ++k)
    if (!strcasecmp(str, list[k])) PetscFunctionReturn(PETSC_SUCCESS);
  SETERRQ(comm, PETSC_ERR_ARG_WRONG, "%s: '%s' is not one of %s", name, str, choices);
}

PetscErrorCode IndOptionsEnum_Private(PetscOptionItems *po, const char opt[], const char text[],
  const char *const *list, PetscEnum cur, PetscEnum *value, PetscBool *set)
{
  char      str[256], name[256], kind[512];
  PetscBool given;
  PetscInt  n = 0;

  PetscFunctionBeginUser;
  while (list[n]) ++n;
  n -= 2; /* an enum's list ends with its type name and prefix */
  FullName(po, opt, name, sizeof(name));
  PetscCall(Raw(po, opt, str, sizeof(str), &given));
  if (given) PetscCall(CheckChoice(po->comm, name, str, list, n));
  if (Listing(po)) {
    Choices(list, n, kind, sizeof(kind));
    PetscCall(HelpLine(po, opt, kind, text, list[cur], given, str));
  }
  WithoutHelp(po, PetscOptionsEnum_Private(po, opt, text, "", list, cur, value, set));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndOptionsEList_Private(PetscOptionItems *po, const char opt[], const char text[],
  const char *const *list, PetscInt n, PetscInt cur, PetscInt *value, PetscBool *set)
{
  char      str[256], name[256], kind[512];
  PetscBool given;

  PetscFunctionBeginUser;
  FullName(po, opt, name, sizeof(name));
  PetscCall(Raw(po, opt, str, sizeof(str), &given));
  if (given) PetscCall(CheckChoice(po->comm, name, str, list, n));
  if (Listing(po)) {
    Choices(list, n, kind, sizeof(kind));
    PetscCall(HelpLine(po, opt, kind, text, list[cur], given, str));
  }
  WithoutHelp(po, PetscOptionsEList_Private(po, opt, text, "", list, n, list[cur], value, set));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndOptionsType_Private(PetscOptionItems *po, const char opt[], const char text[],
  IndRegistry *registry, const char cur[], char value[], size_t len, PetscBool *set)
{
  PetscInt  icur = 0, v;
  PetscBool given = PETSC_FALSE;

  PetscFunctionBeginUser;
  PetscCall(IndRegistryReady(registry));
  for (PetscInt k = 0; k < registry->n; ++k)
    if (!strcmp(registry->name[k], cur)) icur = k;
  v = icur;
  PetscCall(IndOptionsEList_Private(po, opt, text, registry->names, registry->n, icur, &v, &given));
  PetscCall(PetscStrncpy(value, registry->name[v], len));
  if (set) *set = given;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndOptionsString_Private(PetscOptionItems *po, const char opt[], const char text[], const char what[],
  const char dflt[], const char cur[], char value[], size_t len, PetscBool *set)
{
  char      str[PETSC_MAX_PATH_LEN];
  PetscBool given;

  PetscFunctionBeginUser;
  PetscCall(Raw(po, opt, str, sizeof(str), &given));
  if (Listing(po)) PetscCall(HelpLine(po, opt, what, text, dflt ? dflt : cur, given, str));
  WithoutHelp(po, PetscOptionsString_Private(po, opt, text, "", cur, value, len, set));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndOptionsStringArray_Private(PetscOptionItems *po, const char opt[], const char text[],
  const char what[], char *values[], PetscInt *n, PetscBool *set)
{
  char      str[4096], name[256];
  PetscBool given;
  PetscInt  count = 1;

  PetscFunctionBeginUser;
  FullName(po, opt, name, sizeof(name));
  PetscCall(Raw(po, opt, str, sizeof(str), &given));
  if (given) {
    PetscCheck(str[0], po->comm, PETSC_ERR_ARG_WRONG, "%s needs a value (%s)", name, what);
    for (const char *c = str; *c; ++c) count += *c == ',';
    PetscCheck(count <= *n, po->comm, PETSC_ERR_ARG_SIZ,
      "%s: '%s' has %" PetscInt_FMT " entries, at most %" PetscInt_FMT " are supported", name, str, count, *n);
  }
  if (Listing(po)) PetscCall(HelpLine(po, opt, what, text, "none", given, str));
  WithoutHelp(po, PetscOptionsStringArray_Private(po, opt, text, "", values, n, set));
  /* "a=1, b=2" (quoted, or from an options file): the entries without the blanks around them */
  for (PetscInt i = 0; given && i < *n; ++i) {
    char  *v = values[i];
    size_t len;
    memmove(v, v + strspn(v, " \t"), strlen(v + strspn(v, " \t")) + 1);
    len = strlen(v);
    while (len && (v[len - 1] == ' ' || v[len - 1] == '\t')) v[--len] = 0;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The part the real and integer lists share: each entry checked, and the -help line with the current
   values as default. */
static PetscErrorCode CheckAndListArray(PetscOptionItems *po, const char opt[], const char text[], const char what[],
                                        const char dflt[], const PetscReal *reals, const PetscInt *ints, PetscInt n)
{
  char      str[1024], name[256], def[256] = "";
  PetscBool given;

  PetscFunctionBeginUser;
  FullName(po, opt, name, sizeof(name));
  PetscCall(Raw(po, opt, str, sizeof(str), &given));
  if (given) PetscCall(CheckList(po->comm, name, str, what, ints ? PETSC_TRUE : PETSC_FALSE, n));
  if (Listing(po)) {
    for (PetscInt k = 0; k < n; ++k) {
      size_t l = strlen(def);
      if (ints) snprintf(def + l, sizeof(def) - l, "%s%" PetscInt_FMT, k ? "," : "", ints[k]);
      else snprintf(def + l, sizeof(def) - l, "%s%g", k ? "," : "", (double)reals[k]);
    }
    PetscCall(HelpLine(po, opt, what, text, dflt ? dflt : def, given, str));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndOptionsRealArray_Private(PetscOptionItems *po, const char opt[], const char text[], const char what[],
  const char dflt[], PetscReal values[], PetscInt *n, PetscBool *set)
{
  PetscFunctionBeginUser;
  PetscCall(CheckAndListArray(po, opt, text, what, dflt, values, NULL, *n));
  WithoutHelp(po, PetscOptionsRealArray_Private(po, opt, text, "", values, n, set));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndOptionsIntArray_Private(PetscOptionItems *po, const char opt[], const char text[], const char what[],
  const char dflt[], PetscInt values[], PetscInt *n, PetscBool *set)
{
  PetscFunctionBeginUser;
  PetscCall(CheckAndListArray(po, opt, text, what, dflt, NULL, values, *n));
  WithoutHelp(po, PetscOptionsIntArray_Private(po, opt, text, "", values, n, set));
  PetscFunctionReturn(PETSC_SUCCESS);
}
