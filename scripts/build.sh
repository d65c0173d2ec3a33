#!/usr/bin/env bash
# Builds dist/AngularKinematics.fmu, dist/EulerRates.fmu, dist/AttitudePropagator.fmu (FMI 2.0) and dist/fmi3/*.fmu (FMI 3.0),
# and the C tests and tools: first the x86_64-windows DLLs (preset windows, mingw-w64, in
# build-win64/) and the aarch64-linux FMI 3 binaries (preset aarch64, in build-aarch64/), then the
# x86_64-linux binaries (preset release, in build/), which it packages with the other platforms'
# binaries, the sources and the documentation.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/configure.sh windows
cmake --build build-win64 --parallel 2
bash scripts/configure.sh aarch64
cmake --build build-aarch64 --parallel 2 --target AngularKinematics_fmi3 EulerRates_fmi3 AttitudePropagator_fmi3 fmi3_driver
win64="$PWD/build-win64/fmu/binaries/win64"
win3="$PWD/build-win64/fmu3/binaries/x86_64-windows"
arm3="$PWD/build-aarch64/fmu3/binaries/aarch64-linux"
bash scripts/configure.sh release \
  -DAK_EXTRA_PLATFORM_BINARIES="$win64/AngularKinematics.dll;$win64/EulerRates.dll;$win64/AttitudePropagator.dll" \
  -DAK_EXTRA_FMI3_BINARIES="$win3/AngularKinematics.dll;$win3/EulerRates.dll;$win3/AttitudePropagator.dll;$arm3/AngularKinematics.so;$arm3/EulerRates.so;$arm3/AttitudePropagator.so"
cmake --build build --parallel 2
