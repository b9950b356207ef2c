#include <ctype.h>
#include "material_impl.h"
#include "ind_material.h"
#include "ind_elasticity.h"
#include "ind_hardening.h"
#include "ind_densification.h"

const char *const IndModelTypes[] = {"elastic", "plastic", "densifying", "IndModel", "IND_MODEL_", NULL};

static PetscErrorCode ReadPlastic(MPI_Comm comm, const char prefix[], IndMaterial *m)
{
  IndPlasticParams *pp = &m->plastic;
  char              title[2 * IND_NAME_LEN + 64];

  PetscFunctionBeginUser;
  PetscCall(PetscSNPrintf(title, sizeof(title), IND_TITLE "Plasticity of volume region '%s' (-%smodel plastic)",
    m->region, prefix));
  PetscOptionsBegin(comm, prefix, title, "Material");
  {
    char name[IND_NAME_LEN], option[2 * IND_NAME_LEN];
    PetscCall(IndOptionsType("-hardening", "Isotropic hardening law", &IndHardeningRegistry, "voce", name,
                             sizeof(name), NULL));
    PetscCall(PetscSNPrintf(option, sizeof(option), "-%shardening", prefix));
    PetscCall(IndHardeningFind(comm, option, name, &pp->law));
  }
  PetscCall(pp->law->read(PetscOptionsObject, comm, m->region, pp));
  PetscCall(IndOptionsReal("-kinematic", "Prager kinematic hardening modulus H", "GPa", NULL, pp->H, &pp->H, NULL));
  PetscCall(IndOptionsInt("-return_max_it", "Iteration cap of the scalar return-map solve", "0, meaning 100",
    pp->max_iterations, &pp->max_iterations, NULL));
  PetscOptionsEnd();
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The ellipse of ind_densification.h: no hardening law; the options name its own parameters. */
static PetscErrorCode ReadDensifying(MPI_Comm comm, const char prefix[], IndMaterial *m)
{
  IndPlasticParams *pp = &m->plastic;
  char              title[2 * IND_NAME_LEN + 64];
  PetscBool         has_yield, has_pc;

  PetscFunctionBeginUser;
  PetscCall(PetscSNPrintf(title, sizeof(title), IND_TITLE "Densifying plasticity of volume region '%s' (-%smodel "
    "densifying)", m->region, prefix));
  PetscOptionsBegin(comm, prefix, title, "Material");
  PetscCall(IndOptionsReal("-yield", "von Mises stress at which it yields without pressure", "GPa", IND_REQUIRED,
    pp->R0, &pp->R0, &has_yield));
  PetscCall(IndOptionsReal("-yield_pressure", "Pressure at which it yields (compacts) without shear", "GPa",
    IND_REQUIRED, pp->yield_pressure, &pp->yield_pressure, &has_pc));
  PetscCall(IndOptionsReal("-densification_modulus", "Growth of the yield pressure with compaction -tr(eps_p)",
    "GPa", NULL, pp->densification_modulus, &pp->densification_modulus, NULL));
  PetscCall(IndOptionsInt("-return_max_it", "Iteration cap of the scalar return-map solve", "0, meaning 100",
    pp->max_iterations, &pp->max_iterations, NULL));
  PetscOptionsEnd();
  if (IndHelpListing()) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCheck(has_yield, comm, PETSC_ERR_ARG_WRONG, "Region '%s' is densifying: option -%syield (GPa) is missing",
    m->region, prefix);
  PetscCheck(has_pc, comm, PETSC_ERR_ARG_WRONG,
    "Region '%s' is densifying: option -%syield_pressure (GPa) is missing", m->region, prefix);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A volume's name prefixes its options (-film_young): a blank or a sign the command line or an options file would
   split it at ('thin film') makes them impossible to give, so the name is refused with one that would do. */
static PetscErrorCode CheckPrefixName(MPI_Comm comm, const char region[])
{
  char   better[IND_NAME_LEN];
  size_t k = 0, bad = 0;

  PetscFunctionBeginUser;
  for (; region[k] && k + 1 < sizeof(better); ++k) {
    const PetscBool ok = (PetscBool)(isalnum((unsigned char)region[k]) || region[k] == '_' || region[k] == '-' ||
                                     region[k] == '.');
    better[k] = ok ? region[k] : '_';
    bad += !ok;
  }
  better[k] = 0;
  PetscCheck(!bad, comm, PETSC_ERR_USER_INPUT,
    "Volume region '%s' cannot name options (-%s_young): a volume's physical name may hold letters, digits, '_', '-' "
    "and '.'; rename it in the mesh (e.g. '%s')", region, region, better);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* hint ends the message of a missing material: on the default box, what a first run without options needs */
static PetscErrorCode ReadMaterial(MPI_Comm comm, const char region[], const char hint[], IndMaterial *m)
{
  char      prefix[IND_NAME_LEN + 2], opt[IND_NAME_LEN + 32], title[2 * IND_NAME_LEN + 64];
  PetscBool has_E, has_nu;

  PetscFunctionBeginUser;
  PetscCall(CheckPrefixName(comm, region));
  PetscCall(PetscStrncpy(m->region, region, sizeof(m->region)));
  PetscCall(PetscSNPrintf(prefix, sizeof(prefix), "%s_", region));
  PetscCall(PetscSNPrintf(title, sizeof(title), IND_TITLE "Material of volume region '%s' (-%s*)", region, prefix));
  PetscOptionsBegin(comm, prefix, title, "Material");
  PetscCall(IndOptionsReal("-young", "Young's modulus", "GPa", IND_REQUIRED, m->young, &m->young, &has_E));
  PetscCall(IndOptionsReal("-poisson", "Poisson's ratio", "", IND_REQUIRED, m->poisson, &m->poisson, &has_nu));
  PetscCall(IndOptionsEnum("-model", "Constitutive model", IndModelTypes, (PetscEnum)m->model, (PetscEnum *)&m->model,
    NULL));
  PetscOptionsEnd();
  if (IndHelpListing()) { /* the listing reads, it does not judge */
    if (m->model == IND_MODEL_PLASTIC) PetscCall(ReadPlastic(comm, prefix, m));
    if (m->model == IND_MODEL_DENSIFYING) PetscCall(ReadDensifying(comm, prefix, m));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(PetscSNPrintf(opt, sizeof(opt), "-%syoung", prefix));
  PetscCheck(has_E, comm, PETSC_ERR_ARG_WRONG, "Region '%s' needs a material: option %s (GPa) is missing%s", region, opt,
    hint);
  PetscCheck(m->young > 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "%s must be > 0 (GPa), got %g", opt, (double)m->young);
  PetscCall(PetscSNPrintf(opt, sizeof(opt), "-%spoisson", prefix));
  PetscCheck(has_nu, comm, PETSC_ERR_ARG_WRONG, "Region '%s' needs a material: option %s is missing", region, opt);
  PetscCheck(m->poisson > -1.0 && m->poisson < 0.5, comm, PETSC_ERR_ARG_OUTOFRANGE,
    "%s must lie in (-1, 0.5), got %g", opt, (double)m->poisson);
  IndElasticModuli(m->young, m->poisson, &m->kappa, &m->mu);
  m->plastic.kappa        = m->kappa;
  m->plastic.mu           = m->mu;
  m->plastic.elastic_only = m->model == IND_MODEL_ELASTIC ? PETSC_TRUE : PETSC_FALSE;
  if (m->model == IND_MODEL_DENSIFYING) {
    PetscCall(ReadDensifying(comm, prefix, m));
    PetscCall(IndDensifyingParamsCheck(&m->plastic, prefix, comm));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  if (m->model == IND_MODEL_PLASTIC) PetscCall(ReadPlastic(comm, prefix, m));
  PetscCall(IndPlasticParamsCheck(&m->plastic, prefix, comm));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode IndMaterialsCreate(IndMesh mesh, IndDisc space, IndMaterials *out)
{
  IndMaterials         mats;
  DM                   dm;
  MPI_Comm             comm;
  PetscInt             unassigned = 0, first = -1, nregions;
  const IndRegion     *regions;
  const char          *source;
  const IndDiscLayout *disc;

  PetscFunctionBeginUser;
  PetscCall(IndMeshGetDM(mesh, &dm));
  PetscCall(IndMeshGetRegions(mesh, &nregions, &regions));
  PetscCall(IndMeshGetSource(mesh, &source));
  PetscCall(IndDiscGetLayout(space, &disc));
  comm = PetscObjectComm((PetscObject)dm);
  PetscCall(PetscCalloc1(1, &mats));
  PetscCall(PetscMalloc1(disc->ncell, &mats->cell_material));
  for (PetscInt i = 0; i < disc->ncell; ++i) mats->cell_material[i] = -1;
  for (PetscInt r = 0; r < nregions; ++r) {
    DMLabel label;
    IS      cells;
    if (regions[r].dim != 3) continue;
    if (!IndHelpListing()) PetscCall(IndMeshCheckRegionNotEmpty(mesh, regions[r].name, 3, NULL));
    PetscCall(ReadMaterial(comm, regions[r].name,
      strcmp(source, "box") ? "" : " (with no -mesh_file indent takes PETSc's box mesh, one region 'domain'; the "
      "paper's case is -options_file inputs/berkovich.opts, and -help lists every option)", &mats->mat[mats->n]));
    PetscCall(DMGetLabel(dm, regions[r].name, &label));
    PetscCall(DMLabelGetStratumIS(label, 1, &cells));
    if (cells) {
      const PetscInt *c;
      PetscInt        n;
      PetscCall(ISGetLocalSize(cells, &n));
      PetscCall(ISGetIndices(cells, &c));
      for (PetscInt k = 0; k < n; ++k) {
        PetscInt i = c[k] - disc->cStart;
        if (i < 0 || i >= disc->ncell) continue;
        PetscCheck(mats->cell_material[i] < 0, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG,
          "Cell %" PetscInt_FMT " lies in two volume regions, '%s' and '%s'", c[k],
          mats->mat[mats->cell_material[i]].region, regions[r].name);
        mats->cell_material[i] = mats->n;
      }
      PetscCall(ISRestoreIndices(cells, &c));
      PetscCall(ISDestroy(&cells));
    }
    mats->n++;
  }
  for (PetscInt i = 0; i < disc->ncell; ++i)
    if (mats->cell_material[i] < 0) {
      if (!unassigned++) first = disc->cStart + i;
    }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &unassigned, 1, MPIU_INT, MPI_SUM, comm));
  PetscCheck(!unassigned || IndHelpListing(), comm, PETSC_ERR_ARG_WRONG,
    "%" PetscInt_FMT " cells of mesh '%s' (e.g. local cell %" PetscInt_FMT ") belong to no physical volume: give every "
    "volume a physical name in gmsh", unassigned, source, first);
  *out = mats;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscBool IndMaterialsArePlastic(IndMaterials mats)
{
  for (PetscInt k = 0; k < mats->n; ++k)
    if (mats->mat[k].model != IND_MODEL_ELASTIC) return PETSC_TRUE;
  return PETSC_FALSE;
}

PetscBool IndMaterialsHaveBackStress(IndMaterials mats)
{
  for (PetscInt k = 0; k < mats->n; ++k)
    if (mats->mat[k].model != IND_MODEL_ELASTIC && mats->mat[k].plastic.H > 0) return PETSC_TRUE;
  return PETSC_FALSE;
}

PetscBool IndMaterialsAreDensifying(IndMaterials mats)
{
  for (PetscInt k = 0; k < mats->n; ++k)
    if (mats->mat[k].model == IND_MODEL_DENSIFYING) return PETSC_TRUE;
  return PETSC_FALSE;
}

PetscErrorCode IndMaterialsDestroy(IndMaterials *mats)
{
  PetscFunctionBeginUser;
  if (!*mats) PetscFunctionReturn(PETSC_SUCCESS);
  for (PetscInt k = 0; k < (*mats)->n; ++k) {
    IndPlasticParams *pp = &(*mats)->mat[k].plastic;
    if (pp->law && pp->law->destroy) PetscCall(pp->law->destroy(pp));
  }
  PetscCall(PetscFree((*mats)->cell_material));
  PetscCall(PetscFree(*mats));
  PetscFunctionReturn(PETSC_SUCCESS);
}

IND_GETTER(PetscInt, IndMaterialsGetCount, IndMaterials, o->n)

const IndMaterial *IndMaterialsGet(IndMaterials mats, PetscInt k)
{
  return &mats->mat[k];
}
