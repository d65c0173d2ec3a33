"""Writes fmu_src/models/<Model>/ls_ref/ (FMI 2) and fmu_src/models/<Model>/fmi3/ls_ref/ (FMI 3):
the reference result each FMU carries in
extra/org.fmi-standard.fmi-ls-ref/ (the layered standard FMI-LS-REF, version 1.0.0-alpha.1, as the
Reference FMUs carry theirs since v0.0.41): fmi-ls-manifest.xml, <Model>_in.csv (the inputs) and
<Model>_out.csv (the result). The experiment is the cross-check's (scripts/make_cross_check.py), in
Co-Simulation with the master of examples/cross_check.py. CMake copies the files into the FMU;
`python examples/ci_check.py --ls-ref FMU` re-simulates an FMU against the files it carries.

    .venv/bin/python scripts/make_ls_ref.py [--dist DIR] [--out DIR]
--out DIR writes DIR/<fmi2|fmi3>/<Model>/ instead (the test compares a fresh run with it)."""
import argparse
import pathlib
import shutil
import sys

from examples.cross_check import START, STEP, STOP
from scripts.make_cross_check import ROOT, reference_run

LS_NAME, LS_VERSION = "org.fmi-standard.fmi-ls-ref", "1.0.0-alpha.1"
# The draft's root attribute (github.com/modelica/fmi-ls-ref, schema/...ReferenceManifest.xsd).
LS_DESCRIPTION = "Layered Standard providing reference stimuli and results for an FMU."
MANIFEST = """<?xml version="1.0" encoding="UTF-8"?>
<fmiReferences
    xmlns:fmi-ls="http://fmi-standard.org/fmi-ls-manifest"
    fmi-ls:fmi-ls-name="{name}"
    fmi-ls:fmi-ls-version="{version}"
    fmi-ls:fmi-ls-description="{description}">
    <Experiment name="reference" description="{experiment}"
        startTime="{start}" stopTime="{stop}" stepSize="{step}">
        <Stimuli type="text/csv" source="{model}_in.csv"/>
        <References type="text/csv" source="{model}_out.csv"/>
    </Experiment>
    <Related type="text/csv" source="{model}_in.csv" role="testcase" description="Input of the reference experiment"/>
    <Related type="text/csv" source="{model}_out.csv" role="result" description="Output of the reference experiment"/>
</fmiReferences>
"""
EXPERIMENT = ("Co-Simulation, fixed step: at each row of {model}_in.csv set the inputs, read the "
              "outputs of {model}_out.csv, step to the next row")


def model_folder(version, model):
    """Where a model's reference result is kept: its model folder, FMI 2 or FMI 3 part."""
    return ROOT / "fmu_src" / "models" / model / ("ls_ref" if version == "fmi2" else "fmi3/ls_ref")


def make(fmu, out=None):
    description, write, inputs, outputs = reference_run(fmu, "cs")
    model = description.modelName
    version = "fmi2" if description.fmiVersion == "2.0" else "fmi3"
    folder = out / version / model if out is not None else model_folder(version, model)
    shutil.rmtree(folder, ignore_errors=True)
    folder.mkdir(parents=True)
    write(folder / f"{model}_in.csv", *inputs)
    write(folder / f"{model}_out.csv", *outputs)
    (folder / "fmi-ls-manifest.xml").write_text(MANIFEST.format(
        name=LS_NAME, version=LS_VERSION, description=LS_DESCRIPTION, model=model,
        experiment=EXPERIMENT.format(model=model), start=START, stop=STOP, step=STEP))
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
