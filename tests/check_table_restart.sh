#!/usr/bin/env bash
# A table indenter's restart: a run stopped after 2 steps continues with its -indenter_profile file unchanged, and
# is refused in one line when the file's points changed since the checkpoint (the options only name the file).
#   check_table_restart.sh INDENT TABLE WORKDIR -- <indent options>
set -u
indent=$1 table=$2 work=$3
shift 4
rm -rf "$work" && mkdir -p "$work" && cp "$table" "$work/t.csv"
opts=("$@" -indenter_type table -indenter_profile "$work/t.csv" -quiet)
fail() { echo "FAIL: $*"; exit 1; }
for run in same changed; do
  "$indent" "${opts[@]}" -output_dir "$work/$run" -checkpoint_stop_after_step 2 > "$work/$run.log" 2>&1
  [ $? -eq 75 ] || fail "the $run run did not stop with its checkpoint (status 75): $(tail -n 1 "$work/$run.log")"
done
"$indent" "${opts[@]}" -output_dir "$work/same" -restart "$work/same" > "$work/same2.log" 2>&1 ||
  fail "the restart with the same table failed: $(tail -n 1 "$work/same2.log")"
echo "ok: the restart with the same table continued"
# one height changed (line 5 of the file: its 3rd point)
sed -i '5s/,.*/,0.0012/' "$work/t.csv"
"$indent" "${opts[@]}" -output_dir "$work/changed" -restart "$work/changed" > "$work/changed2.log" 2>&1 &&
  fail "the restart with a changed table ran"
last=$(tail -n 1 "$work/changed2.log")
[[ $last == "indent: error: -indenter_profile: the file's points are not those the checkpoint was made with"* ]] ||
  fail "the changed table's restart did not end with the line naming it: $last"
echo "ok: $last"
