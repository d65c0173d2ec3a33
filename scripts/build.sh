#!/usr/bin/env bash
# Builds dist/<Model>.fmu (FMI 2.0) and dist/fmi3/<Model>.fmu (FMI 3.0) for every model of
# codegen/project.py (scripts/models.sh), and the C tests and tools: first the other platforms'
# binaries, each in its build folder (docs/platforms.md):
#   preset windows         x86_64-windows DLLs (mingw-w64), build-win64/
#   preset windows32       x86-windows DLLs (mingw-w64 i686, SSE2), build-win32/
#   preset aarch64         aarch64-linux FMI 3 binaries (and FMI 2 ones, for the tests only:
#                          FMI 2 names no aarch64-linux platform), build-aarch64/
#   preset riscv64         riscv64-linux FMI 3 binaries (and FMI 2 ones, for the tests only,
#                          as aarch64's), build-riscv64/
#   presets darwin-x86_64, darwin-aarch64   the macOS dylibs (zig), build-darwin-*/, of which the
#                          FMI 2 ones are combined into one universal dylib per model
#                          (cmake/fat_macho.py) for binaries/darwin64, in build-darwin64/
# then the x86_64-linux binaries (preset release, in build/), which it packages with the other
# platforms' binaries, the sources and the documentation.
set -euo pipefail
cd "$(dirname "$0")/.."
models=$(bash scripts/models.sh)
bash scripts/configure.sh windows
cmake --build build-win64 --parallel 2
bash scripts/configure.sh windows32
cmake --build build-win32 --parallel 2 --target fmi2_binaries fmi3_binaries fmu_driver fmi3_driver
for arch in aarch64 riscv64; do
  bash scripts/configure.sh "$arch"
  cmake --build "build-$arch" --parallel 2 --target fmi2_binaries fmi3_binaries fmu_driver fmi3_driver
done
for arch in x86_64 aarch64; do
  bash scripts/configure.sh "darwin-$arch"
  cmake --build "build-darwin-$arch" --parallel 2 --target fmi2_binaries fmi3_binaries
done
darwin64="$PWD/build-darwin64/darwin64"
mkdir -p "$darwin64"
for model in $models; do
  .venv/bin/python cmake/fat_macho.py "$darwin64/$model.dylib" \
    "build-darwin-x86_64/fmu/binaries/darwin64/$model.dylib" \
    "build-darwin-aarch64/fmu/binaries/darwin64/$model.dylib"
done
fmi2_binaries="" fmi3_binaries=""
for model in $models; do
  fmi2_binaries+="${fmi2_binaries:+;}$PWD/build-win64/fmu/binaries/win64/$model.dll"
  fmi2_binaries+=";$PWD/build-win32/fmu/binaries/win32/$model.dll;$darwin64/$model.dylib"
  for binary in build-win64/fmu3/binaries/x86_64-windows/$model.dll \
                build-win32/fmu3/binaries/x86-windows/$model.dll \
                build-aarch64/fmu3/binaries/aarch64-linux/$model.so \
                build-riscv64/fmu3/binaries/riscv64-linux/$model.so \
                build-darwin-x86_64/fmu3/binaries/x86_64-darwin/$model.dylib \
                build-darwin-aarch64/fmu3/binaries/aarch64-darwin/$model.dylib; do
    fmi3_binaries+="${fmi3_binaries:+;}$PWD/$binary"
  done
done
bash scripts/configure.sh release \
  -DAK_EXTRA_PLATFORM_BINARIES="$fmi2_binaries" -DAK_EXTRA_FMI3_BINARIES="$fmi3_binaries"
cmake --build build --parallel 2
