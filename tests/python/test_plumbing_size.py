"""The FMI plumbing stays no bigger than it must be: the runtime and the two FMI layers
(fmu_src/runtime, fmu_src/fmi2, fmu_src/fmi3), every line counted, within the budget that
docs/architecture.md states, so that a new feature there pays for its lines."""
import pathlib
import re

ROOT = pathlib.Path(__file__).resolve().parents[2]
FOLDERS = ("runtime", "fmi2", "fmi3")


def plumbing_lines():
    return {folder: sum(len(path.read_text().splitlines())
                        for path in sorted((ROOT / "fmu_src" / folder).iterdir()))
            for folder in FOLDERS}


def test_plumbing_within_its_budget():
    text = (ROOT / "docs" / "architecture.md").read_text()
    budget = int(re.search(r"at most ([\d,]+) lines", text).group(1).replace(",", ""))
    lines = plumbing_lines()
    assert sum(lines.values()) <= budget, f"plumbing {lines}: {sum(lines.values())} > {budget}"
