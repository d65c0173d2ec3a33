#!/usr/bin/env bash
# The whole test suite, what CI runs (.ci/run):
#   set up once (scripts/setup.sh: toolchains, wine, the abuse-test tools, .venv), build once per
#   CMake preset, then: the C tests (ctest), a short benchmark run (no timing asserted: it checks
#   that the FMU evaluates exactly when an input changed), the bounded abuse tests (sanitizers,
#   valgrind, static analysis, fuzzing, soak: scripts/test_abuse.sh) beside the FMUs through fmpy
#   (pytest); the abuse tests' output follows pytest's, and one line says how each ended.
#
#   bash scripts/test.sh              everything (CI)
#   bash scripts/test.sh --quick      the edit loop: build, ctest, pytest without the slow tests
#   bash scripts/test.sh [--quick] -- PYTEST_ARGS...   e.g. -- -k fmu_state
set -euo pipefail
cd "$(dirname "$0")/.."
quick=
if [ "${1:-}" = --quick ]; then
  quick=1
  shift
fi
[ "${1:-}" = -- ] && shift

bash scripts/setup.sh --with-wine
bash scripts/setup_importers.sh # OpenJDK, Maven, the FMI4j driver (tests/python/test_fmi4j.py)
[ -n "$quick" ] || bash scripts/setup_abuse_tools.sh
export AK_SET_UP=1 # the scripts below skip their own set-up and build
# pytest on every core (pytest-xdist); the two wine test files share one worker (xdist_group).
PARALLEL="-n logical --dist loadgroup"
bash scripts/build.sh
ctest --test-dir build --output-on-failure
if [ -n "$quick" ]; then
  .venv/bin/python -m pytest $PARALLEL -m "not slow" "$@"
  exit
fi
bash bench/run.sh --quick
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
