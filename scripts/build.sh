#!/usr/bin/env bash
# Builds dist/AngularKinematics.fmu, dist/EulerRates.fmu and dist/AttitudePropagator.fmu (and the C tests and tools): first the
# x86_64-windows DLLs (preset windows, mingw-w64, in build-win64/), then the x86_64-linux
# binaries (preset release, in build/), which it packages with the Windows ones, the sources and
# the documentation.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/configure.sh windows
cmake --build build-win64 --parallel 2
win64="$PWD/build-win64/fmu/binaries/win64"
bash scripts/configure.sh release \
  -DAK_EXTRA_PLATFORM_BINARIES="$win64/AngularKinematics.dll;$win64/EulerRates.dll;$win64/AttitudePropagator.dll"
cmake --build build --parallel 2
