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
