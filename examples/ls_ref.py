"""The reference result an FMU carries by the layered standard FMI-LS-REF (1.0.0-alpha.1):
extra/org.fmi-standard.fmi-ls-ref/fmi-ls-manifest.xml names, in its <Experiment>, the inputs
(<Stimuli>) and the result (<References>), CSV files beside it. check_carried re-simulates the FMU
over those inputs in Co-Simulation with the master of cross_check.py and compares the result's
columns (cross_check.check_model, same tolerance)."""
import pathlib
import shutil
import tempfile
import xml.etree.ElementTree as ET
import zipfile

from fmpy import read_model_description

if __package__:  # examples.ls_ref, in the repository
    from examples.cross_check import check_model, read_csv
else:  # copied beside examples/ci_check.py, which imports it as a file of its folder
    from cross_check import check_model, read_csv

FOLDER = "extra/org.fmi-standard.fmi-ls-ref/"
LS_NAME = "org.fmi-standard.fmi-ls-ref"
LS = "{http://fmi-standard.org/fmi-ls-manifest}"


def carried(fmu):
    """(inputs file name, result file name, {name: bytes} of the folder), or a reason string."""
    with zipfile.ZipFile(fmu) as archive:
        files = {n[len(FOLDER):]: archive.read(n) for n in archive.namelist()
                 if n.startswith(FOLDER) and not n.endswith("/")}
    if "fmi-ls-manifest.xml" not in files:
        return f"{fmu} carries no {FOLDER}fmi-ls-manifest.xml"
    root = ET.fromstring(files["fmi-ls-manifest.xml"])
    if root.tag != "fmiReferences" or root.get(LS + "fmi-ls-name") != LS_NAME:
        return f"{fmu}: {FOLDER}fmi-ls-manifest.xml is not an {LS_NAME} manifest"
    experiment = root.find("Experiment")
    stimuli = experiment.find("Stimuli") if experiment is not None else None
    result = experiment.find("References") if experiment is not None else None
    if stimuli is None or result is None:
        return f"{fmu}: the manifest names no <Experiment> with <Stimuli> and <References>"
    missing = {stimuli.get("source"), result.get("source")} - set(files)
    if missing:
        return f"{fmu}: the manifest names files the FMU does not carry: {sorted(missing)}"
    return stimuli.get("source"), result.get("source"), files


def check_carried(fmu):
    """0 the FMU computes the result it carries, 1 it differs, 2 nothing to compare."""
    found = carried(fmu)
    if isinstance(found, str):
        print(found)
        return 2
    inputs, result, files = found
    description = read_model_description(str(fmu))
    model = description.modelName
    folder = pathlib.Path(tempfile.mkdtemp()) / model
    try:
        folder.mkdir()
        shutil.copyfile(fmu, folder / f"{model}.fmu")
        (folder / f"{model}_in.csv").write_bytes(files[inputs])
        (folder / f"{model}_ref.csv").write_bytes(files[result])
        times = read_csv(folder / f"{model}_in.csv")[1][:, 0]
        (folder / f"{model}_ref.opt").write_text(
            f"StartTime, {float(times[0])!r}\nStopTime, {float(times[-1])!r}\n")
        print(f"{fmu}: {FOLDER}{result} over {inputs}")
        return check_model(folder, "cs", description.fmiVersion, "carried")
    finally:
        shutil.rmtree(folder.parent, ignore_errors=True)
