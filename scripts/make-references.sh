#!/usr/bin/env bash
# Regenerates the regression references in tests/reference/ on 1 rank. Run it only for an intended
# change of results, and say why in the commit message.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
build=${BUILD_DIR:-$top/build}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$build/indent" -options_file "$top/inputs/elastic_block.opts" -dm_plex_box_faces 8,2,2 -quiet -ksp_rtol 1e-12 -output_dir "$tmp/elastic_block"
cp "$tmp/elastic_block/indent.h5" "$top/tests/reference/elastic_block.h5"
echo "wrote tests/reference/elastic_block.h5"
"$build/indent" -options_file "$top/inputs/plastic_block.opts" -dm_plex_box_faces 8,2,2 -quiet -ksp_rtol 1e-12 -snes_rtol 1e-12 -output_dir "$tmp/plastic_block"
cp "$tmp/plastic_block/indent.h5" "$top/tests/reference/plastic_block.h5"
echo "wrote tests/reference/plastic_block.h5"
# The coarse paper case: options as in tests/CMakeLists.txt (PAPER_COARSE_OPTS); mesh made by gmsh.
"$build/indent" -options_file "$top/inputs/berkovich.opts" -mesh_file "$top/inputs/berkovich_half.geo" \
  -mesh_geo_parameters h_tip=20,h_far=400 -load_depth 30 -load_steps 6 -load_unload_steps 50 \
  -contact_uzawa_rtol 1e-9 -snes_rtol 1e-10 -ksp_rtol 1e-12 -quiet -output_dir "$tmp/berkovich_paper"
/usr/bin/python3 "$top/scripts/slim-reference.py" "$tmp/berkovich_paper/indent.h5" "$top/tests/reference/berkovich_paper.h5" \
  displacement von_mises plastic_strain contact_pressure
cp "$tmp/berkovich_paper/load_displacement.csv" "$top/tests/reference/berkovich_paper.csv"
echo "wrote tests/reference/berkovich_paper.h5 and berkovich_paper.csv"
