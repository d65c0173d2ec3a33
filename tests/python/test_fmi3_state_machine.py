"""The FMI 3.0 state machines: every function of the table below, called with valid arguments in
every state an instance of either interface can reach, returns fmi3OK exactly where the standard
allows it (written here from FMI 3.0 sections 3.2 and 4.2, independently of the C table) and
otherwise fmi3Error with a message naming the function and the state; an instance stays usable
after a refused call. And fmpy simulates both interfaces start to end."""
import ctypes

import numpy as np
import pytest
from fmpy import simulate_fmu

from fmi3_support import MODELS, ERROR, OK, Instance3, doubles, fmu3_path, unzipped, vrs

CS_STATES = ["Instantiated", "Initialization Mode", "Step Mode", "Terminated"]
ME_STATES = ["Instantiated", "Initialization Mode", "Event Mode", "Continuous-Time Mode",
             "Terminated"]
ALL = set(CS_STATES + ME_STATES)
# Where the partial derivatives, and model exchange's states, are defined (FMI 3, 2_2, 2_3).
READ_CS = {"Initialization Mode", "Step Mode", "Terminated"}
READ_ME = {"Initialization Mode", "Event Mode", "Continuous-Time Mode", "Terminated"}
# fmi3Get{VariableType} also in Instantiated: "Returns the current start values as defined in
# modelDescription.xml or as set by fmi3Set{VariableType}" (2_3, State: Instantiated).
GET_CS = {"Instantiated"} | READ_CS
GET_ME = {"Instantiated"} | READ_ME

# function: (states allowed for co-simulation, states allowed for model exchange)
ALLOWED = {
    "fmi3EnterInitializationMode": ({"Instantiated"}, {"Instantiated"}),
    "fmi3ExitInitializationMode": ({"Initialization Mode"}, {"Initialization Mode"}),
    "fmi3EnterEventMode": (set(), {"Continuous-Time Mode"}),
    "fmi3Terminate": ({"Step Mode"}, {"Event Mode", "Continuous-Time Mode"}),
    "fmi3GetFloat64": (GET_CS, GET_ME),
    "fmi3SetFloat64": ({"Instantiated", "Initialization Mode", "Step Mode"},
                       {"Instantiated", "Initialization Mode", "Event Mode",
                        "Continuous-Time Mode"}),
    "fmi3SetInt64": ({"Instantiated", "Initialization Mode"},
                     {"Instantiated", "Initialization Mode"}),
    "fmi3DoStep": ({"Step Mode"}, set()),
    "fmi3EnterStepMode": (set(), set()),  # from Event Mode, which co-simulation never uses here
    "fmi3GetOutputDerivatives": ({"Step Mode", "Terminated"}, set()),
    "fmi3GetDirectionalDerivative": (READ_CS, READ_ME),
    "fmi3GetAdjointDerivative": (READ_CS, READ_ME),
    "fmi3EnterContinuousTimeMode": (set(), {"Event Mode"}),
    "fmi3UpdateDiscreteStates": (set(), {"Event Mode"}),
    "fmi3CompletedIntegratorStep": (set(), {"Continuous-Time Mode"}),
    "fmi3SetTime": (set(), {"Continuous-Time Mode"}),  # 3_2: "t := (time, 0) | fmi3SetTime"
    "fmi3GetNumberOfContinuousStates": (set(), set(ME_STATES)),
    "fmi3GetContinuousStates": (set(), READ_ME),
    "fmi3GetContinuousStateDerivatives": (set(), READ_ME),
    "fmi3GetEventIndicators": (set(), READ_ME),
    "fmi3GetFMUState": (set(CS_STATES), set(ME_STATES)),
    "fmi3SetDebugLogging": (set(CS_STATES), set(ME_STATES)),
    "fmi3Reset": (set(CS_STATES), set(ME_STATES)),
}


# Functions of one interface only (co-simulation without Event Mode here).
CS_ONLY = {"fmi3DoStep", "fmi3EnterStepMode", "fmi3GetOutputDerivatives"}
ME_ONLY = {"fmi3EnterEventMode", "fmi3EnterContinuousTimeMode", "fmi3UpdateDiscreteStates",
           "fmi3CompletedIntegratorStep", "fmi3SetTime", "fmi3GetNumberOfContinuousStates",
           "fmi3GetContinuousStates", "fmi3GetContinuousStateDerivatives",
           "fmi3GetEventIndicators"}


def enter(instance, state, me):
    if state == "Instantiated":
        return
    assert instance.call("fmi3EnterInitializationMode", False, 0.0, 0.0, False, 0.0) == OK
    if state == "Initialization Mode":
        return
    assert instance.call("fmi3ExitInitializationMode") == OK
    if state == "Continuous-Time Mode":
        assert instance.call("fmi3EnterContinuousTimeMode") == OK
    if state == "Terminated":
        assert instance.call("fmi3Terminate") == OK


def call(instance, function):
    """The function with valid arguments; the status."""
    b = [ctypes.c_bool() for _ in range(6)]
    refs = [ctypes.byref(x) for x in b]
    d = ctypes.c_double()
    n = ctypes.c_size_t()
    out = (ctypes.c_double * 9)()
    if function in ("fmi3ExitInitializationMode", "fmi3EnterEventMode", "fmi3Terminate",
                    "fmi3EnterStepMode", "fmi3EnterContinuousTimeMode", "fmi3Reset"):
        return instance.call(function)
    args = {
        "fmi3EnterInitializationMode": (False, 0.0, 0.0, False, 0.0),
        "fmi3GetFloat64": (vrs([0]), 1, out, 3),
        "fmi3SetFloat64": (vrs([0]), 1, doubles([0.1, 0.2, 0.3]), 3),
        "fmi3SetInt64": (vrs([70]), 1, (ctypes.c_int64 * 1)(3), 1),
        "fmi3DoStep": (ctypes.c_double(0.0), ctypes.c_double(0.01), True, refs[0], refs[1],
                       refs[2], ctypes.byref(d)),
        "fmi3GetOutputDerivatives": (vrs([9]), 1, (ctypes.c_int32 * 1)(1), out, 3),
        "fmi3GetDirectionalDerivative": (vrs([9]), 1, vrs([0]), 1, doubles([1, 0, 0]), 3, out, 3),
        "fmi3GetAdjointDerivative": (vrs([9]), 1, vrs([0]), 1, doubles([1, 0, 0]), 3, out, 3),
        "fmi3UpdateDiscreteStates": (*refs[:5], ctypes.byref(d)),
        "fmi3CompletedIntegratorStep": (True, refs[0], refs[1]),
        "fmi3SetTime": (ctypes.c_double(0.5),),
        "fmi3GetNumberOfContinuousStates": (ctypes.byref(n),),
        "fmi3GetContinuousStates": (out, 0),
        "fmi3GetContinuousStateDerivatives": (out, 0),
        "fmi3GetEventIndicators": (out, 0),
        "fmi3SetDebugLogging": (True, 0, None),
    }
    if function == "fmi3GetFMUState":
        state = ctypes.c_void_p()
        status = instance.call(function, ctypes.byref(state))
        if status == OK:
            assert instance.call("fmi3FreeFMUState", ctypes.byref(state)) == OK
        return status
    return instance.call(function, *args[function])


@pytest.mark.parametrize("fmi_type", ["CoSimulation", "ModelExchange"])
@pytest.mark.parametrize("function", sorted(ALLOWED))
def test_function_allowed_exactly_in_the_standard_states(function, fmi_type):
    me = fmi_type == "ModelExchange"
    allowed = ALLOWED[function][1 if me else 0]
    for state in ME_STATES if me else CS_STATES:
        instance = Instance3("AngularKinematics", fmi_type=fmi_type)
        try:
            enter(instance, state, me)
            before = instance.snapshot()
            status = call(instance, function)
            if state in allowed:
                assert status == OK, (function, state, instance.messages)
                continue
            assert status == ERROR, (function, state)
            message = instance.errors()[-1]
            assert message.startswith(function), message
            if function == "fmi3SetInt64" and state != "Terminated":
                assert "sequence" in message and "variability fixed" in message, message
            elif function in (CS_ONLY if me else ME_ONLY):
                assert "not available to this instance" in message, message
            else:
                assert f"illegal call in state {state}" in message, message
            # Refused: every variable and the FMU state bit for bit as before the call.
            assert instance.snapshot() == before, (function, state)
            # Still usable: a reset works and the instance can be initialized again.
            assert instance.call("fmi3Reset") == OK
            enter(instance, "Initialization Mode", me)
        finally:
            instance.free()


@pytest.mark.parametrize("model", MODELS)
@pytest.mark.parametrize("fmi_type", ["CoSimulation", "ModelExchange"])
def test_fmpy_simulates_both_interfaces(model, fmi_type):
    md = unzipped(model)[1]
    variables = {v.name: v for v in md.modelVariables}
    first_input = next(v for v in md.modelVariables if v.causality == "input")
    # 3 elements, or 4 (a quaternion): the values repeated to the shape
    start = {first_input.name: np.resize([0.3, -0.2, 0.9],
                                         int(np.prod([int(d.start) for d in first_input.dimensions])))
             .tolist()}
    if "sequence" in variables:
        start["sequence"] = 13
    if "q0" in variables:  # a model whose state q starts at the parameter q0
        start["q0"] = [0.5, 0.5, 0.5, -0.5]
    result = simulate_fmu(str(fmu3_path(model)), fmi_type=fmi_type, stop_time=0.5,
                          output_interval=0.1, start_values=start)
    assert len(result) == 6 and result["time"][-1] == pytest.approx(0.5)
    for output in (v for v in md.modelVariables if v.causality == "output"):
        shape = tuple(int(d.start) for d in output.dimensions)
        assert result[output.name].shape == (6, *shape), output.name
    # an output or state q is unit (a state q drifts under CVode, ME); an input q need not be
    if "q" in variables and variables["q"].causality != "input":
        norm2 = result["q"][:, 0] ** 2 + (result["q"][:, 1:] ** 2).sum(axis=1)
        assert np.allclose(norm2, 1.0, rtol=0, atol=1e-3 if md.derivatives else 1e-8)
    if "q0" in variables:  # the state starts at q0 and moves (CVode or the step)
        assert result["q"][0].tolist() == [0.5, 0.5, 0.5, -0.5]
        assert not np.allclose(result["q"][-1], result["q"][0])


# The continuous-state functions with AttitudePropagator's 4 states, by the standard (FMI 3.0,
# section 3.2): (states where it is allowed, the call).
STATE_FUNCTIONS = {
    "fmi3GetNumberOfContinuousStates": (set(ME_STATES),
                                        lambda i: i.call("fmi3GetNumberOfContinuousStates",
                                                         ctypes.byref(ctypes.c_size_t()))),
    "fmi3GetContinuousStates": (READ_ME, lambda i: i.call("fmi3GetContinuousStates",
                                                          (ctypes.c_double * 4)(), 4)),
    "fmi3SetContinuousStates": ({"Continuous-Time Mode"},
                                lambda i: i.call("fmi3SetContinuousStates",
                                                 doubles([0.5, 0.5, 0.5, 0.5]), 4)),
    "fmi3GetContinuousStateDerivatives": (READ_ME,
                                          lambda i: i.call("fmi3GetContinuousStateDerivatives",
                                                           (ctypes.c_double * 4)(), 4)),
    "fmi3GetNominalsOfContinuousStates": (READ_ME,
                                          lambda i: i.call("fmi3GetNominalsOfContinuousStates",
                                                           (ctypes.c_double * 4)(), 4)),
}


@pytest.mark.parametrize("function", sorted(STATE_FUNCTIONS))
def test_state_functions_with_states_allowed_exactly_in_the_standard_states(function):
    allowed, make_call = STATE_FUNCTIONS[function]
    for state in ME_STATES:
        instance = Instance3("AttitudePropagator", fmi_type="ModelExchange")
        try:
            enter(instance, state, True)
            before = instance.snapshot()
            status = make_call(instance)
            if state in allowed:
                assert status == OK, (function, state, instance.messages)
                continue
            assert status == ERROR, (function, state)
            assert instance.errors()[-1].startswith(f"{function}: illegal call in state {state}")
            assert instance.snapshot() == before, (function, state)
        finally:
            instance.free()
    cs = Instance3("AttitudePropagator")
    try:
        enter(cs, "Step Mode", False)
        before = cs.snapshot()
        assert make_call(cs) == ERROR and "not available to this instance" in cs.errors()[-1]
        assert cs.snapshot() == before
    finally:
        cs.free()


def test_reset_returns_to_instantiated_with_start_values():
    instance = Instance3("AngularKinematics")
    try:
        instance.initialize(parameters={"sequence": 5}, inputs={"theta": [1.0, 2.0, 0.5]})
        assert instance.do_step(0.0, 0.1) == (OK, 0.1)
        assert instance.call("fmi3Reset") == OK
        # Instantiated again: the variables read their start values, not the step's, and the
        # outputs are those of the start values (all zero: every angle and rate starts at 0).
        status, values = instance.get_raw(["theta", "omega_fixed"])
        assert status == OK and values["theta"].tolist() == [0.0, 0.0, 0.0]
        assert values["omega_fixed"].tolist() == [0.0, 0.0, 0.0]
        assert instance.set({"theta": [0.25, 0.5, 0.75]}) == OK  # and what was set since
        status, values = instance.get_raw(["theta"])
        assert status == OK and values["theta"].tolist() == [0.25, 0.5, 0.75]
        assert instance.call("fmi3Reset") == OK
        instance.initialize()
        assert instance.get(["theta"])["theta"].tolist() == [0.0, 0.0, 0.0]
        sequence = (ctypes.c_int64 * 1)()
        assert instance.call("fmi3GetInt64", vrs([70]), 1, sequence, 1) == OK
        assert sequence[0] == 1
        assert instance.do_step(0.0, 0.25) == (OK, 0.25)  # the time started again from 0
    finally:
        instance.free()


def test_getters_in_instantiated_return_start_values_or_what_was_set():
    """FMI 3, 2_3, State: Instantiated: fmi3Get{VariableType} "returns the current start values as
    defined in modelDescription.xml or as set by fmi3Set{VariableType}"."""
    instance = Instance3("EulerRates")
    try:
        status, values = instance.get_raw(["tolerance", "theta"])
        assert status == OK and values["tolerance"].tolist() == [1e-4]
        assert values["theta"].tolist() == [0.0, 0.0, 0.0]
        assert instance.call("fmi3SetFloat64", vrs([instance.vr["theta"]]), 1,
                             doubles([0.1, 0.2, 0.3]), 3) == OK
        status, values = instance.get_raw(["theta"])
        assert status == OK and values["theta"].tolist() == [0.1, 0.2, 0.3]
        frame = (ctypes.c_int64 * 1)()
        assert instance.call("fmi3GetInt64", vrs([instance.vr["frame"]]), 1, frame, 1) == OK
        assert frame[0] == 1
    finally:
        instance.free()
