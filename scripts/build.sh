#!/usr/bin/env bash
# Builds dist/AngularKinematics.fmu and dist/EulerRates.fmu (and the test tools) in build/: first the
# Windows x86-64 binaries,
# cross-compiled with mingw-w64 in build-win64/ (cmake/mingw-w64-x86_64.cmake), then the Linux
# binaries, each packaged together with its Windows one, its sources and the documentation.
set -euo pipefail
cd "$(dirname "$0")/.."
python="$PWD/.venv/bin/python"

configure() {  # configure BUILD_DIR [CMAKE_OPTIONS...]: quiet unless it fails
  local dir=$1
  shift
  mkdir -p "$dir"
  if ! cmake -S . -B "$dir" -DPython3_EXECUTABLE="$python" "$@" >"$dir/configure.log" 2>&1; then
    cat "$dir/configure.log"
    exit 1
  fi
}

configure build-win64 -DCMAKE_TOOLCHAIN_FILE=cmake/mingw-w64-x86_64.cmake -DAK_PACKAGE_FMU=OFF
cmake --build build-win64 --parallel 2
win64="$PWD/build-win64/fmu/binaries/win64"
configure build -DAK_EXTRA_PLATFORM_BINARIES="$win64/AngularKinematics.dll;$win64/EulerRates.dll"
cmake --build build --parallel 2
