#!/usr/bin/env bash
# expect_error.sh [--fresh DIR]... [--keep FILE]... [--absent FILE]... [--after-output] REGEX COMMAND...
# Passes when COMMAND
#   - exits non-zero,
#   - prints (stdout and stderr together) exactly one line, "<program>: error: <message>", matching REGEX;
#     with --after-output, other lines may come before it (a -help listing, a run's step lines), but the
#     error line must be the last and come once, and nothing may look like a PETSc report ("PETSC ERROR",
#     "Configure options", options "not used" or "left") or an MPI banner (MPI_ABORT, "Primary job"),
#   - (after removing every --fresh DIR, an output directory a rerun would otherwise find holding a run)
#   - leaves every --keep FILE byte-identical (FILE is created first, with known content, if missing:
#     a file of an earlier run that a failed run must not touch), and makes no --absent FILE.
# mpiexec's own banner about a non-zero exit is not indent's output: OMPI_MCA_orte_execute_quiet=1 turns it
# off (Open MPI; doc/testing.md, "Bad input"); mpiexec still exits with the failing status.
export OMPI_MCA_orte_execute_quiet=1
keep=()
absent=()
after=0
while [ $# -gt 0 ]; do
  case $1 in
    --keep) keep+=("$2"); shift 2 ;;
    --fresh) rm -rf -- "$2"; shift 2 ;;
    --absent) absent+=("$2"); rm -f -- "$2"; shift 2 ;;
    --after-output) after=1; shift ;;
    *) break ;;
  esac
done
regex=$1
shift
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
for k in "${!keep[@]}"; do
  f=${keep[$k]}
  if [ ! -e "$f" ]; then
    mkdir -p "$(dirname "$f")"
    printf 'an earlier run'"'"'s file, which a failed run must leave as it is\n%s\n' "$f" > "$f"
  fi
  cp -p -- "$f" "$scratch/keep$k"
done

out=$("$@" 2>&1)
status=$?
fail() {
  echo "FAIL: $1"
  echo "--- output of: $*"
  echo "$out" | head -n 30
  exit 1
}
[ $status -ne 0 ] || fail "expected a non-zero exit"
last=$(tail -n 1 <<<"$out")
nlines=$(grep -c '' <<<"$out")
grep -Eq -- '^[a-z-]+: error: ' <<<"$last" || fail "exit $status, but the last line is not '<program>: error: ...'"
grep -Eq -- "$regex" <<<"$last" || fail "exit $status, but the error line does not match /$regex/"
if [ $after -eq 0 ]; then
  [ "$nlines" -eq 1 ] || fail "exit $status, but $nlines lines of output instead of one"
else
  [ "$(grep -Ec -- '^[a-z-]+: error: ' <<<"$out")" -eq 1 ] || fail "more than one error line"
  report='PETSC ERROR|Configure options|not used|Option left|MPI_ABORT|Primary job'
  if grep -Eq -- "$report" <<<"$out"; then
    fail "output resembling a PETSc report or an MPI banner: $(grep -Em1 -- "$report" <<<"$out")"
  fi
fi
for k in "${!keep[@]}"; do
  cmp -s -- "$scratch/keep$k" "${keep[$k]}" || fail "'${keep[$k]}' was changed or removed by the failed run"
done
for f in "${absent[@]}"; do
  [ ! -e "$f" ] || fail "the failed run made '$f'"
done
echo "ok: exit $status, $nlines line(s); $last"
