"""The reference result an FMU carries by the layered standard FMI-LS-REF (1.0.0-alpha.1):
extra/org.fmi-standard.fmi-ls-ref/fmi-ls-manifest.xml relates files by role. check_carried takes
the file of role experiment (the experiments format of FMI-LS-REF 1.0.0-alpha.1, MIME type
application/x-ma-ls-experiments), reads from it the interface (the experiment's name, cs), start,
stop, step, comparison tolerance, inputs (<Stimuli>, the manifest's testcase) and result
(<References>, the manifest's result), re-simulates the FMU over those inputs with the master of
cross_check.py and compares the result's columns to that tolerance."""
import pathlib
import posixpath
import shutil
import tempfile
import xml.etree.ElementTree as ET
import zipfile

import numpy as np
from fmpy import read_model_description

if __package__:  # examples.ls_ref, in the repository
    from examples.cross_check import check_model, read_csv
else:  # copied beside examples/ci_check.py, which imports it as a file of its folder
    from cross_check import check_model, read_csv

FOLDER = "extra/org.fmi-standard.fmi-ls-ref/"
LS_NAME, LS_VERSION = "org.fmi-standard.fmi-ls-ref", "1.0.0-alpha.1"
# Fixed by the schema (fmi3LayeredStandardReferenceManifest.xsd).
LS_DESCRIPTION = "Layered Standard providing information on related files included in an FMU."
LS = "{http://fmi-standard.org/fmi-ls-manifest}"
EXPERIMENTS_TYPE = "application/x-ma-ls-experiments"
EXPERIMENT_NAME = "cs"  # the interface the result was made in, in the FMI Cross-Check's words
DOCUMENT = "../../documentation/index.html"  # the FMU's page, relative to FOLDER
INTERFACES = ("cs", "me")


def member(source):
    """The archive path of a manifest's relative source."""
    return posixpath.normpath(FOLDER + source)


def related(root, role):
    """The <Related> elements whose main role is role."""
    return [r for r in root.findall("Related") if (r.get("role") or "").split("/")[0] == role]


def experiment_settings(fmu, text, sources):
    """{interface, start, stop, step, tolerance, inputs, result} of the first <Experiment> of an
    experiments file, or a reason string; sources maps the manifest's roles to their sources."""
    root = ET.fromstring(text)
    experiment = root.find("Experiment") if root.tag == "Experiments" else None
    if experiment is None:
        return f"{fmu}: the experiment file holds no <Experiments> with an <Experiment>"
    settings = {"interface": experiment.get("name")}
    if settings["interface"] not in INTERFACES:
        return (f"{fmu}: the experiment's name {settings['interface']!r} is not an interface "
                f"{INTERFACES}")
    for key, attribute in (("start", "startTime"), ("stop", "stopTime"), ("step", "stepSize"),
                           ("tolerance", "tolerance")):
        try:
            settings[key] = float(experiment.get(attribute))
        except (TypeError, ValueError):
            return (f"{fmu}: the experiment's {attribute} is {experiment.get(attribute)!r}, "
                    "not a number")
    for key, element, role in (("inputs", "Stimuli", "testcase"),
                               ("result", "References", "result")):
        found = experiment.find(element)
        settings[key] = found.get("source") if found is not None else None
        if settings[key] is None or settings[key] not in sources.get(role, []):
            return (f"{fmu}: the experiment's <{element}> {settings[key]!r} is not a file the "
                    f"manifest relates as {role} ({sources.get(role, [])})")
    return settings


def carried(fmu):
    """(experiment settings, {archive path: bytes}), or a reason string."""
    with zipfile.ZipFile(fmu) as archive:
        files = {n: archive.read(n) for n in archive.namelist() if not n.endswith("/")}
    manifest = FOLDER + "fmi-ls-manifest.xml"
    if manifest not in files:
        return f"{fmu} carries no {manifest}"
    root = ET.fromstring(files[manifest])
    if root.tag != "fmiReferences" or root.get(LS + "fmi-ls-name") != LS_NAME:
        return f"{fmu}: {manifest} is not an {LS_NAME} manifest"
    sources = {}
    for item in root.findall("Related"):
        sources.setdefault(item.get("role", "").split("/")[0], []).append(item.get("source"))
    experiments = [r for r in related(root, "experiment") if r.get("type") == EXPERIMENTS_TYPE]
    if not experiments:
        return f"{fmu}: the manifest relates no file of role experiment and type {EXPERIMENTS_TYPE}"
    needed = ([experiments[0].get("source")] + sources.get("testcase", [])
              + sources.get("result", []))
    missing = sorted(str(s) for s in needed if s is None or member(s) not in files)
    if missing:
        return f"{fmu}: the manifest relates files the FMU does not carry: {missing}"
    settings = experiment_settings(fmu, files[member(experiments[0].get("source"))], sources)
    return settings if isinstance(settings, str) else (settings, files)


def grid_mismatch(times, settings):
    """Why the inputs' times are not the experiment's grid (start to stop by step), or None."""
    expected = np.arange(settings["start"], settings["stop"] + settings["step"] / 2,
                         settings["step"])
    if len(times) != len(expected) or not np.allclose(times, expected, rtol=0, atol=1e-9):
        return (f"the times of {settings['inputs']} ({times[0]:g} to {times[-1]:g}, "
                f"{len(times)} rows) are not the experiment's startTime {settings['start']:g}, "
                f"stopTime {settings['stop']:g}, stepSize {settings['step']:g}")
    return None


def check_carried(fmu):
    """0 the FMU computes the result it carries, 1 it differs, 2 nothing to compare."""
    found = carried(fmu)
    if isinstance(found, str):
        print(found)
        return 2
    settings, files = found
    description = read_model_description(str(fmu))
    model = description.modelName
    folder = pathlib.Path(tempfile.mkdtemp()) / model
    try:
        folder.mkdir()
        shutil.copyfile(fmu, folder / f"{model}.fmu")
        (folder / f"{model}_in.csv").write_bytes(files[member(settings["inputs"])])
        (folder / f"{model}_ref.csv").write_bytes(files[member(settings["result"])])
        mismatch = grid_mismatch(read_csv(folder / f"{model}_in.csv")[1][:, 0], settings)
        if mismatch:
            print(f"{fmu}: {mismatch}")
            return 2
        (folder / f"{model}_ref.opt").write_text(
            f"StartTime, {settings['start']!r}\nStopTime, {settings['stop']!r}\n")
        print(f"{fmu}: {FOLDER}{settings['result']} over {settings['inputs']}, "
              f"{settings['interface']}, step {settings['step']:g} s, "
              f"tolerance per value {settings['tolerance']:g} * (1 + |reference|)")
        return check_model(folder, settings["interface"], description.fmiVersion, "carried",
                           relative=settings["tolerance"], absolute=settings["tolerance"])
    finally:
        shutil.rmtree(folder.parent, ignore_errors=True)
