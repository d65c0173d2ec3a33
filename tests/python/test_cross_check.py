"""dist/cross-check/ (scripts/make_cross_check.py): fmpy's cross-check validator reports 0
problems (and a problem for a name fmpy's reader splits); every model in every FMI version,
interface and platform the FMUs carry; at most 10 reference values, named as in the FMU, the inputs
as the FMU's; each platform folder's result computed by its own binary where that runs here
(wine, qemu-aarch64: scripts/cross_check_platforms.py), its README naming the binary, and every
folder's result bit for bit the others'; FMI 3.0 results equal FMI 2.0's; AngularKinematics right
against the 40-digit reference; examples/ci_check.py --cross-check passing on it (fmpy's
x86_64-linux run against the results of the other binaries) and failing on a moved value.

External: making the folder runs the Windows binaries under wine and the aarch64-linux ones under
qemu, with the drivers of the cross builds."""
import pathlib
import re
import shutil
import subprocess
import sys
import time
import zipfile

import numpy as np
import pytest
from fmpy import read_model_description
from fmpy.cross_check.validate_vendor_repo import validate_test_fmu

from codegen import project, reference

from codegen.project import VERSION
from examples.cross_check import read_csv, read_options
from scripts.cross_check_platforms import HOST, proof
from scripts.cross_check_readme import TOOL_ID

# wine's prefix is shared with the other wine test files: one worker for all (test_platforms.py)
pytestmark = [pytest.mark.xdist_group("wine"), pytest.mark.external]

ROOT = pathlib.Path(__file__).resolve().parents[2]

MODELS = sorted(project.MODELS)
PLATFORMS = {"2.0": {"linux64", "win64", "win32", "darwin64"},
             "3.0": {"x86_64-linux", "x86_64-windows", "aarch64-linux", "riscv64-linux",
                     "x86-windows", "x86_64-darwin", "aarch64-darwin"}}
FMUS = {"2.0": ROOT / "dist", "3.0": ROOT / "dist" / "fmi3"}
# The folders whose binary runs here (docs/platforms.md), with the words their README says it by.
RUN_HERE = {"2.0": {"win64": "under wine"},
            "3.0": {"x86_64-windows": "under wine", "aarch64-linux": "under qemu-aarch64",
                    "riscv64-linux": "under qemu-riscv64"}}
# One folder per FMI version, interface (cs, me), platform and model: per model 8 FMI 2, 14 FMI 3.
FOLDERS = sum(len(platforms) for platforms in PLATFORMS.values()) * 2 * len(MODELS)


def run(*arguments):
    return subprocess.run([sys.executable, *map(str, arguments)], capture_output=True, text=True,
                          timeout=300, cwd=ROOT)


@pytest.fixture(scope="module")
def made(tmp_path_factory, fmu_path, euler_fmu_path):
    """(the folder, make_cross_check's printout, its time in seconds)."""
    out = tmp_path_factory.mktemp("cross-check")
    start = time.monotonic()
    done = run(ROOT / "scripts" / "make_cross_check.py", "--out", out)
    assert done.returncode == 0, done.stdout + done.stderr
    return out, done.stdout, time.monotonic() - start


@pytest.fixture(scope="module")
def folder(made):
    return made[0]


def model_folder(root, version, interface, platform, model):
    return root / "fmus" / version / interface / platform / TOOL_ID / VERSION / model


def cases():
    return [(v, i, p, m) for v in PLATFORMS for i in ("cs", "me") for p in sorted(PLATFORMS[v])
            for m in MODELS]


def test_validator_reports_no_problems(folder, report):
    done = run("-m", "fmpy.cross_check.validate_vendor_repo", folder)
    report(done.stdout.strip().splitlines()[1])
    assert done.returncode == 0, done.stdout[-3000:]
    assert f"0 problems found in {folder}" in done.stdout
    assert f"Validated {FOLDERS} FMUs" in done.stdout  # FMI 3 folders counted, not read
    # It skips fmus/3.0/: its check of one folder, run on each FMI 3 folder.
    fmi3 = [model_folder(folder, *case) for case in cases() if case[0] == "3.0"]
    assert len(fmi3) == len(PLATFORMS["3.0"]) * 2 * len(MODELS)
    assert all(validate_test_fmu(str(here)) == [] for here in fmi3)


def test_validator_fails_on_a_name_with_a_comma(folder, tmp_path):
    """What it said of the old AngularKinematics_ref.csv: fmpy's reader splits "R[1,1]"."""
    source = model_folder(folder, "2.0", "cs", "linux64", "AngularKinematics")
    copy = model_folder(tmp_path, "2.0", "cs", "linux64", "AngularKinematics")
    shutil.copytree(source, copy)
    path = copy / "AngularKinematics_ref.csv"
    path.write_text(path.read_text().replace('"q[1]"', '"R[1,1]"', 1))
    done = run("-m", "fmpy.cross_check.validate_vendor_repo", tmp_path)
    assert done.returncode == 1 and "1 problems found" in done.stdout, done.stdout[-2000:]
    assert "AngularKinematics_ref.csv" in done.stdout


@pytest.mark.parametrize("version,interface,platform,model", cases())
def test_layout(folder, version, interface, platform, model):
    here = model_folder(folder, version, interface, platform, model)
    assert {p.name for p in here.iterdir()} == {
        f"{model}.fmu", f"{model}_in.csv", f"{model}_ref.csv", f"{model}_ref.opt", "README.md"}
    fmu = FMUS[version] / f"{model}.fmu"
    assert (here / f"{model}.fmu").read_bytes() == fmu.read_bytes()
    with zipfile.ZipFile(fmu) as archive:
        assert any(n.startswith(f"binaries/{platform}/") for n in archive.namelist())
    assert read_options(here / f"{model}_ref.opt") == dict(StartTime=0.0, StopTime=4.0,
                                                           StepSize=0.01, RelTol=0.0)
    description = read_model_description(str(fmu))
    inputs = [v.name for v in description.modelVariables if v.causality == "input"]
    in_header = (here / f"{model}_in.csv").read_text().splitlines()[0]
    assert in_header == ",".join(f'"{n}"' for n in ["time"] + inputs)
    ref_header = (here / f"{model}_ref.csv").read_text().splitlines()[0].split(",")
    names = {v.name for v in description.modelVariables}
    assert all(n.strip('"') in names for n in ref_header[1:]) and "," not in "".join(ref_header)
    in_names, in_table = read_csv(here / f"{model}_in.csv")
    ref_names, ref_table = read_csv(here / f"{model}_ref.csv")
    assert len(ref_names) - 1 <= 10  # values, not only columns: an FMI 3 array counts its elements
    assert len(in_table) == len(ref_table) == 401
    assert np.array_equal(in_table[:, 0], ref_table[:, 0])
    assert f"`{TOOL_ID}`" in (here / "README.md").read_text()


@pytest.mark.parametrize("version", sorted(PLATFORMS))
def test_three_fmus_for_each_platform_and_variant(folder, version):
    """The rules ask an exporting tool for at least three FMUs per platform and FMI variant: the
    platforms are the FMUs' binaries/ folders, every model in each."""
    for model in MODELS:
        with zipfile.ZipFile(FMUS[version] / f"{model}.fmu") as archive:
            carried = {n.split("/")[1] for n in archive.namelist()
                       if n.startswith("binaries/") and n.count("/") >= 2}
        assert carried == PLATFORMS[version]
    for interface in ("cs", "me"):
        here = folder / "fmus" / version / interface
        assert {p.name for p in here.iterdir()} == PLATFORMS[version]
        for platform in PLATFORMS[version]:
            models = here / platform / TOOL_ID / VERSION
            assert sorted(p.name for p in models.iterdir()) == MODELS


def test_tool_folder_is_an_id():
    """The IDs of fmi-standard.org's tools list are letters, digits, '_', '-', '.'."""
    assert re.fullmatch(r"[A-Za-z][A-Za-z0-9_.-]*", TOOL_ID)


@pytest.mark.parametrize("interface", ["cs", "me"])
@pytest.mark.parametrize("model", MODELS)
def test_fmi3_results_equal_fmi2(folder, interface, model):
    fmi2 = read_csv(model_folder(folder, "2.0", interface, "linux64", model) / f"{model}_ref.csv")
    fmi3 = read_csv(model_folder(folder, "3.0", interface, "x86_64-linux", model) /
                    f"{model}_ref.csv")
    assert fmi2[0] == fmi3[0]
    assert np.array_equal(fmi2[1], fmi3[1])


@pytest.mark.parametrize("interface", ["cs", "me"])
def test_reference_results_are_right(folder, interface, report):
    """Our shipped numbers, against the sympy/mpmath reference (40 digits), every 20th row."""
    here = model_folder(folder, "2.0", interface, "linux64", "AngularKinematics")
    in_names, inputs = read_csv(here / "AngularKinematics_in.csv")
    out_names, outputs = read_csv(here / "AngularKinematics_ref.csv")
    inputs = inputs[:, [in_names.index(n) for n in reference.INPUT_NAMES]]
    body = [n for n in reference.OUTPUT_NAMES if "_body" in n] + [f"q[{i}]" for i in range(1, 5)]
    got = outputs[:, [out_names.index(n) for n in body]]
    worst = 0.0
    for row in range(0, len(inputs), 20):
        exact = reference.outputs(inputs[row])
        exact = np.concatenate([[exact[reference.OUTPUT_NAMES.index(n)] for n in body[:6]],
                                reference.quaternion("body123", inputs[row][:3])])
        worst = max(worst, float((np.abs(got[row] - exact) / (1 + np.abs(exact))).max()))
    report(f"{interface}: AngularKinematics_ref.csv vs 40-digit reference: {worst:.2e} (21 rows)")
    assert worst < 1e-14


def move(path, row, column, element=0, tolerances=3.0):
    """One value moved by `tolerances` times the tolerance the cross-check promises,
    1e-12 + 1e-12 |value|."""
    lines = path.read_text().splitlines()
    cells = lines[row].split(",")
    values = cells[column].split()
    value = float(values[element])
    values[element] = repr(value + tolerances * (1e-12 + 1e-12 * abs(value)))
    cells[column] = " ".join(values)
    lines[row] = ",".join(cells)
    path.write_text("\n".join(lines) + "\n")


def test_ci_check_passes_then_fails_on_a_moved_value(folder, report):
    done = run(ROOT / "examples" / "ci_check.py", "--cross-check", folder)
    assert done.returncode == 0, done.stdout + done.stderr
    assert FOLDERS == 22 * len(MODELS)
    assert done.stdout.count(" ok ") == FOLDERS
    assert done.stdout.count("largest deviation 0\n") == FOLDERS

    # Half the tolerance passes (a tolerance 10 times tighter would not), three times fails (a
    # tolerance 10 times looser would not).
    euler = model_folder(folder, "2.0", "me", "win64", "EulerRates") / "EulerRates_ref.csv"
    attitude = (model_folder(folder, "3.0", "cs", "aarch64-linux", "AttitudePropagator") /
                "AttitudePropagator_ref.csv")
    saved = {path: path.read_text() for path in (euler, attitude)}
    move(euler, 200, 1, tolerances=0.5)
    done = run(ROOT / "examples" / "ci_check.py", "--cross-check", folder)
    assert done.returncode == 0, done.stdout
    assert done.stdout.count(" ok ") == FOLDERS
    for path, text in saved.items():
        path.write_text(text)
    move(euler, 200, 1)  # theta_dot[1] at t = 1.99 s
    move(attitude, 301, 1, element=2)  # q[3] at t = 3 s
    done = run(ROOT / "examples" / "ci_check.py", "--cross-check", folder)
    for path, text in saved.items():  # the folder as made, for the tests after this one
        path.write_text(text)
    report(f"one value in each of two folders moved by 3 tolerances: exit {done.returncode}")
    assert done.returncode == 1, done.stdout
    assert "DIFFERENT me EulerRates theta_dot[1]" in done.stdout and "t = 1.99 s" in done.stdout
    assert "DIFFERENT cs AttitudePropagator q[3]" in done.stdout and "t = 3 s" in done.stdout
    assert done.stdout.count(" ok ") == FOLDERS - 2 and done.stdout.count("FAILED ") == 2


def test_each_folder_says_which_binary_computed_it(made, report):
    """The folders of the platforms that run here hold their own binary's result; the others
    (macOS; x86 Windows without a 32-bit wine) the host's, and name the test that proves the bits
    of their binary."""
    root, printout, seconds = made
    own = 0
    for version, interface, platform, model in cases():
        text = (model_folder(root, version, interface, platform, model) / "README.md").read_text()
        text = " ".join(text.split())
        if platform == HOST[version]:
            assert f"computed by this folder's {platform} binary, through fmpy" in text
        elif platform in RUN_HERE[version]:
            assert (f"computed by this folder's {platform} binary, run "
                    f"{RUN_HERE[version][platform]}") in text
            own += 1
        elif "darwin" in platform or "run under wine" not in text:  # x86: a 32-bit wine runs it
            assert f"computed by the {HOST[version]} binary through fmpy" in text
            assert proof(platform) in text and "tests/python/test_" in proof(platform)
            assert ("darwin" in proof(platform)) == ("darwin" in platform)
    assert own == 2 * len(MODELS) * sum(map(len, RUN_HERE.values())) == 8 * len(MODELS)
    assert printout.count("its own binary") >= own
    report(f"{own} folders computed by their own binary under wine or qemu; make_cross_check "
           f"took {seconds:.1f} s")


def disagreements(root):
    """Every folder whose <Model>_ref.csv differs in any bit from the host folder's of the same
    FMI version, interface and model: bits, not a tolerance, because every platform's binary
    computes the same bits (docs/platforms.md), and one that does not is a finding even within
    the cross-check's tolerance."""
    found = []
    for version in PLATFORMS:
        for interface in ("cs", "me"):
            for model in MODELS:
                bits = {platform: read_csv(model_folder(root, version, interface, platform, model)
                                           / f"{model}_ref.csv")[1].view(np.uint64)
                        for platform in sorted(PLATFORMS[version])}
                host = bits[HOST[version]]
                found += [f"{version} {interface} {platform} {model}: "
                          f"{np.count_nonzero(b != host)} values differ"
                          for platform, b in bits.items()
                          if b.shape != host.shape or (b != host).any()]
    return found


def test_every_folder_has_the_bits_of_the_others(folder, report):
    assert disagreements(folder) == []
    values = sum(read_csv(model_folder(folder, *case) / f"{case[3]}_ref.csv")[1].size
                 for case in cases())
    report(f"{FOLDERS} folders, {values} values: every folder bit for bit its host folder's")


def test_one_ulp_in_one_folder_is_a_disagreement(folder, tmp_path):
    """What the check above finds: one value of one folder one ulp off (far inside the
    cross-check's tolerance, which ci_check --cross-check applies)."""
    for case in cases():
        name = f"{case[3]}_ref.csv"
        (model_folder(tmp_path, *case)).mkdir(parents=True)
        shutil.copyfile(model_folder(folder, *case) / name, model_folder(tmp_path, *case) / name)
    path = model_folder(tmp_path, "3.0", "me", "aarch64-linux", "AttitudePropagator") / \
        "AttitudePropagator_ref.csv"
    lines = path.read_text().splitlines()
    cells = lines[301].split(",")
    values = cells[1].split()
    values[2] = repr(float(np.nextafter(float(values[2]), np.inf)))
    cells[1] = " ".join(values)
    lines[301] = ",".join(cells)
    path.write_text("\n".join(lines) + "\n")
    assert disagreements(tmp_path) == ["3.0 me aarch64-linux AttitudePropagator: 1 values differ"]
