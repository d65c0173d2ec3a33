"""The rebuilt FMUs compute, bit for bit, what release 0.2 computed: digests of every output over
seeded random states, all 24 sequences (and both frames of EulerRates), recorded from the 0.2
FMUs by golden_outputs.py into data/golden_0.2.json."""
import json
import pathlib

import pytest

from golden_outputs import digests

RECORD = json.loads((pathlib.Path(__file__).parent / "data" / "golden_0.2.json").read_text())


@pytest.mark.parametrize("model", ["AngularKinematics", "EulerRates"])
def test_outputs_bit_identical_to_release_0_2(model, root, report):
    name, got = digests(str(root / "dist" / f"{model}.fmu"))
    assert name == model
    differ = sorted(k for k in RECORD[model] if got.get(k) != RECORD[model][k])
    assert not differ, f"{model}: outputs differ from 0.2 for sequence[/frame] {differ}"
    report(f"{model}: {len(got)} cases x 120 states, every output bit-identical to 0.2")
