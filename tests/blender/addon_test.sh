#!/usr/bin/env bash
# The Blender add-on installed from its zip and used headless by a script of tests/blender/:
# addon_test.py (the add-on's every control) by default, or another, such as
# getting_started_test.py (docs/getting-started.md's cape). The script prints "NAME: PASS".
#
#   tests/blender/addon_test.sh DINAM SOURCE_DIR ADDON_ZIP [SCRIPT NAME]
#
# Exits 77 (CTest: skipped) when Blender is not installed; scripts/install-deps.sh installs it.
set -euo pipefail
dinam=$(realpath "$1")
source_dir=$(realpath "$2")
addon=$(realpath "$3")
script=${4:-addon_test.py}
name=${5:-addon}
if ! command -v blender >/dev/null; then
  echo "SKIPPED: blender is not installed (scripts/install-deps.sh installs it)"
  exit 77
fi
work=$(mktemp -d /tmp/dinam-addon-XXXXXX)
# Blender installs add-ons into the user's configuration: keep this test's apart, every user
# folder Blender reads (its configuration, scripts, data files) its own.
export BLENDER_USER_CONFIG="$work/config" BLENDER_USER_SCRIPTS="$work/scripts" \
  BLENDER_USER_DATAFILES="$work/datafiles" HOME="$work/home"
trap 'rm -rf "$work"' EXIT
blender -b --factory-startup --python-exit-code 1 --python "$source_dir/tests/blender/$script" \
  -- "$addon" "$dinam" "$work/run" >"$work/blender.log" 2>&1 || { cat "$work/blender.log"; exit 1; }
grep "^$name:" "$work/blender.log"
grep -q "^$name: PASS" "$work/blender.log"
