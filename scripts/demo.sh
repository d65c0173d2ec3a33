#!/usr/bin/env bash
# The main job: simulate a tumbling body with fmpy (demo/tumbling_body.py), which writes
# results/tumbling_body.csv and the plot results/tumbling_body.png. It sets up and builds only what
# that needs: the native C toolchain, CMake and the pinned packages of requirements-demo.txt
# (scripts/setup.sh --demo), then the FMI 2.0 build-demo/dist/AngularKinematics.fmu with the
# x86_64-linux binary only (CMake preset demo). The FMUs for seven platforms, in dist/, are
# `bash scripts/build.sh`'s; this one stays out of dist/, whose FMUs the tests check.
#   bash scripts/demo.sh [demo/tumbling_body.py's options, e.g. --stop-time 5]
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh --demo
bash scripts/configure.sh demo
cmake --build build-demo --parallel 2 --target fmu_AngularKinematics
fmu=build-demo/dist/AngularKinematics.fmu
# The build's README of the folder describes dist/'s FMUs; this one says what is here.
cat >build-demo/dist/README.md <<'EOF'
# build-demo/dist/: the demo's FMU

`AngularKinematics.fmu`, written by `bash scripts/demo.sh`: FMI 2.0, Co-Simulation and Model
Exchange, the x86_64-linux binary only (`binaries/linux64`), C sources. The FMUs for seven platforms
are written to `dist/` by `bash scripts/build.sh`.
EOF
echo "demo: built $fmu (FMI 2.0, x86_64-linux binary only;" \
     "bash scripts/build.sh builds the seven-platform FMUs in dist/)"
.venv/bin/python -m demo.tumbling_body --fmu "$fmu" "$@"
