"""Writes fmu_src/models/<Model>/ls_ref/ (FMI 2) and fmu_src/models/<Model>/fmi3/ls_ref/ (FMI 3):
the reference result each FMU carries in extra/org.fmi-standard.fmi-ls-ref/ by the layered
standard FMI-LS-REF (github.com/modelica/fmi-ls-ref; fmi-ls-version 1.0.0-alpha.1, the version its
specification names). The manifest fmi-ls-manifest.xml relates each file by its role:

    <Model>.exp        experiment  the experiment's settings (start, stop, step, the master, the
                                   comparison tolerance) and its inputs and result, in the
                                   experiments format of FMI-LS-REF 1.0.0-alpha.1 (MIME type
                                   application/x-ma-ls-experiments)
    <Model>_in.csv     testcase    the inputs
    <Model>_out.csv    result      the result
    ../../documentation/index.html  document  the FMU's page

The experiment is the cross-check's (scripts/make_cross_check.py), in Co-Simulation with the
master of examples/cross_check.py. CMake copies the files into the FMU;
`python examples/ci_check.py --ls-ref FMU` re-simulates an FMU against the files it carries.

    .venv/bin/python scripts/make_ls_ref.py [--dist DIR] [--out DIR]
--out DIR writes DIR/<fmi2|fmi3>/<Model>/ instead (the test compares a fresh run with it)."""
import argparse
import pathlib
import shutil
import sys

from examples.cross_check import RELATIVE, START, STEP, STOP
from examples.ls_ref import (DOCUMENT, EXPERIMENT_NAME, EXPERIMENTS_TYPE, LS_DESCRIPTION, LS_NAME,
                             LS_VERSION)
from scripts.make_cross_check import ROOT, reference_run

MANIFEST = """<?xml version="1.0" encoding="UTF-8"?>
<fmiReferences
    xmlns:fmi-ls="http://fmi-standard.org/fmi-ls-manifest"
    fmi-ls:fmi-ls-name="{name}"
    fmi-ls:fmi-ls-version="{version}"
    fmi-ls:fmi-ls-description="{description}">
    <Related type="{experiments_type}" source="{model}.exp" role="experiment" description="The reference experiment: its settings, inputs and result"/>
    <Related type="text/csv" source="{model}_in.csv" role="testcase" description="Inputs of the reference experiment"/>
    <Related type="text/csv" source="{model}_out.csv" role="result" description="Result of the reference experiment"/>
    <Related type="text/html" source="{document}" role="document" description="The FMU's documentation"/>
</fmiReferences>
"""
# The tolerance is the comparison's: every value y of the result must satisfy
# |y - y_reference| <= tolerance * (1 + |y_reference|): cross_check.py's RELATIVE and ABSOLUTE,
# which are equal (tests/python/test_ls_ref.py checks).
EXPERIMENTS = """<?xml version="1.0" encoding="UTF-8"?>
<Experiments name="{model} reference" description="The experiment that made {model}_out.csv. Every value y of a rerun must satisfy |y - y_reference| &lt;= tolerance * (1 + |y_reference|).">
    <Experiment name="{experiment}" description="Co-Simulation (cs), fixed step, the master of examples/cross_check.py: set up, initialize, then at each row of {model}_in.csv set the inputs and read the outputs, and step to the next row's time"
        startTime="{start!r}" stopTime="{stop!r}" stepSize="{step!r}" tolerance="{tolerance!r}">
        <Stimuli type="text/csv" source="{model}_in.csv"/>
        <References type="text/csv" source="{model}_out.csv"/>
    </Experiment>
</Experiments>
"""


def model_folder(version, model):
    """Where a model's reference result is kept: its model folder, FMI 2 or FMI 3 part."""
    return ROOT / "fmu_src" / "models" / model / ("ls_ref" if version == "fmi2" else "fmi3/ls_ref")


def make(fmu, out=None):
    description, write, inputs, outputs = reference_run(fmu, EXPERIMENT_NAME)
    model = description.modelName
    version = "fmi2" if description.fmiVersion == "2.0" else "fmi3"
    folder = out / version / model if out is not None else model_folder(version, model)
    shutil.rmtree(folder, ignore_errors=True)
    folder.mkdir(parents=True)
    write(folder / f"{model}_in.csv", *inputs)
    write(folder / f"{model}_out.csv", *outputs)
    (folder / f"{model}.exp").write_text(EXPERIMENTS.format(
        model=model, experiment=EXPERIMENT_NAME, start=START, stop=STOP, step=STEP,
        tolerance=RELATIVE))
    (folder / "fmi-ls-manifest.xml").write_text(MANIFEST.format(
        name=LS_NAME, version=LS_VERSION, description=LS_DESCRIPTION, model=model,
        experiments_type=EXPERIMENTS_TYPE, document=DOCUMENT))
    return folder


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--dist", default=str(ROOT / "dist"))
    parser.add_argument("--out")
    args = parser.parse_args(argv)
    dist = pathlib.Path(args.dist)
    out = pathlib.Path(args.out) if args.out else None
    fmus = sorted(dist.glob("*.fmu")) + sorted((dist / "fmi3").glob("*.fmu"))
    if not fmus:
        print(f"no .fmu in {dist}: build first (bash scripts/build.sh)")
        return 2
    for fmu in fmus:
        print(f"wrote {make(fmu, out).relative_to(out if out is not None else ROOT)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
