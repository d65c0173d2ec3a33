# Sourced by bench/run.sh and bench/guard.sh: instructions per step of one driver loop under
# valgrind --tool=callgrind. The difference between two run lengths (AK_SMALL_STEPS,
# AK_LARGE_STEPS), so that loading, instantiation and the checks before timing cancel out: exact,
# independent of the machine's load. Arguments: the driver's command, with STEPS where the step
# count goes.
instructions_per_step() {
  local small=${AK_SMALL_STEPS:-10000} large=${AK_LARGE_STEPS:-110000} a b out
  # A driver that fails (a check before timing, an FMU that refuses a call) gives no count: its
  # exit status is the client's (valgrind passes it on).
  if ! out=$(valgrind --tool=callgrind --callgrind-out-file=/dev/null "${@//STEPS/$small}" 2>&1); then
    echo "instructions_per_step: the driver failed: $*" >&2
    echo "$out" | grep -v '^==' | tail -5 >&2
    return 1
  fi
  a=$(echo "$out" | sed -n 's/.*Collected : //p')
  if ! out=$(valgrind --tool=callgrind --callgrind-out-file=/dev/null "${@//STEPS/$large}" 2>&1); then
    echo "instructions_per_step: the driver failed: $*" >&2
    echo "$out" | grep -v '^==' | tail -5 >&2
    return 1
  fi
  b=$(echo "$out" | sed -n 's/.*Collected : //p')
  if [ -z "$a" ] || [ -z "$b" ]; then
    echo "instructions_per_step: callgrind gave no count for: $*" >&2
    return 1
  fi
  echo $(( (b - a) / (large - small) ))
}
