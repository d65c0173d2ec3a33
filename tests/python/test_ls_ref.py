"""The reference result each FMU carries in extra/org.fmi-standard.fmi-ls-ref/ (FMI-LS-REF
1.0.0-alpha.1), written while packaging by scripts/make_ls_ref.py (cmake/ls_ref.cmake). The
carried files are what the packaged FMU computes; every packaged
manifest is valid against the schema copies of tests/schemas/fmi-ls-ref/ and relates the
experiment, its inputs, its result and the FMU's page by role; examples/ci_check.py --ls-ref
passes on an FMU carrying them, takes the experiment's settings from its file, fails on a moved
value and reports an FMU carrying none."""
import pathlib
import subprocess
import sys
import xml.etree.ElementTree as ET
import zipfile

import numpy as np
import pytest
from fmpy import read_model_description

from examples.cross_check import ABSOLUTE, RELATIVE, read_csv
from examples.ls_ref import FOLDER, LS, member

from ls_ref_schema import MANIFEST_SCHEMAS, experiments_errors, manifest_errors

from codegen.project import MODELS

ROOT = pathlib.Path(__file__).resolve().parents[2]

CASES = [(v, m) for v in ("fmi2", "fmi3") for m in MODELS]


def run(*arguments):
    return subprocess.run([sys.executable, *map(str, arguments)], capture_output=True, text=True,
                          timeout=300, cwd=ROOT)


def dist_fmu(version, model):
    return ROOT / "dist" / ("" if version == "fmi2" else "fmi3") / f"{model}.fmu"


def carried(version, model):
    """{file name: bytes} of the files the dist FMU carries in extra/."""
    with zipfile.ZipFile(dist_fmu(version, model)) as archive:
        return {n[len(FOLDER):]: archive.read(n) for n in archive.namelist()
                if n.startswith(FOLDER) and not n.endswith("/")}


def carried_folder(tmp_path, version, model):
    """The carried files, written into a folder."""
    folder = tmp_path / "carried" / version / model
    folder.mkdir(parents=True)
    for name, data in carried(version, model).items():
        (folder / name).write_bytes(data)
    return folder


def without_ls_ref(source, path):
    """A copy of the FMU without extra/org.fmi-standard.fmi-ls-ref/."""
    with zipfile.ZipFile(source) as archive, zipfile.ZipFile(path, "w") as out:
        for item in archive.infolist():
            if not item.filename.startswith(FOLDER):
                out.writestr(item, archive.read(item))
    return path


def carrying(tmp_path, version, model, change=None):
    """A copy of the dist FMU with its files in extra/ written again; change(name, text) -> text
    may alter a file on the way."""
    path = without_ls_ref(dist_fmu(version, model), tmp_path / f"{model}_{version}.fmu")
    with zipfile.ZipFile(path, "a") as archive:
        for name, data in sorted(carried(version, model).items()):
            text = data.decode()
            archive.writestr(FOLDER + name, change(name, text) if change else text)
    return path


@pytest.mark.parametrize("version,model", CASES)
def test_carried_files_are_what_the_fmu_computes(tmp_path, version, model):
    """scripts/make_ls_ref.py run on the dist FMU stripped of its files gives them back byte for
    byte: the build made them with the binary it packaged. Four files, named by the model."""
    bare = without_ls_ref(dist_fmu(version, model), tmp_path / "bare.fmu")
    done = run("-m", "scripts.make_ls_ref", bare, tmp_path / "made")
    assert done.returncode == 0, done.stdout + done.stderr
    made = {p.name: p.read_bytes() for p in (tmp_path / "made").iterdir()}
    assert sorted(made) == sorted(["fmi-ls-manifest.xml", f"{model}.exp", f"{model}_in.csv",
                                   f"{model}_out.csv"])
    assert carried(version, model) == made


@pytest.mark.parametrize("version,model", CASES)
def test_manifest_relates_the_files_by_role(tmp_path, version, model):
    folder = carried_folder(tmp_path, version, model)
    root = ET.parse(folder / "fmi-ls-manifest.xml").getroot()
    assert root.tag == "fmiReferences"
    assert root.get(LS + "fmi-ls-name") == "org.fmi-standard.fmi-ls-ref"
    assert root.get(LS + "fmi-ls-version") == "1.0.0-alpha.1"
    roles = {r.get("role"): (r.get("source"), r.get("type")) for r in root.findall("Related")}
    assert roles == {"experiment": (f"{model}.exp", "application/x-ma-ls-experiments"),
                     "testcase": (f"{model}_in.csv", "text/csv"),
                     "result": (f"{model}_out.csv", "text/csv"),
                     "document": ("../../documentation/index.html", "text/html")}
    experiment = ET.parse(folder / f"{model}.exp").getroot().find("Experiment")
    assert experiment.get("name") == "cs"
    stimuli = experiment.find("Stimuli").get("source")
    result = experiment.find("References").get("source")
    assert (stimuli, result) == (roles["testcase"][0], roles["result"][0])
    in_names, inputs = read_csv(folder / stimuli)
    out_names, outputs = read_csv(folder / result)
    assert np.array_equal(inputs[:, 0], outputs[:, 0]) and len(inputs) == 401
    assert [float(experiment.get(k)) for k in ("startTime", "stopTime", "stepSize")] == [
        inputs[0, 0], inputs[-1, 0], 0.01]
    # one tolerance stands for both parts of cross_check.py's
    assert float(experiment.get("tolerance")) == RELATIVE == ABSOLUTE
    description = read_model_description(str(dist_fmu(version, model)))
    header = (folder / stimuli).read_text().splitlines()[0]
    assert header == ",".join(f'"{n}"' for n in ["time"] + [
        v.name for v in description.modelVariables if v.causality == "input"])
    assert 1 < len(out_names) - 1 <= 10


def packaged_fmus():
    return sorted((ROOT / "dist").glob("*.fmu")) + sorted((ROOT / "dist" / "fmi3").glob("*.fmu"))


def test_packaged_manifests_are_valid_against_the_schemas():
    """Every FMU of dist/ and dist/fmi3/: its manifest against FMI-LS-REF's current schema and
    1.0.0-alpha.1's, its experiment file against 1.0.0-alpha.1's experiments schema, and every
    file the manifest relates is in the FMU."""
    fmus = packaged_fmus()
    assert len(fmus) == 2 * len(MODELS)
    invalid, absent = {}, {}
    for fmu in fmus:
        with zipfile.ZipFile(fmu) as archive:
            names = set(archive.namelist())
            manifest = archive.read(FOLDER + "fmi-ls-manifest.xml")
            sources = {r.get("role"): r.get("source")
                       for r in ET.fromstring(manifest).findall("Related")}
            absent[fmu.name] = sorted(s for s in sources.values() if member(s) not in names)
            experiments = sources.get("experiment")
            if experiments is not None and member(experiments) in names:
                invalid[f"{fmu} {experiments}"] = experiments_errors(
                    archive.read(member(experiments)))
        for schema in MANIFEST_SCHEMAS:
            invalid[f"{fmu} against {schema}"] = manifest_errors(manifest, schema)
        absent[fmu.name] += [] if experiments else ["no file of role experiment"]
    assert {name: faults for name, faults in invalid.items() if faults} == {}
    assert {name: files for name, files in absent.items() if files} == {}


@pytest.mark.parametrize("plant,expected", [
    (lambda text: text.replace("    <Related", '    <Experiment name="x"/>\n    <Related', 1),
     "Unexpected child with tag 'Experiment' at position 1. (at /fmiReferences)"),
    (lambda text: text.replace("information on related files", "reference stimuli and results"),
     "attribute '{http://fmi-standard.org/fmi-ls-manifest}fmi-ls-description' has a fixed value "
     "'Layered Standard providing information on related files included in an FMU.'"),
    (lambda text: text.replace('role="document"', 'role="documentation"'),
     "attribute role='documentation': value doesn't match any pattern"),
])
def test_schemas_refuse_a_planted_fault(plant, expected):
    """A fault planted in a carried manifest: both schemas name it."""
    text = carried("fmi3", "EulerRates")["fmi-ls-manifest.xml"].decode()
    assert manifest_errors(text.encode(), MANIFEST_SCHEMAS[0]) == []
    for schema in MANIFEST_SCHEMAS:
        errors = manifest_errors(plant(text).encode(), schema)
        assert any(expected in e for e in errors), (schema, errors)


@pytest.mark.parametrize("version,model", CASES)
def test_ci_check_passes_on_an_fmu_carrying_its_reference(tmp_path, version, model):
    done = run(ROOT / "examples" / "ci_check.py", "--ls-ref", carrying(tmp_path, version, model))
    assert done.returncode == 0, done.stdout + done.stderr
    assert "largest deviation 0\n" in done.stdout and "PASSED" in done.stdout


def move(name, text):
    """q[2] of AttitudePropagator's FMI 3 result at t = 1 s, 1e-9 relative off."""
    if not name.endswith("_out.csv"):
        return text
    lines = text.splitlines()
    cells = lines[101].split(",")  # t = 1 s
    values = cells[1].split()
    values[1] = repr(float(values[1]) * (1 + 1e-9))  # q[2]
    cells[1] = " ".join(values)
    lines[101] = ",".join(cells)
    return "\n".join(lines) + "\n"


def test_ci_check_fails_on_a_moved_value_and_without_a_reference(tmp_path, report):
    fmu = carrying(tmp_path, "fmi3", "AttitudePropagator", move)
    done = run(ROOT / "examples" / "ci_check.py", "--ls-ref", fmu)
    report(f"a 1e-9 relative change of one carried value: exit {done.returncode}")
    assert done.returncode == 1, done.stdout
    assert "DIFFERENT cs AttitudePropagator q[2]" in done.stdout and "t = 1 s" in done.stdout
    bare = without_ls_ref(dist_fmu("fmi2", "EulerRates"), tmp_path / "bare.fmu")
    done = run(ROOT / "examples" / "ci_check.py", "--ls-ref", bare)
    assert done.returncode == 2 and "carries no extra/org.fmi-standard.fmi-ls-ref/" in done.stdout


def test_ci_check_takes_the_settings_from_the_experiment_file(tmp_path):
    """The tolerance and the time grid come from <Model>.exp: a tolerance of 1e-6 passes the
    value moved by 1e-9; a stepSize of 0.02 makes the carried inputs no longer its grid."""
    def loose(name, text):
        return move(name, text).replace('tolerance="1e-12"', 'tolerance="1e-06"')
    done = run(ROOT / "examples" / "ci_check.py", "--ls-ref",
               carrying(tmp_path, "fmi3", "AttitudePropagator", loose))
    assert done.returncode == 0 and "tolerance per value 1e-06" in done.stdout, done.stdout

    def coarse(name, text):
        return text.replace('stepSize="0.01"', 'stepSize="0.02"')
    done = run(ROOT / "examples" / "ci_check.py", "--ls-ref",
               carrying(tmp_path, "fmi2", "EulerRates", coarse))
    assert done.returncode == 2, done.stdout
    assert ("EulerRates_in.csv (0 to 4, 401 rows) are not the experiment's startTime 0, "
            "stopTime 4, stepSize 0.02") in done.stdout


def test_ci_check_help_names_the_option():
    done = run(ROOT / "examples" / "ci_check.py", "--help")
    text = " ".join(done.stdout.split())
    assert done.returncode == 0
    assert ("--ls-ref FMU instead: re-simulate the FMU against the reference result it carries "
            "(FMI-LS-REF,") in text
