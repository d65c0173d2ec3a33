#!/usr/bin/env bash
# Prints the models, one per line, as codegen/project.py lists them (MODELS), read from the
# generated cmake/generated.cmake so that no Python is needed:  for model in $(bash scripts/models.sh)
set -euo pipefail
cd "$(dirname "$0")/.."
sed -n 's/^set(AK_MODELS \(.*\))$/\1/p' cmake/generated.cmake | tr ' ' '\n'
