#!/usr/bin/env bash
# Builds the previous release's FMU binaries (the commit of bench/previous_release.txt) in a
# scratch worktree, /tmp/ak-previous-COMMIT, with that commit's own release preset, and prints
# the worktree's path. The FMU libraries only (no tests, no bench targets): the current drivers
# load them with dlopen (same GUIDs, same value references). Built once, reused after.
#   bash bench/previous_release.sh    ->  /tmp/ak-previous-ad3edad
set -euo pipefail
cd "$(dirname "$0")/.."
commit=$(head -1 bench/previous_release.txt)
dir=${AK_PREVIOUS_DIR:-/tmp/ak-previous-$commit}
if [ ! -d "$dir" ]; then
  git worktree add --detach "$dir" "$commit" >&2
fi
[ -e "$dir/.venv" ] || ln -s "$(readlink -f .venv)" "$dir/.venv"
if [ ! -f "$dir/build/fmu3/binaries/x86_64-linux/EulerRates.so" ]; then
  (cd "$dir" && bash scripts/configure.sh release &&
    cmake --build build --parallel 2 --target AngularKinematics AngularKinematics_fmi3 \
      EulerRates EulerRates_fmi3 AttitudePropagator AttitudePropagator_fmi3) >&2
fi
echo "$dir"
