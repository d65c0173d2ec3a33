#!/usr/bin/env bash
# Installs, from Debian's packages and only when missing, the tools of the abuse tests
# (docs/abuse_testing.md): clang with libFuzzer and its sanitizer runtimes, llvm-symbolizer for
# readable reports, valgrind and cppcheck. GCC's own sanitizer runtimes come with gcc.
# Idempotent: a second run installs nothing and does not touch the network.
set -euo pipefail

# apt quietly (its output goes to a log, printed only on failure), waiting up to 10 minutes for a
# lock another apt holds instead of failing at once.
apt_run() {
  local log
  log=$(mktemp)
  if ! DEBIAN_FRONTEND=noninteractive apt-get -o DPkg::Lock::Timeout=600 -qq "$@" >"$log" 2>&1; then
    tail -n 40 "$log"
    rm -f "$log"
    echo "setup_abuse_tools: apt-get $1 failed (last lines above)" >&2
    exit 1
  fi
  rm -f "$log"
}

missing=()
command -v clang >/dev/null 2>&1 || missing+=(clang)
command -v llvm-symbolizer >/dev/null 2>&1 || missing+=(llvm)
command -v valgrind >/dev/null 2>&1 || missing+=(valgrind)
command -v cppcheck >/dev/null 2>&1 || missing+=(cppcheck)
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup_abuse_tools: installing ${missing[*]} from Debian's packages"
  apt_run update
  apt_run install -y --no-install-recommends "${missing[@]}"
  updated=yes
fi

# libFuzzer and clang's sanitizer runtimes are a separate package, named after clang's version.
runtime_dir=$(clang -print-runtime-dir 2>/dev/null || true)
if [ ! -f "$runtime_dir/libclang_rt.fuzzer-x86_64.a" ] && \
   [ ! -f "$(clang -print-file-name=libclang_rt.fuzzer-x86_64.a)" ]; then
  version=$(clang -dumpversion | cut -d. -f1)
  echo "setup_abuse_tools: installing libclang-rt-$version-dev (libFuzzer) from Debian's packages"
  [ "${updated:-}" = yes ] || apt_run update
  apt_run install -y --no-install-recommends "libclang-rt-$version-dev"
fi
