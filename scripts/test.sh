#!/usr/bin/env bash
# The whole test suite: set up, build, run the core's unit tests (ctest) and the FMU's tests
# through fmpy (pytest).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh --with-wine
bash scripts/build.sh
ctest --test-dir build --output-on-failure
.venv/bin/python -m pytest tests "$@"
