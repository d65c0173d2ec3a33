#!/usr/bin/env bash
# Fuzzes both FMI layers of every model with libFuzzer + ASan + UBSan: the FMI 2 layer with
# tests/c/fuzz_fmi2.c (built once per model: build-fuzz/fuzz_fmi2_<Model>), starting from the corpus kept in the repository
# (tests/fuzz_corpus/, one for every model: the encoding is the same), and the FMI 3 layer with
# tests/c/fuzz_fmi3.c (build-fuzz/fuzz_fmi3_<Model>).
#
#   bash scripts/fuzz.sh [seconds [--keep]]     (default 60 seconds per model)
#   AK_FUZZ_MODELS=EulerRates bash scripts/fuzz.sh 300     one model only
#
# For each model, first every input of the corpus is replayed (a regression test), then one
# fuzzing process runs for the given time; the model's FMI 3 fuzzer runs beside them (one core
# each). New inputs go to a scratch folder; with --keep the ones
# that add coverage are merged into the repository's corpus (commit them). A crashing input is
# written to build-fuzz/crash-* and fails the run; replay it with
#   AK_FUZZ_TRACE=1 build-fuzz/fuzz_fmi2_<Model> build-fuzz/crash-...
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
keep=${2:-}
models=${AK_FUZZ_MODELS:-$(bash scripts/models.sh)}
corpus=tests/fuzz_corpus

if [ -z "${AK_SET_UP:-}" ]; then
  bash scripts/setup.sh
  bash scripts/setup_abuse_tools.sh
fi
bash scripts/configure.sh fuzz
targets=()
for model in $models; do targets+=("fuzz_fmi2_$model" "fuzz_fmi3_$model"); done
cmake --build build-fuzz --parallel 2 --target "${targets[@]}" >build-fuzz/build.log 2>&1 || {
  cat build-fuzz/build.log
  exit 1
}

if [ ! -d "$corpus" ] || [ -z "$(ls -A "$corpus")" ]; then
  .venv/bin/python tests/c/fuzz_seeds.py "$corpus"
fi
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1

scratch=$(mktemp -d)
# A failure stops the fuzzer in the background too, which is waited for before its folder goes.
trap 'kill $(jobs -p) 2>/dev/null || true; wait; rm -rf "$scratch"' EXIT

# The FMI 3 layer of a model: its own encoding (tests/c/fuzz_fmi3.c), fuzzed from scratch. It runs
# in the background beside the model's FMI 2 fuzzer: libFuzzer uses one core, the machine has two.
fuzz_fmi3() {
  local model=$1
  mkdir -p "$scratch/fmi3-$model"
  "build-fuzz/fuzz_fmi3_$model" -max_total_time="$seconds" -print_final_stats=1 \
    -artifact_prefix=build-fuzz/fmi3- "$scratch/fmi3-$model" >"build-fuzz/fuzz3-$model.log" 2>&1
}

for model in $models; do
  fuzzer=build-fuzz/"fuzz_fmi2_$model"
  echo "fuzz ($model, FMI 3): fuzzing for $seconds s"
  fuzz_fmi3 "$model" &
  fmi3_pid=$!
  echo "fuzz ($model): replaying the $(ls "$corpus" | wc -l) inputs of $corpus"
  if ! "$fuzzer" -runs=0 -artifact_prefix=build-fuzz/ "$corpus" >"build-fuzz/replay-$model.log" 2>&1; then
    tail -60 "build-fuzz/replay-$model.log"
    echo "fuzz ($model): FAILED replaying the corpus"
    exit 1
  fi
  grep -E "INITED|DONE" "build-fuzz/replay-$model.log"

  mkdir -p "$scratch/$model"
  echo "fuzz ($model): fuzzing for $seconds s"
  "$fuzzer" -max_total_time="$seconds" -print_final_stats=1 \
    -artifact_prefix=build-fuzz/ "$scratch/$model" "$corpus" >"build-fuzz/fuzz-$model.log" 2>&1 || {
    tail -60 "build-fuzz/fuzz-$model.log"
    echo "fuzz ($model): FAILED, crashing input in build-fuzz/"
    exit 1
  }
  grep -E "^stat::(number_of_executed_units|average_exec_per_sec|new_units_added|peak_rss_mb)|^Done" \
    "build-fuzz/fuzz-$model.log" | sed "s/^/    /"
  echo "fuzz ($model): 0 crashes in $seconds s"

  if ! wait "$fmi3_pid"; then
    tail -60 "build-fuzz/fuzz3-$model.log"
    echo "fuzz ($model, FMI 3): FAILED, crashing input in build-fuzz/"
    exit 1
  fi
  grep -E "^stat::(number_of_executed_units|new_units_added)" "build-fuzz/fuzz3-$model.log" | sed "s/^/    /"
  echo "fuzz ($model, FMI 3): 0 crashes in $seconds s"

  if [ "$keep" = --keep ]; then
    before=$(ls "$corpus" | wc -l)
    "$fuzzer" -merge=1 "$corpus" "$scratch/$model" >"build-fuzz/merge-$model.log" 2>&1
    echo "fuzz ($model): corpus $corpus: $before -> $(ls "$corpus" | wc -l) inputs"
  fi
done
