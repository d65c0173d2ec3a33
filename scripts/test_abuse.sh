#!/usr/bin/env bash
# The bounded abuse tests that CI runs (a few minutes): ASan+UBSan, TSan and valgrind runs of the C
# tests, static analysis, 10 s of fuzzing per fuzzer after replaying its corpus (AK_FUZZ_SECONDS),
# a soak of 1e6 steps per model. docs/abuse_testing.md gives the long versions.
#   bash scripts/test_abuse.sh
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/check_sanitizers.sh --quick
bash scripts/check_static.sh
bash scripts/fuzz.sh "${AK_FUZZ_SECONDS:-10}"
bash scripts/soak.sh 1000000
