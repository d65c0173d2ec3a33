"""examples/ssp/Tumbling.ssp (make_tumbling_ssp.py) run by fmpy's SSP master, libcosim and Ecos from
the .ssp itself: each returns {"element.output": values after each of STEPS steps of STEP}."""
import numpy as np
from fmpy.ssp.ssd import Parameter, ParameterSet, read_ssd
from fmpy.ssp.simulation import simulate_ssp

from examples.engines import NANOSECONDS, STEP, STEPS
from examples.ssp.make_tumbling_ssp import BINDINGS, COMPONENTS, PARAMETER_SET, scalars


def outputs():
    """[(element, output variable)] of the system's components, as make_tumbling_ssp declares."""
    return [(element, scalar) for element, (_, _, names) in COMPONENTS.items()
            for name in names for scalar in scalars(name)]


def run_fmpy(ssp):
    # simulate_ssp leaves the .ssd's parameter bindings aside: hand them over, named by the
    # component's path as its parameter_set wants.
    parameters = ParameterSet(name=PARAMETER_SET)
    parameters.parameters = []
    for element in read_ssd(str(ssp)).system.elements:
        if element.name in BINDINGS:
            bound = element.parameterBindings[0].parameterValues[0].parameters
            parameters.parameters += [Parameter(name=f"{element.name}.{p.name}", type=p.type,
                                                value=p.value) for p in bound]
    result = simulate_ssp(str(ssp), stop_time=STEPS * STEP, step_size=STEP,
                          parameter_set=parameters)
    assert len(result) == STEPS  # row k: time t_k, the values after the step from t_k
    return {f"{e}.{n}": np.asarray(result[f"{e}.{n}"], dtype=float) for e, n in outputs()}


def run_libcosim(ssp):
    from libcosimpy.CosimExecution import CosimExecution
    from libcosimpy.CosimLogging import CosimLogLevel, log_output_level
    from libcosimpy.CosimObserver import CosimObserver

    log_output_level(CosimLogLevel.WARNING)
    execution = CosimExecution.from_ssp_file(str(ssp), step_size=NANOSECONDS)
    observer = CosimObserver.create_last_value()
    assert execution.add_observer(observer)
    index = {info.name.decode(): info.index for info in execution.slave_infos()}
    refs = {element: {v.name.decode(): v.reference for v in execution.slave_variables(i)}
            for element, i in index.items()}
    values = {f"{e}.{n}": np.empty(STEPS) for e, n in outputs()}
    for k in range(STEPS):
        assert execution.step(), f"libcosim failed at step {k}"
        for element, name in outputs():
            values[f"{element}.{name}"][k] = observer.last_real_values(
                index[element], [refs[element][name]])[0]
    return values


def run_ecos(ssp):
    from ecospy import EcosLib, EcosSimulation

    EcosLib.set_log_level("warn")
    simulation = EcosSimulation(ssp_path=str(ssp), step_size=STEP)
    try:
        assert simulation.init(0.0, PARAMETER_SET)  # Ecos applies a parameter set init names
        values = {f"{e}.{n}": np.empty(STEPS) for e, n in outputs()}
        for k in range(STEPS):
            simulation.step(1)
            for element, name in outputs():
                values[f"{element}.{name}"][k] = simulation.get_real(f"{element}::{name}")
        simulation.terminate()
    finally:
        simulation.free()
    return values


RUNNERS = {"fmpy": run_fmpy, "libcosim": run_libcosim, "Ecos": run_ecos}


# What the masters do differently, so rows are compared as follows (docs/cosimulation.md):
# - the first START rows: fmpy starts every connected input at 0.0 while libcosim and Ecos hand the
#   outputs of the initialization over: they differ, and are left out;
# - Ecos reads the outputs after it has handed the step's outputs to the inputs, so the outputs of
#   an algebraic component (kinematics, rates) already answer the next step's inputs: its row k is
#   fmpy's row k + 1 (SHIFT); the propagator's outputs depend on its state and its held omega only.
START = 2
SHIFT = {"fmpy": 0, "libcosim": 0, "Ecos": 1}


def compare(engine, values, reference):
    """(values compared, values differing in any bit, largest |difference|) of an engine's run
    against fmpy's, rows START to the end of fmpy's run."""
    got, expected = [], []
    for name, column in reference.items():
        shift = 0 if name.startswith("propagator.") else SHIFT[engine]
        got.append(values[name][START - shift:STEPS - shift])
        expected.append(column[START:])
    got, expected = np.array(got), np.array(expected)
    differing = int(np.count_nonzero(got.view(np.int64) != expected.view(np.int64)))
    return got.size, differing, float(np.max(np.abs(got - expected)))
