#!/usr/bin/env bash
# The speed regression guard (docs/performance.md): callgrind instructions per
# cycle of each model and FMI version in build/ against the previous release's, recorded in
# bench/callgrind_previous_release.txt. Fails (exit 1) when any rises more than 3 %. Instruction
# counts, not wall time, so a loaded CI machine does not matter; runs of 2560 and 12800 steps
# (whole turns of the drivers' 256-row input tables), about 15 s on 2 cores.
#   bash bench/guard.sh             compare build/ (scripts/build.sh first) with the record
#   bash bench/guard.sh --record    build the previous release (bench/previous_release.sh) and
#                                   write the record from it, with the current drivers
# The drivers are the current build's in both cases: re-record when bench/bench_fmi3.c or
# bench/bench_attitude.c change their loops, or the compiler or libm change.
# The lines AngularKinematics, EulerRates and AttitudePropagator count the drivers' default rows
# (bench_fmi3: the random rows of bench/bench_inputs.h; bench_attitude: its own 256 rows of
# omega). The lines *-smooth count the same loops on the smooth rows (--inputs smooth: a tumbling
# body sampled every 0.01 s), recorded the same way, from the previous release.
set -euo pipefail
cd "$(dirname "$0")/.."
source bench/instructions.sh
export AK_SMALL_STEPS=2560 AK_LARGE_STEPS=12800
record=bench/callgrind_previous_release.txt
limit_percent=3

# "model FMI-version instructions" lines for the FMU binaries under $1 (a build folder).
measure() {
  local fmi2=$1/fmu/binaries/linux64 fmi3=$1/fmu3/binaries/x86_64-linux
  local kin=(build/bench/bench_fmi3 "$fmi2/AngularKinematics.so" "$fmi3/AngularKinematics.so")
  echo "AngularKinematics 2 $(instructions_per_step "${kin[@]}" STEPS 1 fmi2)"
  echo "AngularKinematics 3 $(instructions_per_step "${kin[@]}" STEPS 1 fmi3)"
  local euler=(build/bench/bench_fmi3 "$fmi2/EulerRates.so" "$fmi3/EulerRates.so")
  echo "EulerRates 2 $(instructions_per_step "${euler[@]}" STEPS 1 fmi2)"
  echo "EulerRates 3 $(instructions_per_step "${euler[@]}" STEPS 1 fmi3)"
  local attitude=(build/bench/bench_attitude "$fmi2/AttitudePropagator.so" --fmi3
    "$fmi3/AttitudePropagator.so" --steps STEPS)
  echo "AttitudePropagator 2 $(instructions_per_step "${attitude[@]}" --only q+theta)"
  echo "AttitudePropagator 3 $(instructions_per_step "${attitude[@]}" --only q+theta3)"
  local smooth=(--inputs smooth)
  echo "AngularKinematics-smooth 2 $(instructions_per_step "${kin[@]}" STEPS 1 fmi2 "${smooth[@]}")"
  echo "AngularKinematics-smooth 3 $(instructions_per_step "${kin[@]}" STEPS 1 fmi3 "${smooth[@]}")"
  echo "AttitudePropagator-smooth 2 $(instructions_per_step "${attitude[@]}" --only q+theta \
    "${smooth[@]}")"
  echo "AttitudePropagator-smooth 3 $(instructions_per_step "${attitude[@]}" --only q+theta3 \
    "${smooth[@]}")"
}

if [ "${1:-}" = --record ]; then
  previous=$(bash bench/previous_release.sh)
  {
    echo "# Callgrind instructions per cycle of the previous release, $(head -1 \
      bench/previous_release.txt) (bench/previous_release.txt),"
    echo "# through the current drivers:"
    echo "# AngularKinematics body123 and EulerRates: set 9 + doStep + get 12 (FMI 3: 3 sets of 3,"
    echo "# one get of 4 arrays);"
    echo "# AttitudePropagator set omega + doStep + get q, theta (FMI 3: one set, one get of 2"
    echo "# arrays)."
    echo "# The drivers' default rows; *-smooth: the same loops on the smooth rows (--inputs smooth)."
    echo "# Written by bash bench/guard.sh --record; a measurement, kept as recorded (not by"
    echo "# python -m codegen: docs/architecture.md)."
    echo "# model FMI-version instructions"
    measure "$previous/build"
  } >"$record"
  cat "$record"
  exit 0
fi

status=0
echo "guard: callgrind instructions per cycle, build/ against the previous release ($record)"
while read -r model version count; do
  recorded=$(awk -v m="$model" -v v="$version" '$1 == m && $2 == v { print $3 }' "$record")
  if [ -z "$recorded" ] || [ -z "$count" ]; then
    echo "guard: FAILED: no figure for $model FMI $version (recorded '$recorded', now '$count')"
    status=1
    continue
  fi
  verdict=$(awk -v c="$count" -v r="$recorded" -v l="$limit_percent" 'BEGIN {
    printf "%+.1f %% %s", 100 * (c - r) / r, (c > r * (1 + l / 100)) ? "FAILED" : "ok" }')
  echo "guard: $model FMI $version: $count instructions, previous release $recorded, $verdict"
  case "$verdict" in *FAILED) status=1 ;; esac
done < <(measure build)
[ "$status" -eq 0 ] ||
  echo "guard: FAILED: a cycle costs more than $limit_percent % over the previous release"
exit "$status"
