#!/usr/bin/env bash
# check_help.sh OUTDIR INDENT [options...]: `INDENT options -help -output_dir OUTDIR` must exit 0, list
# the options of every module (mesh, materials, load path, contact, solver, output, Oliver-Pharr) and
# leave no results: -help lists, it does not run.
out=$1
shift
rm -rf "$out"
text=$("$@" -output_dir "$out" -help 2>&1)
status=$?
# the listing is not shown; PETSc's -malloc_dump report (one line per unfreed block) is, for ctest to judge
grep -E '^\[ *[0-9]+\] ?[0-9]+ bytes [^ ]+\(\) (at|line) ' <<<"$text"
if [ $status -ne 0 ]; then
  echo "FAIL: exit $status from: $* -output_dir $out -help"
  echo "$text" | tail -n 20
  exit 1
fi
missing=""
for opt in -mesh_file -film_young -load_depth -load_unload_steps -contact_friction -contact_uzawa \
  -newton_stall_its -snes_rtol -output_fields -op_fraction; do
  grep -Eq -- "^ *$opt[ :]" <<<"$text" || missing="$missing $opt"
done
if [ -n "$missing" ]; then
  echo "FAIL: -help does not list:$missing"
  exit 1
fi
if ls "$out"/load_displacement.csv "$out"/summary.txt "$out"/*.h5 > /dev/null 2>&1; then
  echo "FAIL: -help left results in $out: $(ls "$out")"
  exit 1
fi
echo "ok: -help listed $(grep -c '^ *-' <<<"$text") option lines and wrote no results"
