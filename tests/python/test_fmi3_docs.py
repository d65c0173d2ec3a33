"""docs/fmi3.md: its fmpy example with array inputs runs and prints what it says; its mapping
table of FMI 2 scalars to FMI 3 arrays is the generator's (docs/fmi3_variables.md, checked by
codegen/generate.py --check) and names every FMI 2 value reference once."""
import pathlib
import re
import subprocess
import sys

from codegen import project
from codegen.models import load

ROOT = pathlib.Path(__file__).resolve().parents[2]


def test_example_runs_and_prints_what_it_says(tmp_path):
    text = (ROOT / "docs" / "fmi3.md").read_text()
    example = re.search(r"```python\n(.*?)```", text, re.S).group(1)
    assert len(example.strip().splitlines()) <= 11
    done = subprocess.run([sys.executable, "-c", example], cwd=ROOT, capture_output=True,
                          text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    assert done.stdout.splitlines()[0] == "[0. 0. 2.]"


def test_mapping_table_covers_every_fmi2_value_reference():
    table = (ROOT / "docs" / "fmi3_variables.md").read_text()
    for model in project.FMI3_MODELS:
        section = table.split(f"## {model}")[1].split("## ")[0]
        m = load(model)
        for entry in m.arrays:
            elements = [s for s in m.scalars if s.base == entry["name"]]
            row = next(line for line in section.splitlines() if line.startswith(f"| {entry['name']} |"))
            assert f"| {entry['vr']} |" in row
            assert f"{elements[0].name} ({elements[0].vr})" in row
            assert f"{elements[-1].name} ({elements[-1].vr})" in row
