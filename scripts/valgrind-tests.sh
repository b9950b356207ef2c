#!/usr/bin/env bash
# Memory hygiene: the unit tests and the small component tests under valgrind memcheck, each on one
# rank with its executable run directly (one also on 2 ranks), the noise of Open MPI and the libraries
# under it suppressed (scripts/valgrind/openmpi.supp). Prints test / exit / errors / definitely lost
# bytes and a verdict; exits 1 on any memcheck error, definitely lost byte or failed test.
#   ./scripts/valgrind-tests.sh [build-dir]    (after scripts/build.sh; default build/)
#   VALGRIND_TESTS_REGEX=patch ./scripts/valgrind-tests.sh    (a subset of those tests)
# Each run leaves its output and valgrind logs in <build-dir>/valgrind/<test>/.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${1:-${BUILD_DIR:-$top/build}}" && pwd)
. "$top/scripts/mpi-env.sh"
exec python3 "$top/scripts/valgrind/memcheck.py" "$build" ${VALGRIND_TESTS_REGEX:+--regex "$VALGRIND_TESTS_REGEX"}
