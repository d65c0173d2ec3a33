#!/usr/bin/env bash
# Rewrites the bad-input table of every model (codegen/project.py MODELS) in docs/bad_input.md with
# what its C driver, build/test_fmi2_calls[_<Model>], observes (it refuses to when any row's check
# fails). The C tables tests/c/fmi2_bad_input_*.c own the messages; run this after changing a row
# or a message. tests/python/test_bad_input_table.py fails while the document is stale.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh >/dev/null
.venv/bin/python - <<'PY'
import pathlib, subprocess, sys
sys.path.insert(0, ".")
from codegen.project import MODELS
path = pathlib.Path("docs/bad_input.md")
text = path.read_text()
for model in MODELS:
    driver = "build/test_fmi2_calls" + ("" if model == "AngularKinematics" else f"_{model}")
    table = subprocess.run([driver, "--table"], check=True, capture_output=True, text=True).stdout
    marker = f"<!-- bad-input table {model}: begin"
    begin = text.index("\n", text.index(marker)) + 1
    end = text.index(f"<!-- bad-input table {model}: end -->")
    text = text[:begin] + table + text[end:]
path.write_text(text)
PY
echo "update_bad_input_table: docs/bad_input.md rewritten"
