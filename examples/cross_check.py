"""Results in the layout of the FMI Cross-Check (github.com/modelica/fmi-cross-check), and the
check that re-simulates them.

    fmus/<2.0|3.0>/<cs|me>/<platform>/<Tool_ID>/<version>/<Model>/
        <Model>.fmu  <Model>_in.csv  <Model>_ref.csv  <Model>_ref.opt  README.md

scripts/make_cross_check.py writes such a folder into dist/cross-check/; examples/ci_check.py
--cross-check DIR re-simulates every <Model>_in.csv under DIR with the FMU beside it (on this
machine's binary of it) and compares the columns of <Model>_ref.csv (which make_cross_check
computed with the folder's platform binary where that runs on the build machine: under wine or
qemu, scripts/cross_check_platforms.py; FMI 3.0: cross_check3.py;
an array's cell holds its elements separated by spaces). The call sequence (also that of the FMI4j
driver, examples/fmi4j/): set up, initialize, then at each row of <Model>_in.csv set the inputs
(after fmi2SetTime in Model Exchange), read the outputs, and in Co-Simulation step to the next
row's time (Model Exchange with continuous states: one explicit Euler step to it, so a second
importer can repeat the arithmetic).

Tolerance per value: |y - y_ref| <= ABSOLUTE + RELATIVE * |y_ref|, 1e-12 each; the FMUs compute
in double precision to ~1e-16, and the reference inputs keep every angle at least 0.5 rad from a
singular configuration."""
import csv
import pathlib
import shutil
import tempfile

import numpy as np
from fmpy import extract, read_model_description
from fmpy.fmi2 import FMU2Model, FMU2Slave

if __package__:  # examples.cross_check, in the repository
    from examples.cross_check3 import euler_step, simulate3
else:  # copied beside examples/ci_check.py, which imports it as a file of its folder
    from cross_check3 import euler_step, simulate3

RELATIVE = 1e-12
ABSOLUTE = 1e-12
START, STOP, STEP = 0.0, 4.0, 0.01


def reference_inputs(input_names, times):
    """Input k(0-based): 0.2 (k mod 3 + 1) + 0.6 sin((0.7 + 0.3 k) t + 0.5 k): smooth, distinct,
    and at most 1.4 rad in size, so that no angle comes near pi/2 (the Tait-Bryan singularity)."""
    k = np.arange(len(input_names))
    t = np.asarray(times)[:, None]
    return 0.2 * (k % 3 + 1) + 0.6 * np.sin((0.7 + 0.3 * k) * t + 0.5 * k)


def real_names(model_description, causality):
    return [v.name for v in model_description.modelVariables
            if v.type == "Real" and v.causality == causality]


def simulate(fmu, interface, times, input_names, inputs, output_names=None):
    """(output names, array len(times) x outputs) of the FMI 2 FMU ('cs' or 'me') over the inputs:
    the named outputs, by default every Real output."""
    description = read_model_description(fmu)
    vr = {v.name: v.valueReference for v in description.modelVariables}
    output_names = output_names or real_names(description, "output")
    unzipdir = extract(fmu, unzipdir=tempfile.mkdtemp())
    try:
        if interface == "cs":
            instance = FMU2Slave(guid=description.guid, unzipDirectory=unzipdir,
                                 modelIdentifier=description.coSimulation.modelIdentifier,
                                 instanceName="fmpy")
        else:
            instance = FMU2Model(guid=description.guid, unzipDirectory=unzipdir,
                                 modelIdentifier=description.modelExchange.modelIdentifier,
                                 instanceName="fmpy")
        states = description.numberOfContinuousStates
        instance.instantiate()
        instance.setupExperiment(startTime=times[0], stopTime=times[-1])
        instance.enterInitializationMode()
        instance.exitInitializationMode()
        if interface == "me":
            instance.newDiscreteStates()
            instance.enterContinuousTimeMode()
        input_vrs = [vr[n] for n in input_names]
        output_vrs = [vr[n] for n in output_names]
        outputs = np.empty((len(times), len(output_names)))
        for row, time in enumerate(times):
            if interface == "me":
                instance.setTime(time)
            instance.setReal(input_vrs, list(inputs[row]))  # fmpy raises on any status but OK
            outputs[row] = instance.getReal(output_vrs)
            if interface == "cs" and row + 1 < len(times):
                instance.doStep(currentCommunicationPoint=time,
                                communicationStepSize=times[row + 1] - time)
            if interface == "me" and states and row + 1 < len(times):
                # the same arithmetic as the FMI4j driver: the two agree bit for bit
                euler_step(instance, states, float(times[row + 1] - time), instance.getDerivatives)
        instance.terminate()
        instance.freeInstance()
    finally:
        shutil.rmtree(unzipdir, ignore_errors=True)
    return output_names, outputs


def write_csv(path, names, table):
    """The cross-check's CSV: quoted names, one row per time, numbers as C literals."""
    header = ",".join(f'"{name}"' for name in names)
    np.savetxt(path, table, delimiter=",", fmt="%.17g", header=header, comments="")


def read_csv(path):
    """(names, table); a cell of several numbers separated by spaces (an FMI 3 array) becomes
    the columns name[1], name[2], ..."""
    with open(path, newline="") as file:
        rows = list(csv.reader(file))
    cells = [[np.array(cell.split(), dtype=float) for cell in row] for row in rows[1:]]
    names = []
    for name, cell in zip(rows[0], cells[0]):
        names += [name] if len(cell) == 1 else [f"{name}[{k + 1}]" for k in range(len(cell))]
    return names, np.array([np.concatenate(row) for row in cells], ndmin=2)


def read_options(path):
    options = {}
    for line in pathlib.Path(path).read_text().splitlines():
        key, value = line.split(",")
        options[key.strip()] = float(value)
    return options


def check_model(folder, interface, fmi_version="2.0", label="", relative=RELATIVE,
                absolute=ABSOLUTE):
    """Re-simulates one <Model>/ folder; prints one line per deviating output and one summary
    line; returns 0 ok, 1 deviation beyond absolute + relative * |reference|."""
    model = folder.name
    in_names, inputs = read_csv(folder / f"{model}_in.csv")
    ref_names, reference = read_csv(folder / f"{model}_ref.csv")
    options = read_options(folder / f"{model}_ref.opt")
    times = inputs[:, 0]
    if abs(times[0] - options["StartTime"]) > 1e-12 or abs(times[-1] - options["StopTime"]) > 1e-12:
        print(f"{folder}: the time grid of {model}_in.csv does not span {model}_ref.opt's")
        return 1
    if len(reference) != len(times) or not np.array_equal(reference[:, 0], times):
        print(f"{folder}: {model}_ref.csv has other times than {model}_in.csv")
        return 1
    run = simulate if fmi_version == "2.0" else simulate3
    names, outputs = run(str(folder / f"{model}.fmu"), interface, times, in_names[1:],
                         inputs[:, 1:], ref_names[1:])
    status = 0
    for k, name in enumerate(names):
        deviation = np.abs(outputs[:, k] - reference[:, k + 1])
        ratio = deviation / (absolute + relative * np.abs(reference[:, k + 1]))
        worst = int(np.argmax(ratio))
        if ratio[worst] > 1:
            status = 1
            print(f"DIFFERENT {interface} {model} {name}: {deviation[worst]:.3g} at "
                  f"t = {times[worst]:g} s ({ratio[worst]:.3g} of the tolerance)")
    largest = float(np.max(np.abs(outputs - reference[:, 1:])))
    print(f"{'ok' if status == 0 else 'FAILED':>9} {fmi_version} {interface} {label} "
          f"{model}: {len(names)} outputs x {len(times)} rows, largest deviation {largest:.3g}")
    return status


def check_folder(root):
    """Every <Model>_ref.opt under root; FMI version and interface from its path
    (fmus/<version>/<cs|me>/<platform>/<Tool_ID>/<tool version>/<Model>)."""
    folders = sorted(path.parent for path in pathlib.Path(root).rglob("*_ref.opt"))
    if not folders:
        print(f"no *_ref.opt under {root}")
        return 2
    print(f"tolerance per value: {ABSOLUTE:g} + {RELATIVE:g} * |reference|")
    status = 0
    for folder in folders:
        fmi_version, interface = folder.parts[-6], folder.parts[-5]
        status = max(status, check_model(folder, interface, fmi_version, folder.parts[-4]))
    return status
