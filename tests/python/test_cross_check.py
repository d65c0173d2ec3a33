"""dist/cross-check/ (scripts/make_cross_check.py): the FMI Cross-Check layout for every FMU and
interface, our results right against the 40-digit reference, and examples/ci_check.py
--cross-check passing on it and failing on a result moved by 1e-9."""
import pathlib
import subprocess
import sys

import numpy as np
import pytest

import reference

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "examples"))
from codegen.project import VERSION  # noqa: E402
from cross_check import read_csv, read_options  # noqa: E402

MODELS = ["AngularKinematics", "EulerRates"]


def run(*arguments):
    return subprocess.run([sys.executable, *map(str, arguments)], capture_output=True, text=True,
                          timeout=300, cwd=ROOT)


@pytest.fixture(scope="module")
def folder(tmp_path_factory, fmu_path, euler_fmu_path):
    out = tmp_path_factory.mktemp("cross-check")
    done = run(ROOT / "scripts" / "make_cross_check.py", "--out", out)
    assert done.returncode == 0, done.stdout + done.stderr
    return out


def model_folder(root, interface, model):
    return root / "fmus" / "2.0" / interface / "linux64" / "AngularKinematics" / VERSION / model


@pytest.mark.parametrize("interface", ["cs", "me"])
@pytest.mark.parametrize("model", MODELS)
def test_layout(folder, interface, model):
    here = model_folder(folder, interface, model)
    expected = {f"{model}.fmu", f"{model}_in.csv", f"{model}_ref.csv", f"{model}_ref.opt",
                "ReadMe.md"}
    assert {p.name for p in here.iterdir()} == expected
    assert read_options(here / f"{model}_ref.opt") == dict(StartTime=0.0, StopTime=4.0,
                                                           StepSize=0.01, RelTol=0.0)
    inputs = read_csv(here / f"{model}_in.csv")[1]
    outputs = read_csv(here / f"{model}_ref.csv")[1]
    assert len(inputs) == len(outputs) == 401
    assert np.array_equal(inputs[:, 0], outputs[:, 0])


@pytest.mark.parametrize("interface", ["cs", "me"])
def test_reference_results_are_right(folder, interface, report):
    """Our shipped numbers, against the sympy/mpmath reference (40 digits), every 20th row."""
    here = model_folder(folder, interface, "AngularKinematics")
    in_names, inputs = read_csv(here / "AngularKinematics_in.csv")
    out_names, outputs = read_csv(here / "AngularKinematics_ref.csv")
    columns_in = [in_names.index(n) for n in reference.INPUT_NAMES]
    columns_out = [out_names.index(n) for n in reference.OUTPUT_NAMES]
    worst = 0.0
    for row in range(0, len(inputs), 20):
        exact = reference.outputs(inputs[row, columns_in])
        error = np.abs(outputs[row, columns_out] - exact) / (1 + np.abs(exact))
        worst = max(worst, float(error.max()))
    report(f"{interface}: AngularKinematics_ref.csv vs 40-digit reference: {worst:.2e} (21 rows)")
    assert worst < 1e-14


def test_ci_check_passes_then_fails_on_a_moved_value(folder, tmp_path, report):
    done = run(ROOT / "examples" / "ci_check.py", "--cross-check", folder)
    assert done.returncode == 0, done.stdout + done.stderr
    assert done.stdout.count(" ok ") == 4 and "largest deviation 0\n" in done.stdout

    here = model_folder(folder, "me", "EulerRates")
    path = here / "EulerRates_ref.csv"
    lines = path.read_text().splitlines()
    cells = lines[200].split(",")
    cells[1] = repr(float(cells[1]) * (1 + 1e-9))  # theta_dot[1] at t = 1.99 s
    lines[200] = ",".join(cells)
    path.write_text("\n".join(lines) + "\n")
    done = run(ROOT / "examples" / "ci_check.py", "--cross-check", folder)
    report(f"a 1e-9 relative change of one value: exit {done.returncode}")
    assert done.returncode == 1, done.stdout
    assert "DIFFERENT me EulerRates theta_dot[1]" in done.stdout
    assert "t = 1.99 s" in done.stdout
