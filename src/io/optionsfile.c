#define _XOPEN_SOURCE 700 /* mkstemp */
#include <ctype.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "ind_optionsfile.h"

static const unsigned char BOM[3] = {0xef, 0xbb, 0xbf};

/* Before MPI starts, the launchers' variables tell the rank: one line, not one per rank. */
static int FirstRank(void)
{
  const char *names[] = {"OMPI_COMM_WORLD_RANK", "PMI_RANK", "PMIX_RANK", "MV2_COMM_WORLD_RANK", "SLURM_PROCID"};
  for (size_t k = 0; k < sizeof(names) / sizeof(names[0]); ++k) {
    const char *v = getenv(names[k]);
    if (v && v[0]) return atoi(v) == 0;
  }
  return 1;
}

/* The file's reason to be refused ("" when it is a readable regular file), and whether it starts with
   a byte-order mark. */
static void Inspect(const char path[], char why[], size_t len, int *bom)
{
  struct stat    st;
  unsigned char  head[3] = {0, 0, 0};
  FILE          *fp;

  why[0] = 0;
  *bom   = 0;
  if (stat(path, &st)) {
    snprintf(why, len, "%s", strerror(errno));
    return;
  }
  if (S_ISDIR(st.st_mode)) {
    snprintf(why, len, "it is a directory");
    return;
  }
  if (!S_ISREG(st.st_mode)) {
    snprintf(why, len, "it is not a regular file");
    return;
  }
  fp = fopen(path, "rb");
  if (!fp) {
    snprintf(why, len, "%s", strerror(errno));
    return;
  }
  *bom = fread(head, 1, 3, fp) == 3 && !memcmp(head, BOM, 3);
  fclose(fp);
}

/* A copy of path without its first three bytes, in the system's temporary directory. */
static int CopyWithoutBOM(const char path[], char copy[], size_t len, char why[], size_t wlen)
{
  const char *dir = getenv("TMPDIR");
  FILE       *in, *out;
  char        buf[8192];
  size_t      n;
  int         fd;

  /* the six trailing characters are mkstemp's template, which it replaces by a unique name */
  snprintf(copy, len, "%s/indent-options-%s", dir && dir[0] ? dir : "/tmp", "XXXXXX");
  fd = mkstemp(copy);
  if (fd < 0) {
    snprintf(why, wlen, "it starts with a byte-order mark, and no copy without it could be made: %s", strerror(errno));
    return 1;
  }
  out = fdopen(fd, "wb");
  in  = fopen(path, "rb");
  if (!out || !in || fseek(in, 3, SEEK_SET)) {
    snprintf(why, wlen, "%s", strerror(errno));
    if (in) fclose(in);
    if (out) fclose(out);
    unlink(copy);
    return 1;
  }
  while ((n = fread(buf, 1, sizeof(buf), in)) > 0)
    if (fwrite(buf, 1, n, out) != n) break;
  fclose(in);
  if (fclose(out)) {
    snprintf(why, wlen, "%s", strerror(errno));
    unlink(copy);
    return 1;
  }
  return 0;
}

int IndOptionsFilesPrepare(const char program[], int argc, char **argv, IndOptionsFileCopies *copies)
{
  copies->n = 0;
  for (int k = 1; k < argc; ++k) {
    char why[PETSC_MAX_PATH_LEN + 128];
    int  bom;
    if (strcmp(argv[k], "-options_file")) continue;
    if (k + 1 >= argc || argv[k + 1][0] == '-') {
      if (FirstRank()) fprintf(stderr, "%s: error: -options_file needs a file name\n", program);
      return 1;
    }
    Inspect(argv[k + 1], why, sizeof(why), &bom);
    if (!why[0] && bom && copies->n < IND_MAX_OPTIONS_FILES) {
      char *copy = copies->path[copies->n];
      if (!CopyWithoutBOM(argv[k + 1], copy, sizeof(copies->path[0]), why, sizeof(why))) {
        argv[k + 1] = copy; /* PETSc reads the copy: UTF-8 text without its mark */
        copies->n++;
      }
    }
    if (why[0]) {
      if (FirstRank()) fprintf(stderr, "%s: error: -options_file '%s': %s\n", program, argv[k + 1], why);
      IndOptionsFilesRemoveCopies(copies);
      return 1;
    }
    ++k;
  }
  return 0;
}

void IndOptionsFilesRemoveCopies(IndOptionsFileCopies *copies)
{
  for (int k = 0; k < copies->n; ++k) unlink(copies->path[k]);
  copies->n = 0;
}

/* PETSc's test for an option's name (PetscOptionsValidKey): '-', an optional second '-', then a letter; so "-5" is a
   value. */
static int IsKey(const char s[])
{
  if (s[0] != '-') return 0;
  if (s[1] == '-') ++s;
  return isalpha((unsigned char)s[1]) != 0;
}

int IndArgsCheckStray(const char program[], int argc, char **argv)
{
  /* PETSc's own walk over the arguments (PetscOptionsInsertArgs): a key takes the next word as its value unless
     that is a key too; -prefix_pop takes none, -options_file and -prefix_push always one. A word that is neither,
     PETSc skips without a word: an unquoted value with a space ("-mesh_geo_parameters a=1, b=2") would lose its
     second half. */
  for (int k = 1; k < argc; ++k) {
    if (!IsKey(argv[k])) {
      if (FirstRank()) {
        if (k > 2 && !IsKey(argv[k - 1]))
          fprintf(stderr, "%s: error: '%s' after '%s %s' is not an option, and an option takes one value: quote a "
                  "value that holds spaces, or write a list without them (a=1,b=2)\n", program, argv[k], argv[k - 2],
                  argv[k - 1]);
        else fprintf(stderr, "%s: error: '%s' is not an option (options start with '-')\n", program, argv[k]);
      }
      return 1;
    }
    if (!strcmp(argv[k], "-prefix_pop")) continue;
    if (k + 1 < argc && (!IsKey(argv[k + 1]) || !strcmp(argv[k], "-options_file") || !strcmp(argv[k], "-prefix_push")))
      ++k;
  }
  return 0;
}
