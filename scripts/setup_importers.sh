#!/usr/bin/env bash
# Installs the other FMI importers of the tests: for tests/python/test_fmi4j.py OpenJDK and Maven
# from Debian's packages when missing, then builds examples/fmi4j/target/fmi4j-driver.jar with FMI4j
# (info.laht.fmi4j:fmi-import, pinned in examples/fmi4j/pom.xml) from Maven Central into ~/.m2; for
# tests/python/test_engines.py Debian's libtbb12, which Ecos's bundled libecosc.so needs (libcosim and
# Ecos themselves are the pinned Python packages libcosimpy and ecospy of requirements.txt).
# Idempotent and quiet: a second run installs nothing, downloads nothing and builds nothing.
# docs/cosimulation.md gives what each part costs.
set -euo pipefail
cd "$(dirname "$0")/.."

missing=()
command -v javac >/dev/null 2>&1 || missing+=(default-jdk-headless)
command -v mvn >/dev/null 2>&1 || missing+=(maven)
dpkg -s libtbb12 >/dev/null 2>&1 || missing+=(libtbb12)
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup_importers: installing ${missing[*]} from Debian's packages"
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends \
    -o DPkg::Lock::Timeout=600 "${missing[@]}" >/dev/null
fi

driver=examples/fmi4j
jar=$driver/target/fmi4j-driver.jar
if [ ! -f "$jar" ] || [ -n "$(find "$driver/pom.xml" "$driver/src" -newer "$jar" -type f)" ]; then
  # Offline when ~/.m2 already holds everything (CI's cache); otherwise from Maven Central.
  mvn -B -q -o -f "$driver/pom.xml" package >/dev/null 2>&1 ||
    mvn -B -q -f "$driver/pom.xml" package
fi
