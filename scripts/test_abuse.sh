#!/usr/bin/env bash
# The bounded abuse tests that CI runs (a few minutes): ASan+UBSan, TSan and valgrind runs of the C
# tests, static analysis, 10 s of fuzzing per fuzzer after replaying its corpus (AK_FUZZ_SECONDS),
# a soak of 1e6 steps per model. docs/abuse_testing.md gives the long versions.
#   bash scripts/test_abuse.sh
# The fuzzing (build-fuzz/) and the static analysis (no build) run beside the sanitizer and soak
# runs, their output in build/fuzz.log and build/static.log, printed after the others'.
set -euo pipefail
cd "$(dirname "$0")/.."
mkdir -p build
bash scripts/fuzz.sh "${AK_FUZZ_SECONDS:-10}" >build/fuzz.log 2>&1 &
fuzz=$!
bash scripts/check_static.sh >build/static.log 2>&1 &
static=$!
trap 'kill "$fuzz" "$static" 2>/dev/null || true' EXIT
bash scripts/check_sanitizers.sh --quick
bash scripts/soak.sh 1000000
status=0
for job in static fuzz; do
  pid=${!job}
  wait "$pid" || { echo "test_abuse: $job FAILED (build/$job.log)"; status=1; }
  echo "=== $job (build/$job.log)"
  cat "build/$job.log"
done
trap - EXIT
exit "$status"
