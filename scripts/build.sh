#!/usr/bin/env bash
# Builds the FMU into dist/AngularKinematics.fmu (and the test tools) in build/.
set -euo pipefail
cd "$(dirname "$0")/.."
mkdir -p build
if ! cmake -S . -B build -DPython3_EXECUTABLE="$PWD/.venv/bin/python" >build/configure.log 2>&1; then
  cat build/configure.log
  exit 1
fi
cmake --build build --parallel 2
