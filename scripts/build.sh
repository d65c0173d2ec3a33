#!/usr/bin/env bash
# Builds dist/<Model>.fmu (FMI 2.0) and dist/fmi3/<Model>.fmu (FMI 3.0) for every model of
# codegen/project.py (scripts/models.sh), and the C tests and tools: first the
# x86_64-windows DLLs (preset windows, mingw-w64, in build-win64/) and the aarch64-linux FMI 3
# binaries (preset aarch64, in build-aarch64/), then the x86_64-linux binaries (preset release, in
# build/), which it packages with the other platforms' binaries, the sources and the documentation.
set -euo pipefail
cd "$(dirname "$0")/.."
models=$(bash scripts/models.sh)
bash scripts/configure.sh windows
cmake --build build-win64 --parallel 2
bash scripts/configure.sh aarch64
cmake --build build-aarch64 --parallel 2 --target fmi3_binaries fmi3_driver
win64="$PWD/build-win64/fmu/binaries/win64"
win3="$PWD/build-win64/fmu3/binaries/x86_64-windows"
arm3="$PWD/build-aarch64/fmu3/binaries/aarch64-linux"
fmi2_binaries="" fmi3_binaries=""
for model in $models; do
  fmi2_binaries+="${fmi2_binaries:+;}$win64/$model.dll"
  fmi3_binaries+="${fmi3_binaries:+;}$win3/$model.dll;$arm3/$model.so"
done
bash scripts/configure.sh release \
  -DAK_EXTRA_PLATFORM_BINARIES="$fmi2_binaries" -DAK_EXTRA_FMI3_BINARIES="$fmi3_binaries"
cmake --build build --parallel 2
