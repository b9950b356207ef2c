#pragma once
/* indent's own options (options.c) and their -help listing (help.c).

   Every option indent reads goes through these wrappers of PetscOptions*() (between PetscOptionsBegin and
   PetscOptionsEnd). Before PETSc converts a value they check it and stop with one line naming the option:
   a number that does not parse ("-load_depth: '60nm' is not a number (nm)"), a real that is not finite
   (inf, nan), an integer, boolean or choice that does not parse, too many values in a list. Ranges
   (> 0, in (-1, 0.5), ...) stay with the modules, which know them.

   With -help each prints one line of its own instead of PETSc's:
     -load_depth <nm>: Largest indenter depth, reached at the end of loading (required with -indenter_type; given: 60)
   with the unit or type in the angle brackets and, in the parentheses, "required ..." or the default
   (dflt: NULL shows the current value as the default, a text starting with "required" is shown as is,
   any other text is shown as "default: <text>"), then the value given on the command line if any.
   Groups whose title starts with IND_TITLE are indent's: -help prints them first (help.c). */
#include <petscsys.h>
#include "ind_registry.h"

#define IND_TITLE     "indent: "
#define IND_HELP_MARK "\037"
#define IND_REQUIRED  "required"

PetscErrorCode IndOptionsReal_Private(PetscOptionItems *, const char opt[], const char text[], const char units[],
  const char dflt[], PetscReal cur, PetscReal *value, PetscBool *set);
PetscErrorCode IndOptionsInt_Private(PetscOptionItems *, const char opt[], const char text[], const char dflt[],
  PetscInt cur, PetscInt *value, PetscBool *set);
PetscErrorCode IndOptionsBool_Private(PetscOptionItems *, const char opt[], const char text[], PetscBool cur,
  PetscBool *value, PetscBool *set);
PetscErrorCode IndOptionsEnum_Private(PetscOptionItems *, const char opt[], const char text[], const char *const *list,
  PetscEnum cur, PetscEnum *value, PetscBool *set);
PetscErrorCode IndOptionsEList_Private(PetscOptionItems *, const char opt[], const char text[],
  const char *const *list, PetscInt n, PetscInt cur, PetscInt *value, PetscBool *set);
PetscErrorCode IndOptionsType_Private(PetscOptionItems *, const char opt[], const char text[],
  IndRegistry *registry, const char cur[], char value[], size_t len, PetscBool *set);
PetscErrorCode IndOptionsString_Private(PetscOptionItems *, const char opt[], const char text[], const char what[],
  const char dflt[], const char cur[], char value[], size_t len, PetscBool *set);
PetscErrorCode IndOptionsStringArray_Private(PetscOptionItems *, const char opt[], const char text[],
  const char what[], char *values[], PetscInt *n, PetscBool *set);
PetscErrorCode IndOptionsRealArray_Private(PetscOptionItems *, const char opt[], const char text[], const char what[],
  const char dflt[], PetscReal values[], PetscInt *n, PetscBool *set);
PetscErrorCode IndOptionsIntArray_Private(PetscOptionItems *, const char opt[], const char text[], const char what[],
  const char dflt[], PetscInt values[], PetscInt *n, PetscBool *set);

/* opt "-name"; units of a real ("nm", "GPa", "degrees", "" dimensionless); what names a string's or
   list's kind ("file", "surface,...", "x,y in nm"). Array sizes: *n in is the most values, out the number read. */
#define IndOptionsReal(opt, text, units, dflt, cur, value, set) \
  IndOptionsReal_Private(PetscOptionsObject, opt, text, units, dflt, cur, value, set)
#define IndOptionsInt(opt, text, dflt, cur, value, set) \
  IndOptionsInt_Private(PetscOptionsObject, opt, text, dflt, cur, value, set)
#define IndOptionsBool(opt, text, cur, value, set) \
  IndOptionsBool_Private(PetscOptionsObject, opt, text, cur, value, set)
#define IndOptionsEnum(opt, text, list, cur, value, set) \
  IndOptionsEnum_Private(PetscOptionsObject, opt, text, list, cur, value, set)
#define IndOptionsEList(opt, text, list, n, cur, value, set) \
  IndOptionsEList_Private(PetscOptionsObject, opt, text, list, n, cur, value, set)
/* A name of the registry (an implementation chosen by its option, as -ksp_type): one of its names. */
#define IndOptionsType(opt, text, registry, cur, value, len, set) \
  IndOptionsType_Private(PetscOptionsObject, opt, text, registry, cur, value, len, set)
#define IndOptionsString(opt, text, what, dflt, cur, value, len, set) \
  IndOptionsString_Private(PetscOptionsObject, opt, text, what, dflt, cur, value, len, set)
#define IndOptionsStringArray(opt, text, what, values, n, set) \
  IndOptionsStringArray_Private(PetscOptionsObject, opt, text, what, values, n, set)
#define IndOptionsRealArray(opt, text, what, dflt, values, n, set) \
  IndOptionsRealArray_Private(PetscOptionsObject, opt, text, what, dflt, values, n, set)
#define IndOptionsIntArray(opt, text, what, dflt, values, n, set) \
  IndOptionsIntArray_Private(PetscOptionsObject, opt, text, what, dflt, values, n, set)

/* Errors on options nobody read, except those PETSc only reads lazily (see options.c). */
PetscErrorCode IndOptionsCheckUnused(MPI_Comm comm);
/* Before the set-up reads any option: an option written with '=' ("-film_young=70", which PETSc takes for an option
   of that whole name and no value) is an error that says how to write it, before the option it meant is reported
   missing. */
PetscErrorCode IndOptionsCheckSpelling(MPI_Comm comm);

/* -help (help.c). IndHelpCaptureBegin() goes before PetscInitialize(): it collects what PETSc and indent
   print for -help. IndHelpCaptureEnd(), after PetscInitialize(), keeps collecting with -help and otherwise
   prints what was collected (-version) and stops. IndHelpPrint(), at the end of a -help run, prints on
   rank 0 the program's intro, indent's groups, then PETSc's. */
void           IndHelpCaptureBegin(void);
PetscErrorCode IndHelpCaptureEnd(void);
PetscErrorCode IndHelpPrint(const char intro[]);
/* Whether this run only lists its options (-help): it reads every option, builds what it must to know
   which options apply (a .geo is not meshed: see mesh.c), solves nothing and writes no file. */
PetscBool      IndHelpListing(void);
/* A silent listing (no -help): the set-up reads every option as a listing does, without meshing a .geo
   or writing a file, so that its unknown-option check comes before the real set-up's work. */
void           IndHelpSetChecking(PetscBool on);
