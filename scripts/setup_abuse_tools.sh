#!/usr/bin/env bash
# Installs, from Debian's packages and only when missing, the tools of the abuse tests
# (docs/abuse_testing.md): clang with libFuzzer and its sanitizer runtimes, llvm-symbolizer for
# readable reports, valgrind and cppcheck. GCC's own sanitizer runtimes come with gcc.
# Idempotent: a second run installs nothing and does not touch the network.
set -euo pipefail

missing=()
command -v clang >/dev/null 2>&1 || missing+=(clang)
command -v llvm-symbolizer >/dev/null 2>&1 || missing+=(llvm)
command -v valgrind >/dev/null 2>&1 || missing+=(valgrind)
command -v cppcheck >/dev/null 2>&1 || missing+=(cppcheck)
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup_abuse_tools: installing ${missing[*]} from Debian's packages"
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends \
    -o DPkg::Lock::Timeout=600 "${missing[@]}" >/dev/null
  updated=yes
fi

# libFuzzer and clang's sanitizer runtimes are a separate package, named after clang's version.
runtime_dir=$(clang -print-runtime-dir 2>/dev/null || true)
if [ ! -f "$runtime_dir/libclang_rt.fuzzer-x86_64.a" ] && \
   [ ! -f "$(clang -print-file-name=libclang_rt.fuzzer-x86_64.a)" ]; then
  version=$(clang -dumpversion | cut -d. -f1)
  echo "setup_abuse_tools: installing libclang-rt-$version-dev (libFuzzer) from Debian's packages"
  [ "${updated:-}" = yes ] || apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends \
    -o DPkg::Lock::Timeout=600 "libclang-rt-$version-dev" >/dev/null
fi
