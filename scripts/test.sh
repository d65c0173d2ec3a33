#!/usr/bin/env bash
# The whole test suite: set up, build, run the core's unit tests (ctest) and the FMU's tests
# through fmpy (pytest), then a short smoke run of the benchmark (it asserts no timing, only that
# it runs, prints its figures and that the FMU does not evaluate when no input changed).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh
ctest --test-dir build --output-on-failure
.venv/bin/python -m pytest tests "$@"
bash bench/run.sh --quick
