#!/usr/bin/env bash
# A motion cache opens in Blender: simulates a small flag (tests/data/end_to_end_flag.yaml) into
# a cache with PC2 and MDD files, then runs scripts/blender-check-cache.py in Blender itself
# (headless), which imports each OBJ, adds Mesh Cache modifiers and compares the moved vertices
# with the cache files; then the same for the cache of its natural modes (`dinam modes`, one
# object per mode); then the round trip onto the artist's own object
# (tests/cache/blender_round_trip.py): a plane subdivided and exported as OBJ in Blender,
# simulated by dinam, moved in Blender by the PC2 on the original object.
#
#   tests/cache/blender_open_test.sh DINAM SOURCE_DIR
#
# Exits 77 (CTest: skipped) when Blender is not installed; scripts/install-deps.sh installs it.
set -euo pipefail
dinam=$(realpath "$1")
source_dir=$(realpath "$2")
if ! command -v blender >/dev/null; then
  echo "SKIPPED: blender is not installed (scripts/install-deps.sh installs it)"
  exit 77
fi
work=$(mktemp -d /tmp/dinam-blender-XXXXXX)
trap 'rm -rf "$work"' EXIT
"$dinam" simulate "$source_dir/tests/data/end_to_end_flag.yaml" -o "$work/cache" --format pc2,mdd --quiet
blender -b --factory-startup --python-exit-code 1 \
  --python "$source_dir/scripts/blender-check-cache.py" -- "$work/cache" >"$work/blender.log" 2>&1 ||
  { cat "$work/blender.log"; exit 1; }
grep '^blender-check:' "$work/blender.log"
grep -q '^blender-check: PASS' "$work/blender.log"
"$dinam" modes "$source_dir/tests/data/end_to_end_flag.yaml" -o "$work/modes" --count 3 --quiet
blender -b --factory-startup --python-exit-code 1 \
  --python "$source_dir/scripts/blender-check-cache.py" -- "$work/modes" >"$work/modes.log" 2>&1 ||
  { cat "$work/modes.log"; exit 1; }
grep '^blender-check:' "$work/modes.log"
grep -q '^blender-check: PASS' "$work/modes.log"

blender -b --factory-startup --python-exit-code 1 --python "$source_dir/tests/cache/blender_round_trip.py" \
  -- make "$work/banner.obj" "$work/banner.blend" >"$work/make.log" 2>&1 || { cat "$work/make.log"; exit 1; }
cat >"$work/banner.yaml" <<'SCENE'
version: 1
duration: 1
fps: 20
gravity: [0, 0, -9.81]
wind: {velocity: [0, 4, 0]}
objects:
  - name: banner
    mesh: {file: banner.obj, up_axis: z}
    material: {density: 1200, youngs_modulus: 2.0e6, radius: 0.002}
    pinned: {box: {min: [-1, -1, 1.99], max: [1, 1, 2.01]}}
SCENE
"$dinam" simulate "$work/banner.yaml" -o "$work/banner-cache" --quiet
blender -b "$work/banner.blend" --python-exit-code 1 --python "$source_dir/tests/cache/blender_round_trip.py" \
  -- check "$work/banner-cache" banner >"$work/check.log" 2>&1 || { cat "$work/check.log"; exit 1; }
grep '^round-trip:' "$work/check.log"
grep -q '^round-trip: PASS' "$work/check.log"
