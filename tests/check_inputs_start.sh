#!/bin/bash
# Every options file given starts a run (its mesh made, its options all used, two load steps solved) on 2 ranks:
# stopped after step 2 with indent's checkpoint status 75. Catches a model file that no longer runs (an option
# renamed or left unused) before a fit's forty forward runs fail on it.
#   check_inputs_start.sh MPIEXEC INDENT WORKDIR FILE.opts...
set -u
mpiexec=$1 indent=$2 work=$3
shift 3
status=0
for opts in "$@"; do
  name=$(basename "$opts" .opts)
  out=$work/$name
  mkdir -p "$out"
  "$mpiexec" -n 2 "$indent" -options_file "$opts" -output_fields 0 -quiet -output_overwrite -output_dir "$out" \
    -checkpoint_stop_after_step 2 > "$out.log" 2>&1
  rc=$?
  if [[ $rc -eq 75 ]] && grep -q "after step 2" "$out.log"; then
    echo "ok: $name ran 2 steps"
  else
    echo "FAIL: $name exited with $rc:"
    tail -n 5 "$out.log"
    status=1
  fi
done
exit $status
