"""The call sequence of cross_check.py for an FMI 3.0 FMU (fmpy's FMU3Slave and FMU3Model): set
up, initialize, then at each row set the inputs (after fmi3SetTime in Model Exchange), read the
outputs, and in Co-Simulation step to the next row's time (Model Exchange with continuous states:
one explicit Euler step to it). Names are element names: theta[2] is element 2 of the array theta,
a name without brackets a scalar; the inputs are whole arrays, in order."""
import ctypes
import re
import shutil
import tempfile

import numpy as np
from fmpy import extract, read_model_description
from fmpy.fmi3 import FMU3Model, FMU3Slave


def element(name):
    """('theta', 1) for theta[2], ('rotation_angle', 0) for a scalar."""
    match = re.fullmatch(r"(.+)\[(\d+)\]", name)
    return (match.group(1), int(match.group(2)) - 1) if match else (name, 0)


def arrays(names):
    """The arrays of the element names, each once, in order of appearance."""
    return list(dict.fromkeys(element(name)[0] for name in names))


def sizes(description):
    return {v.name: int(np.prod([int(d.start) for d in v.dimensions])) if v.dimensions else 1
            for v in description.modelVariables}


def instantiate(description, unzipdir, interface):
    cls, info = ((FMU3Slave, description.coSimulation) if interface == "cs"
                 else (FMU3Model, description.modelExchange))
    instance = cls(guid=description.guid, unzipDirectory=unzipdir,
                   modelIdentifier=info.modelIdentifier, instanceName="fmpy")
    instance.instantiate()
    return instance


def euler_step(instance, states, h, derivatives):
    """One explicit Euler step of the continuous states, element by element in doubles (the FMI4j
    driver does the same arithmetic); derivatives: the instance's getDerivatives (FMI 2) or
    getContinuousStateDerivatives (FMI 3)."""
    x, dx = (ctypes.c_double * states)(), (ctypes.c_double * states)()
    instance.getContinuousStates(x, states)
    derivatives(dx, states)
    for k in range(states):
        x[k] = x[k] + h * dx[k]
    instance.setContinuousStates(x, states)
    instance.completedIntegratorStep()


def layout(description, input_names, output_names):
    """What simulate3 sets and gets: (value references of the input arrays, of the output arrays,
    the number of output values, the index of each named output element among them)."""
    vr = {v.name: v.valueReference for v in description.modelVariables}
    size = sizes(description)
    in_arrays, out_arrays = arrays(input_names), arrays(output_names)
    offset = dict(zip(out_arrays, np.cumsum([0] + [size[a] for a in out_arrays])))
    picks = [int(offset[base] + k) for base, k in map(element, output_names)]
    return ([vr[a] for a in in_arrays], [vr[a] for a in out_arrays],
            int(sum(size[a] for a in out_arrays)), picks)


def simulate3(fmu, interface, times, input_names, inputs, output_names):
    """(output_names, array len(times) x outputs) of the FMI 3 FMU ('cs' or 'me')."""
    description = read_model_description(fmu)
    in_vrs, out_vrs, n_out, picks = layout(description, input_names, output_names)
    unzipdir = extract(fmu, unzipdir=tempfile.mkdtemp())
    try:
        instance = instantiate(description, unzipdir, interface)
        states = description.numberOfContinuousStates
        instance.enterInitializationMode(startTime=times[0], stopTime=times[-1])
        instance.exitInitializationMode()
        if interface == "me":
            instance.updateDiscreteStates()
            instance.enterContinuousTimeMode()
        outputs = np.empty((len(times), len(output_names)))
        for row, time in enumerate(times):
            if interface == "me":
                instance.setTime(time)
            instance.setFloat64(in_vrs, list(inputs[row]))
            values = instance.getFloat64(out_vrs, nValues=n_out)
            outputs[row] = np.asarray(values)[picks]
            if row + 1 < len(times):
                h = float(times[row + 1] - time)
                if interface == "cs":
                    instance.doStep(currentCommunicationPoint=time, communicationStepSize=h)
                elif states:
                    euler_step(instance, states, h,
                               instance.getContinuousStateDerivatives)
        instance.terminate()
        instance.freeInstance()
    finally:
        shutil.rmtree(unzipdir, ignore_errors=True)
    return list(output_names), outputs


def write_csv3(path, names, table):
    """The CSV of an FMI 3 result: one quoted column per array, its elements in one cell
    separated by spaces (the array convention of fmi-standard.org's CSV rules and of fmpy's
    write_csv); names are element names as for simulate3, table their columns after time."""
    groups = arrays(names[1:])
    with open(path, "w") as file:
        file.write(",".join(f'"{name}"' for name in ["time"] + groups) + "\n")
        for row in table:
            cells = {base: [] for base in groups}
            for name, value in zip(names[1:], row[1:]):
                cells[element(name)[0]].append(f"{value:.17g}")
            file.write(",".join([f"{row[0]:.17g}"] + [" ".join(cells[b]) for b in groups]) + "\n")
