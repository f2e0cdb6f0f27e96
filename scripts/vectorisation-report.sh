#!/usr/bin/env bash
# Which loops of the force kernels GCC vectorised, from its own report (-fopt-info-vec), with
# the flags of the existing build (build/compile_commands.json):
#   scripts/vectorisation-report.sh [build-folder]
# Each kind of spring should show two vectorised compute loops (elastic, and yielding), at the
# build's widest vectors (32 bytes with x86-64-v3, 64 for the bending and torsion springs where
# they are built for x86-64-v4; 16 with the x86-64 baseline), each with its
# narrower epilogue. wind.cpp shows the drag loop
# (compute_drag, for faces and bars) and the loop that stores the forces; wind_field.cpp the
# turbulence's loop over points; ground_contact.cpp the loop over touching nodes.
set -euo pipefail
build=${1:-build}
source_dir=$(cd "$(dirname "$0")/.." && pwd)
for kind in axial_spring bending_spring torsion_spring wind wind_field ground_contact; do
  file="$source_dir/src/dynamics/${kind}.cpp"
  command=$(python3 -c '
import json, sys
for entry in json.load(open(sys.argv[1])):
    if entry["file"] == sys.argv[2]:
        print(entry["command"])
        break
' "$build/compile_commands.json" "$file")
  if [[ -z $command ]]; then
    echo "no compile command for $file in $build/compile_commands.json" >&2
    exit 1
  fi
  # The same compiler and flags, writing the object and the report to a scratch folder.
  scratch=$(mktemp -d)
  (cd "$build" && eval "$command" -fopt-info-vec-optimized="$scratch/report.txt" -o "$scratch/kernel.o")
  echo "== ${kind}: vectorised loops"
  grep -E "loop vectorized" "$scratch/report.txt" | sed "s|$source_dir/||" | sort | uniq
  rm -rf "$scratch"
done
