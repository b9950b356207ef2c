#include <stdio.h>
#include <string.h>
#include "ind_hardening.h"
#include "ind_common.h"
#include "ind_options.h"
#include "ind_files.h"

/* A tabulated curve: the stress R (GPa) against the equivalent plastic strain p, from a tensile test (true
   stress against true plastic strain), piecewise linear between its points. Past the last point the stress is
   held (flat, as Abaqus does) or grows with the last segment's slope (-<region>_hardening_beyond slope). */
#define BEYOND_SLOPE(m) ((m)->c[0] != 0)

/* The segment holding p: i with table[2 i] <= p (the last point's index past the end). */
static PetscInt Segment(const IndPlasticParams *m, PetscReal p)
{
  PetscInt lo = 0, hi = m->ntable - 1;
  if (p >= m->table[2 * hi]) return hi;
  while (hi - lo > 1) {
    const PetscInt mid = (lo + hi) / 2;
    if (m->table[2 * mid] <= p) lo = mid;
    else hi = mid;
  }
  return lo;
}

static PetscReal Slope(const IndPlasticParams *m, PetscInt i)
{
  const PetscReal *a = m->table + 2 * i;
  return (a[3] - a[1]) / (a[2] - a[0]);
}

static PetscReal dR(const IndPlasticParams *m, PetscReal p)
{
  const PetscInt i = Segment(m, p);
  if (i == m->ntable - 1) return BEYOND_SLOPE(m) ? Slope(m, i - 1) : 0.0;
  return Slope(m, i);
}

static PetscReal R(const IndPlasticParams *m, PetscReal p)
{
  const PetscInt i = Segment(m, p);
  return m->table[2 * i + 1] + dR(m, p) * (p - m->table[2 * i]);
}

/* The next line of text from *s (without its newline) into line; *s moves past it. */
static PetscBool NextLine(const char **s, char *line, size_t len)
{
  size_t k = 0;
  if (!**s) return PETSC_FALSE;
  while (**s && **s != '\n') {
    if (k + 1 < len && **s != '\r') line[k++] = **s;
    ++*s;
  }
  if (**s) ++*s;
  line[k] = 0;
  return PETSC_TRUE;
}

PetscErrorCode IndHardeningTableParse(MPI_Comm comm, const char text[], const char what[], PetscInt *n,
                                      PetscReal **points)
{
  const char *s = text;
  char        line[512];
  PetscInt    cap = 16, lineno = 0, header = 0;

  PetscFunctionBeginUser;
  *n = 0;
  PetscCall(PetscMalloc1(2 * cap, points));
  while (NextLine(&s, line, sizeof(line))) {
    double a, b;
    char   rest[2];
    ++lineno;
    IndTableLineNormalize(line, (PetscBool)(lineno == 1));
    if (!line[strspn(line, " ")] || line[strspn(line, " ")] == '#') continue;
    if (sscanf(line, "%lf %lf %1s", &a, &b, rest) != 2) {
      /* one header line before the first point: names of the columns */
      PetscCheck(!*n && !header++, comm, PETSC_ERR_FILE_UNEXPECTED,
                 "%s, line %" PetscInt_FMT ": '%s' is not two numbers (plastic strain, stress in GPa)", what, lineno,
                 line);
      continue;
    }
    if (*n == cap) {
      PetscReal *more;
      PetscCall(PetscMalloc1(4 * cap, &more));
      PetscCall(PetscArraycpy(more, *points, 2 * cap));
      PetscCall(PetscFree(*points));
      *points = more;
      cap *= 2;
    }
    PetscCheck(*n || a == 0, comm, PETSC_ERR_FILE_UNEXPECTED,
               "%s, line %" PetscInt_FMT ": the curve starts at plastic strain %g; its first point must be at 0", what,
               lineno, a);
    PetscCheck(!*n || a > (*points)[2 * *n - 2], comm, PETSC_ERR_FILE_UNEXPECTED,
               "%s, line %" PetscInt_FMT ": the plastic strain does not increase (%g after %g)", what, lineno, a,
               (double)(*points)[2 * *n - 2]);
    PetscCheck(!*n || b >= (*points)[2 * *n - 1], comm, PETSC_ERR_FILE_UNEXPECTED,
               "%s, line %" PetscInt_FMT ": the stress falls from %g to %g GPa; the curve must not fall", what, lineno,
               (double)(*points)[2 * *n - 1], b);
    (*points)[2 * *n]     = a;
    (*points)[2 * *n + 1] = b;
    ++*n;
  }
  PetscCheck(*n >= 2, comm, PETSC_ERR_FILE_UNEXPECTED, "%s holds %" PetscInt_FMT " point%s; a curve needs at least 2",
             what, *n, *n == 1 ? "" : "s");
  PetscCheck((*points)[1] > 0, comm, PETSC_ERR_FILE_UNEXPECTED,
             "%s: the stress at zero plastic strain (the yield stress) must be > 0 GPa, got %g", what,
             (double)(*points)[1]);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The file's text, read on rank 0 and given to every rank (PetscFree). */
static PetscErrorCode ReadText(MPI_Comm comm, const char option[], const char path[], char **text)
{
  PetscMPIInt rank;
  long        len = -1;
  FILE       *fp  = NULL;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (!rank && (fp = fopen(path, "rb"))) {
    if (fseek(fp, 0, SEEK_END) == 0) len = ftell(fp);
    rewind(fp);
  }
  PetscCallMPI(MPI_Bcast(&len, 1, MPI_LONG, 0, comm));
  PetscCheck(len >= 0 && len < (1L << 26), comm, PETSC_ERR_FILE_OPEN, "%s: cannot read '%s'%s", option, path,
             len >= 0 ? " (larger than 64 MB)" : "");
  PetscCall(PetscCalloc1(len + 1, text));
  if (!rank && fread(*text, 1, (size_t)len, fp) != (size_t)len) len = -1;
  if (fp) fclose(fp);
  PetscCallMPI(MPI_Bcast(&len, 1, MPI_LONG, 0, comm));
  PetscCheck(len >= 0, comm, PETSC_ERR_FILE_READ, "%s: cannot read '%s'", option, path);
  PetscCallMPI(MPI_Bcast(*text, (int)len, MPI_CHAR, 0, comm));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Read(PetscOptionItems *PetscOptionsObject, MPI_Comm comm, const char region[],
                           IndPlasticParams *m)
{
  const char *const beyond[] = {"flat", "slope"};
  char              path[PETSC_MAX_PATH_LEN] = "", option[IND_NAME_LEN + 32], what[PETSC_MAX_PATH_LEN + 64];
  PetscInt          rule = 0, n;
  PetscBool         set;
  char             *text;
  PetscReal        *points;

  PetscFunctionBeginUser;
  PetscCall(IndOptionsString("-hardening_file", "Tabulated curve: CSV of plastic strain, stress (GPa)", "file",
                             IND_REQUIRED " with table", path, path, sizeof(path), &set));
  PetscCall(IndOptionsEList("-hardening_beyond", "Past the table's last point: the stress held, or its last slope",
                            beyond, 2, rule, &rule, NULL));
  if (IndHelpListing()) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(IndHardeningRequire(comm, region, "hardening_file", set, "CSV of plastic strain, stress in GPa"));
  PetscCall(PetscSNPrintf(option, sizeof(option), "-%s_hardening_file", region));
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s '%s'", option, path));
  PetscCall(ReadText(comm, option, path, &text));
  PetscCall(IndHardeningTableParse(comm, text, what, &n, &points));
  PetscCall(PetscFree(text));
  IndHardeningSetTable(m, n, points, rule == 1 ? PETSC_TRUE : PETSC_FALSE);
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Check(const IndPlasticParams *m, const char pre[], MPI_Comm comm)
{
  PetscFunctionBeginUser;
  PetscCheck(m->table && m->ntable >= 2, comm, PETSC_ERR_ARG_WRONGSTATE, "-%shardening table has no curve", pre);
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Destroy(IndPlasticParams *m)
{
  PetscReal *points = (PetscReal *)m->table; /* its own: Read allocated it */

  PetscFunctionBeginUser;
  PetscCall(PetscFree(points));
  m->table = NULL;
  m->ntable = 0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

const IndHardeningLaw *IndHardeningTable(void)
{
  static const IndHardeningLaw law = {"table", R, dR, Read, Check, Destroy};
  return &law;
}

void IndHardeningSetTable(IndPlasticParams *m, PetscInt n, const PetscReal *points, PetscBool slope_beyond)
{
  m->law    = IndHardeningTable();
  m->table  = points;
  m->ntable = n;
  m->c[0]   = slope_beyond ? 1.0 : 0.0;
  m->R0     = points[1];
}
