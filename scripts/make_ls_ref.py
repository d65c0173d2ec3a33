"""Writes the reference result an FMU carries in extra/org.fmi-standard.fmi-ls-ref/ by the layered
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
master of examples/cross_check.py, run by fmpy on the FMU as packaged without them: CMake packages
each FMU, runs this on it and packages it again with the files, so that they are what the
binary of the build computes, from a clean tree. `python examples/ci_check.py --ls-ref FMU`
re-simulates an FMU against the files it carries.

    .venv/bin/python -m scripts.make_ls_ref FMU FOLDER     (FOLDER is emptied first)"""
import argparse
import pathlib
import shutil
import sys

from examples.cross_check import RELATIVE, START, STEP, STOP
from examples.ls_ref import (DOCUMENT, EXPERIMENT_NAME, EXPERIMENTS_TYPE, LS_DESCRIPTION, LS_NAME,
                             LS_VERSION)
from scripts.make_cross_check import reference_run

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


def make(fmu, folder):
    description, write, inputs, outputs = reference_run(fmu, EXPERIMENT_NAME)
    model = description.modelName
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
    parser.add_argument("fmu", help="the FMU (without the files, or they are ignored)")
    parser.add_argument("folder", help="where to write the four files")
    args = parser.parse_args(argv)
    make(pathlib.Path(args.fmu), pathlib.Path(args.folder))
    return 0


if __name__ == "__main__":
    sys.exit(main())
