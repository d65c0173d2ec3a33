#!/usr/bin/env bash
# The main job: set up, build dist/AngularKinematics.fmu, simulate a tumbling body with fmpy.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh
.venv/bin/python demo/tumbling_body.py "$@"
