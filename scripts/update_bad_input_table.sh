#!/usr/bin/env bash
# Rewrites the table of docs/bad_input.md with what build/test_fmi2_calls observes (it refuses to
# when any row's check fails). Run after changing fmu_src/test/fmi2_bad_input_table.c or a message.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh >/dev/null
table=$(build/test_fmi2_calls --table)
TABLE="$table" .venv/bin/python - <<'PY'
import os, pathlib
path = pathlib.Path("docs/bad_input.md")
text = path.read_text()
begin = text.index("\n", text.index("<!-- bad-input table: begin")) + 1
end = text.index("<!-- bad-input table: end -->")
path.write_text(text[:begin] + os.environ["TABLE"] + "\n" + text[end:])
PY
echo "update_bad_input_table: docs/bad_input.md rewritten"
