#define _POSIX_C_SOURCE 200809L /* strdup, strtok_r */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "ind_common.h"

/* PETSc prints -help as each option is read, so indent's groups come out between PETSc's (the mesh's
   DM, the solver's KSP and PC, viewers). Everything PETSc prints to stdout (PetscHelpPrintf, the type
   lists of PetscOptionsFList, PetscPrintf: all go through PetscVFPrintf) is collected here, line by
   line, into groups by the titles PetscOptionsBegin prints ("----...----" then "Title:"), and printed
   at the end: indent's groups first, then PETSc's, then the lines indent printed ("indent: ..."). */

typedef struct {
  char     *title; /* NULL: lines before any title */
  PetscBool indent;
  PetscBool marked; /* indent's title marker: its unmarked lines are PETSc's (viewers and the like) */
  char     *text;
  size_t    len, cap;
} Group;

static struct {
  PetscBool on;
  Group    *g;
  int       n, cap;
  int       cur, other; /* the group receiving lines; PETSc's lines under indent's titles (-1: none yet) */
  int       said;       /* indent's own messages ("indent: mesh ..."), printed last */
  PetscErrorCode (*print)(FILE *, const char[], va_list); /* PETSc's own PetscVFPrintf */
  PetscBool title_next;
  char      line[8192];
  size_t    ll;
} H;

/* Groups of indent's modules that do not mark their titles yet. */
static const char *const legacy_titles[] = {"Run", "Output", "Output directory and restart", "Oliver-Pharr analysis",
  "Newton", NULL};

static int NewGroup(const char title[], PetscBool indent, PetscBool marked)
{
  if (H.n == H.cap) {
    Group *g = realloc(H.g, sizeof(Group) * (size_t)(H.cap ? 2 * H.cap : 64));
    if (!g) return H.n - 1;
    H.g   = g;
    H.cap = H.cap ? 2 * H.cap : 64;
  }
  memset(&H.g[H.n], 0, sizeof(Group));
  H.g[H.n].title  = title ? strdup(title) : NULL;
  H.g[H.n].indent = indent;
  H.g[H.n].marked = marked;
  return H.n++;
}

static void Append(Group *g, const char s[])
{
  size_t l = strlen(s);
  if (g->len + l + 2 > g->cap) {
    size_t cap  = 2 * (g->len + l + 2) + 256;
    char  *text = realloc(g->text, cap);
    if (!text) return;
    g->text = text;
    g->cap  = cap;
  }
  memcpy(g->text + g->len, s, l);
  g->len += l;
  g->text[g->len++] = '\n';
  g->text[g->len]   = 0;
}

static void Line(char l[])
{
  const size_t mark = strlen(IND_TITLE);
  PetscBool    marked;
  Group       *g;

  if (!strcmp(l, "----------------------------------------")) {
    H.title_next = PETSC_TRUE;
    return;
  }
  if (H.title_next) {
    size_t    len    = strlen(l);
    PetscBool indent = PETSC_FALSE, titled = strncmp(l, IND_TITLE, mark) ? PETSC_FALSE : PETSC_TRUE;
    H.title_next     = PETSC_FALSE;
    if (len && l[len - 1] == ':') l[len - 1] = 0;
    if (titled) indent = PETSC_TRUE;
    for (const char *const *t = legacy_titles; *t && !indent; ++t)
      if (!strcmp(l, *t)) indent = PETSC_TRUE;
    H.cur = NewGroup(titled ? l + mark : l, indent, titled);
    return;
  }
  marked = l[0] == IND_HELP_MARK[0] ? PETSC_TRUE : PETSC_FALSE;
  g      = &H.g[H.cur];
  if (!strncmp(l, "indent", 6) && strstr(l, ": ") && !strchr(l, '<')) g = &H.g[H.said];
  if (g->marked && !marked) {
    if (H.other < 0) H.other = NewGroup("Other PETSc options read during indent's set-up", PETSC_FALSE, PETSC_FALSE);
    g = &H.g[H.other];
  }
  Append(g, marked ? l + 1 : l);
}

/* PETSc prints through here on the rank that prints (rank 0 of the object's communicator). */
static PetscErrorCode Capture(FILE *fd, const char fmt[], va_list ap)
{
  char buf[16384];

  if (fd != stdout || !H.on) return H.print(fd, fmt, ap);
  vsnprintf(buf, sizeof(buf), fmt, ap);
  for (const char *c = buf; *c; ++c) {
    if (*c == '\n') {
      H.line[H.ll] = 0;
      Line(H.line);
      H.ll = 0;
    } else if (H.ll + 1 < sizeof(H.line)) H.line[H.ll++] = *c;
  }
  return PETSC_SUCCESS;
}

void IndHelpCaptureBegin(void)
{
  memset(&H, 0, sizeof(H));
  H.other = -1;
  H.cur   = NewGroup(NULL, PETSC_FALSE, PETSC_FALSE);
  H.said  = NewGroup(NULL, PETSC_TRUE, PETSC_FALSE);
  H.on    = PETSC_TRUE;
  H.print = PetscVFPrintf;
  PetscVFPrintf = Capture;
}

static void Free(void)
{
  for (int k = 0; k < H.n; ++k) {
    free(H.g[k].title);
    free(H.g[k].text);
  }
  free(H.g);
  H.g = NULL;
  H.n = H.cap = 0;
}

static void PrintGroup(const Group *g, PetscBool dashes)
{
  if (g->title) printf("%s%s:\n", dashes ? "----------------------------------------\n" : "\n", g->title);
  if (g->text) fputs(g->text, stdout);
}

PetscErrorCode IndHelpCaptureEnd(void)
{
  PetscFunctionBeginUser;
  if (!H.on || IndHelpListing()) PetscFunctionReturn(PETSC_SUCCESS);
  /* not a listing: what was printed (-version) goes out as PETSc printed it */
  H.on = PETSC_FALSE;
  for (int k = 0; k < H.n; ++k) PrintGroup(&H.g[k], PETSC_TRUE);
  fflush(stdout);
  Free();
  PetscVFPrintf = H.print;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndHelpPrint(const char intro[])
{
  PetscFunctionBeginUser;
  if (!H.on) PetscFunctionReturn(PETSC_SUCCESS);
  if (H.ll) { /* an unfinished last line */
    H.line[H.ll] = 0;
    Line(H.line);
    H.ll = 0;
  }
  if (PetscGlobalRank == 0) {
    fputs(intro, stdout);
    printf("\nOptions of %s (lengths in nm, moduli and stresses in GPa, angles in degrees; an option marked "
      "\"required\" has no default):\n",
           intro && !strncmp(intro, "indent-op", 9) ? "indent-op" : "indent");
    for (int k = 0; k < H.n; ++k)
      if (H.g[k].indent && H.g[k].title) PrintGroup(&H.g[k], PETSC_FALSE);
    printf("\nOptions of PETSc (solvers, preconditioners, meshes, viewers, logging; "
      "https://petsc.org/release/manualpages/):\n");
    for (int k = 0; k < H.n; ++k)
      if (!H.g[k].indent) PrintGroup(&H.g[k], PETSC_TRUE);
    if (H.g[H.said].text) printf("\n%s", H.g[H.said].text);
    fflush(stdout);
  }
  Free();
  H.on          = PETSC_FALSE;
  PetscVFPrintf = H.print;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscBool checking; /* IndHelpSetChecking */

void IndHelpSetChecking(PetscBool on)
{
  checking = on;
}

PetscBool IndHelpListing(void)
{
  PetscBool help = PETSC_FALSE;
  if (checking) return PETSC_TRUE;
  if (PetscOptionsHasHelp(NULL, &help)) return PETSC_FALSE;
  return help;
}
