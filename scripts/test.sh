#!/usr/bin/env bash
# The whole test suite, what CI runs (.ci/run):
#   set up once (scripts/setup.sh: toolchains, wine, the abuse-test tools, .venv), build once per
#   CMake preset, then: the C tests (ctest), a short benchmark run (no timing asserted: it checks
#   that the FMU evaluates exactly when an input changed), the speed regression guard
#   (bench/guard.sh: callgrind instruction counts, a few seconds), the bounded abuse tests
#   (sanitizers, valgrind, static analysis, fuzzing, soak: scripts/test_abuse.sh) beside the FMUs
#   through fmpy (pytest); the abuse tests' output follows pytest's, and one line says how each
#   ended.
#
#   bash scripts/test.sh              everything (CI)
#   bash scripts/test.sh --quick      the edit loop: the native build only (preset release), ctest,
#                                     pytest without the tests marked slow or external (wine,
#                                     qemu, the JVM, the cross builds: pytest.ini)
#   bash scripts/test.sh [--quick] -- PYTEST_ARGS...   e.g. -- -k fmu_state
set -euo pipefail
cd "$(dirname "$0")/.."
quick=
if [ "${1:-}" = --quick ]; then
  quick=1
  shift
fi
[ "${1:-}" = -- ] && shift

# pytest on every core (pytest-xdist); the two wine test files share one worker (xdist_group).
PARALLEL="-n logical --dist loadgroup"
if [ -n "$quick" ]; then
  # The native preset only (no cross build): the FMUs get this build's x86_64-linux binaries and
  # keep the other platforms' binaries of the last full build, if there was one (CMake's cache).
  # The tests that need those or run them (wine, qemu, the JVM) are marked external.
  [ -n "${AK_SET_UP:-}" ] || bash scripts/setup.sh
  bash scripts/configure.sh release
  cmake --build build --parallel 2
  ctest --test-dir build --output-on-failure
  .venv/bin/python -m pytest $PARALLEL -m "not slow and not external" "$@"
  exit
fi
bash scripts/setup.sh --with-wine
bash scripts/setup_importers.sh # OpenJDK, Maven, the FMI4j driver (tests/python/test_fmi4j.py)
bash scripts/setup_abuse_tools.sh
export AK_SET_UP=1 # the scripts below skip their own set-up and build
bash scripts/build.sh
# The proof builds (docs/platforms.md): the 32-bit x86 code as static musl drivers that run here,
# and zig's x86_64-linux binaries, whose printouts must equal gcc's (tests/python/test_platforms.py).
bash scripts/configure.sh x86-musl
cmake --build build-x86-musl --parallel 2 --target linked_drivers
bash scripts/configure.sh zig-linux
cmake --build build-zig-linux --parallel 2 --target fmi2_binaries fmi3_binaries fmu_driver fmi3_driver
ctest --test-dir build --output-on-failure
bash bench/run.sh --quick
bash bench/guard.sh # callgrind instructions per cycle at most 3 % over the previous release's
# The abuse tests run beside pytest: they use their own build folders and, for most of their time
# (valgrind, cppcheck, TSan, one fuzzer of two), one core, so together the two keep both busy.
# Their output goes to build/abuse.log, printed when pytest is done.
echo "test.sh: the abuse tests (scripts/test_abuse.sh) run beside pytest; output in build/abuse.log"
bash scripts/test_abuse.sh >build/abuse.log 2>&1 &
abuse=$!
trap 'kill "$abuse" 2>/dev/null || true' EXIT # an interrupted run stops them too
pytest_status=0
.venv/bin/python -m pytest $PARALLEL "$@" || pytest_status=$?
abuse_status=0
wait "$abuse" || abuse_status=$?
trap - EXIT
echo "=== the abuse tests (build/abuse.log)"
cat build/abuse.log
echo "test.sh: pytest exit status $pytest_status, abuse tests exit status $abuse_status"
[ "$pytest_status" -eq 0 ] && [ "$abuse_status" -eq 0 ]
