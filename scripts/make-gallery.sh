#!/usr/bin/env bash
# Renders the README's gallery: one 480×270 still of each shipped scene into docs/gallery/.
# Usage: scripts/make-gallery.sh [path/to/dinam]   (default build/dinam)
set -euo pipefail
cd "$(dirname "$0")/.."
dinam=${1:-build/dinam}
mkdir -p docs/gallery
# The frame that shows each scene best.
declare -A frame=([flag]=50 [windy_flag]=70 [ball]=6 [trampoline]=54 [rope]=16 [wire_chair]=80
                  [shaken_tower]=233 [storm_flag]=120 [draped_chair]=50
                  [ball_in_net]=8 [rope_heap]=60 [finishes]=30)
for scene in scenes/*.yaml; do
  name=$(basename "$scene" .yaml)
  n=${frame[$name]:-60}
  work=$(mktemp -d)
  "$dinam" render "$scene" -o "$work" --frames "$n-$n" --size 480x270 --movie none -q
  cp "$work/frame_$(printf '%04d' "$n").png" "docs/gallery/$name.png"
  rm -rf "$work"
  echo "docs/gallery/$name.png (frame $n)"
done
# Downloaded models (assimp-testmodels), dropped: frame 20, just after they land.
for scene in scenes/real_meshes/*.yaml; do
  name=real_$(basename "$scene" .yaml)
  work=$(mktemp -d)
  "$dinam" render "$scene" -o "$work" --frames 20-20 --size 480x270 --movie none -q
  cp "$work/frame_0020.png" "docs/gallery/$name.png"
  rm -rf "$work"
  echo "docs/gallery/$name.png (frame 20)"
done
