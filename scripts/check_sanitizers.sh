#!/usr/bin/env bash
# Runs the C tests of the FMI layers (test_fmi2_calls_<Model>, test_fmi2_instances_<Model>,
# soak_fmi2_<Model> and fmi3_abuse_<Model> for every model, abuse_attitude for AttitudePropagator;
# and the core's test_kinematics) under AddressSanitizer + UndefinedBehaviorSanitizer, ThreadSanitizer and
# valgrind memcheck, and the pytest suite through fmpy with both FMUs built with ASan+UBSan. Any
# report fails the run. docs/abuse_testing.md explains what each proves.
#
#   bash scripts/check_sanitizers.sh            full sizes
#   bash scripts/check_sanitizers.sh --quick    the bounded sizes CI runs
set -euo pipefail
cd "$(dirname "$0")/.."
quick=${1:-}

if [ -z "${AK_SET_UP:-}" ]; then
  bash scripts/setup.sh
  bash scripts/setup_abuse_tools.sh
fi

if [ "$quick" = --quick ]; then
  steps=50; soak=200000; valgrind_steps=3; valgrind_soak=20000
else
  steps=1000; soak=10000000; valgrind_steps=50; valgrind_soak=1000000
fi

configure_and_build() { # preset, targets...: the preset's folder is build-<preset>
  local preset=$1 folder=build-$1
  shift
  bash scripts/configure.sh "$preset"
  cmake --build "$folder" --parallel 2 --target "$@" >"$folder/build.log" 2>&1 || {
    cat "$folder/build.log"
    exit 1
  }
}

run() { # label, command...
  local label=$1
  shift
  echo "--- $label: $*"
  "$@"
}

export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:detect_stack_use_after_return=1:strict_string_checks=1:check_initialization_order=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export TSAN_OPTIONS=halt_on_error=1:second_deadlock_stack=1
models=$(bash scripts/models.sh)
per_model() { # prefix: prefix<Model> for every model
  local model
  for model in $models; do printf '%s%s ' "$1" "$model"; done
}

programs="$(per_model test_fmi2_calls_) $(per_model test_fmi2_instances_) $(per_model soak_fmi2_)
  $(per_model fmi3_abuse_)"
echo "=== AddressSanitizer + UndefinedBehaviorSanitizer (gcc, build-asan/)"
# shellcheck disable=SC2086
configure_and_build asan $programs test_kinematics test_attitude abuse_attitude
run asan+ubsan build-asan/test_kinematics
run asan+ubsan build-asan/test_attitude
run asan+ubsan build-asan/abuse_attitude 4 50 "$steps" "$soak"
for model in $models; do # the FMI 2 layer, then the FMI 3 layer (tests/c/fmi3_abuse.c)
  run asan+ubsan "build-asan/test_fmi2_calls_$model"
  run asan+ubsan "build-asan/test_fmi2_instances_$model" 1000 4 "$steps"
  run asan+ubsan "build-asan/soak_fmi2_$model" "$soak" --no-rss-check
  run asan+ubsan "build-asan/fmi3_abuse_$model" calls
  run asan+ubsan "build-asan/fmi3_abuse_$model" instances 1000 4 "$steps"
  run asan+ubsan "build-asan/fmi3_abuse_$model" soak "$soak"
done

# The instrumented binaries inside a real master: the whole pytest suite through fmpy.
# Leak detection is off here only because the Python interpreter itself does not free everything
# at exit; the FMU's leaks are checked by the C programs above and by valgrind below.
# shellcheck disable=SC2046
configure_and_build asan $(per_model fmu_) $(per_model fmu3_) $(per_model model_info_)
# --quick: the tests of the FMI layer only (calls, bad input, FMU state, model exchange,
# derivatives, EulerRates); the whole suite takes a minute and a half under ASan. Never
# tests/python/test_windows_binary.py and the other tests of the other platforms' binaries packaged in
# dist/ (test_fmi3_platforms.py, test_platforms.py, test_darwin_binaries.py), which the ASan build does
# not make.
if [ "$quick" = --quick ]; then
  suite=$(printf 'tests/python/%s ' test_fmi_calls.py test_bad_input.py test_fmu_state.py \
    test_model_exchange.py test_directional_derivatives.py test_output_derivatives.py \
    test_input_interpolation.py test_euler_rates.py test_value_runs.py test_fmi3_state_machine.py \
    test_fmi3_bad_input.py test_fmi3_fmu_state.py test_fmi3_derivatives.py test_fmi3_cosimulation.py \
    test_fmi3_bit_identity.py test_fmi3_attitude.py test_attitude_fmu.py test_attitude_derivatives.py)
else
  suite="tests/python --ignore=tests/python/test_windows_binary.py --ignore=tests/python/test_fmi3_platforms.py
    --ignore=tests/python/test_platforms.py --ignore=tests/python/test_darwin_binaries.py"
fi
echo "--- asan+ubsan: pytest through fmpy with the FMUs of build-asan/dist/ and build-asan/dist/fmi3/"
# shellcheck disable=SC2086
AK_FMU_DIR="$PWD/build-asan/dist" AK_FMU3_DIR="$PWD/build-asan/dist/fmi3" \
  LD_PRELOAD="$(gcc -print-file-name=libasan.so) $(gcc -print-file-name=libubsan.so)" \
  ASAN_OPTIONS=detect_leaks=0:abort_on_error=1 .venv/bin/python -m pytest -n logical $suite -q -p no:cacheprovider \
    --basetemp=build-asan/pytest-tmp \
  | tail -1

echo "=== ThreadSanitizer (gcc, build-tsan/)"
# shellcheck disable=SC2046
configure_and_build tsan $(per_model test_fmi2_instances_) $(per_model fmi3_abuse_) abuse_attitude
run tsan build-tsan/abuse_attitude 8 50 "$steps" 1000
for model in $models; do
  run tsan "build-tsan/test_fmi2_instances_$model" 1000 4 "$steps"
  run tsan "build-tsan/test_fmi2_instances_$model" 64 8 "$steps"
  run tsan "build-tsan/fmi3_abuse_$model" instances 1000 4 "$steps"
  run tsan "build-tsan/fmi3_abuse_$model" parallel "$steps"
done

echo "=== valgrind memcheck (the normal build, build/)"
[ -n "${AK_SET_UP:-}" ] || bash scripts/build.sh >/dev/null
memcheck() { # program, arguments...: valgrind's summary printed, any error or leak fails
  local log
  log="build/memcheck-$(basename "$1").log"
  echo "--- memcheck: $*"
  valgrind --error-exitcode=99 --leak-check=full --show-leak-kinds=all --errors-for-leak-kinds=all \
    --log-file="$log" "$@"
  grep -E "ERROR SUMMARY|in use at exit|total heap usage" "$log" | sed 's/^==[0-9]*== /    valgrind: /'
}
memcheck build/test_kinematics
memcheck build/abuse_attitude 4 20 "$valgrind_steps" "$valgrind_soak"
for model in $models; do
  memcheck "build/test_fmi2_calls_$model"
  memcheck "build/test_fmi2_instances_$model" 1000 4 "$valgrind_steps"
  memcheck "build/soak_fmi2_$model" "$valgrind_soak" --no-rss-check
  memcheck "build/fmi3_abuse_$model" calls
  memcheck "build/fmi3_abuse_$model" instances 100 4 "$valgrind_steps"
  memcheck "build/fmi3_abuse_$model" soak "$valgrind_soak"
done

echo "check_sanitizers: ASan+UBSan, TSan and memcheck: 0 errors, 0 leaks"
