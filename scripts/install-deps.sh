#!/usr/bin/env bash
# Installs every Debian 12 package dinam needs to build, test and render, when it is missing;
# with --render, only what building the program and rendering need (the README's first command).
# Non-interactive and idempotent: a second run with everything present does nothing but check.
set -euo pipefail

render_only=false
case "${1:-}" in
  "") ;;
  --render) render_only=true ;;
  *) echo "usage: $0 [--render]" >&2; exit 2 ;;
esac

# Building the program and rendering a movie.
packages=(
  g++ cmake make pkg-config python3
  libeigen3-dev libassimp-dev libosmesa6-dev libgl-dev libpng-dev zlib1g-dev
  libyaml-cpp-dev libcli11-dev libfmt-dev nlohmann-json3-dev libssl-dev
  # Newton's method and the natural modes: Spectra's Lanczos on Eigen's sparse matrices, and
  # SuiteSparse's CHOLMOD for large models' factorisations, its dense blocks through the
  # single-threaded OpenBLAS (src/solver/CMakeLists.txt).
  libspectra-dev libsuitesparse-dev libopenblas0-serial
  ffmpeg
)
# The page `dinam view` writes draws with three.js, which the build puts into the program: npm
# fetches the version web/package-lock.json pins, below. Debian's npm, unless the machine has an
# npm already (a Node.js from elsewhere, whose own npm Debian's would conflict with).
command -v npm >/dev/null || packages+=(npm)
# The tests and benchmarks.
$render_only || packages+=(
  libgtest-dev libgmock-dev libbenchmark-dev
  # Real components the tests use where users meet them: Blender opens the motion cache
  # (tests/cache/blender_open_test.sh), and a one-node Slurm cluster runs the render farm
  # (tests/farm/slurm_farm_test.sh; the test starts and stops its own daemons).
  blender slurm-wlm munge
  # A real browser loads the page `dinam view` writes (tests/app/view_test.cpp), headless.
  chromium
  # Real meshes as users download them: the sweep (tests/real_meshes/) reads assimp's own test
  # models with `dinam info`, through a Python script.
  assimp-testmodels
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -gt 0 ]; then
  echo "install-deps: installing ${missing[*]}" >&2
  sudo_cmd=()
  if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update -qq
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# three.js from the npm registry, at the version and checksum web/package-lock.json pins, into
# web/node_modules (ignored by git); never fetched at build or run time.
web="$(cd "$(dirname "$0")/.." && pwd)/web"
if [ ! -f "$web/node_modules/three/build/three.module.min.js" ]; then
  echo "install-deps: installing three.js (npm ci in web/)" >&2
  npm ci --prefix "$web" --no-audit --no-fund --loglevel=error >/dev/null
fi
