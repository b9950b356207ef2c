#define _POSIX_C_SOURCE 200809L /* strdup, strtok_r */
#include <ctype.h>
#include <stdio.h>
#include <errno.h>
#include <math.h>
#include <string.h>
#include <stdlib.h>
#include <signal.h>
#include <time.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include "ind_files.h"
#include "ind_iofault.h"
#include "ind_signals.h"

/* Runs cmd with sh in a process group of its own, so that a signal meant for indent's group (a job
   launcher's, a terminal's) does not kill it unseen; a stop signal indent receives meanwhile ends it
   (*stopped: that signal). Returns system()'s status, or -1 when it cannot start. */
static int RunShell(const char cmd[], int *stopped)
{
  const struct timespec pause = {0, 20000000};
  int                   status;
  pid_t                 pid;

  *stopped = 0;
  pid      = fork();
  if (pid < 0) return -1;
  if (pid == 0) {
    (void)setpgid(0, 0);
    execl("/bin/sh", "sh", "-c", cmd, (char *)NULL);
    _exit(127);
  }
  (void)setpgid(pid, pid); /* either may run first */
  for (;;) {
    const pid_t done = waitpid(pid, &status, WNOHANG);
    if (done == pid) break;
    if (done < 0 && errno != EINTR) return -1;
    if (!*stopped && (*stopped = IndSignalsReceived())) (void)kill(-pid, SIGTERM);
    nanosleep(&pause, NULL);
  }
  return status;
}

/* On rank 0: why dir cannot be (made) a writable directory, or "" when it can. */
static void DirectoryProblem(const char dir[], PetscBool create, char why[], size_t len)
{
  char        path[PETSC_MAX_PATH_LEN];
  struct stat st;

  why[0] = 0;
  snprintf(path, sizeof(path), "%s", dir);
  if (!stat(path, &st)) {
    if (!S_ISDIR(st.st_mode)) snprintf(why, len, "it exists and is not a directory");
    else if (access(path, W_OK)) snprintf(why, len, "it is not writable: %s", strerror(errno));
    return;
  }
  /* the nearest existing ancestor must be a writable directory */
  for (char *slash = strrchr(path, '/'); slash; slash = strrchr(path, '/')) {
    *slash = 0;
    if (!path[0]) snprintf(path, sizeof(path), "/");
    if (!stat(path, &st)) break;
    if (!strcmp(path, "/")) break;
  }
  if (!strchr(dir, '/') || stat(path, &st)) snprintf(path, sizeof(path), ".");
  if (stat(path, &st)) snprintf(why, len, "'%s' does not exist", path);
  else if (!S_ISDIR(st.st_mode)) snprintf(why, len, "'%s' is not a directory", path);
  else if (create && access(path, W_OK)) snprintf(why, len, "'%s' is not writable", path);
}

PetscErrorCode IndCheckDirectory(MPI_Comm comm, const char dir[], const char option[])
{
  PetscMPIInt rank;
  char        why[PETSC_MAX_PATH_LEN + 64] = "";

  PetscFunctionBeginUser;
  PetscCheck(dir[0], comm, PETSC_ERR_ARG_WRONG, "%s must not be empty", option);
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (!rank) DirectoryProblem(dir, PETSC_TRUE, why, sizeof(why));
  PetscCallMPI(MPI_Bcast(why, sizeof(why), MPI_CHAR, 0, comm));
  PetscCheck(!why[0], comm, PETSC_ERR_FILE_OPEN, "%s '%s' cannot be the output directory: %s", option, dir, why);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndMakeDirectory(MPI_Comm comm, const char dir[], const char option[])
{
  PetscMPIInt rank;
  int         err = 0;
  char        path[PETSC_MAX_PATH_LEN], why[PETSC_MAX_PATH_LEN + 64] = "";

  PetscFunctionBeginUser;
  if (IndHelpListing()) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0) {
    PetscCall(PetscStrncpy(path, dir, sizeof(path)));
    for (char *p = path + 1; *p && !err; ++p)
      if (*p == '/') {
        *p = 0;
        if (mkdir(path, 0777) && errno != EEXIST) err = errno;
        *p = '/';
      }
    if (!err && mkdir(path, 0777) && errno != EEXIST) err = errno;
    if (err) snprintf(why, sizeof(why), "%s", strerror(err));
    else DirectoryProblem(dir, PETSC_TRUE, why, sizeof(why)); /* mkdir leaves an existing file be */
  }
  PetscCallMPI(MPI_Bcast(why, sizeof(why), MPI_CHAR, 0, comm));
  PetscCheck(!why[0], comm, PETSC_ERR_FILE_OPEN, "Cannot create or write to the output directory '%s' (%s): %s", dir,
    option, why);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Paths and values go to a shell: single quotes keep spaces and specials literal, so a quote itself
   is refused rather than escaped. */
static PetscBool Quotable(const char s[])
{
  return strchr(s, '\'') ? PETSC_FALSE : PETSC_TRUE;
}


/* gmsh's own first error line in its log ("Error   : 'x.geo', line 2: syntax error (is)"), without its tag: what the
   user most needs of a failed meshing. said[0] = 0 when the log has none. */
static void FirstGmshError(const char log[], char said[], size_t len)
{
  FILE *fp = fopen(log, "r");
  char  line[1024];

  said[0] = 0;
  if (!fp) return;
  while (fgets(line, sizeof(line), fp))
    if (!strncmp(line, "Error", 5)) {
      const char *text = strchr(line, ':');
      text             = text ? text + 1 : line;
      while (*text == ' ') text++;
      line[strcspn(line, "\r\n")] = 0;
      snprintf(said, len, "%.300s", text);
      break;
    }
  fclose(fp);
}
PetscErrorCode IndGmshMesh(MPI_Comm comm, const char gmsh[], const char geo[], char *params[], PetscInt nparams,
  const char msh[])
{
  PetscMPIInt rank;
  int         status = 0, cause = 0, stopped = 0;
  char        cmd[4 * PETSC_MAX_PATH_LEN], log[PETSC_MAX_PATH_LEN + 8], tmp[PETSC_MAX_PATH_LEN + 8], said[320] = "";

  PetscFunctionBeginUser;
  PetscCheck(Quotable(gmsh) && Quotable(geo) && Quotable(msh), comm, PETSC_ERR_ARG_WRONG,
    "-mesh_file, -mesh_gmsh and the mesh's output path must not contain a single quote");
  PetscCall(PetscSNPrintf(log, sizeof(log), "%s.log", msh));
  PetscCall(PetscSNPrintf(tmp, sizeof(tmp), "%s.tmp", msh));
  PetscCall(PetscSNPrintf(cmd, sizeof(cmd), "'%s' -3 '%s' -format msh41", gmsh, geo));
  for (PetscInt i = 0; i < nparams; ++i) {
    char  *eq = strchr(params[i], '='), tail[PETSC_MAX_PATH_LEN];
    PetscCheck(eq && eq != params[i] && eq[1] && Quotable(params[i]), comm, PETSC_ERR_ARG_WRONG,
      "-mesh_geo_parameters: '%s' is not name=value", params[i]);
    PetscCall(PetscSNPrintf(tail, sizeof(tail), " -setnumber '%.*s' '%s'", (int)(eq - params[i]), params[i], eq + 1));
    PetscCall(PetscStrlcat(cmd, tail, sizeof(cmd)));
  }
  {
    char tail[3 * PETSC_MAX_PATH_LEN];
    PetscCall(PetscSNPrintf(tail, sizeof(tail), " -o '%s' > '%s' 2>&1", tmp, log));
    PetscCall(PetscStrlcat(cmd, tail, sizeof(cmd)));
  }
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (!rank) {
    (void)remove(tmp);
    status = RunShell(cmd, &stopped);
    if (stopped) status = -4;
    if (status == 0) {
      PetscBool ok;
      PetscCall(PetscTestFile(tmp, 'r', &ok));
      if (!ok) status = -1;
    }
    /* gmsh does not check its writes: a full disk leaves a truncated mesh and status 0 */
    if (status == 0 && (cause = IndIOFaultFileCause(tmp))) status = -3;
    if (status == 0 && rename(tmp, msh)) status = -2;
    if (status) (void)remove(tmp);
    if (status > 0 || status == -1) FirstGmshError(log, said, sizeof(said));
  }
  PetscCallMPI(MPI_Bcast(said, (PetscMPIInt)sizeof(said), MPI_CHAR, 0, comm));
  PetscCallMPI(MPI_Bcast(&status, 1, MPI_INT, 0, comm));
  PetscCallMPI(MPI_Bcast(&cause, 1, MPI_INT, 0, comm));
  PetscCallMPI(MPI_Bcast(&stopped, 1, MPI_INT, 0, comm));
  PetscCheck(status != -4, comm, PETSC_ERR_SIG,
             "stopped by %s while gmsh meshed '%s' (-mesh_file): no step was solved, so there is nothing to continue "
             "from; run again", IndSignalName(stopped), geo);
  PetscCheck(status != -3, comm, PETSC_ERR_FILE_WRITE, "gmsh could not write the mesh of '%s' (-mesh_file) to '%s': %s",
             geo, msh, strerror(cause));
  PetscCheck(status != -2, comm, PETSC_ERR_FILE_WRITE,
    "gmsh meshed '%s' (-mesh_file) but its mesh could not be renamed to '%s'", geo, msh);
  PetscCheck(status == 0, comm, PETSC_ERR_USER_INPUT,
    "gmsh could not mesh '%s' (-mesh_file)%s%s: see '%s'; the command was: %s", geo, said[0] ? ": " : "", said, log,
    cmd);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* ---- what a .geo declares ------------------------------------------------------------------------- */

static PetscBool IdentStart(char c)
{
  return isalpha((unsigned char)c) || c == '_' ? PETSC_TRUE : PETSC_FALSE;
}

static PetscBool IdentChar(char c)
{
  return isalnum((unsigned char)c) || c == '_' ? PETSC_TRUE : PETSC_FALSE;
}

static void Add(char list[][IND_NAME_LEN], PetscInt *n, const char *s, size_t len)
{
  if (*n >= IND_GEO_MAX || len == 0 || len >= IND_NAME_LEN) return;
  for (PetscInt k = 0; k < *n; ++k)
    if (strlen(list[k]) == len && !strncmp(list[k], s, len)) return;
  memcpy(list[*n], s, len);
  list[(*n)++][len] = 0;
}

/* Whether word starts at s as a whole word. */
static PetscBool Word(const char *text, const char *s, const char *word)
{
  const size_t l = strlen(word);
  if (strncmp(s, word, l)) return PETSC_FALSE;
  if (s > text && IdentChar(s[-1])) return PETSC_FALSE;
  return IdentChar(s[l]) ? PETSC_FALSE : PETSC_TRUE;
}

static const char *SkipSpace(const char *s)
{
  while (*s && isspace((unsigned char)*s)) ++s;
  return s;
}

/* The text with comments blanked out (strings kept). */
static char *WithoutComments(const char text[])
{
  size_t n = strlen(text);
  char  *out = malloc(n + 1);
  int    instr = 0;

  if (!out) return NULL;
  for (size_t i = 0; i < n; ++i) {
    char c = text[i];
    if (instr) {
      if (c == '\\' && i + 1 < n) {
        out[i] = c;
        out[i + 1] = text[i + 1];
        ++i;
        continue;
      }
      if (c == '"') instr = 0;
      out[i] = c;
    } else if (c == '"') {
      instr  = 1;
      out[i] = c;
    } else if (c == '/' && text[i + 1] == '/') {
      while (i < n && text[i] != '\n') out[i++] = ' ';
      if (i < n) out[i] = '\n';
    } else if (c == '/' && text[i + 1] == '*') {
      out[i] = out[i + 1] = ' ';
      for (i += 2; i < n && !(text[i] == '*' && text[i + 1] == '/'); ++i) out[i] = text[i] == '\n' ? '\n' : ' ';
      if (i < n) {
        out[i] = out[i + 1] = ' ';
        ++i;
      }
    } else out[i] = c;
  }
  out[n] = 0;
  return out;
}

/* DefineConstant[ a = 1, b = {2, Min 1}, ... ]: the names at the top level of the brackets. */
static const char *DefineConstant(const char *s, IndGeoInfo *info)
{
  int depth = 0, instr = 0, entry = 1;

  s = SkipSpace(s);
  if (*s != '[') return s;
  for (++s; *s; ++s) {
    if (instr) {
      if (*s == '\\' && s[1]) ++s;
      else if (*s == '"') instr = 0;
      continue;
    }
    if (*s == '"') instr = 1;
    else if (*s == '[' || *s == '{' || *s == '(') depth++;
    else if (*s == ']' || *s == '}' || *s == ')') {
      if (depth == 0) return s + 1;
      depth--;
    } else if (*s == ',' && depth == 0) entry = 1;
    else if (entry && !isspace((unsigned char)*s)) {
      entry = 0;
      if (IdentStart(*s)) {
        const char *b = s, *e = s;
        while (IdentChar(*e)) ++e;
        if (*SkipSpace(e) == '=') Add(info->params, &info->nparams, b, (size_t)(e - b));
        s = e - 1;
      }
    }
  }
  return s;
}

/* Physical Volume("film") = ... or Physical Volume(3) = ... */
static void Physical(const char *s, IndGeoInfo *info)
{
  PetscBool   vol = PETSC_FALSE;
  const char *p   = SkipSpace(s + strlen("Physical"));

  if (Word(s, p, "Volume")) vol = PETSC_TRUE;
  else if (!Word(s, p, "Surface")) return;
  p = SkipSpace(p + (vol ? 6 : 7));
  if (*p != '(') return;
  p = SkipSpace(p + 1);
  if (*p == '"') {
    const char *e = strchr(p + 1, '"');
    if (e) {
      if (vol) Add(info->volumes, &info->nvolumes, p + 1, (size_t)(e - p - 1));
      else Add(info->surfaces, &info->nsurfaces, p + 1, (size_t)(e - p - 1));
    }
  } else if (isdigit((unsigned char)*p)) {
    char name[IND_NAME_LEN];
    int  tag = atoi(p);
    snprintf(name, sizeof(name), "%s%d", vol ? "volume" : "surface", tag);
    if (vol) Add(info->volumes, &info->nvolumes, name, strlen(name));
    else Add(info->surfaces, &info->nsurfaces, name, strlen(name));
  }
}

void IndGeoScan(const char text[], IndGeoInfo *info)
{
  char *t = WithoutComments(text);
  int   instr = 0;

  memset(info, 0, sizeof(*info));
  if (!t) return;
  for (const char *s = t; *s; ++s) {
    if (instr) {
      if (*s == '\\' && s[1]) ++s;
      else if (*s == '"') instr = 0;
      continue;
    }
    if (*s == '"') {
      instr = 1;
      continue;
    }
    if (Word(t, s, "DefineConstant")) s = DefineConstant(s + strlen("DefineConstant"), info) - 1;
    else if (Word(t, s, "DefineNumber")) { /* name = DefineNumber[...] */
      const char *b = s - 1, *e;
      while (b >= t && isspace((unsigned char)*b)) --b;
      if (b >= t && *b == '=') {
        --b;
        while (b >= t && isspace((unsigned char)*b)) --b;
        e = b + 1;
        while (b >= t && IdentChar(*b)) --b;
        if (IdentStart(b[1])) Add(info->params, &info->nparams, b + 1, (size_t)(e - b - 1));
      }
    } else if (Word(t, s, "Exists")) {
      const char *p = SkipSpace(s + 6), *e;
      if (*p == '(') {
        p = SkipSpace(p + 1);
        for (e = p; IdentChar(*e); ++e) {}
        if (IdentStart(*p) && *SkipSpace(e) == ')') Add(info->params, &info->nparams, p, (size_t)(e - p));
      }
    } else if (Word(t, s, "Physical")) Physical(s, info);
  }
  free(t);
}

PetscErrorCode IndGeoRead(MPI_Comm comm, const char geo[], IndGeoInfo *info)
{
  PetscMPIInt rank;
  int         err = 0;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCall(PetscMemzero(info, sizeof(*info)));
  if (!rank) {
    FILE *fp = fopen(geo, "rb");
    char *text = NULL;
    long  len  = 0;
    if (!fp || fseek(fp, 0, SEEK_END) || (len = ftell(fp)) < 0 || fseek(fp, 0, SEEK_SET)) err = errno ? errno : EIO;
    if (!err && !(text = malloc((size_t)len + 1))) err = ENOMEM;
    if (!err && fread(text, 1, (size_t)len, fp) != (size_t)len) err = EIO;
    if (!err) {
      text[len] = 0;
      IndGeoScan(text, info);
    }
    free(text);
    if (fp) fclose(fp);
  }
  PetscCallMPI(MPI_Bcast(&err, 1, MPI_INT, 0, comm));
  PetscCheck(!err, comm, PETSC_ERR_FILE_READ, "Cannot read the geometry '%s' (-mesh_file): %s", geo, strerror(err));
  PetscCallMPI(MPI_Bcast(info, sizeof(*info), MPI_BYTE, 0, comm));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndGeoCheckParameters(MPI_Comm comm, const char geo[], const IndGeoInfo *info, char *params[],
  PetscInt nparams)
{
  char known[IND_GEO_MAX * (IND_NAME_LEN + 2)] = "";

  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < info->nparams; ++k) {
    PetscCall(PetscStrlcat(known, k ? ", " : "", sizeof(known)));
    PetscCall(PetscStrlcat(known, info->params[k], sizeof(known)));
  }
  for (PetscInt i = 0; i < nparams; ++i) {
    const char *eq = strchr(params[i], '=');
    PetscBool   found = PETSC_FALSE;
    char       *end;
    double      v;
    PetscCheck(eq && eq != params[i] && eq[1], comm, PETSC_ERR_ARG_WRONG,
      "-mesh_geo_parameters: '%s' is not name=value", params[i]);
    for (PetscInt k = 0; k < info->nparams && !found; ++k)
      if (strlen(info->params[k]) == (size_t)(eq - params[i]) && !strncmp(info->params[k], params[i],
        (size_t)(eq - params[i]))) found = PETSC_TRUE;
    /* gmsh's own options (Mesh.MeshSizeMax, ...) are settable too */
    if (memchr(params[i], '.', (size_t)(eq - params[i]))) found = PETSC_TRUE;
    PetscCheck(found, comm, PETSC_ERR_ARG_WRONG,
      "-mesh_geo_parameters: '%.*s' is not a parameter of '%s' (gmsh would ignore it); %s%s", (int)(eq - params[i]),
      params[i], geo,
               info->nparams ? "its parameters are: " : "it defines none (DefineConstant[...])", known);
    v = strtod(eq + 1, &end);
    PetscCheck(end != eq + 1 && !*end, comm, PETSC_ERR_ARG_WRONG,
      "-mesh_geo_parameters: '%s' for '%.*s' is not a number", eq + 1, (int)(eq - params[i]), params[i]);
    PetscCheck(isfinite(v), comm, PETSC_ERR_ARG_OUTOFRANGE,
      "-mesh_geo_parameters: '%s' for '%.*s' is not a finite number", eq + 1, (int)(eq - params[i]), params[i]);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

void IndTableLineNormalize(char line[], PetscBool first)
{
  const PetscBool decimal_comma = strchr(line, ';') || strchr(line, '\t') ? PETSC_TRUE : PETSC_FALSE;
  char           *w             = line;

  if (first && (unsigned char)line[0] == 0xef && (unsigned char)line[1] == 0xbb && (unsigned char)line[2] == 0xbf)
    memmove(line, line + 3, strlen(line + 3) + 1);
  for (char *r = line; *r; ++r) {
    if (*r == '\r' || *r == '\n') continue;
    if (*r == ',') *w++ = decimal_comma ? '.' : ' ';
    else if (*r == ';' || *r == '\t') *w++ = ' ';
    else *w++ = *r;
  }
  *w = 0;
}
