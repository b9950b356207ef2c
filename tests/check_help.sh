#!/usr/bin/env bash
# check_help.sh OUTDIR INDENT [options...]: `INDENT options -help -output_dir OUTDIR` on a case meshed from a
# .geo must
#   - exit 0 and list the options of every module (mesh, materials, load path, contact, solver, output,
#     Oliver-Pharr);
#   - list indent's options first, in groups, then PETSc's: every indent option before the line
#     "Options of PETSc", PETSc's solver options after it;
#   - give units and required values: -load_depth <nm>, -film_young <GPa> "required" (no default of 0),
#     -indenter_axis with its two values, a group per volume region naming it;
#   - neither run gmsh (given here as a stand-in that leaves a mark) nor create the output directory.
out=$1
shift
rm -rf "$out" "$out.gmsh-ran"
fake=$(mktemp)
trap 'rm -f "$fake"' EXIT
printf '#!/bin/sh\ntouch "%s"\nexit 1\n' "$out.gmsh-ran" > "$fake"
chmod +x "$fake"
text=$("$@" -mesh_gmsh "$fake" -output_dir "$out" -help 2>&1)
status=$?
# the listing is not shown; PETSc's -malloc_dump report (one line per unfreed block) is, for ctest to judge
grep -E '^\[ *[0-9]+\] ?[0-9]+ bytes [^ ]+\(\) (at|line) ' <<<"$text"
fail() {
  echo "FAIL: $1"
  exit 1
}
[ $status -eq 0 ] || { echo "$text" | tail -n 20; fail "exit $status from: $* -output_dir $out -help"; }
missing=""
for opt in -mesh_file -film_young -load_depth -load_unload_steps -contact_friction -contact_uzawa \
  -newton_stall_its -snes_rtol -output_fields -op_fraction; do
  grep -Eq -- "^ *$opt[ :<]" <<<"$text" || missing="$missing $opt"
done
[ -z "$missing" ] || fail "-help does not list:$missing"
# the line number of the first line matching $1
at() { grep -nE -- "$1" <<<"$text" | head -n 1 | cut -d: -f1; }
petsc=$(at '^Options of PETSc')
[ -n "$petsc" ] || fail "no 'Options of PETSc' section"
for opt in -mesh_file -film_young -substrate_poisson -bc_symmetry -indenter_axis -load_depth -formulation -op_fraction \
  -newton_stall_its -output_fields; do
  line=$(at "^ *$opt[ :<]")
  [ "$line" -lt "$petsc" ] || fail "$opt is listed after PETSc's options (line $line, PETSc's from $petsc)"
done
for opt in -snes_rtol -ksp_type -pc_type; do
  line=$(at "^ *$opt[ :<]")
  [ -n "$line" ] && [ "$line" -gt "$petsc" ] || fail "PETSc's $opt is not listed after indent's options"
done
# a line matching $1, or fail saying $2 and showing the line of option $3
expect() {
  grep -Eq -- "$1" <<<"$text" || fail "$2: $(grep -E -- "^ *$3[ <]" <<<"$text" | head -n 1)"
}
expect '^ *-load_depth <nm>: .*\(required with -indenter_type; given: 60\)' \
  "-load_depth shows no unit or required mark" -load_depth
expect '^ *-film_young <GPa>: .*\(required; given: 70\)' "-film_young is not marked required with its unit" -film_young
expect '^ *-indenter_axis <x,y in nm>: .*\(default: 0,0\)' "-indenter_axis does not show its two values" -indenter_axis
for region in film substrate; do
  expect "^Material of volume region '$region' \\(-${region}_\\*\\):" "no group naming the region '$region'" \
    "-${region}_young"
done
[ ! -e "$out.gmsh-ran" ] || fail "-help ran gmsh"
[ ! -e "$out" ] || fail "-help created the output directory $out: $(ls -A "$out")"
ours=$(head -n "$petsc" <<<"$text" | grep -c '^ *-')
echo "ok: -help listed $(grep -c '^ *-' <<<"$text") option lines, indent's $ours first; no gmsh, no output directory"
