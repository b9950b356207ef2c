#!/usr/bin/env bash
# Sets up (Debian packages, build) and runs the whole test suite with ctest.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
"$top/scripts/install-deps.sh"
"$top/scripts/build.sh"
. "$top/scripts/mpi-env.sh"
cd "${BUILD_DIR:-$top/build}"
# nproc counts OMP_NUM_THREADS, which mpi-env.sh sets to 1 for the tests' BLAS: without this the suite ran one test
# at a time
ctest -j "$(env -u OMP_NUM_THREADS -u OMP_THREAD_LIMIT nproc)" --output-on-failure "$@"
