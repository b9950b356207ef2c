#!/usr/bin/env bash
# Sets up (Debian packages, build) and runs the default example on 2 ranks.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
"$top/scripts/install-deps.sh"
"$top/scripts/build.sh"
. "$top/scripts/mpi-env.sh"
cd "$top"
mpiexec -n 2 "${BUILD_DIR:-$top/build}/indent" -options_file inputs/plastic_block.opts "$@"
echo "Output: indent.xdmf (open in ParaView) and indent.h5 in -output_dir (inputs/plastic_block.opts: output/plastic_block)"
