#!/usr/bin/env bash
# Rewrites the two tables of docs/bad_input.md (AngularKinematics, EulerRates) with what
# build/test_fmi2_calls and build/test_fmi2_calls_EulerRates observe (it refuses to when any row's
# check fails). Run after changing a row of fmu_src/test/fmi2_bad_input_*.c or a message.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh >/dev/null
ak=$(build/test_fmi2_calls --table)
er=$(build/test_fmi2_calls_EulerRates --table)
TABLE_AngularKinematics="$ak" TABLE_EulerRates="$er" .venv/bin/python - <<'PY'
import os, pathlib
path = pathlib.Path("docs/bad_input.md")
text = path.read_text()
for model in ("AngularKinematics", "EulerRates"):
    marker = f"<!-- bad-input table {model}: begin"
    begin = text.index("\n", text.index(marker)) + 1
    end = text.index(f"<!-- bad-input table {model}: end -->")
    text = text[:begin] + os.environ[f"TABLE_{model}"] + "\n" + text[end:]
path.write_text(text)
PY
echo "update_bad_input_table: docs/bad_input.md rewritten"
