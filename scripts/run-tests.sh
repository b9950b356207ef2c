#!/usr/bin/env bash
# Sets up (Debian packages, build) and runs the whole test suite with ctest.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
"$top/scripts/install-deps.sh"
"$top/scripts/build.sh"
. "$top/scripts/mpi-env.sh"
cd "${BUILD_DIR:-$top/build}"
ctest -j "$(nproc)" --output-on-failure "$@"
