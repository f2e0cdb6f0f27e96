#!/usr/bin/env bash
# The USD stage of a motion cache (src/cache/usd_stage.hpp) holds what its OBJ and PC2 files hold,
# and the look: simulates tests/data/usd_stage.yaml (every kind of prim, and a textured UV sphere
# with its seam), the end-to-end flag (120 frames) and the shipped flag (its texture) with the
# default --format, and reads each stage with tests/cache/usd_stage_check.py, a parser of USD's
# text grammar written for the test. Then: --format pc2 writes no stage, and a --format
# without a point cache is refused before anything is written.
#
#   tests/cache/usd_stage_test.sh DINAM SOURCE_DIR PYTHON
set -euo pipefail
dinam=$(realpath "$1")
source_dir=$(realpath "$2")
python=$3
check="$source_dir/tests/cache/usd_stage_check.py"
work=$(mktemp -d /tmp/dinam-usd-XXXXXX)
trap 'rm -rf "$work"' EXIT

"$dinam" simulate "$source_dir/tests/data/usd_stage.yaml" -o "$work/kinds" --quiet
# The pole is drawn at its wire radius (2 cm), the sail's wires at their render_radius (4 mm).
# The ball, a UV sphere, has 61 texture coordinates on 42 points: its seam and poles must stay, and
# it wears its mesh file's texture, copied beside the stage.
"$python" "$check" "$work/kinds" --expect pole_1=BasisCurves --expect flag=Mesh \
  --expect flag_wires=BasisCurves --expect net=BasisCurves --expect sail=Mesh \
  --expect sail_wires=BasisCurves --expect frame=BasisCurves --expect ball=Mesh \
  --width pole_1=0.04 --width sail_wires=0.008 --texture ball --seams ball
cmp "$work/kinds/ball_texture.png" "$source_dir/tests/data/quad.png"
grep -q 'displayName = "pole 1"' "$work/kinds/scene.usda"
# The sail is a grid, with texture coordinates; the banner's OBJ has none.
grep -q 'texCoord2f\[\] primvars:st' <(sed -n '/def Mesh "sail"/,/def /p' "$work/kinds/scene.usda")
! grep -q 'primvars:st' <(sed -n '/def Mesh "flag"/,/def BasisCurves/p' "$work/kinds/scene.usda")
# The frame's closed square is one curve that ends where it began.
grep -q 'int\[\] primvars:dinam:node = \[4, 5, 5, 6, 5, 7, 8, 0, 1, 2, 3, 0\]' "$work/kinds/scene.usda"

"$dinam" simulate "$source_dir/tests/data/end_to_end_flag.yaml" -o "$work/flag" --quiet
"$python" "$check" "$work/flag" --expect pole=BasisCurves --expect cloth=Mesh

# The shipped flag, a quarter of a second of it: its cloth wears the tricolour through its
# material, the pole its grey metal.
mkdir -p "$work/shipped/scenes"
ln -s "$source_dir/assets" "$work/shipped/assets"
sed 's/^duration: .*/duration: 0.25/' "$source_dir/scenes/flag.yaml" >"$work/shipped/scenes/flag.yaml"
"$dinam" simulate "$work/shipped/scenes/flag.yaml" -o "$work/shipped/cache" --quiet
"$python" "$check" "$work/shipped/cache" --expect pole=BasisCurves --expect flag=Mesh --texture flag
cmp "$work/shipped/cache/flag_texture.png" "$source_dir/assets/flag.png"
grep -q 'float inputs:metallic = 1' <(sed -n '/def Material "pole"/,/def Material/p' \
  "$work/shipped/cache/scene.usda")

"$dinam" simulate "$source_dir/tests/data/usd_stage.yaml" -o "$work/pc2" --format pc2 --quiet
test ! -e "$work/pc2/scene.usda"
! grep -q '"usd"' "$work/pc2/manifest.json"

# A stage alone: written and whole, no point cache beside it; dinam's own readers refuse the
# folder with the format that would serve them.
# (the stage the same, byte for byte, as the one beside the point caches of $work/kinds, which
# the checks above read).
"$dinam" simulate "$source_dir/tests/data/usd_stage.yaml" -o "$work/stage" --format usd --quiet
cmp "$work/stage/scene.usda" "$work/kinds/scene.usda"
test -z "$(find "$work/stage" -name '*.pc2' -o -name '*.mdd')"
status=0
"$dinam" render "$source_dir/tests/data/usd_stage.yaml" --cache "$work/stage" -o "$work/drawn" \
  --quiet 2>"$work/stage.err" || status=$?
test "$status" -eq 2
grep -q 'USD stage alone' "$work/stage.err"
grep -q 'format pc2,usd' "$work/stage.err"
test ! -e "$work/drawn"
echo "usd stage: PASS"
