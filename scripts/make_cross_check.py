"""Writes dist/cross-check/: every FMU of dist/ (FMI 2.0) and dist/fmi3/ (FMI 3.0) with its
reference inputs and our own results, per interface and per platform the FMU carries, in the
layout of the FMI Cross-Check (examples/cross_check.py describes it). Check it with
`python -m fmpy.cross_check.validate_vendor_repo dist/cross-check`.

Each platform folder's result is computed by that folder's binary where it runs here (fmpy on
x86_64-linux; the others under wine or qemu, scripts/cross_check_platforms.py), else it is the
x86_64-linux result, and the folder's README says which and the test that proves the bits equal.

    .venv/bin/python scripts/make_cross_check.py [--dist DIR] [--out DIR]"""
import argparse
import concurrent.futures
import pathlib
import shutil
import sys
import zipfile

import numpy as np
from fmpy import read_model_description

from codegen.models import load
from codegen.project import MODELS, VERSION
from examples.cross_check import START, STEP, STOP, reference_inputs, simulate, write_csv
from examples.cross_check3 import simulate3, write_csv3
from scripts.cross_check_platforms import HOST, RUNNERS, origin, run_binary
from scripts.cross_check_readme import TOOL_ID, readme

ROOT = pathlib.Path(__file__).resolve().parent.parent

# The reference variables of each model (the rules recommend at most 10), FMI 2 names; in FMI 3
# the arrays that hold these elements: CROSS_CHECK_OUTPUTS of its description.
REFERENCE_OUTPUTS = {name: load(name).cross_check_outputs for name in MODELS}


def platforms(fmu):
    """The binaries/<platform>/ folders of the FMU: the FMI 2 names (linux64, win64, ...) are the
    cross-check's; FMI 3's are its platform tuples (x86_64-linux, ...)."""
    with zipfile.ZipFile(fmu) as archive:
        return sorted({n.split("/")[1] for n in archive.namelist()
                       if n.startswith("binaries/") and n.count("/") >= 2 and n.split("/")[1]})


def input_names(description):
    """FMI 2 element names of the Float64/Real inputs (FMI 3 arrays expanded: theta[1], ...)."""
    names = []
    for v in description.modelVariables:
        if v.causality == "input" and v.type in ("Real", "Float64"):
            count = int(np.prod([int(d.start) for d in v.dimensions])) if v.dimensions else 1
            names += [v.name] if not v.dimensions else [f"{v.name}[{k + 1}]" for k in range(count)]
    return names


def reference_run(fmu, interface, platform=None):
    """The reference experiment of the FMU in one interface: (description, write, table of the
    inputs, table of the reference outputs), each table with its names, time first; write is
    the CSV writer of the FMU's FMI version. The outputs are fmpy's, with the host's binary; with
    a platform, those of that platform's binary where it runs here (None where it does not)."""
    description = read_model_description(str(fmu))
    times = np.round(np.arange(START, STOP + STEP / 2, STEP), 12)
    inputs_names = input_names(description)
    inputs = reference_inputs(inputs_names, times)
    output_names = REFERENCE_OUTPUTS[description.modelName]
    run, write = ((simulate, write_csv) if description.fmiVersion == "2.0"
                  else (simulate3, write_csv3))
    if platform is None:
        names, outputs = run(str(fmu), interface, times, inputs_names, inputs, output_names)
    else:
        names, outputs = output_names, run_binary(fmu, platform, description, interface, times,
                                                  inputs_names, inputs, output_names)
        if outputs is None:
            return None
    return (description, write, (["time"] + inputs_names, np.column_stack([times, inputs])),
            (["time"] + names, np.column_stack([times, outputs])))


def own_runs(fmus):
    """{(fmu, interface, platform): reference_run} of every folder computed by its own binary
    under wine or qemu. The runs wait mostly for the emulator's start (wine: about a second), so
    they run side by side; the first under wine alone, since it may create wine's prefix."""
    jobs = [(fmu, interface, platform) for fmu in fmus for interface in ("cs", "me")
            for platform in platforms(fmu)
            if origin(platform, read_model_description(str(fmu)).fmiVersion) == "own"]
    first = [job for job in jobs if RUNNERS[job[2]].windows][:1]
    runs = {job: reference_run(*job) for job in first}
    rest = [job for job in jobs if job not in runs]
    with concurrent.futures.ThreadPoolExecutor(max_workers=4) as pool:
        runs.update(zip(rest, pool.map(lambda job: reference_run(*job), rest)))
    return runs


def make(fmu, out, runs=None):
    """The folders of one FMU; runs: own_runs' results (by default computed here)."""
    runs = own_runs([fmu]) if runs is None else runs
    written = []
    for interface in ("cs", "me"):
        host = reference_run(fmu, interface)
        description, write, inputs, _ = host
        model, version = description.modelName, description.fmiVersion
        for platform in platforms(fmu):
            how = origin(platform, version)
            outputs = (runs[fmu, interface, platform] if how == "own" else host)[3]
            folder = out / "fmus" / version / interface / platform / TOOL_ID / VERSION / model
            folder.mkdir(parents=True, exist_ok=True)
            shutil.copyfile(fmu, folder / f"{model}.fmu")
            write(folder / f"{model}_in.csv", *inputs)
            write(folder / f"{model}_ref.csv", *outputs)
            (folder / f"{model}_ref.opt").write_text(
                f"StartTime, {START}\nStopTime, {STOP}\nStepSize, {STEP}\nRelTol, 0\n")
            (folder / "README.md").write_text(readme(
                model, version, interface, platform, outputs[0][1:],
                description.numberOfContinuousStates, how))
            written.append((folder, how))
    return written


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--dist", default=str(ROOT / "dist"))
    parser.add_argument("--out", default=str(ROOT / "dist" / "cross-check"))
    args = parser.parse_args(argv)
    out = pathlib.Path(args.out)
    shutil.rmtree(out, ignore_errors=True)
    dist = pathlib.Path(args.dist)
    fmus = sorted(dist.glob("*.fmu")) + sorted((dist / "fmi3").glob("*.fmu"))
    if not fmus:
        print(f"no .fmu in {args.dist}: build first (bash scripts/build.sh)")
        return 2
    runs = own_runs(fmus)
    for fmu in fmus:
        for folder, how in make(fmu, out, runs):
            version = folder.parts[-6]
            print(f"wrote {folder.relative_to(out)}: " + {
                "host": "fmpy, this machine's binary",
                "own": "its own binary (scripts/cross_check_platforms.py)",
                "copied": f"copied from {HOST[version]}: its binary does not run here"}[how])
    return 0


if __name__ == "__main__":
    sys.exit(main())
