#!/usr/bin/env bash
# Soak: one instance through many steps with inputs changing every step (build/soak_fmi2_<Model>,
# then the FMI 3 layer's build/fmi3_abuse_<Model> soak, for every model; normal optimized build). Prints steps/s and the resident memory at the start and the end; fails on any
# failed call, drifted output, logged message, allocation during the run, or memory growth.
#   bash scripts/soak.sh [steps]      (default 10000000)
set -euo pipefail
cd "$(dirname "$0")/.."
steps=${1:-10000000}
if [ -z "${AK_SET_UP:-}" ]; then
  bash scripts/setup.sh
  bash scripts/build.sh >/dev/null
fi
for model in $(bash scripts/models.sh); do
  build/soak_fmi2_"$model" "$steps"
  build/fmi3_abuse_"$model" soak "$steps"
done
