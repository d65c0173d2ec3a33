#!/usr/bin/env bash
# The whole test suite: set up, build, run the core's unit tests and the C tests of the FMI layer
# (ctest), a short smoke run of the benchmark (it asserts no timing, only that it runs, prints its
# figures and that the FMU does not evaluate when no input changed), the bounded abuse tests
# (sanitizers, valgrind, static analysis, fuzzing, soak: scripts/test_abuse.sh), then the FMU's
# tests through fmpy (pytest), last so that its summary closes the output.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh --with-wine
bash scripts/build.sh
ctest --test-dir build --output-on-failure
bash bench/run.sh --quick
bash scripts/test_abuse.sh
.venv/bin/python -m pytest tests "$@"
