#!/usr/bin/env bash
# The whole test suite: set up, build, run the core's unit tests (ctest) and the FMU's tests
# through fmpy (pytest), then the bounded abuse tests (sanitizers, valgrind, static analysis,
# fuzzing, soak: scripts/test_abuse.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh
ctest --test-dir build --output-on-failure
.venv/bin/python -m pytest tests "$@"
bash scripts/test_abuse.sh
