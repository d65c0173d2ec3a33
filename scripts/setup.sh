#!/usr/bin/env bash
# Prepares a machine for building and testing: C toolchain, CMake, mingw-w64 for the Windows
# binaries (x86_64 and i686), gcc-aarch64-linux-gnu, gcc-riscv64-linux-gnu and qemu-user for the
# aarch64-linux and riscv64-linux FMI 3 binaries (from Debian's packages if missing; with
# --with-wine also wine, to test the Windows binary), and a Python virtual environment .venv with
# the pinned packages of requirements.txt, among them zig (ziglang) for the macOS binaries and the
# proof builds (docs/platforms.md), and the project's own packages (pyproject.toml) installed
# editable.
#   bash scripts/setup.sh [--with-wine]
#   bash scripts/setup.sh --demo    only what scripts/demo.sh needs: the native C toolchain, CMake
#                                   and make, and in .venv the pinned packages of
#                                   requirements-demo.txt (a later run without --demo adds the rest)
# Idempotent: a second run installs nothing.
set -euo pipefail
cd "$(dirname "$0")/.."
demo=
[ "${1:-}" = --demo ] && demo=1

# apt quietly (its output goes to a log, printed only on failure), waiting up to 10 minutes for a
# lock another apt holds instead of failing at once.
apt_install() {
  echo "setup: installing $* from Debian's packages"
  local log
  log=$(mktemp)
  if ! { apt-get -o DPkg::Lock::Timeout=600 update -qq &&
         DEBIAN_FRONTEND=noninteractive apt-get -o DPkg::Lock::Timeout=600 install -y -qq \
           --no-install-recommends "$@"; } >"$log" 2>&1; then
    tail -n 40 "$log"
    rm -f "$log"
    echo "setup: apt-get failed (last lines above)" >&2
    exit 1
  fi
  rm -f "$log"
}

missing=()
command -v cmake >/dev/null 2>&1 || missing+=(cmake)
# CMake's default generator; Debian's cmake only recommends make, which --no-install-recommends skips.
command -v make >/dev/null 2>&1 || missing+=(make)
command -v cc >/dev/null 2>&1 || missing+=(gcc libc6-dev)
command -v python3 >/dev/null 2>&1 || missing+=(python3)
if [ -z "$demo" ]; then # the cross compilers and ccache: the seven-platform build and the tests
  # The Windows binary is cross-compiled with mingw-w64; the tests run it under wine (--with-wine).
  command -v x86_64-w64-mingw32-gcc >/dev/null 2>&1 || missing+=(gcc-mingw-w64-x86-64-win32)
  # The 32-bit Windows binary: mingw-w64 for i686 (the macOS ones: zig, from requirements.txt).
  command -v i686-w64-mingw32-gcc >/dev/null 2>&1 || missing+=(gcc-mingw-w64-i686-win32)
  # The aarch64-linux FMI 3 binaries are cross-compiled with Debian's gcc and run under qemu-user.
  command -v aarch64-linux-gnu-gcc >/dev/null 2>&1 || missing+=(gcc-aarch64-linux-gnu)
  [ -f /usr/aarch64-linux-gnu/lib/libc.so.6 ] || missing+=(libc6-dev-arm64-cross)
  # The riscv64-linux FMI 3 binaries likewise (Scrt1.o: the C library's development files, which
  # gcc-riscv64-linux-gnu does not pull in).
  command -v riscv64-linux-gnu-gcc >/dev/null 2>&1 || missing+=(gcc-riscv64-linux-gnu)
  [ -f /usr/riscv64-linux-gnu/lib/Scrt1.o ] || missing+=(libc6-dev-riscv64-cross)
  { command -v qemu-aarch64 && command -v qemu-riscv64; } >/dev/null 2>&1 || missing+=(qemu-user)
  # ccache: the build folders compile the same sources; a second run recompiles nothing unchanged.
  command -v ccache >/dev/null 2>&1 || missing+=(ccache)
  if [ "${1:-}" = "--with-wine" ]; then
    command -v wine64 >/dev/null 2>&1 || command -v wine >/dev/null 2>&1 ||
      [ -x /usr/lib/wine/wine64 ] || missing+=(wine64)
  fi
fi
if [ ${#missing[@]} -gt 0 ]; then
  apt_install "${missing[@]}"
fi

stamp=.venv/.requirements-installed
if [ ! -x .venv/bin/python ]; then
  # Debian ships venv's pip bootstrap (ensurepip) in python3-venv, also when python3 is there.
  if ! python3 -m venv .venv >/dev/null 2>&1; then
    rm -rf .venv
    apt_install python3-venv
    python3 -m venv .venv
  fi
fi
if [ -n "$demo" ]; then
  demo_stamp=.venv/.requirements-demo-installed
  # The full set (requirements.txt) holds the demo's too.
  if ! cmp -s requirements.txt "$stamp" && ! cmp -s requirements-demo.txt "$demo_stamp"; then
    # --no-deps: exactly the listed pins, which name every dependency but FMPy's cmake wheel
    # (requirements-demo.txt); --no-compile: Python compiles what the demo imports when it does,
    # a few seconds less than compiling every module of the packages first.
    .venv/bin/python -m pip install --quiet --disable-pip-version-check --no-deps --no-compile \
      -r requirements-demo.txt
    cp requirements-demo.txt "$demo_stamp"
  fi
  exit 0 # the demo runs its modules with python -m from the checkout: no editable install needed
fi
if ! cmp -s requirements.txt "$stamp"; then
  .venv/bin/python -m pip install --quiet --disable-pip-version-check -r requirements.txt
  cp requirements.txt "$stamp"
fi

# The project's own packages (pyproject.toml: codegen, examples, demo, scripts, bench, tools),
# editable, so that every module imports the others by package name from anywhere. Again when
# pyproject.toml changed or the install no longer imports (the checkout moved). A .venv linked
# from another checkout (scripts/release.sh's clones) keeps that checkout's install: the clone
# runs its modules with python -m from its own root, where its own packages come first.
project_stamp=.venv/.project-installed
python=$PWD/.venv/bin/python
if [ ! -f "$project_stamp" ] || ! cmp -s pyproject.toml "$project_stamp" ||
  ! (cd / && "$python" -c "import codegen.project") >/dev/null 2>&1; then
  .venv/bin/python -m pip install --quiet --disable-pip-version-check --no-deps -e .
  cp pyproject.toml "$project_stamp"
fi
