#!/usr/bin/env bash
# expect_error.sh REGEX COMMAND...: passes when COMMAND exits non-zero AND its output matches REGEX.
regex=$1
shift
out=$("$@" 2>&1)
status=$?
if [ $status -eq 0 ]; then
  echo "FAIL: expected a non-zero exit from: $*"
  echo "$out" | tail -n 20
  exit 1
fi
if ! grep -Eq -- "$regex" <<<"$out"; then
  echo "FAIL: exit $status, but the output does not match /$regex/:"
  echo "$out" | grep -E "PETSC ERROR: [A-Za-z]" | head -n 8
  exit 1
fi
echo "ok: exit $status with the expected message: $(grep -Eo -- "$regex.*" <<<"$out" | head -n 1)"
