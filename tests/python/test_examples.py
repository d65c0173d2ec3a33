"""The demo (CSV, plot, progress bar; what scripts/demo.sh installs and builds, and the script run
in a scratch copy) and the examples: the CI simulation check and a bounded Dask sweep, each shown
to pass and shown to fail when it should."""
import csv
import importlib.metadata
import json
import pathlib
import re
import shutil
import subprocess
import sys
import zipfile

import numpy as np
import pytest
from packaging.requirements import Requirement
from packaging.utils import canonicalize_name

from codegen import reference
from conftest import project

ROOT = pathlib.Path(__file__).resolve().parents[2]
PYTHON = sys.executable
CI_CHECK = ROOT / "examples" / "ci_check.py"
STORED_REFERENCE = ROOT / "examples" / "reference" / "tumbling_body_reference.csv"


def run(*arguments, timeout=300):
    return subprocess.run([PYTHON, *map(str, arguments)], capture_output=True, text=True,
                          timeout=timeout, cwd=ROOT)


def test_demo_writes_csv_and_plot(fmu_path, tmp_path):
    output = tmp_path / "demo.csv"
    done = run(ROOT / "demo" / "tumbling_body.py", "--fmu", fmu_path, "--stop-time", "2",
               "--output", output)
    assert done.returncode == 0, done.stderr
    # Said where the result is shown: the rows lag the inputs by one step (fmpy records after it).
    assert "the CSV row at time t holds the outputs of the inputs of t - 0.01 s" in done.stdout
    with output.open() as file:
        rows = list(csv.reader(file))
    assert len(rows) == 1 + 201
    assert {"omega_fixed[1]", "alpha_body[3]", "theta[2]"} <= set(h.strip('"') for h in rows[0])
    picture = output.with_suffix(".png").read_bytes()
    assert picture.startswith(b"\x89PNG\r\n\x1a\n")
    width, height = int.from_bytes(picture[16:20], "big"), int.from_bytes(picture[20:24], "big")
    assert (width, height) == (900, 585)


def test_demo_shows_progress_on_runs_past_the_delay(fmu_path, capsys, monkeypatch):
    from demo import tumbling_body
    monkeypatch.setattr(tumbling_body, "PROGRESS_DELAY", 0.0)
    tumbling_body.simulate(fmu_path, 1.0, 0.01)
    assert "100/100" in capsys.readouterr().err
    monkeypatch.setattr(tumbling_body, "PROGRESS_DELAY", 60.0)
    tumbling_body.simulate(fmu_path, 1.0, 0.01)
    assert capsys.readouterr().err == ""


def pins(path):
    """{canonical name: version} of a requirements file of name==version lines."""
    found = {}
    for line in path.read_text().splitlines():
        line = line.split("#")[0].strip()
        if line:
            name, _, version = line.partition("==")
            assert version, f"{path.name}: {line} is not pinned"
            found[canonicalize_name(name)] = version
    return found


def test_demo_requirements_are_pinned_as_in_requirements_txt():
    demo, full = pins(ROOT / "requirements-demo.txt"), pins(ROOT / "requirements.txt")
    assert {"fmpy", "numpy", "matplotlib", "tqdm", "markdown"} <= demo.keys()
    assert {name: version for name, version in demo.items() if full.get(name) != version} == {}


def test_demo_requirements_hold_every_dependency_but_fmpys_cmake():
    """scripts/setup.sh --demo installs requirements-demo.txt with --no-deps: it must name every
    package its packages need (read from the installed ones, which requirements.txt pins alike),
    leaving out only the cmake wheel that FMPy declares for compiling source FMUs."""
    demo = pins(ROOT / "requirements-demo.txt")
    needed = set()
    for name, version in demo.items():
        distribution = importlib.metadata.distribution(name)
        assert distribution.version == version, name
        for requirement in map(Requirement, distribution.requires or []):
            if requirement.marker is None or requirement.marker.evaluate({"extra": ""}):
                needed.add(canonicalize_name(requirement.name))
    assert needed - demo.keys() == {"cmake"}


def demo_script():
    """(preset, build folder, target, FMU) of scripts/demo.sh."""
    text = (ROOT / "scripts" / "demo.sh").read_text()
    preset = re.search(r"^bash scripts/configure\.sh (\S+)$", text, re.M).group(1)
    folder, target = re.search(r"^cmake --build (\S+) .*--target (\S+)$", text, re.M).groups()
    fmu = re.search(r"^fmu=(\S+)$", text, re.M).group(1)
    return preset, folder, target, fmu


def test_demo_builds_only_the_fmu_it_simulates_outside_dist():
    preset, folder, target, fmu = demo_script()
    presets = json.loads((ROOT / "CMakePresets.json").read_text())["configurePresets"]
    variables = next(p for p in presets if p["name"] == preset)["cacheVariables"]
    model = pathlib.Path(fmu).stem
    # The model of demo/tumbling_body.py's default FMU, packaged by its own target.
    assert model == "AngularKinematics" and model in project.MODELS
    assert target == f"fmu_{model}"
    assert next(p for p in presets if p["name"] == preset)["binaryDir"] == f"${{sourceDir}}/{folder}"
    assert variables["AK_DIST_DIR"] == f"${{sourceDir}}/{pathlib.Path(fmu).parent}"
    assert not fmu.startswith("dist/")  # dist/ holds the seven-platform FMUs the tests check
    commands = [line.strip() for line in (ROOT / "scripts" / "demo.sh").read_text().splitlines()
                if line.strip() and not line.lstrip().startswith("#")]
    assert "bash scripts/setup.sh --demo" in commands
    assert not [line for line in commands if line.startswith("bash scripts/build.sh")]


@pytest.mark.slow  # configures and builds an FMU (about 20 s on 2 cores)
def test_demo_script_in_a_scratch_copy(tmp_path):
    """bash scripts/demo.sh in a copy of the checkout (its tracked and new files) with this .venv:
    it installs nothing more, builds the one-platform FMU outside dist/ and simulates it."""
    listed = subprocess.run(["git", "ls-files", "-z", "--cached", "--others", "--exclude-standard"],
                            cwd=ROOT, check=True, capture_output=True, text=True).stdout
    scratch = tmp_path / "checkout"
    for name in filter(None, listed.split("\0")):
        if (ROOT / name).is_file():
            (scratch / name).parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(ROOT / name, scratch / name)
    (scratch / ".venv").symlink_to(pathlib.Path(sys.prefix).resolve())
    done = subprocess.run(["bash", "scripts/demo.sh", "--stop-time", "1", "--no-progress"],
                          cwd=scratch, capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stdout[-3000:] + done.stderr[-3000:]
    _, _, _, fmu = demo_script()
    assert f"demo: built {fmu} (FMI 2.0, x86_64-linux binary only;" in done.stdout
    assert "simulated 100 steps of 0.01 s to t = 1 s" in done.stdout
    with zipfile.ZipFile(scratch / fmu) as archive:
        binaries = {name for name in archive.namelist()
                    if name.startswith("binaries/") and not name.endswith("/")}
    assert binaries == {"binaries/linux64/AngularKinematics.so"}
    assert not list((scratch / "dist").glob("**/*.fmu"))
    assert (scratch / "results" / "tumbling_body.png").is_file()


def test_stored_reference_agrees_with_the_sympy_reference(report):
    names = reference.INPUT_NAMES + reference.OUTPUT_NAMES
    table = np.loadtxt(STORED_REFERENCE, delimiter=",", skiprows=1)
    header = STORED_REFERENCE.read_text().splitlines()[0].split(",")
    assert header == ["time"] + names
    worst = 0.0
    for row in table[::4]:
        inputs, outputs = row[1:10], row[10:]
        scale_w = np.abs(inputs[3:6]).sum()
        scale = np.array([scale_w] * 6 + [np.abs(inputs[6:9]).sum() + scale_w ** 2] * 6)
        worst = max(worst, (np.abs(outputs - reference.outputs(inputs)) / scale).max())
    report(f"{len(table[::4])} rows of the stored CI reference: worst scaled error {worst:.1e}")
    assert worst <= 1e-14


def test_ci_check_passes_on_the_stored_reference(fmu_path):
    done = run(CI_CHECK, "--fmu", fmu_path)
    assert done.returncode == 0, done.stdout + done.stderr
    assert "PASSED" in done.stdout and "REGRESSION" not in done.stdout


def tampered(tmp_path, column, row, relative=0.0, tolerances=0.0):
    """The stored reference with one value moved: by `relative` times itself, or by `tolerances`
    times the tolerance ci_check promises, 1e-12 + 1e-12 |value|."""
    lines = STORED_REFERENCE.read_text().splitlines()
    k = lines[0].split(",").index(column)
    values = lines[1 + row].split(",")
    value = float(values[k])
    values[k] = repr(value * (1 + relative) + tolerances * (1e-12 + 1e-12 * abs(value)))
    lines[1 + row] = ",".join(values)
    path = tmp_path / f"tampered_{relative:g}_{tolerances:g}.csv"
    path.write_text("\n".join(lines) + "\n")
    return path


def test_ci_check_without_an_fmu_exits_2_with_a_message(tmp_path):
    missing = tmp_path / "nonexistent.fmu"
    done = run(CI_CHECK, "--fmu", missing)
    assert done.returncode == 2, done.stdout + done.stderr
    assert f"no FMU at {missing}" in done.stdout
    assert "Traceback" not in done.stdout + done.stderr


def test_ci_check_with_a_file_that_is_no_fmu_exits_2(tmp_path):
    broken = tmp_path / "broken.fmu"
    broken.write_text("not a zip archive")
    done = run(CI_CHECK, "--fmu", broken)
    assert done.returncode == 2, done.stdout + done.stderr
    assert "could not be simulated" in done.stdout and "Traceback" not in done.stderr


def test_ci_check_help_is_complete():
    """The summary is whole sentences and every option says what it is."""
    done = run(CI_CHECK, "--help")
    assert done.returncode == 0, done.stderr
    text = " ".join(done.stdout.split())
    assert ("A simulation check to copy into CI: runs a reference trajectory through an FMU with "
            "fmpy and compares every output with a stored reference result; exits 1 on a "
            "regression.") in text
    for option, words in (("--fmu FMU", "the FMU to check"),
                          ("--reference REFERENCE", "the stored reference result"),
                          ("--update", "store this run as the new reference")):
        assert f"{option} {words}" in text, option
    assert "Exit status: 0 all outputs within tolerance, 1 regression, 2 the run cannot be" in text


def test_ci_check_fails_on_a_regression(fmu_path, tmp_path):
    """Three times the tolerance away: a check with a tolerance 10 times looser would pass it."""
    done = run(CI_CHECK, "--fmu", fmu_path, "--reference",
               tampered(tmp_path, "alpha_body[2]", 100, tolerances=3.0))
    assert done.returncode == 1, done.stdout + done.stderr
    assert [line.split()[1] for line in done.stdout.splitlines() if "REGRESSION" in line] == ["alpha_body[2]"]
    assert "FAILED" in done.stdout


def test_ci_check_tolerates_last_bit_differences(fmu_path, tmp_path):
    done = run(CI_CHECK, "--fmu", fmu_path, "--reference", tampered(tmp_path, "omega_fixed[1]", 50, 1e-14))
    assert done.returncode == 0, done.stdout


def test_ci_check_tolerates_half_its_tolerance(fmu_path, tmp_path):
    """Half the tolerance away: a check with a tolerance 10 times tighter would fail it."""
    done = run(CI_CHECK, "--fmu", fmu_path, "--reference",
               tampered(tmp_path, "alpha_body[2]", 100, tolerances=0.5))
    assert done.returncode == 0, done.stdout
    line = next(line for line in done.stdout.splitlines() if "alpha_body[2]" in line)
    assert "(0.5 of the tolerance)" in line, line


def test_ci_check_refuses_another_trajectory(fmu_path, tmp_path):
    done = run(CI_CHECK, "--fmu", fmu_path, "--reference", tampered(tmp_path, "theta[1]", 10, relative=1e-6))
    assert done.returncode == 2, done.stdout


@pytest.mark.slow  # starts a Dask cluster
@pytest.mark.parametrize("tolerance, status", [("1e-14", 0), ("1e-17", 1)])
def test_bounded_dask_sweep(fmu_path, tmp_path, tolerance, status, report):
    """8 simulations on a local cluster of 2 worker processes; with a tolerance below the FMU's
    rounding errors the same sweep must fail."""
    output = tmp_path / "sweep.csv"
    done = run(ROOT / "examples" / "dask_sweep.py", "--fmu", fmu_path, "--count", "8",
               "--stop-time", "1", "--tolerance", tolerance, "--output", output, "--no-progress")
    assert done.returncode == status, done.stdout + done.stderr[-3000:]
    with output.open() as file:
        cases = list(csv.DictReader(file))
    assert [int(c["case"]) for c in cases] == list(range(8))
    assert all(int(c["rows"]) == 101 for c in cases)
    if status == 0:
        report(done.stdout.strip().replace("\n", "; "))
    else:
        assert "FAILED case" in done.stdout
