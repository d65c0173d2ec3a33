"""One Co-Simulation scenario run by three masters: fmpy (simulate_fmu), libcosim (PyPI libcosimpy)
and Ecos (PyPI ecospy), each returning the outputs after every step.

The scenario: STEPS steps of STEP = 2**-6 s from 0; before step k every Real input is set to the
cross-check's reference input (examples/cross_check.py) at t_k = k STEP and held over the step. Each
master sets the inputs, calls doStep(t_k, STEP) and reads the outputs: row k holds the outputs at
t_(k+1). STEP is a power of two so that t_k, the step sizes and libcosim's nanosecond clock are
exact in doubles in every master. fmpy gets the inputs as a table with two rows per t_k (the
previous value, then the new one): an input event at each t_k, so it sets the table's values
themselves rather than interpolated ones; no master sets input derivatives."""
import pathlib
import re
import zipfile

import numpy as np
from fmpy import read_model_description, simulate_fmu

from examples.cross_check import real_names, reference_inputs

ROOT = pathlib.Path(__file__).resolve().parents[1]

STEP = 2.0 ** -6
STEPS = 100
NANOSECONDS = round(STEP * 1e9)  # 15625000: libcosim's clock counts whole nanoseconds
assert NANOSECONDS / 1e9 == STEP


def fmi_version(fmu):
    with zipfile.ZipFile(fmu) as archive:
        return re.search(rb'fmiVersion="([^"]*)"', archive.read("modelDescription.xml")).group(1).decode()


def scenario(fmu):
    """(input names, output names, inputs: STEPS x inputs) of an FMU, in the FMI 2 names of its
    model (theta[1], ...): an FMI 3 FMU's importer has to map them to its arrays."""
    fmu = pathlib.Path(fmu)
    if fmi_version(fmu) != "2.0":
        fmu = ROOT / "dist" / f"{fmu.stem}.fmu"
    description = read_model_description(str(fmu))
    inputs = real_names(description, "input")
    times = np.arange(STEPS) * STEP
    return inputs, real_names(description, "output"), reference_inputs(inputs, times)


def run_fmpy(fmu):
    input_names, output_names, inputs = scenario(fmu)
    times = np.arange(STEPS) * STEP
    # Two rows per t_k (value before, value from t_k on): fmpy applies the value after the event.
    rows = [(0.0, *inputs[0])]
    for k in range(1, STEPS):
        rows += [(times[k], *inputs[k - 1]), (times[k], *inputs[k])]
    signals = np.array(rows, dtype=[("time", float)] + [(name, float) for name in input_names])
    result = simulate_fmu(str(fmu), fmi_type="CoSimulation", stop_time=STEPS * STEP,
                          output_interval=STEP, input=signals, output=output_names)
    assert np.array_equal(result["time"], np.arange(STEPS + 1) * STEP)
    return output_names, np.column_stack([result[name][1:] for name in output_names])


def run_libcosim(fmu):
    from libcosimpy.CosimExecution import CosimExecution
    from libcosimpy.CosimLogging import CosimLogLevel, log_output_level
    from libcosimpy.CosimManipulator import CosimManipulator
    from libcosimpy.CosimObserver import CosimObserver
    from libcosimpy.CosimSlave import CosimLocalSlave
    from libcosimpy._internal import get_last_error_message

    log_output_level(CosimLogLevel.WARNING)  # its default traces every FMI call
    input_names, output_names, inputs = scenario(fmu)
    execution = CosimExecution.from_step_size(NANOSECONDS)
    local = CosimLocalSlave(fmu_path=str(fmu), instance_name="fmu")
    if not local.ptr():  # libcosimpy passes a NULL slave on, and libcosim crashes on it
        raise RuntimeError(get_last_error_message())
    slave = execution.add_local_slave(local)
    vr = {v.name.decode(): v.reference for v in execution.slave_variables(slave)}
    manipulator = CosimManipulator.create_override()
    observer = CosimObserver.create_last_value()
    assert execution.add_manipulator(manipulator) and execution.add_observer(observer)
    input_vrs, output_vrs = [vr[n] for n in input_names], [vr[n] for n in output_names]
    outputs = np.empty((STEPS, len(output_names)))
    for k in range(STEPS):
        assert manipulator.slave_real_values(slave, input_vrs, list(inputs[k]))
        assert execution.step(), f"libcosim failed at step {k}"
        outputs[k] = observer.last_real_values(slave, output_vrs)
    assert execution.status().current_time == STEPS * NANOSECONDS
    return output_names, outputs


def run_ecos(fmu):
    from ecospy import EcosLib, EcosSimulation, EcosSimulationStructure

    EcosLib.set_log_level("warn")
    input_names, output_names, inputs = scenario(fmu)
    structure = EcosSimulationStructure()
    structure.add_model("fmu", str(fmu))
    simulation = EcosSimulation(structure=structure, step_size=STEP)
    try:
        assert simulation.init(0.0) is not False
        outputs = np.empty((STEPS, len(output_names)))
        for k in range(STEPS):
            for name, value in zip(input_names, inputs[k]):
                simulation.set_real(f"fmu::{name}", float(value))
            simulation.step(1)
            outputs[k] = [simulation.get_real(f"fmu::{name}") for name in output_names]
        assert simulation.get_time() == STEPS * STEP
        simulation.terminate()
    finally:
        simulation.free()
        structure.free()
    return output_names, outputs


RUNNERS = {"libcosim": run_libcosim, "Ecos": run_ecos}
