"""A second, independent FMI 2 importer: FMI4j (JNI, from Maven Central) runs every FMU of dist/ in
Co-Simulation and Model Exchange through examples/fmi4j/ (FmuRun.java) over the cross-check's
reference inputs; every status must be fmi2OK and every output equal fmpy's bit for bit (the same
binary, the same inputs, the same call sequence: examples/cross_check.py; Model Exchange with
continuous states integrates them by explicit Euler steps in both).

scripts/setup_importers.sh builds the driver; outside CI the test skips when Java or the driver is
missing, in CI (CI=true) that fails."""
import csv
import os
import re
import pathlib
import shutil
import subprocess
import time
import zipfile

import numpy as np
import pytest
from fmpy import read_model_description

from examples.cross_check import (START, STEP, STOP, real_names, reference_inputs, simulate,
                                  write_csv)

ROOT = pathlib.Path(__file__).resolve().parents[2]

JAR = ROOT / "examples" / "fmi4j" / "target" / "fmi4j-driver.jar"
pytestmark = pytest.mark.external  # the JVM


def fmi_version(fmu):
    with zipfile.ZipFile(fmu) as archive:
        return re.search(rb'fmiVersion="([^"]*)"', archive.read("modelDescription.xml")).group(1)


FMUS = sorted(p for p in (ROOT / "dist").glob("*.fmu") if fmi_version(p) == b"2.0")
# The FMUs under test are dist/'s, never a sanitizer build: no sanitizer runtime inside the JVM.
JAVA_ENV = {k: v for k, v in os.environ.items() if k not in ("LD_PRELOAD", "ASAN_OPTIONS")}



@pytest.fixture(scope="module")
def java():
    java = shutil.which("java")
    if java is None or not JAR.is_file():
        message = f"java or {JAR} missing: run bash scripts/setup_importers.sh"
        if os.environ.get("CI") == "true":
            pytest.fail(message)
        pytest.skip(message)
    return java


def test_every_fmu_is_covered():
    assert {p.stem for p in FMUS} >= {"AngularKinematics", "EulerRates"}


@pytest.mark.parametrize("interface", ["cs", "me"])
@pytest.mark.parametrize("fmu", FMUS, ids=[p.stem for p in FMUS])
def test_fmi4j_equals_fmpy_bit_for_bit(java, fmu, interface, tmp_path, report):
    description = read_model_description(str(fmu))
    times = np.round(np.arange(START, STOP + STEP / 2, STEP), 12)
    input_names = real_names(description, "input")
    inputs = reference_inputs(input_names, times)
    write_csv(tmp_path / "in.csv", ["time"] + input_names, np.column_stack([times, inputs]))

    began = time.perf_counter()
    done = subprocess.run([java, "-jar", str(JAR), str(fmu), interface, str(tmp_path / "in.csv"),
                           str(tmp_path / "out.csv")], capture_output=True, text=True, timeout=300,
                          env=JAVA_ENV)
    seconds = time.perf_counter() - began
    assert done.returncode == 0, done.stderr

    with open(tmp_path / "out.csv", newline="") as file:
        rows = list(csv.reader(file))
    names, statuses = rows[0], [row[-1] for row in rows[1:]]
    assert names[-1] == "status" and set(statuses) == {"OK"}
    fmi4j = np.array([[float(cell) for cell in row[:-1]] for row in rows[1:]])
    expected_names, fmpy_outputs = simulate(str(fmu), interface, times, input_names, inputs)
    assert names[1:-1] == expected_names
    assert np.array_equal(fmi4j[:, 0], times)
    outputs = fmi4j[:, 1:len(expected_names) + 1]
    differing = int(np.count_nonzero(outputs.view(np.int64) != fmpy_outputs.view(np.int64)))
    report(f"{outputs.size} values ({len(times)} rows x {len(expected_names)} outputs), "
           f"{differing} differ in any bit; {len(statuses)} rows all OK; java run {seconds:.2f} s")
    assert differing == 0
    if description.numberOfContinuousStates:  # both importers integrated the states
        states = [names.index(v.name) - 1 for v in description.modelVariables
                  if v.name in ("q[1]", "q[2]", "q[3]", "q[4]")]
        assert states and not np.array_equal(outputs[0, states], outputs[-1, states])
