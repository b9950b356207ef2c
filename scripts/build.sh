#!/usr/bin/env bash
# Configure and build indent into build/ (or $BUILD_DIR). Assumes the dependencies are installed.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
build=${BUILD_DIR:-$top/build}
mkdir -p "$build"
cmake -S "$top" -B "$build" -DCMAKE_BUILD_TYPE=${CMAKE_BUILD_TYPE:-RelWithDebInfo} > "$build/configure.log" 2>&1 || { cat "$build/configure.log"; exit 1; }
# not OMP_NUM_THREADS's count (scripts/mpi-env.sh sets it to 1), which nproc would give
cmake --build "$build" -j "$(env -u OMP_NUM_THREADS -u OMP_THREAD_LIMIT nproc)"
