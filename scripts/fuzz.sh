#!/usr/bin/env bash
# Builds the libFuzzer targets with clang (address and undefined-behaviour sanitizers, in
# build-fuzz/) and runs each for RUNS executions (default 10 million), seeded with the shipped
# scenes and meshes and every input kept in tests/fuzz/regressions/. New inputs that crash land in
# build-fuzz/artifacts/<target>/; keep each one, once fixed, in tests/fuzz/regressions/<target>/
# (or, when assimp itself crashed or hung on it, in tests/fuzz/assimp-failures/), where CTest
# replays it.
#
#   scripts/fuzz.sh [RUNS] [scene|mesh|mesh_wire|cache_manifest|point_cache|png|tolerance_file]
#
# FUZZ_SECONDS=3600 stops each target after that long instead (whichever comes first).
#
# Needs clang and its runtime: sudo apt-get install clang libclang-rt-14-dev libomp-14-dev
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-10000000}
only=${2:-}
for tool in clang clang++; do
  command -v "$tool" >/dev/null || {
    echo "fuzz.sh: $tool is missing: sudo apt-get install clang libclang-rt-14-dev libomp-14-dev" >&2
    exit 2
  }
done

cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_COMPILER=clang \
  -DCMAKE_CXX_COMPILER=clang++ -DDINAM_FUZZ=ON -DDINAM_BUILD_BENCH=OFF -DDINAM_X86_64_V3=OFF \
  -DCMAKE_CXX_FLAGS="-fsanitize=address,undefined,fuzzer-no-link -fno-sanitize-recover=undefined" \
  >/dev/null
cmake --build build-fuzz -j"$(nproc)" --target fuzz_scene_reader fuzz_mesh fuzz_mesh_wire \
  fuzz_cache_manifest fuzz_point_cache fuzz_png fuzz_tolerance_file >/dev/null

# The sanitizers' suppressions are the asan preset's: only leaks inside third-party libraries.
export LSAN_OPTIONS="suppressions=$PWD/tests/sanitizers/lsan.supp:print_suppressions=0"
corpus=build-fuzz/corpus
for target in scene mesh mesh_wire cache_manifest point_cache png tolerance_file; do
  mkdir -p "$corpus/$target" "build-fuzz/artifacts/$target"
done
cp scenes/*.yaml tests/fuzz/regressions/scene/* "$corpus/scene/" 2>/dev/null || true
cp assets/* tests/data/* tests/fuzz/regressions/mesh/* "$corpus/mesh/" 2>/dev/null || true
cp tests/fuzz/mesh-wire-seeds/* tests/fuzz/regressions/mesh_wire/* "$corpus/mesh_wire/" 2>/dev/null ||
  true
cp tests/fuzz/manifest-seeds/* tests/fuzz/regressions/cache_manifest/* "$corpus/cache_manifest/" \
  2>/dev/null || true
cp tests/fuzz/point-cache-seeds/* tests/bad_input/files/billion_frames.mdd \
  tests/fuzz/regressions/point_cache/* "$corpus/point_cache/" 2>/dev/null || true
cp tests/data/quad.png tests/bad_input/files/*.png tests/golden/rope_0001.png \
  tests/fuzz/regressions/png/* "$corpus/png/" 2>/dev/null || true
cp tests/golden/tolerances.yaml tests/fuzz/tolerance-seeds/* tests/fuzz/regressions/tolerance_file/* \
  "$corpus/tolerance_file/" 2>/dev/null || true

common=(-runs="$runs" -max_total_time="${FUZZ_SECONDS:-0}" -max_len=65536 -timeout=20 -rss_limit_mb=4096 -print_final_stats=1)
if [ -z "$only" ] || [ "$only" = scene ]; then
  echo "fuzz.sh: scene reader, $runs runs"
  build-fuzz/tests/fuzz/fuzz_scene_reader "${common[@]}" \
    -artifact_prefix=build-fuzz/artifacts/scene/ "$corpus/scene"
fi
if [ -z "$only" ] || [ "$only" = mesh ]; then
  # assimp may crash on some inputs; fork mode goes on past them and keeps each in artifacts/.
  echo "fuzz.sh: mesh loading and model building, $runs runs"
  build-fuzz/tests/fuzz/fuzz_mesh "${common[@]}" -fork=1 -ignore_crashes=1 -ignore_timeouts=1 \
    -ignore_ooms=1 -artifact_prefix=build-fuzz/artifacts/mesh/ "$corpus/mesh"
fi
if [ -z "$only" ] || [ "$only" = mesh_wire ]; then
  echo "fuzz.sh: what the importing child sends back, $runs runs"
  build-fuzz/tests/fuzz/fuzz_mesh_wire "${common[@]}" \
    -artifact_prefix=build-fuzz/artifacts/mesh_wire/ "$corpus/mesh_wire"
fi
if [ -z "$only" ] || [ "$only" = cache_manifest ]; then
  echo "fuzz.sh: a motion cache's manifest, $runs runs"
  build-fuzz/tests/fuzz/fuzz_cache_manifest "${common[@]}" \
    -artifact_prefix=build-fuzz/artifacts/cache_manifest/ "$corpus/cache_manifest"
fi
for target in point_cache png tolerance_file; do
  if [ -z "$only" ] || [ "$only" = "$target" ]; then
    echo "fuzz.sh: $target, $runs runs"
    "build-fuzz/tests/fuzz/fuzz_$target" "${common[@]}" \
      -artifact_prefix="build-fuzz/artifacts/$target/" "$corpus/$target"
  fi
done
