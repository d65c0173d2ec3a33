"""The rebuilt FMUs compute, bit for bit, what release 0.2 computed: digests of every output 0.2
had (their names are in the record; an output added since does not enter them, nor one whose
change CHANGELOG.md records: golden_outputs.CHANGED_SINCE_0_2) over seeded random states, all 24
sequences (and both frames of EulerRates), recorded from the 0.2 FMUs by golden_outputs.py into
data/golden_0.2.json."""
import json
import pathlib

import pytest

from golden_outputs import CHANGED_SINCE_0_2, digests

RECORD = json.loads((pathlib.Path(__file__).parent / "data" / "golden_0.2.json").read_text())


@pytest.mark.parametrize("model", ["AngularKinematics", "EulerRates"])
def test_outputs_bit_identical_to_release_0_2(model, root, report):
    recorded = RECORD[model]
    name, outputs, got = digests(str(root / "dist" / f"{model}.fmu"), recorded["outputs"])
    assert name == model and outputs == recorded["outputs"]
    assert recorded["left_out"] == CHANGED_SINCE_0_2.get(model, [])
    changelog = (root / "CHANGELOG.md").read_text()
    assert all(f"`{n}`" in changelog for n in recorded["left_out"])
    assert set(got) == set(recorded["digests"])
    differ = sorted(k for k in recorded["digests"] if got[k] != recorded["digests"][k])
    assert not differ, f"{model}: outputs differ from 0.2 for sequence[/frame] {differ}"
    report(f"{model}: {len(got)} cases x 120 states, the {len(outputs)} outputs of 0.2 bit-identical"
           f" (left out, as CHANGELOG.md records: {', '.join(recorded['left_out']) or 'none'})")
