"""A new model is one folder and one line of the model list: `python -m codegen new-model Probe
--like EulerRates` in a scratch copy of the repository, then the native build gives Probe's FMI 2
and FMI 3 FMUs, which simulate to EulerRates' outputs bit for bit (the same code), the generic
tests run on them, and no hand-written file outside fmu_src/models/Probe/ names Probe but the
model list (every other file that does is generated and says so)."""
import re
import shutil
import subprocess
import sys

import numpy as np
import pytest
from fmpy import simulate_fmu

from conftest import ROOT, fmu_path_of, project
from fmi3_support import fmu3_path

# Tests that run every model of the list (the `model` fixture or fmi3_support.MODELS): they run
# on Probe in the scratch copy.
GENERIC_TESTS = ["test_fmi_calls.py", "test_model_exchange.py", "test_fmu_state.py",
                 "test_bad_input.py", "test_bad_input_table.py", "test_fmi3_state_machine.py",
                 "test_fmi3_fmu_state.py", "test_value_references.py"]


def run(command, cwd, timeout=900):
    done = subprocess.run(command, cwd=cwd, capture_output=True, text=True, timeout=timeout)
    assert done.returncode == 0, f"{command}:\n{done.stdout[-4000:]}\n{done.stderr[-4000:]}"
    return done


@pytest.fixture(scope="module")
def scratch(tmp_path_factory):
    """The repository's tracked files, copied, with Probe added and its native FMUs built."""
    root = tmp_path_factory.mktemp("new-model") / "repository"
    files = subprocess.run(["git", "ls-files", "-z"], cwd=ROOT, capture_output=True, check=True)
    for name in files.stdout.decode().split("\0"):
        if name and (ROOT / name).is_file():
            (root / name).parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(ROOT / name, root / name)
    (root / ".venv").symlink_to(ROOT / ".venv")
    named_before = naming(root)
    run([sys.executable, "-m", "codegen", "new-model", "Probe", "--like", "EulerRates"], root)
    # The other models' FMUs as built here (the generic tests compare with some of them), then
    # Probe's FMUs, variable table and bad-input driver, and the documents generated from them.
    for fmu in [*ROOT.glob("dist/*.fmu"), *ROOT.glob("dist/fmi3/*.fmu")]:
        (root / fmu.relative_to(ROOT)).parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(fmu, root / fmu.relative_to(ROOT))
    run(["bash", "scripts/configure.sh", "release"], root)
    drivers = [f"test_fmi2_calls_{model}" for model in project.MODELS] + ["test_fmi2_calls_Probe"]
    run(["cmake", "--build", "build", "--parallel", "2", "--target", "fmu_Probe", "fmu3_Probe",
         "model_info_Probe", *drivers], root)
    run([sys.executable, "-m", "codegen", "--stage", "bad-input tables"], root)
    return root, named_before


def naming(root):
    """{file: the numbers of its lines that name Probe} under root, build outputs aside."""
    done = subprocess.run(["git", "grep", "-n", "--no-index", "-I", "Probe", "--", "."],
                          cwd=root, capture_output=True, text=True)
    lines = {}
    for line in done.stdout.splitlines():
        path, number, _ = line.split(":", 2)
        if not path.startswith(("build/", ".venv/")):
            lines.setdefault(path, []).append(int(number) - 1)
    return lines


def generated_says_so(path, lines):
    """The file says in its first lines that it is generated, or each of `lines` (numbers) stands
    in a block marked as generated (BEGIN ... generated ... END, as README's table)."""
    text = path.read_text().splitlines()
    if any(re.search(r"generated|written by `?python -m codegen", line, re.I) for line in text[:3]):
        return True
    inside, marked = 0, set()
    for k, line in enumerate(text):
        if re.search(r"BEGIN .*generated|: begin \(generated", line):
            inside += 1
        if inside:
            marked.add(k)
        if re.search(r"<!-- END |: end -->", line):
            inside -= 1
    return set(lines) <= marked


@pytest.mark.slow  # a native build of two FMUs in a scratch copy
def test_a_new_model_touches_its_folder_and_the_model_list_only(scratch, report):
    """The files that name the new model only since new-model (this test names it before)."""
    root, before = scratch
    new = {p: n for p, n in naming(root).items() if p not in before}
    assert "codegen/project.py" in new
    outside = {p: n for p, n in new.items()
               if not p.startswith("fmu_src/models/Probe/") and p != "codegen/project.py"}
    hand_written = [p for p, n in outside.items() if not generated_says_so(root / p, n)]
    assert hand_written == [], hand_written
    assert len([p for p in new if p.startswith("fmu_src/models/Probe/")]) >= 10
    report(f"new-model Probe: {len(new) - len(outside) - 1} files in its folder, the model list, "
           f"{len(outside)} generated files ({', '.join(sorted(outside))})")


@pytest.mark.slow
@pytest.mark.parametrize("version", [2, 3])
def test_the_new_models_fmus_simulate_like_the_model_they_copy(scratch, version):
    root = scratch[0]
    start = {"sequence": 5, "frame": 2}
    if version == 2:
        probe, original = root / "dist" / "Probe.fmu", fmu_path_of("EulerRates")
        start.update({"theta[2]": 0.4, "omega[1]": 0.7, "omega_dot[3]": -1.5})
    else:
        probe, original = root / "dist" / "fmi3" / "Probe.fmu", fmu3_path("EulerRates")
        start.update({"theta": [0.1, 0.4, -0.3], "omega": [0.7, 0.2, 0.0],
                      "omega_dot": [0.0, 0.0, -1.5]})
    results = [simulate_fmu(str(path), stop_time=0.5, output_interval=0.1, start_values=start)
               for path in (probe, original)]
    assert results[0].dtype.names == results[1].dtype.names
    for name in results[0].dtype.names:
        assert np.array_equal(results[0][name], results[1][name]), name
    assert any(np.any(results[0][n] != 0) for n in results[0].dtype.names
               if n.startswith("theta_dot")), "the inputs moved no output"


@pytest.mark.slow
def test_the_generic_tests_run_on_the_new_model(scratch, report):
    done = subprocess.run(
        [sys.executable, "-m", "pytest", "-q", "-n", "0", "-p", "no:cacheprovider", "-k", "Probe",
         "-m", "not external", *[f"tests/python/{name}" for name in GENERIC_TESTS]],
        cwd=scratch[0], capture_output=True, text=True, timeout=900)
    summary = done.stdout.strip().splitlines()[-1]
    assert done.returncode == 0, done.stdout[-6000:]
    passed = int(re.search(r"(\d+) passed", summary).group(1))
    assert passed >= 100, summary
    report(f"the generic tests on the new model Probe: {summary}")
