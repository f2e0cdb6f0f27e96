#!/usr/bin/env bash
# Mesh files on which assimp itself crashes or loops for ever (found by scripts/fuzz.sh, kept in
# tests/fuzz/assimp-failures/) must stop only their scene: `dinam info` on a scene naming each one
# exits 2 with a message about the importer, at the default limit on the importer's processor
# time (2 s and 2 s a megabyte: these files are a few bytes). The outer `timeout` only stops a
# hang; it asserts no speed.
#
#   tests/fuzz/assimp_failures_test.sh DINAM SOURCE_DIR
set -euo pipefail
dinam=$(realpath "$1")
failures=$(realpath "$2")/tests/fuzz/assimp-failures
work=$(mktemp -d /tmp/dinam-assimp-XXXXXX)
trap 'rm -rf "$work"' EXIT
count=0
for mesh in "$failures"/*; do
  cp "$mesh" "$work/"
  name=$(basename "$mesh")
  printf 'version: 1\nduration: 1\nobjects:\n  - mesh: {file: %s}\n    material: {density: 1000, youngs_modulus: 1e6, radius: 0.01}\n' \
    "$name" >"$work/scene.yaml"
  status=0
  output=$(timeout 300 "$dinam" info "$work/scene.yaml" 2>&1) || status=$?
  if [ "$status" -ne 2 ] || ! grep -q "mesh importer (assimp)" <<<"$output" ||
    { [[ $name == *hang* ]] && ! grep -q "in 2 s of processor time" <<<"$output"; }; then
    echo "FAIL: $name: exit $status: $output"
    exit 1
  fi
  echo "$name: refused: ${output#*error: }" | cut -c1-160
  count=$((count + 1))
done
[ "$count" -gt 0 ] || { echo "FAIL: no files in $failures"; exit 1; }
echo "PASS: $count files on which assimp fails were refused, dinam unharmed"
