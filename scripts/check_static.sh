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

# The FMI 3 layer, with the include folders of its build (cmake/fmi3.cmake), once per model.
for model in AngularKinematics EulerRates; do
  includes="-Ifmu_src/core -Ifmu_src/models -Ifmu_src/fmi3 -Ifmu_src/common -Ifmu_src/models/$model"
  # shellcheck disable=SC2086
  cppcheck --enable=all --std=c11 --error-exitcode=1 --inline-suppr --quiet \
    --suppress=missingIncludeSystem --suppress=unusedFunction --suppress=ConfigurationNotChecked \
    $includes -I "$headers" fmu_src/fmi3 "fmu_src/models/$model/fmi3"
  for source in fmu_src/fmi3/*.c fmu_src/models/"$model"/fmi3/*.c; do
    # shellcheck disable=SC2086
    gcc -std=c11 -fanalyzer -O1 -Wall -Wextra -Werror $includes -I"$headers" -c "$source" -o /dev/null
  done
done
echo "check_static: cppcheck and gcc -fanalyzer: 0 findings in fmu_src/fmi3/"

for source in fmu_src/*.c; do
  gcc -std=c11 -fanalyzer -O1 -Wall -Wextra -Werror -Ifmu_src -I"$headers" -c "$source" -o /dev/null
done
echo "check_static: gcc -fanalyzer: 0 findings in fmu_src/*.c"

