#!/usr/bin/env bash
# Static analysis: cppcheck (Debian's package) over the FMU's sources and their C tests, and
# GCC's -fanalyzer over the FMU's sources. Any finding fails the run.
#   bash scripts/check_static.sh
set -euo pipefail
cd "$(dirname "$0")/.."
if [ -z "${AK_SET_UP:-}" ]; then
  bash scripts/setup.sh
  bash scripts/setup_abuse_tools.sh
fi
headers=$(.venv/bin/python -c "import fmpy, os; print(os.path.join(os.path.dirname(fmpy.__file__), 'c-code'))")

# unusedFunction: the FMI entry points are called by the master, not by anything cppcheck sees.
cppcheck --version
cppcheck --enable=all --std=c11 --error-exitcode=1 --inline-suppr --quiet \
  --suppress=missingIncludeSystem --suppress=unusedFunction \
  -I fmu_src -I "$headers" fmu_src
echo "check_static: cppcheck: 0 findings in fmu_src/"

for source in fmu_src/*.c; do
  gcc -std=c11 -fanalyzer -O1 -Wall -Wextra -Werror -Ifmu_src -I"$headers" -c "$source" -o /dev/null
done
echo "check_static: gcc -fanalyzer: 0 findings in fmu_src/*.c"
