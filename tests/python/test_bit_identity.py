"""The rebuilt FMUs compute, bit for bit, what the last release whose outputs moved computed:
digests of its outputs (their names are in the record; an output added since does not enter
them) over seeded random states, all 24 sequences (and both frames of EulerRates), recorded by
golden_outputs.py. A change of these bits is a decision: CHANGELOG.md records it with its figures
(golden_outputs.py compare counts the values that moved and by how many ulp), and the record is
written again. AttitudePropagator, which has states, is pinned by what the project's own masters
print over its steps (tests/python/data/attitude_0.4.json)."""
import hashlib
import json
import pathlib
import subprocess

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


ATTITUDE_RECORD = json.loads(
    (pathlib.Path(__file__).parent / "data" / f"attitude_{RELEASE}.json").read_text())
ATTITUDE_LIBRARY = {2: "fmu/binaries/linux64", 3: "fmu3/binaries/x86_64-linux"}


@pytest.mark.parametrize("fmi", [2, 3])
def test_attitude_propagator_prints_the_bits_of_the_recorded_release(fmi, root, report):
    """tools/fmu_driver.c (every output after each of 400 steps) and tools/fmi3_driver.c (every
    sequence and frame, 64 steps, with the derivatives) print what they printed with the
    release's binaries."""
    recorded = ATTITUDE_RECORD[f"fmi{fmi}"]
    driver = root / "build" / ("fmu_driver" if fmi == 2 else "fmi3_driver")
    library = root / "build" / ATTITUDE_LIBRARY[fmi] / "AttitudePropagator.so"
    assert driver.is_file() and library.is_file(), "bash scripts/build.sh builds them"
    done = subprocess.run([str(driver), str(library), *recorded["arguments"]], capture_output=True,
                          timeout=300)
    assert done.returncode == 0, done.stderr[-2000:]
    assert hashlib.sha256(done.stdout).hexdigest() == recorded["sha256"], \
        f"AttitudePropagator FMI {fmi}: the driver's output differs from {RELEASE}'s"
    report(f"AttitudePropagator FMI {fmi}: {len(done.stdout.splitlines())} lines of the driver, "
           f"bit-identical to {RELEASE}")
