"""The bad-input tables of docs/bad_input.md, one per model: what each model's C driver
(build/test_fmi2_calls_<Model>, tests/c/fmi2_bad_input_*.c) observes, printed by `--table`. The
driver refuses to print when a row's check fails. Needs the built drivers (bash scripts/build.sh);
tests/python/test_bad_input_table.py checks the document against them."""
import subprocess

from codegen.models import ROOT
from codegen.project import MODELS

PAGE = ROOT / "docs" / "bad_input.md"
BUILD = ROOT / "build"


def driver(model):
    """build/test_fmi2_calls_<Model> (cmake/abuse_tests.cmake)."""
    return BUILD / f"test_fmi2_calls_{model}"


def why_not_here():
    """None when every model's driver is built, else what is missing."""
    missing = [str(driver(m).relative_to(ROOT)) for m in MODELS if not driver(m).is_file()]
    return f"no {', '.join(missing)} (run bash scripts/build.sh first)" if missing else None


def outputs():
    text = PAGE.read_text()
    for model in MODELS:
        table = subprocess.run([str(driver(model)), "--table"], check=True, capture_output=True,
                               text=True).stdout
        marker = f"<!-- bad-input table {model}: begin"
        begin = text.index("\n", text.index(marker)) + 1
        end = text.index(f"<!-- bad-input table {model}: end -->")
        text = text[:begin] + table + text[end:]
    return {PAGE: text}
