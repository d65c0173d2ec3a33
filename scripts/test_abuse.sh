#!/usr/bin/env bash
# The bounded abuse tests that CI runs (a few minutes): ASan+UBSan, TSan and valgrind runs of the C
# tests, static analysis, 10 s of fuzzing per fuzzer after replaying its corpus (AK_FUZZ_SECONDS),
# a soak of 1e6 steps per model. docs/abuse_testing.md gives the long versions.
#   bash scripts/test_abuse.sh
# The fuzzing (its own build folder, build-fuzz/) runs beside the other checks, its output in
# build/fuzz.log, printed after theirs.
set -euo pipefail
cd "$(dirname "$0")/.."
mkdir -p build
bash scripts/fuzz.sh "${AK_FUZZ_SECONDS:-10}" >build/fuzz.log 2>&1 &
fuzz=$!
trap 'kill "$fuzz" 2>/dev/null || true' EXIT
bash scripts/check_sanitizers.sh --quick
bash scripts/check_static.sh
bash scripts/soak.sh 1000000
fuzz_status=0
wait "$fuzz" || fuzz_status=$?
trap - EXIT
echo "=== fuzzing (build/fuzz.log)"
cat build/fuzz.log
exit "$fuzz_status"
