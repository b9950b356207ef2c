/* -indenter_profile: the table of an indenter of revolution, read on rank 0 and broadcast. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "ind_indenter_profile.h"
#include "ind_files.h"

#define IND_PROFILE_MAX_POINTS 100000

/* Parses the file into pts (pairs r, height with the first height subtracted); on bad input, msg holds the
   one line that says why and the return value is 1. */
static int Parse(const char file[], PetscReal *pts, PetscInt *n, char msg[], size_t len)
{
  FILE    *fp = fopen(file, "r");
  char     line[512];
  PetscInt lineno = 0, data = 0;
  int      header = 0;

  *n = 0;
  if (!fp) {
    snprintf(msg, len, "-indenter_profile '%s': cannot open the file", file);
    return 1;
  }
  while (fgets(line, sizeof(line), fp)) {
    char  *s = line, *end;
    double r, h;
    lineno++;
    IndTableLineNormalize(line, (PetscBool)(lineno == 1));
    while (*s == ' ') ++s;
    if (*s == '#' || *s == 0) continue;
    r = strtod(s, &end);
    if (end == s) {
      if (data == 0 && !header) { /* one header line before the data */
        header = 1;
        continue;
      }
      snprintf(msg, len, "-indenter_profile '%s', line %d: not a pair of numbers r,height (nm)", file, (int)lineno);
      fclose(fp);
      return 1;
    }
    s = end;
    while (*s == ' ') ++s;
    h = strtod(s, &end);
    if (end == s) {
      snprintf(msg, len, "-indenter_profile '%s', line %d: not a pair of numbers r,height (nm)", file, (int)lineno);
      fclose(fp);
      return 1;
    }
    if (data >= IND_PROFILE_MAX_POINTS) {
      snprintf(msg, len, "-indenter_profile '%s': more than %d points", file, IND_PROFILE_MAX_POINTS);
      fclose(fp);
      return 1;
    }
    if (data == 0 && r != 0) {
      snprintf(msg, len, "-indenter_profile '%s', line %d: the first point must be the tip, r = 0 (got %g nm)", file,
               (int)lineno, r);
      fclose(fp);
      return 1;
    }
    if (data > 0 && !(r > pts[2 * data - 2])) {
      snprintf(msg, len, "-indenter_profile '%s', line %d: r must increase from point to point (%g after %g nm)",
               file, (int)lineno, r, (double)pts[2 * data - 2]);
      fclose(fp);
      return 1;
    }
    if (data > 0 && h < pts[2 * data - 1] + pts[1]) {
      snprintf(msg, len,
               "-indenter_profile '%s', line %d: the height must not fall away from the tip (%g after %g nm): the "
               "table is the indenter's lower surface, lowest at r = 0", file, (int)lineno, h,
               (double)(pts[2 * data - 1] + pts[1]));
      fclose(fp);
      return 1;
    }
    pts[2 * data]     = r;
    pts[2 * data + 1] = data == 0 ? h : h - pts[1];
    data++;
  }
  fclose(fp);
  if (data > 0) pts[1] = 0;
  *n = data;
  if (data < 2) {
    snprintf(msg, len, "-indenter_profile '%s': %d point(s); a profile needs at least 2 (r,height per line, nm)", file,
             (int)data);
    return 1;
  }
  if (!(pts[2 * data - 1] > pts[2 * data - 3])) {
    snprintf(msg, len,
             "-indenter_profile '%s': the last segment is flat; past its last point the table goes on along it, which "
             "must rise (a flat punch is -indenter_type flat)", file);
    return 1;
  }
  return 0;
}

PetscErrorCode IndIndenterReadProfile(MPI_Comm comm, const char file[], PetscReal **profile, PetscInt *n)
{
  PetscMPIInt rank;
  PetscReal  *pts = NULL;
  PetscInt    np  = 0;
  char        msg[PETSC_MAX_PATH_LEN + 256] = "";
  int         bad = 0;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (!rank) {
    PetscCall(PetscMalloc1(2 * IND_PROFILE_MAX_POINTS, &pts));
    bad = Parse(file, pts, &np, msg, sizeof(msg));
  }
  PetscCallMPI(MPI_Bcast(&bad, 1, MPI_INT, 0, comm));
  PetscCallMPI(MPI_Bcast(msg, (PetscMPIInt)sizeof(msg), MPI_CHAR, 0, comm));
  if (bad) PetscCall(PetscFree(pts));
  PetscCheck(!bad, comm, PETSC_ERR_USER_INPUT, "%s", msg);
  PetscCallMPI(MPI_Bcast(&np, 1, MPIU_INT, 0, comm));
  if (rank) PetscCall(PetscMalloc1(2 * np, &pts));
  PetscCallMPI(MPI_Bcast(pts, (PetscMPIInt)(2 * np), MPIU_REAL, 0, comm));
  *profile = pts;
  *n       = np;
  PetscFunctionReturn(PETSC_SUCCESS);
}
