#!/usr/bin/env bash
# The history stores a back stress only when some material hardens kinematically: a checkpoint made with a
# Prager modulus continues with it, and a restart without one (the other layout) is refused in one line (by the
# check of the model's options, before the history's own check of its values per cell).
#   check_history_layout.sh INDENT WORKDIR -- <indent options, with -domain_kinematic 1>
set -u
indent=$1 work=$2
shift 3
rm -rf "$work" && mkdir -p "$work"
opts=("$@" -quiet)
fail() { echo "FAIL: $*"; exit 1; }
for run in same other; do
  "$indent" "${opts[@]}" -output_dir "$work/$run" -checkpoint_stop_after_step 1 > "$work/$run.log" 2>&1
  [ $? -eq 75 ] || fail "the $run run did not stop with its checkpoint (status 75): $(tail -n 1 "$work/$run.log")"
done
"$indent" "${opts[@]}" -output_dir "$work/same" -restart "$work/same" > "$work/same2.log" 2>&1 ||
  fail "the restart with the same material failed: $(tail -n 1 "$work/same2.log")"
echo "ok: the restart with the same material continued"
"$indent" "${opts[@]}" -domain_kinematic 0 -output_dir "$work/other" -restart "$work/other" > "$work/other2.log" 2>&1 &&
  fail "the restart without kinematic hardening ran"
last=$(tail -n 1 "$work/other2.log")
[[ $last == "indent: error: -restart "*"the checkpoint was made with -domain_kinematic 1, this run gives"* ]] ||
  fail "the restart without kinematic hardening did not end with the line saying why: $last"
echo "ok: $last"
