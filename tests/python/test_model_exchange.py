"""Model exchange: the same FMU through fmi2ModelExchange, with zero continuous states and zero
event indicators, gives the co-simulation outputs, and its state machine is enforced (for every
model: the `model` fixture)."""
import ctypes

import numpy as np
import pytest
from fmpy import simulate_fmu
from fmpy.fmi2 import fmi2EventInfo

from codegen import reference
from demo import trajectories

C = ctypes
# Prototypes of the functions of the other interface, which fmpy does not load for an instance.
PROTOTYPES = {
    "fmi2DoStep": (C.c_void_p, C.c_double, C.c_double, C.c_int),
    "fmi2SetRealInputDerivatives": (C.c_void_p, C.c_void_p, C.c_size_t, C.c_void_p, C.c_void_p),
    "fmi2GetRealOutputDerivatives": (C.c_void_p, C.c_void_p, C.c_size_t, C.c_void_p, C.c_void_p),
    "fmi2GetRealStatus": (C.c_void_p, C.c_int, C.c_void_p),
    "fmi2EnterEventMode": (C.c_void_p,),
    "fmi2SetTime": (C.c_void_p, C.c_double),
    "fmi2GetDerivatives": (C.c_void_p, C.c_void_p, C.c_size_t),
    "fmi2GetNominalsOfContinuousStates": (C.c_void_p, C.c_void_p, C.c_size_t),
}


def call_other_interface(instance, function, *args):
    prototype = C.CFUNCTYPE(C.c_int, *PROTOTYPES[function])
    return prototype((function, instance.fmu.dll))(instance.component, *args)

INPUTS = dict(zip(reference.INPUT_NAMES, [0.3, -0.7, 1.1, 0.5, -1.5, 2.0, 3.0, -0.25, 0.8]))
STEP = 1e-2
STOP = 2.0


def expected_outputs(inputs):
    return reference.outputs([inputs[n] for n in reference.INPUT_NAMES])


@pytest.fixture(scope="module")
def simulations(fmu_path):
    times = np.arange(0.0, STOP + STEP / 2, STEP)
    signals = trajectories.input_signals(times)
    names = reference.INPUT_NAMES + reference.OUTPUT_NAMES
    common = dict(stop_time=STOP, output_interval=STEP, input=signals, output=names)
    me = simulate_fmu(fmu_path, fmi_type="ModelExchange", **common)
    cs = simulate_fmu(fmu_path, fmi_type="CoSimulation", **common)
    return times, signals, me, cs


def test_simulate_fmu_model_exchange_gives_the_co_simulation_outputs(simulations, report):
    times, signals, me, cs = simulations
    assert np.allclose(me["time"], times, atol=1e-12)
    assert np.allclose(cs["time"], times, atol=1e-12)
    # fmpy's model-exchange loop samples after setting the inputs of t: row k holds the inputs
    # of grid point k. Its co-simulation loop samples after the step from t: row k + 1 holds them.
    for name in reference.INPUT_NAMES:
        assert np.array_equal(me[name], signals[name])
        assert np.array_equal(cs[name][1:], signals[name][:-1])
    for name in reference.OUTPUT_NAMES:
        assert np.array_equal(me[name][:-1], cs[name][1:]), name
    # And both are the kinematics of the inputs they hold.
    worst = 0.0
    for row in me[::10]:
        inputs = [row[n] for n in reference.INPUT_NAMES]
        got = np.array([row[n] for n in reference.OUTPUT_NAMES])
        expected = reference.outputs(inputs)
        worst = max(worst, (np.abs(got - expected) / (1.0 + np.abs(expected))).max())
    report(f"{len(me)} rows bitwise equal to co-simulation; worst error vs reference {worst:.1e}")
    assert worst < 1e-14


def walk_to(instance, state):
    """Brings a model-exchange instance from Instantiated to the given state."""
    if state == "Instantiated":
        return
    instance.fmu.setupExperiment(startTime=0.0)
    instance.fmu.enterInitializationMode()
    if state == "InitializationMode":
        return
    instance.fmu.exitInitializationMode()
    if state == "EventMode":
        return
    instance.fmu.enterContinuousTimeMode()
    if state == "ContinuousTimeMode":
        return
    instance.fmu.terminate()
    assert state == "Terminated"


def test_full_model_exchange_run_by_hand(make_instance):
    instance = make_instance(fmi_type="ModelExchange", logging_on=True)
    assert instance.set(INPUTS) == 0  # inputs may be set in Instantiated
    instance.fmu.setupExperiment(startTime=1.0)
    instance.fmu.enterInitializationMode()
    instance.fmu.exitInitializationMode()  # into EventMode
    info = instance.fmu.newDiscreteStates()
    assert info == (False, False, False, False, False, 0.0)
    instance.fmu.enterContinuousTimeMode()
    assert np.allclose(instance.get(reference.OUTPUT_NAMES), expected_outputs(INPUTS), rtol=1e-14)
    changed = dict(INPUTS)
    for k, t in enumerate(np.linspace(1.0, 2.0, 11)[1:]):
        instance.fmu.setTime(t)
        changed["theta[2]"] = 0.1 * k
        changed["theta_ddot[1]"] = -k
        assert instance.set(changed) == 0  # continuous inputs in ContinuousTimeMode
        for function in ("fmi2GetDerivatives", "fmi2GetContinuousStates", "fmi2GetEventIndicators"):
            assert instance.call(function, None, 0) == 0
        assert instance.fmu.completedIntegratorStep() == (False, False)
        # Direct feedthrough: the outputs follow the inputs at once.
        assert np.allclose(instance.get(reference.OUTPUT_NAMES), expected_outputs(changed), rtol=1e-14)
    instance.fmu.enterEventMode()
    assert instance.set(INPUTS) == 0  # inputs in EventMode
    instance.fmu.newDiscreteStates()
    instance.fmu.enterContinuousTimeMode()
    instance.fmu.terminate()
    assert np.allclose(instance.get(reference.OUTPUT_NAMES), expected_outputs(INPUTS), rtol=1e-14)
    assert instance.errors() == []
    assert "fmi2SetTime: time = 2" in [m for _, _, m in instance.messages]


ILLEGAL = [
    ("Instantiated", "fmi2EnterEventMode", ()),
    ("Instantiated", "fmi2SetTime", (0.5,)),
    ("Instantiated", "fmi2GetDerivatives", (None, 0)),
    ("InitializationMode", "fmi2EnterContinuousTimeMode", ()),
    ("InitializationMode", "fmi2Terminate", ()),
    ("InitializationMode", "fmi2GetDerivatives", (None, 0)),
    ("EventMode", "fmi2CompletedIntegratorStep", (1, ctypes.byref(ctypes.c_int()), ctypes.byref(ctypes.c_int()))),
    ("EventMode", "fmi2SetContinuousStates", (None, 0)),
    ("EventMode", "fmi2ExitInitializationMode", ()),
    ("ContinuousTimeMode", "fmi2NewDiscreteStates", (ctypes.byref(fmi2EventInfo()),)),
    ("ContinuousTimeMode", "fmi2EnterContinuousTimeMode", ()),
    ("ContinuousTimeMode", "fmi2EnterInitializationMode", ()),
    ("Terminated", "fmi2SetReal", ((ctypes.c_uint * 1)(0), 1, (ctypes.c_double * 1)(1.0))),
    ("Terminated", "fmi2EnterEventMode", ()),
    ("Terminated", "fmi2SetTime", (3.0,)),
]


@pytest.mark.parametrize("state,function,args", ILLEGAL)
def test_illegal_model_exchange_calls_are_refused(state, function, args, make_model_instance):
    instance = make_model_instance(fmi_type="ModelExchange")
    walk_to(instance, state)
    before = instance.snapshot()
    assert instance.call(function, *args) == 3
    assert instance.errors() == [f"{function}: illegal call in state {state}"]
    assert instance.snapshot() == before
    # The state is unchanged: a call legal there still works.
    legal = {"Instantiated": ("fmi2SetupExperiment", (0, 0.0, 0.0, 0, 0.0)),
             "InitializationMode": ("fmi2ExitInitializationMode", ()),
             "EventMode": ("fmi2EnterContinuousTimeMode", ()),
             "ContinuousTimeMode": ("fmi2SetTime", (0.25,)),
             "Terminated": ("fmi2Reset", ())}[state]
    assert instance.call(legal[0], *legal[1]) == 0


@pytest.mark.parametrize("function,args", [
    ("fmi2DoStep", (0.0, 0.1, 1)),
    ("fmi2SetRealInputDerivatives", (None, 0, None, None)),
    ("fmi2GetRealOutputDerivatives", (None, 0, None, None)),
    ("fmi2GetRealStatus", (2, ctypes.byref(ctypes.c_double()))),
])
def test_co_simulation_functions_are_refused_on_model_exchange_instances(function, args,
                                                                          make_model_instance):
    instance = make_model_instance(fmi_type="ModelExchange")
    walk_to(instance, "EventMode")
    before = instance.snapshot()
    status = call_other_interface(instance, function, *args)
    assert status == 3
    assert instance.snapshot() == before
    assert instance.errors() == [f"{function}: a co-simulation function, but this instance was "
                                 "created for model exchange (fmi2ModelExchange)"]


@pytest.mark.parametrize("function,args", [
    ("fmi2EnterEventMode", ()),
    ("fmi2SetTime", (0.5,)),
    ("fmi2GetDerivatives", (None, 0)),
    ("fmi2GetNominalsOfContinuousStates", (None, 0)),
])
def test_model_exchange_functions_are_refused_on_co_simulation_instances(function, args,
                                                                          make_model_instance):
    instance = make_model_instance()
    instance.initialize()
    before = instance.snapshot()
    status = call_other_interface(instance, function, *args)
    assert status == 3
    assert instance.snapshot() == before
    assert instance.errors() == [f"{function}: a model-exchange function, but this instance was "
                                 "created for co-simulation (fmi2CoSimulation)"]
    assert instance.call("fmi2DoStep", 0.0, 0.1, 1) == 0


@pytest.mark.parametrize("function,name", [
    ("fmi2GetDerivatives", "nx"), ("fmi2GetContinuousStates", "nx"),
    ("fmi2SetContinuousStates", "nx"), ("fmi2GetEventIndicators", "ni"),
    ("fmi2GetNominalsOfContinuousStates", "nx"),
])
def test_state_and_indicator_arrays_must_have_the_described_length(function, name, model,
                                                                    make_model_instance):
    """Event-indicator arrays must be empty; state arrays must hold numberOfContinuousStates
    elements (empty for a model without states)."""
    states = model.description.numberOfContinuousStates
    length = 0 if name == "ni" else states
    instance = make_model_instance(fmi_type="ModelExchange")
    walk_to(instance, "ContinuousTimeMode")
    buffer = (ctypes.c_double * (length + 1))(*([1.0] * (length + 1)))
    before = instance.snapshot()
    assert instance.call(function, buffer, length + 1) == 3
    assert instance.snapshot() == before
    if length == 0:
        kinds = "no event indicators" if states else "no continuous states and no event indicators"
        expected = f"{function}: {name} = 1, but this FMU has {kinds} ({name} must be 0)"
    else:
        expected = (f"{function}: nx = {length + 1}, but this FMU has {states} continuous states "
                    "(numberOfContinuousStates)")
    assert instance.errors() == [expected]
    assert instance.call(function, buffer, length) == 0


def test_null_and_non_finite_arguments(make_model_instance):
    instance = make_model_instance(fmi_type="ModelExchange")
    walk_to(instance, "EventMode")
    before = instance.snapshot()
    assert instance.call("fmi2NewDiscreteStates", None) == 3
    assert instance.snapshot() == before
    instance.fmu.enterContinuousTimeMode()
    before = instance.snapshot()
    assert instance.call("fmi2SetTime", float("nan")) == 3
    assert instance.call("fmi2CompletedIntegratorStep", 1, None, ctypes.byref(ctypes.c_int())) == 3
    assert instance.snapshot() == before
    assert instance.errors() == ["fmi2NewDiscreteStates: eventInfo is NULL",
                                 "fmi2SetTime: time = nan is not finite",
                                 "fmi2CompletedIntegratorStep: enterEventMode is NULL"]


def test_reset_and_reinitialize_a_model_exchange_instance(make_instance):
    instance = make_instance(fmi_type="ModelExchange")
    walk_to(instance, "ContinuousTimeMode")
    instance.set(INPUTS)
    assert instance.call("fmi2Reset") == 0
    assert instance.call("fmi2SetTime", 1.0) == 3  # back in Instantiated
    walk_to(instance, "ContinuousTimeMode")
    assert np.array_equal(instance.get(reference.OUTPUT_NAMES), np.zeros(12))
