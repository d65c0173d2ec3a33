#!/usr/bin/env bash
# Static analysis; any finding fails the run.
# - cppcheck (Debian's package), once per model over the sources of its binary as one program:
#   the core sources of the model (its description's CORE), runtime, FMI layer, models/model_*.c
#   (what every model shares) and the model's folder (which defines AK_MODEL);
# - cppcheck's unusedFunction over the sources of every model at once (a core function one model
#   does not call may serve another), exempting by name only the FMI 2.0 entry points: what only
#   the tests or the benchmark call lives in tests/ or bench/ (each FMU's own list is checked by
#   tests/python/test_dead_code.py);
# - GCC's -fanalyzer over every .c file of fmu_src/, with each model's include folders.
#   bash scripts/check_static.sh
set -euo pipefail
cd "$(dirname "$0")/.."
if [ -z "${AK_SET_UP:-}" ]; then
  bash scripts/setup.sh
  bash scripts/setup_abuse_tools.sh
fi
headers=$(.venv/bin/python -c "import fmpy, os; print(os.path.join(os.path.dirname(fmpy.__file__), 'c-code'))")
read -r -a models <<<"$(.venv/bin/python -c "from codegen.project import MODELS; print(' '.join(MODELS))")"
includes=(-I fmu_src/core -I fmu_src/elementary -I fmu_src/models -I fmu_src/runtime -I fmu_src/fmi2 -I fmu_src/common -I "$headers")
common=(fmu_src/core/*.c fmu_src/elementary/*.c fmu_src/runtime/*.c fmu_src/fmi2/*.c fmu_src/models/model_*.c)
# The core sources of a model's binary (cmake/generated.cmake's AK_CORE_SOURCES_<Model>).
core_of() {
  .venv/bin/python -c "from codegen.models import load; print(' '.join('fmu_src/' + s for s in load('$1').core_sources))"
}
cppcheck --version

for model in "${models[@]}"; do
  read -r -a core <<<"$(core_of "$model")"
  cppcheck --enable=all --std=c11 --error-exitcode=1 --inline-suppr --quiet \
    --suppress=missingIncludeSystem --suppress=unusedFunction \
    "${includes[@]}" -I "fmu_src/models/$model" "${core[@]}" fmu_src/runtime/*.c fmu_src/fmi2/*.c \
    fmu_src/models/model_*.c "fmu_src/models/$model"/*.c
  echo "check_static: cppcheck: 0 findings in the sources of $model"
done

# The entry points the importer calls through the shared library, by name, from the standard's
# own list (the FMI2_Export declarations of fmi2Functions.h): nothing in the sources calls them.
suppressions=$(mktemp)
trap 'rm -f "$suppressions"' EXIT
{
  echo '<?xml version="1.0"?>'
  echo '<suppressions>'
  echo '  <!-- Reason: an FMI 2.0 entry point, called by the importer, never by the FMU itself. -->'
  grep -oE 'FMI2_Export +fmi2[A-Za-z]+TYPE +fmi2[A-Za-z]+;' "$headers/fmi2Functions.h" |
    awk '{ sub(";", "", $3); printf "  <suppress><id>unusedFunction</id><symbolName>%s</symbolName></suppress>\n", $3 }'
  echo '</suppressions>'
} >"$suppressions"
model_folders=()
for model in "${models[@]}"; do
  model_folders+=(-I "fmu_src/models/$model")
done
cppcheck --enable=unusedFunction --std=c11 --error-exitcode=1 --inline-suppr --quiet \
  --suppress=missingIncludeSystem --suppress-xml="$suppressions" \
  "${includes[@]}" "${model_folders[@]}" "${common[@]}" fmu_src/models/*/*.c
echo "check_static: cppcheck unusedFunction: 0 findings (exempt by name: $(grep -c '<symbolName>' "$suppressions") symbols, each with its reason)"

for source in "${common[@]}"; do
  gcc -std=c11 -fanalyzer -O1 -Wall -Wextra -Werror "${includes[@]}" -c "$source" -o /dev/null
done
echo "check_static: gcc -fanalyzer: 0 findings in ${common[*]}"
for model in "${models[@]}"; do
  for source in "fmu_src/models/$model"/*.c; do
    gcc -std=c11 -fanalyzer -O1 -Wall -Wextra -Werror "${includes[@]}" -I "fmu_src/models/$model" \
      -c "$source" -o /dev/null
  done
  echo "check_static: gcc -fanalyzer: 0 findings in the sources of $model"
done

# The FMI 3 layer, with the include folders of its build (cmake/fmi3.cmake), once per model that
# has an FMI 3 table. unusedFunction: only the FMI 3.0 entry points are exempt, as above.
{
  echo '<?xml version="1.0"?>'
  echo '<suppressions>'
  echo '  <!-- Reason: an FMI 3.0 entry point, called by the importer, never by the FMU itself. -->'
  echo '  <!-- Reason: the runtime'"'"'s input derivatives, which the FMI 2 layer calls; FMI 3 has none. -->'
  for symbol in ak_set_input_derivatives; do
    echo "  <suppress><id>unusedFunction</id><symbolName>$symbol</symbolName></suppress>"
  done
  grep -oE 'FMI3_Export +fmi3[A-Za-z0-9]+TYPE +fmi3[A-Za-z0-9]+;' "$headers/fmi3Functions.h" |
    awk '{ sub(";", "", $3); printf "  <suppress><id>unusedFunction</id><symbolName>%s</symbolName></suppress>\n", $3 }'
  echo '</suppressions>'
} >"$suppressions"
for model in "${models[@]}"; do
  [ -d "fmu_src/models/$model/fmi3" ] || continue
  read -r -a core <<<"$(core_of "$model")"
  fmi3_includes=(-I fmu_src/core -I fmu_src/elementary -I fmu_src/models -I fmu_src/runtime -I fmu_src/fmi3 -I fmu_src/common
                 -I "fmu_src/models/$model" -I "$headers")
  cppcheck --enable=all --std=c11 --error-exitcode=1 --inline-suppr --quiet \
    --suppress=missingIncludeSystem --suppress=ConfigurationNotChecked --suppress=unusedFunction \
    "${fmi3_includes[@]}" \
    fmu_src/fmi3 "fmu_src/models/$model/fmi3" "${core[@]}" fmu_src/runtime/*.c \
    fmu_src/models/model_*.c \
    "fmu_src/models/$model"/*.c
  for source in fmu_src/fmi3/*.c fmu_src/models/"$model"/fmi3/*.c; do
    gcc -std=c11 -fanalyzer -O1 -Wall -Wextra -Werror "${fmi3_includes[@]}" -c "$source" -o /dev/null
  done
  echo "check_static: cppcheck and gcc -fanalyzer: 0 findings in the FMI 3 sources of $model"
done
cppcheck --enable=unusedFunction --std=c11 --error-exitcode=1 --inline-suppr --quiet \
  --suppress=missingIncludeSystem --suppress-xml="$suppressions" \
  -I fmu_src/core -I fmu_src/elementary -I fmu_src/models -I fmu_src/runtime -I fmu_src/fmi3 -I fmu_src/common \
  -I "$headers" "${model_folders[@]}" fmu_src/core/*.c fmu_src/elementary/*.c fmu_src/runtime/*.c fmu_src/models/model_*.c \
  fmu_src/fmi3/*.c \
  fmu_src/models/*/*.c fmu_src/models/*/fmi3/*.c
echo "check_static: cppcheck unusedFunction: 0 findings in the FMI 3 build (exempt by name: $(grep -c '<symbolName>' "$suppressions") symbols, each with its reason)"
