#!/usr/bin/env bash
# Configures one CMake preset (CMakePresets.json) quietly: the log is printed only on failure.
#   bash scripts/configure.sh PRESET [CMAKE_OPTIONS...]
set -euo pipefail
cd "$(dirname "$0")/.."
preset=$1
shift
log=$(mktemp)
if ! cmake --preset "$preset" "$@" >"$log" 2>&1; then
  cat "$log"
  rm -f "$log"
  exit 1
fi
rm -f "$log"
