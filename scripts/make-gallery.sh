#!/usr/bin/env bash
# Renders the README's gallery: one 480×270 still of each shipped scene into docs/gallery/.
# Usage: scripts/make-gallery.sh [path/to/dinam]   (default build/dinam)
set -euo pipefail
cd "$(dirname "$0")/.."
dinam=${1:-build/dinam}
mkdir -p docs/gallery
# The frame that shows each scene best: docs/gallery/frames.txt (the snapshot tests check the
# framing there).
for scene in scenes/*.yaml; do
  name=$(basename "$scene" .yaml)
  n=$(awk -v s="$name" '$1 == s { print $2 }' docs/gallery/frames.txt)
  n=${n:-60}
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
