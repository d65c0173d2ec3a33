"""Writes dist/cross-check/: every stateless FMI 2 FMU of dist/ with its reference inputs and our own
results, per interface, in the layout of the FMI Cross-Check (examples/cross_check.py describes it).
An FMU with continuous states (AttitudePropagator) is left out, and said so: its outputs are not a
function of each row's inputs, which is what this layout's README promises.

    .venv/bin/python scripts/make_cross_check.py [--dist DIR] [--out DIR]"""
import argparse
import pathlib
import shutil
import sys

import numpy as np
from fmpy import read_model_description

ROOT = pathlib.Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "examples"))
sys.path.insert(0, str(ROOT))
from codegen.project import VERSION  # noqa: E402
from cross_check import (START, STEP, STOP, real_names, reference_inputs, simulate,  # noqa: E402
                         write_csv)

README = """# {model} ({interface}), AngularKinematics {version}

Made by scripts/make_cross_check.py from dist/{model}.fmu. {model}_in.csv holds the inputs at
every communication point (StepSize {step} s from {start} to {stop} s); {model}_ref.csv every Real
output of the FMU at that point, computed by the FMU itself through fmpy with this call sequence:
set up and initialize, then at each row set the inputs{me_note}, read the outputs{cs_note}. The model
has no state: each output row is its function of that row's inputs alone, so any master that sets
a row's inputs and reads the outputs at the same time must get these numbers to within
1e-12 + 1e-12 |reference| (`python examples/ci_check.py --cross-check DIR` checks that).
"""


def make(fmu, out):
    description = read_model_description(str(fmu))
    model = description.modelName
    if description.fmiVersion != "2.0":
        return []
    if description.numberOfContinuousStates:
        print(f"skipped {fmu.name}: {description.numberOfContinuousStates} continuous states, its "
              "outputs are not a function of each row's inputs alone")
        return []
    times = np.round(np.arange(START, STOP + STEP / 2, STEP), 12)
    input_names = real_names(description, "input")
    inputs = reference_inputs(input_names, times)
    written = []
    for interface, present in (("cs", description.coSimulation),
                               ("me", description.modelExchange)):
        if present is None:
            continue
        folder = out / "fmus" / "2.0" / interface / "linux64" / "AngularKinematics" / VERSION / model
        folder.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(fmu, folder / f"{model}.fmu")
        write_csv(folder / f"{model}_in.csv", ["time"] + input_names,
                  np.column_stack([times, inputs]))
        names, outputs = simulate(str(fmu), interface, times, input_names, inputs)
        write_csv(folder / f"{model}_ref.csv", ["time"] + names, np.column_stack([times, outputs]))
        (folder / f"{model}_ref.opt").write_text(
            f"StartTime, {START}\nStopTime, {STOP}\nStepSize, {STEP}\nRelTol, 0\n")
        (folder / "ReadMe.md").write_text(README.format(
            model=model, interface={"cs": "Co-Simulation", "me": "Model Exchange"}[interface],
            version=VERSION, step=STEP, start=START, stop=STOP,
            me_note=" (after fmi2SetTime)" if interface == "me" else "",
            cs_note=", then fmi2DoStep to the next row" if interface == "cs" else ""))
        written.append(folder)
    return written


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--dist", default=str(ROOT / "dist"))
    parser.add_argument("--out", default=str(ROOT / "dist" / "cross-check"))
    args = parser.parse_args(argv)
    out = pathlib.Path(args.out)
    shutil.rmtree(out, ignore_errors=True)
    fmus = sorted(pathlib.Path(args.dist).glob("*.fmu"))
    if not fmus:
        print(f"no .fmu in {args.dist}: build first (bash scripts/build.sh)")
        return 2
    for fmu in fmus:
        for folder in make(fmu, out):
            print(f"wrote {folder.relative_to(out)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
