#!/usr/bin/env bash
# The benchmark (docs/performance.md). Builds the FMU, the driver and the pass-through FMU in
# Release in build/, then prints, for this machine:
#   1. the C driver's figures (bench/bench_fmu.c): set/doStep/get cycle (12 outputs, all
#      outputs, one lazy output) vs. the bare core, gets
#      without input change, gets after one input change, scaling with the step count;
#   2. instruction counts per step under callgrind, when valgrind is installed (stable where
#      timings are noisy);
#   3. the fmpy comparison (bench/fmpy_bench.py): simulate_fmu with AngularKinematics vs. the
#      pass-through FMU;
#   4. each of the 24 sequences against its own anchor and every output against the all-outputs
#      anchor (bench/bench_sequences_fmu.c), in time and, with callgrind, in instructions;
#   5. AttitudePropagator (bench/bench_attitude.c): set omega + doStep + get q (and theta), FMI 2
#      and FMI 3, vs. the bare quaternion update (and the update + angle extraction), frozen
#      copies in bench/attitude_anchor.c, over the largest step count of --steps;
#   5b. PointKinematics (bench/bench_point.c): set 24 + doStep + get 18, FMI 2, vs. the
#      pass-through's cycle with the same counts plus the hand-written formula;
#   5c. QuaternionKinematics (bench/bench_quaternion.c): set 12 + doStep + get 32, FMI 2, vs. the
#      pass-through's cycle with the same counts plus the hand-written body123 formula, on random
#      and smooth rows of its own (q, q_dot, q_ddot);
#   6. the project's sincos beside the C library's sin and cos (bench/bench_sincos.c), and three
#      atan2 at once (ak_atan2_three) beside three ak_atan2 and three C library atan2
#      (bench/bench_atan2.c);
#   7. the goals table: each time goal, its median ratio on each input kind, the pass-through
#      FMU's cycle beside it, met or not.
# The timed drivers (1, 4, 5 and bench/bench_fmi3.c) run on both input kinds of
# bench/bench_inputs.h: random rows (angles anywhere at every step) and smooth rows (a tumbling
# body sampled every 0.01 s, as a co-simulation feeds it); each times the pass-through FMU
# (bench/passthrough/: FMI 2 and FMI 3, inputs copied to outputs) with the same numbers of
# inputs, outputs and calls, alternately with the rest, and prints it beside every ratio.
# The anchors every ratio is to do not move with the FMU: the hand-written 1-2-3
# formula (tests/c/kinematics_123.c) and the bare quaternion update; the general core is a figure
# of its own. Unless --quick or --no-previous, the previous release's binaries
# (bench/previous_release.sh, a scratch worktree) are timed alternately with the current build.
# It asserts no timing; it fails only if something does not run or the FMU evaluates when it
# should not (the driver counts the evaluations through the logCalls trace).
#
# Usage: bash bench/run.sh [--quick] [--steps LIST] [--repeats R] [--calls N]
#                          [--fmpy-steps N] [--fmpy-repeats R] [--no-callgrind] [--no-previous]
#                          [--inputs random|smooth|both]
#   --quick          a bounded run for CI (well under 30 s): small counts, no callgrind, no
#                    previous release
#   --steps LIST     step counts of the scaling runs (default 1e3,1e4,1e5,1e6,1e7)
#   --repeats R      repeats per figure of the driver, median quoted (default 5)
#   --calls N        iterations of the driver's single-call loops (default 1e6)
#   --fmpy-steps N   steps per fmpy simulation (default 100000)
#   --fmpy-repeats R fmpy simulations per FMU (default 5)
#   --inputs KIND    the input rows of the timed drivers: random, smooth or both (default both)
# The whole output is also written to build/last-run.md; the goals table's figures to
# build/bench-figures.txt.
set -euo pipefail
cd "$(dirname "$0")/.."

arguments="$*"
steps=1e3,1e4,1e5,1e6,1e7
repeats=5
calls=1e6
fmpy_steps=100000
fmpy_repeats=5
callgrind=yes
previous=yes
fmi3_steps=1e6 # per run of bench/bench_fmi3.c (--quick: 1e5)
sequence_steps=2e5 # per loop of bench/bench_sequences_fmu.c (--quick: 2e4)
kinds=(random smooth)
while [ $# -gt 0 ]; do
  case "$1" in
    --quick) steps=1e3,1e4,1e5; repeats=3; calls=1e5; fmpy_steps=2000; fmpy_repeats=3
             callgrind=no; fmi3_steps=1e5; sequence_steps=2e4; previous=no ;;
    --steps) steps="$2"; shift ;;
    --repeats) repeats="$2"; shift ;;
    --calls) calls="$2"; shift ;;
    --fmpy-steps) fmpy_steps="$2"; shift ;;
    --fmpy-repeats) fmpy_repeats="$2"; shift ;;
    --no-callgrind) callgrind=no ;;
    --no-previous) previous=no ;;
    --inputs) case "$2" in
                random|smooth) kinds=("$2") ;;
                both) kinds=(random smooth) ;;
                *) echo "bench/run.sh: --inputs random, smooth or both" >&2; exit 2 ;;
              esac
              shift ;;
    *) echo "bench/run.sh: unknown option $1 (see the header of bench/run.sh)" >&2; exit 2 ;;
  esac
  shift
done

# The release build (preset release, build/): what dist/ ships.
if [ -z "${AK_SET_UP:-}" ]; then
  bash scripts/setup.sh
  bash scripts/build.sh >/dev/null
fi

fmu_so=build/fmu/binaries/linux64/AngularKinematics.so
fmu3_so=build/fmu3/binaries/x86_64-linux/AngularKinematics.so
driver=build/bench/bench_fmu
ap_so=build/fmu/binaries/linux64/AttitudePropagator.so
ap3_so=build/fmu3/binaries/x86_64-linux/AttitudePropagator.so
pt_so=build/passthrough/PassThrough.so
pt3_so=build/passthrough/PassThrough3.so
passthroughs=(--passthrough "$pt_so" --passthrough3 "$pt3_so")
figures=build/bench-figures.txt # "key kind ratio beside passthrough-ns" lines of the drivers
: >"$figures"
previous_fmi3=() previous_ap=()
if [ "$previous" = yes ]; then
  previous_build=$(bash bench/previous_release.sh)/build
  previous_fmi3=("$previous_build/fmu/binaries/linux64/AngularKinematics.so"
                 "$previous_build/fmu3/binaries/x86_64-linux/AngularKinematics.so")
  previous_ap=(--previous "$previous_build/fmu/binaries/linux64/AttitudePropagator.so"
               --previous3 "$previous_build/fmu3/binaries/x86_64-linux/AttitudePropagator.so")
fi

# The calls in one function of a binary, counted: "sincos@plt x3, ...".
calls_in() {
  local calls
  # Link-time optimization may rename a static function name.lto_priv.N.
  calls=$(objdump -d --no-show-raw-insn "$1" | awk "/<$2(\\.lto_priv\\.[0-9]+)?>:/,/^\$/" |
    sed -n 's/.*call.*<\(.*\)>.*/\1/p' | sort | uniq -c |
    awk '{printf "%s%s x%s", sep, $2, $1; sep=", "}')
  echo "${calls:-none (function not found or no call)}"
}

machine() {
  local model cores flags lto
  model=$(lscpu 2>/dev/null | sed -n 's/^Model name:[[:space:]]*//p' | head -1)
  cores=$(nproc)
  flags=$(sed -n 's/^CMAKE_C_FLAGS_RELEASE:STRING=//p' build/CMakeCache.txt)
  lto=$(sed -n 's/^AK_LTO:BOOL=//p' build/CMakeCache.txt)
  echo "Machine: ${model:-unknown CPU}, ${cores} cores ($(uname -m), $(uname -r))"
  echo "Compiler: $(cc --version | head -1); Release flags: ${flags}, link-time optimization ${lto}"
  echo "Date: $(date -u '+%Y-%m-%d %H:%M UTC'); load average: $(cut -d' ' -f1-3 /proc/loadavg)"
  if command -v objdump >/dev/null 2>&1; then
    # The driver's bare core is ak_general_angular_kinematics for body123, inlined into its
    # timing loop; the FMU runs its sequence kernel through the model's evaluate, evaluate_all
    # (every output after an input changed: evaluate, then evaluate_lazy) and evaluate_lazy (the
    # lazy group after a main read).
    echo "Calls in the driver's core loop time_core (core inlined): $(calls_in "$driver" time_core)"
    echo "Calls in the FMU's evaluate: $(calls_in "$fmu_so" evaluate)"
    echo "Calls in the FMU's evaluate_all: $(calls_in "$fmu_so" evaluate_all)"
    echo "Calls in the FMU's evaluate_lazy: $(calls_in "$fmu_so" evaluate_lazy)"
  fi
}

source bench/instructions.sh # instructions_per_step

# One table of instruction counts: a title, then "label|instructions" rows, the first the anchor
# the others are divided by.
instruction_table() {
  local title=$1 core=${2#*|}
  shift
  echo "$title"
  echo
  echo "| loop | instructions per step | / anchor |"
  echo "|---|---:|---:|"
  for row in "$@"; do
    awk -v l="${row%|*}" -v c="${row#*|}" -v k="$core" \
      'BEGIN { printf "| %s | %d | %.2f |\n", l, c, c / k }'
  done
}

callgrind_table() {
  local fmu=("$driver" "$fmu_so") fmi3=(build/bench/bench_fmi3 "$fmu_so" "$fmu3_so")
  local ap=(build/bench/bench_attitude "$ap_so" --fmi3 "$ap3_so" --steps STEPS --only)
  instruction_table \
    "Instructions per step under valgrind --tool=callgrind (exact, independent of machine load):" \
    "anchor: hand-written 1-2-3 formula|$(instructions_per_step "${fmu[@]}" --only anchor \
      --steps STEPS)" \
    "general core, body123|$(instructions_per_step "${fmu[@]}" --only core --steps STEPS)" \
    "set 9 + doStep + get 12|$(instructions_per_step "${fmu[@]}" --only cycle --steps STEPS)" \
    "set 9 + doStep + get all outputs|$(instructions_per_step "${fmu[@]}" --only all --steps STEPS)" \
    "set 9 + doStep + get R[1,1]|$(instructions_per_step "${fmu[@]}" --only lazy --steps STEPS)" \
    "get 12, no input changed|$(instructions_per_step "${fmu[@]}" --only get --steps STEPS)"
  echo
  local rows=("FMI 2: set 9 + doStep + get 12|$(instructions_per_step "${fmi3[@]}" STEPS 1 fmi2)"
    "FMI 3: 3 sets of 3 + doStep + get of 4 arrays|$(instructions_per_step "${fmi3[@]}" STEPS 1 fmi3)"
    "FMI 3: one set of the 3 arrays + doStep + get of 4 arrays|$(instructions_per_step "${fmi3[@]}" \
      STEPS 1 fmi3-one-set)"
    "pass-through FMU, FMI 2: set 9 + doStep + get 12|$(instructions_per_step "${fmi3[@]}" \
      STEPS 1 pt2 "${passthroughs[@]}")"
    "pass-through FMU, FMI 3: one set of 3 arrays + doStep + get of 4 arrays|$(\
      instructions_per_step "${fmi3[@]}" STEPS 1 pt3-one-set "${passthroughs[@]}")")
  if [ ${#previous_fmi3[@]} -gt 0 ]; then
    local old=(build/bench/bench_fmi3 "${previous_fmi3[@]}")
    rows+=("previous release, FMI 2 cycle|$(instructions_per_step "${old[@]}" STEPS 1 fmi2)"
      "previous release, FMI 3 cycle|$(instructions_per_step "${old[@]}" STEPS 1 fmi3)")
  fi
  instruction_table "bench_fmi3's loops against the same anchor:" \
    "anchor: hand-written 1-2-3 formula|$(instructions_per_step "${fmi3[@]}" STEPS 1 k123)" \
    "general core, body123, inlined|$(instructions_per_step "${fmi3[@]}" STEPS 1 core)" "${rows[@]}"
  echo
  rows=("update + angles of body123|$(instructions_per_step "${ap[@]}" angles)"
    "FMI 2: set omega + doStep + get q|$(instructions_per_step "${ap[@]}" q)"
    "FMI 2: set omega + doStep + get q, theta|$(instructions_per_step "${ap[@]}" q+theta)"
    "FMI 3: set omega + doStep + get q|$(instructions_per_step "${ap[@]}" q3)"
    "FMI 3: set omega + doStep + get q, theta|$(instructions_per_step "${ap[@]}" q+theta3)")
  if [ ${#previous_ap[@]} -gt 0 ]; then
    local old_ap=(build/bench/bench_attitude "${previous_ap[1]}" --fmi3 "${previous_ap[3]}"
      --steps STEPS --only)
    rows+=("previous release, FMI 2: get q|$(instructions_per_step "${old_ap[@]}" q)"
      "previous release, FMI 2: get q, theta|$(instructions_per_step "${old_ap[@]}" q+theta)"
      "previous release, FMI 3: get q|$(instructions_per_step "${old_ap[@]}" q3)"
      "previous release, FMI 3: get q, theta|$(instructions_per_step "${old_ap[@]}" q+theta3)")
  fi
  instruction_table "AttitudePropagator against the bare quaternion update:" \
    "anchor: bare quaternion update|$(instructions_per_step "${ap[@]}" bare)" "${rows[@]}"
  local qk=(build/bench/bench_quaternion build/fmu/binaries/linux64/QuaternionKinematics.so
    "$pt_so" STEPS 1) kind
  for kind in "${kinds[@]}"; do
    echo
    instruction_table "QuaternionKinematics, $kind rows, against its hand-written body123 formula:" \
      "anchor: hand-written body123 formula|$(instructions_per_step "${qk[@]}" "$kind" anchor)" \
      "pass-through FMU, FMI 2: set 12 + doStep + get 32|$(instructions_per_step "${qk[@]}" \
        "$kind" passthrough)" \
      "FMI 2: set 12 + doStep + get 32|$(instructions_per_step "${qk[@]}" "$kind" quaternion)"
  done
}

# Each sequence's FMI 2 cycle against its own anchor (bench/anchors_sequences.c), and the cycle
# reading every output against the all-outputs anchor: instructions per step, with short runs
# (2560 and 12800 steps, whole turns of the input table) to keep the 50 valgrind runs brief.
sequence_callgrind_table() {
  local run=(build/bench/bench_sequences_fmu "$fmu_so" --steps STEPS --only) k a c
  echo "Every sequence, instructions per step: its FMI 2 cycle (set 9 + doStep + get 12) against"
  echo "its anchor, the closed-form formula of bench/anchors_sequences.c:"
  echo
  echo "| sequence | anchor | cycle | cycle / anchor |"
  echo "|---|---:|---:|---:|"
  for k in $(seq 1 24); do
    a=$(AK_SMALL_STEPS=2560 AK_LARGE_STEPS=12800 instructions_per_step "${run[@]}" anchor "$k")
    c=$(AK_SMALL_STEPS=2560 AK_LARGE_STEPS=12800 instructions_per_step "${run[@]}" cycle "$k")
    awk -v k="$k" -v a="$a" -v c="$c" 'BEGIN {
      split("123 132 213 231 312 321 121 131 212 232 313 323", o, " ")
      printf "| %s%s | %d | %d | %.2f |\n", k <= 12 ? "body" : "space", o[(k - 1) % 12 + 1], a, c,
        c / a }'
  done
  echo
  a=$(AK_SMALL_STEPS=2560 AK_LARGE_STEPS=12800 instructions_per_step "${run[@]}" all-anchor 1)
  c=$(AK_SMALL_STEPS=2560 AK_LARGE_STEPS=12800 instructions_per_step "${run[@]}" all 1)
  instruction_table "Every output (body123), instructions per step:" \
    "anchor: all outputs from the core's functions, no FMI|$a" \
    "set 9 + doStep + get every output|$c"
}

# The time goals against the drivers' figures (build/bench-figures.txt): per goal, the median
# ratio on each input kind, the pass-through's cycle and its ratio beside, met or not. For a
# ratio to an anchor, the pass-through's ratio is (pass-through cycle + anchor) / anchor, what the
# ratio would be if the FMU added only the pass-through's calls to the anchor; for FMI 3 / FMI 2,
# the pass-through's own FMI 3 cycle / its FMI 2 cycle.
goals_table() {
  echo "Goals (time, medians of alternating repeats; \"pass-through\": its cycle in ns and its ratio"
  echo "beside, per input kind: (pass-through + anchor) / anchor, or for FMI 3 / FMI 2 the"
  echo "pass-through's own FMI 3 / FMI 2):"
  echo
  awk -v kinds="${kinds[*]}" '
    { ratio[$1, $2] = $3; beside[$1, $2] = $4; ns[$1, $2] = $5 }
    END {
      n = split("ak-fmi2 ak-fmi3 ap-fmi2-q ap-fmi3-q ap-fmi2-theta ap-fmi3-theta qk-fmi2", keys, " ")
      split("1.3 1.05 1.5 1.5 1.3 1.3 1.3", limits, " ")
      goal["ak-fmi2"] = "AngularKinematics body123 FMI 2 cycle / hand-written 1-2-3 formula"
      goal["ak-fmi3"] = "AngularKinematics FMI 3 cycle (one set of the 3 arrays) / FMI 2 cycle"
      goal["ap-fmi2-q"] = "AttitudePropagator FMI 2, get q / bare quaternion update"
      goal["ap-fmi3-q"] = "AttitudePropagator FMI 3, get q / bare quaternion update"
      goal["ap-fmi2-theta"] = "AttitudePropagator FMI 2, get q, theta / update + angles"
      goal["ap-fmi3-theta"] = "AttitudePropagator FMI 3, get q, theta / update + angles"
      goal["qk-fmi2"] = "QuaternionKinematics FMI 2 cycle / (pass-through + body123 formula)"
      m = split(kinds, kind, " ")
      printf "| goal | at most |"
      for (j = 1; j <= m; j++) printf " %s |", kind[j]
      for (j = 1; j <= m; j++) printf " pass-through, %s |", kind[j]
      printf " met |\n|---|---:|"
      for (j = 1; j <= 2 * m; j++) printf "---:|"
      printf "---|\n"
      for (i = 1; i <= n; i++) {
        k = keys[i]; met = ""; missing = 0
        printf "| %s | %s |", goal[k], limits[i]
        for (j = 1; j <= m; j++) {
          if ((k, kind[j]) in ratio) {
            printf " %.3f |", ratio[k, kind[j]]
            if (ratio[k, kind[j]] > limits[i] + 0) met = met (met == "" ? "" : ", ") "not on " kind[j]
          } else {
            printf " - |"; missing = 1
          }
        }
        for (j = 1; j <= m; j++) {
          if ((k, kind[j]) in ratio) printf " %.1f ns, %.3f |", ns[k, kind[j]], beside[k, kind[j]]
          else printf " - |"
        }
        printf " %s |\n", missing ? "no figure" : (met == "" ? "yes" : "no (" met ")")
      }
    }' "$figures"
}

{
  echo "## AngularKinematics benchmark (bash bench/run.sh${arguments:+ $arguments})"
  echo
  machine
  echo
  for kind in "${kinds[@]}"; do
    echo "### AngularKinematics, $kind inputs"
    echo
    "$driver" "$fmu_so" --steps "$steps" --repeats "$repeats" --calls "$calls" --inputs "$kind" \
      --passthrough "$pt_so"
    echo
    # The FMI 3 cycle beside the FMI 2 cycle and the core, alternately (bench/bench_fmi3.c).
    AK_BENCH_FIGURES=$figures build/bench/bench_fmi3 "$fmu_so" "$fmu3_so" "$fmi3_steps" \
      "$repeats" all "${previous_fmi3[@]}" --inputs "$kind" "${passthroughs[@]}"
    echo
    # Every sequence against its own anchor; every output against the all-outputs anchor.
    build/bench/bench_sequences_fmu "$fmu_so" --steps "$sequence_steps" --repeats "$repeats" \
      --inputs "$kind" --passthrough "$pt_so"
    echo
  done
  if [ "$callgrind" = yes ] && command -v valgrind >/dev/null 2>&1; then
    callgrind_table
    echo
    sequence_callgrind_table
    echo
  fi
  .venv/bin/python bench/fmpy_bench.py --fmu dist/AngularKinematics.fmu \
    --passthrough build/passthrough/PassThrough.so --steps "$fmpy_steps" \
    --repeats "$fmpy_repeats"
  echo
  # AttitudePropagator (bench/bench_attitude.c): one CS step beside the bare quaternion update.
  for kind in "${kinds[@]}"; do
    echo "### AttitudePropagator, $kind inputs"
    echo
    AK_BENCH_FIGURES=$figures build/bench/bench_attitude "$ap_so" --fmi3 "$ap3_so" \
      --steps "${steps##*,}" --repeats "$repeats" "${previous_ap[@]}" --inputs "$kind" \
      "${passthroughs[@]}"
    echo
  done
  # PointKinematics (bench/bench_point.c): its FMI 2 cycle beside the pass-through's cycle with
  # the same counts plus its hand-written formula (bench/point_anchor.c).
  echo "### PointKinematics"
  echo
  build/bench/bench_point build/fmu/binaries/linux64/PointKinematics.so \
    build/passthrough/PassThrough.so "${steps##*,}" "$repeats"
  echo
  # QuaternionKinematics (bench/bench_quaternion.c): the same, with its body123 formula
  # (bench/quaternion_anchor.c), on its random and smooth rows.
  echo "### QuaternionKinematics"
  echo
  AK_BENCH_FIGURES=$figures build/bench/bench_quaternion \
    build/fmu/binaries/linux64/QuaternionKinematics.so build/passthrough/PassThrough.so \
    "${steps##*,}" "$repeats" "$([ ${#kinds[@]} -eq 1 ] && echo "${kinds[0]}" || echo both)"
  echo
  # The project's sincos beside the C library's (bench/bench_sincos.c).
  build/bench/bench_sincos --calls "$(awk -v c="$calls" 'BEGIN { print (c < 4096 ? 4096 : 40 * c) }')" --repeats "$repeats"
  echo
  # Three atan2 at once beside three ak_atan2 and the C library's (bench/bench_atan2.c).
  build/bench/bench_atan2 --calls "$(awk -v c="$calls" 'BEGIN { print (c < 4096 ? 4096 : 2 * c) }')" --repeats "$repeats"
  echo
  goals_table
} | tee build/last-run.md
