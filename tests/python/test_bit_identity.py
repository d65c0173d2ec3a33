"""The rebuilt FMUs compute, bit for bit, what the last release whose outputs moved computed:
digests of its outputs (their names are in the record; an output added since does not enter
them) over seeded random states, all 24 sequences (and both frames of EulerRates), recorded by
golden_outputs.py. A change of these bits is a decision: CHANGELOG.md records it with its figures
(golden_outputs.py compare counts the values that moved and by how many ulp), and the record is
written again."""
import json
import pathlib

import pytest

from golden_outputs import MODELS_RECORDED, digests

RELEASE = "0.4"
RECORD = json.loads((pathlib.Path(__file__).parent / "data" / f"golden_{RELEASE}.json").read_text())


@pytest.mark.parametrize("model", MODELS_RECORDED)
def test_outputs_bit_identical_to_the_recorded_release(model, root, report):
    recorded = RECORD[model]
    name, outputs, got = digests(str(root / "dist" / f"{model}.fmu"), recorded["outputs"])
    assert name == model and outputs == recorded["outputs"]
    assert set(got) == set(recorded["digests"])
    differ = sorted(k for k in recorded["digests"] if got[k] != recorded["digests"][k])
    assert not differ, f"{model}: outputs differ from {RELEASE} for sequence[/frame] {differ}"
    report(f"{model}: {len(got)} cases x 120 states, the {len(outputs)} outputs of {RELEASE}"
           " bit-identical")
