#!/usr/bin/env bash
# Sets up (Debian packages, build) and runs the default example on 2 ranks: the mesh-converged
# paper's case (160k dofs: Berkovich into a 300 nm aluminium film on silicon, with friction; gmsh mesh),
# then prints its summary and makes the plots. Extra arguments go to indent, e.g. a finer mesh:
#   ./scripts/run-example.sh -mesh_geo_parameters h_tip=10,h_far=250
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
"$top/scripts/install-deps.sh"
"$top/scripts/build.sh"
. "$top/scripts/mpi-env.sh"
cd "$top"
out=output/berkovich_h4
# An interrupted example continues from its last checkpoint (every 10 steps, or on SIGUSR1 to mpiexec); a finished one is
# replaced (indent itself refuses to overwrite a run unless told to).
if [ -f "$out/checkpoint.h5" ]; then again=(-restart "$out"); else again=(-output_overwrite); fi
mpiexec -n 2 "${BUILD_DIR:-$top/build}/indent" -options_file inputs/berkovich.opts \
  -mesh_geo_parameters h_tip=4,h_far=250 -output_dir "$out" "${again[@]}" "$@"
/usr/bin/python3 scripts/plot-indent.py "$out"
echo "Output in $out: load_displacement.csv, summary.txt, plots (*.png), imprint.csv, indent.xdmf + indent.h5 (ParaView); guide: doc/paper-case.md"
