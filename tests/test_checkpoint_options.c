static const char help[] = "The model options a checkpoint compares: solver, output and run-control options left out,\n"
                           "sorted; the first difference between two sets described by name.\n";

#include <string.h>
#include "ind_checkpoint.h"
#include "unit_report.h"

static void Expect(const char *what, const char *got, const char *want)
{
  const PetscBool ok = strstr(got, want) ? PETSC_TRUE : PETSC_FALSE;
  Report(what, ok ? 0.0 : 1.0, 0.0);
  if (!ok) printf("    got '%s', expected it to contain '%s'\n", got, want);
}

int main(int argc, char **argv)
{
  char *text, what[600];

  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  PetscCall(PetscOptionsClear(NULL));
  PetscCall(PetscOptionsInsertString(NULL,
    "-film_yield 0.3 -ksp_rtol 1e-5 -bc_fixed bottom -output_dir out -restart out "
                                           "-checkpoint_every 5 -quiet -load_depth 60 -contact_friction 0.1 "
                                             "-snes_rtol 1e-9 "
                                           "-mesh_geo_parameters h_tip=4,h_far=250 -op_fraction 0.5 -indenter_axis "
                                             "0,0,-1"));
  PetscCall(IndCheckpointModelOptions(&text));
  Expect("model options sorted, solver/output/run-control ones left out", text,
         "-bc_fixed bottom\n-contact_friction 0.1\n-film_yield 0.3\n-indenter_axis 0,0,-1\n-load_depth 60\n"
         "-mesh_geo_parameters h_tip=4,h_far=250\n");
  Report("nothing else kept", strlen(text) == strlen("-bc_fixed bottom\n-contact_friction 0.1\n-film_yield 0.3\n"
                                                     "-indenter_axis 0,0,-1\n-load_depth 60\n-mesh_geo_parameters "
                                                       "h_tip=4,h_far=250\n")
                                ? 0.0
                                : 1.0,
         0.0);
  PetscCall(PetscFree(text));

  IndCheckpointOptionsDiffer("-a 1\n-b 2\n", "-a 1\n-b 2\n", what, sizeof(what));
  Report("equal sets: no difference", what[0] ? 1.0 : 0.0, 0.0);
  IndCheckpointOptionsDiffer("-a 1\n-b 2\n", "-a 1\n-b 3\n", what, sizeof(what));
  Expect("a changed value names both", what, "made with -b 2, this run gives -b 3");
  IndCheckpointOptionsDiffer("-a 1\n-b 2\n", "-a 1\n", what, sizeof(what));
  Expect("an option the run lacks", what, "made with -b 2, which this run does not give");
  IndCheckpointOptionsDiffer("-a 1\n", "-a 1\n-c 4\n", what, sizeof(what));
  Expect("an option the checkpoint lacks", what, "this run gives -c 4, which the checkpoint was made without");
  IndCheckpointOptionsDiffer("-b 2\n", "-a 1\n-b 2\n", what, sizeof(what));
  Expect("an option the checkpoint lacks, sorted first", what, "this run gives -a 1");
  PetscCall(PetscFinalize());
  return failures ? 1 : 0;
}
