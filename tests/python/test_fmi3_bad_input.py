"""Bad input to the FMI 3 FMUs, as for FMI 2: each call below returns fmi3Error, logs one error
naming the function, the variable and the value, and changes nothing (every input, parameter and
output reads back bit-identical afterwards); none crashes. Also the functions of what the models
do not have (other types, clocks, configuration mode, scheduled execution)."""
import ctypes
import math

import pytest

from fmi3_support import ERROR, OK, Instance3, doubles, unzipped, vrs

I64 = ctypes.c_int64
NULL = None


def f64(instance, vr_list, values, n=None):
    values = list(values)
    return instance.call("fmi3SetFloat64", vrs(vr_list), len(vr_list), doubles(values),
                         len(values) if n is None else n)


def get64(instance, vr_list, n):
    out = (ctypes.c_double * max(n, 1))(*[7.0] * max(n, 1))
    status = instance.call("fmi3GetFloat64", vrs(vr_list), len(vr_list), out, n)
    assert list(out) == [7.0] * max(n, 1), "a refused get wrote values"
    return status


def step(instance, t, h, null_flag=False):
    b = [ctypes.c_bool() for _ in range(3)]
    last = ctypes.c_double()
    return instance.call("fmi3DoStep", ctypes.c_double(t), ctypes.c_double(h), True,
                         None if null_flag else ctypes.byref(b[0]), ctypes.byref(b[1]),
                         ctypes.byref(b[2]), ctypes.byref(last))


def sensitivity(instance, function, unknowns, knowns, seed, n_sens):
    out = (ctypes.c_double * 30)()
    return instance.call(function, vrs(unknowns), len(unknowns), vrs(knowns), len(knowns),
                         doubles(seed), len(seed), out, n_sens)


# (name, model, call on an initialized co-simulation instance, words the message must hold);
# non-finite inputs, outputs set, unknown value references (test_bad_input.py) and bad arguments
# of fmi3GetDirectionalDerivative (test_directional_derivatives.py): over both layers.
CASES = [
    ("too few values", "AngularKinematics", lambda i: f64(i, [0], [0.1, 0.2]),
     ["fmi3SetFloat64", "nValues = 2", "theta", "3 elements", "too few"]),
    ("too many values", "AngularKinematics", lambda i: f64(i, [0, 3], [0.5] * 7),
     ["fmi3SetFloat64", "nValues = 7", "theta .. theta_dot", "6 elements", "too many"]),
    ("too many values to get", "AngularKinematics", lambda i: get64(i, [21], 10),
     ["fmi3GetFloat64", "nValues = 10", "R", "9 elements"]),
    ("too few values to get", "AngularKinematics", lambda i: get64(i, [9, 30], 6),
     ["fmi3GetFloat64", "nValues = 6", "omega_fixed .. q", "7 elements"]),
    ("inner element", "AngularKinematics", lambda i: f64(i, [0, 1], [1.0] * 6),
     ["fmi3SetFloat64", "valueReferences[1] = 1 is not"]),
    ("Float64 on an Enumeration", "AngularKinematics", lambda i: f64(i, [70], [2.0]),
     ["fmi3SetFloat64", "sequence", "Enumeration"]),
    ("Int64 on a Float64", "AngularKinematics",
     lambda i: i.call("fmi3GetInt64", vrs([0]), 1, (I64 * 3)(), 3),
     ["fmi3GetInt64", "theta", "Float64"]),
    ("set time", "AngularKinematics", lambda i: f64(i, [1000], [1.0]),
     ["fmi3SetFloat64", "time", "independent"]),
    ("sequence after initialization", "AngularKinematics",
     lambda i: i.call("fmi3SetInt64", vrs([70]), 1, (I64 * 1)(3), 1),
     ["fmi3SetInt64", "sequence", "variability fixed", "Step Mode"]),
    ("NULL values", "AngularKinematics",
     lambda i: i.call("fmi3SetFloat64", vrs([0]), 1, NULL, 3),
     ["fmi3SetFloat64", "values is NULL", "nValues = 3"]),
    ("NULL value references", "AngularKinematics",
     lambda i: i.call("fmi3GetFloat64", NULL, 2, doubles([0] * 6), 6),
     ["fmi3GetFloat64", "valueReferences is NULL", "nValueReferences = 2"]),
    ("zero step", "AngularKinematics", lambda i: step(i, 0.0, 0.0),
     ["fmi3DoStep", "communicationStepSize = 0"]),
    ("negative step", "AngularKinematics", lambda i: step(i, 0.0, -0.5),
     ["fmi3DoStep", "communicationStepSize = -0.5"]),
    ("NaN step", "AngularKinematics", lambda i: step(i, 0.0, math.nan),
     ["fmi3DoStep", "communicationStepSize = nan"]),
    ("step from another time", "AngularKinematics", lambda i: step(i, 0.5, 0.1),
     ["fmi3DoStep", "currentCommunicationPoint = 0.5"]),
    ("step past the stop time", "AngularKinematics", lambda i: step(i, 0.0, 20.0),
     ["fmi3DoStep", "stopTime = 10"]),
    ("NULL step flag", "AngularKinematics", lambda i: step(i, 0.0, 0.1, null_flag=True),
     ["fmi3DoStep", "eventHandlingNeeded is NULL"]),
    ("wrong state", "AngularKinematics",
     lambda i: i.call("fmi3EnterInitializationMode", False, 0.0, 0.0, False, 0.0),
     ["fmi3EnterInitializationMode", "illegal call in state Step Mode"]),
    ("output derivative of order 2", "AngularKinematics",
     lambda i: i.call("fmi3GetOutputDerivatives", vrs([9]), 1, (ctypes.c_int32 * 1)(2),
                      doubles([0] * 3), 3),
     ["fmi3GetOutputDerivatives", "orders[0] = 2", "omega_fixed"]),
    ("output derivative of an input", "AngularKinematics",
     lambda i: i.call("fmi3GetOutputDerivatives", vrs([0]), 1, (ctypes.c_int32 * 1)(1),
                      doubles([0] * 3), 3),
     ["fmi3GetOutputDerivatives", "theta", "an input; expected an output"]),
    ("wrong nSeed", "AngularKinematics",
     lambda i: sensitivity(i, "fmi3GetAdjointDerivative", [9], [0], [1, 0], 3),
     ["fmi3GetAdjointDerivative", "nSeed = 2", "omega_fixed"]),
    ("wrong nSensitivity", "AngularKinematics",
     lambda i: sensitivity(i, "fmi3GetDirectionalDerivative", [9, 21], [0], [1, 0, 0], 3),
     ["fmi3GetDirectionalDerivative", "nSensitivity = 3", "omega_fixed .. R", "12 elements"]),
    ("unknown log category", "AngularKinematics",
     lambda i: i.call("fmi3SetDebugLogging", True, 1, (ctypes.c_char_p * 1)(b"logAll")),
     ["fmi3SetDebugLogging", "logAll"]),
    ("wrong nDependencies", "AngularKinematics",
     lambda i: i.call("fmi3GetVariableDependencies", 9, (ctypes.c_size_t * 9)(),
                      vrs([0] * 9), (ctypes.c_size_t * 9)(), (ctypes.c_int * 9)(), 5),
     ["fmi3GetVariableDependencies", "nDependencies = 5", "omega_fixed"]),
    ("continuous states", "AngularKinematics",
     lambda i: i.call("fmi3GetNumberOfContinuousStates", ctypes.byref(ctypes.c_size_t())),
     ["fmi3GetNumberOfContinuousStates", "not available"]),
    ("Float32", "AngularKinematics",
     lambda i: i.call("fmi3GetFloat32", vrs([0]), 1, (ctypes.c_float * 3)(), 3),
     ["fmi3GetFloat32", "valueReferences[0] = 0", "no Float32 variables"]),
    ("Boolean", "AngularKinematics",
     lambda i: i.call("fmi3SetBoolean", vrs([70]), 1, (ctypes.c_bool * 1)(True), 1),
     ["fmi3SetBoolean", "70", "no Boolean variables"]),
    ("String", "AngularKinematics",
     lambda i: i.call("fmi3GetString", vrs([0]), 1, (ctypes.c_char_p * 1)(), 1),
     ["fmi3GetString", "no String variables"]),
    ("Binary", "AngularKinematics",
     lambda i: i.call("fmi3GetBinary", vrs([0]), 1, (ctypes.c_size_t * 1)(),
                      (ctypes.POINTER(ctypes.c_ubyte) * 1)(), 1),
     ["fmi3GetBinary", "no Binary variables"]),
    ("Clock", "AngularKinematics",
     lambda i: i.call("fmi3GetClock", vrs([0]), 1, (ctypes.c_bool * 1)()),
     ["fmi3GetClock", "no Clock variables"]),
    ("Interval", "AngularKinematics",
     lambda i: i.call("fmi3GetIntervalDecimal", vrs([0]), 1, doubles([0]), (ctypes.c_int * 1)()),
     ["fmi3GetIntervalDecimal", "no Clock variables"]),
    ("Configuration Mode", "AngularKinematics", lambda i: i.call("fmi3EnterConfigurationMode"),
     ["fmi3EnterConfigurationMode", "structural parameters"]),
    ("discrete states of clocks", "AngularKinematics",
     lambda i: i.call("fmi3EvaluateDiscreteStates"), ["fmi3EvaluateDiscreteStates", "Clock"]),
    ("model partition", "AngularKinematics",
     lambda i: i.call("fmi3ActivateModelPartition", 0, ctypes.c_double(0.0)),
     ["fmi3ActivateModelPartition", "ScheduledExecution"]),
    ("tolerance out of range", "EulerRates", None, None),  # Instantiated: test below
]


@pytest.mark.parametrize("name, model, bad_call, words", [c for c in CASES if c[2]],
                         ids=[c[0] for c in CASES if c[2]])
def test_refused_with_message_and_nothing_changed(name, model, bad_call, words):
    instance = Instance3(model)
    try:
        instance.initialize(parameters={"sequence": 9}, stop_time=10.0,
                            inputs={"theta": [0.1, 0.2, 0.3], "theta_dot": [1.0, -1.0, 0.5],
                                    "theta_ddot": [0.25, 0.0, -2.0]})
        before = instance.snapshot()
        n_errors = len(instance.errors())
        assert bad_call(instance) == ERROR
        errors = instance.errors()[n_errors:]
        assert len(errors) == 1, errors
        for word in words:
            assert word in errors[0], (word, errors[0])
        assert instance.snapshot() == before
        assert instance.do_step(0.0, 0.5)[0] == OK  # still usable
    finally:
        instance.free()


@pytest.mark.parametrize("model, name, value, words", [
    ("AngularKinematics", "sequence", 25, ["sequence = 25", "Enumeration Sequence"]),
    ("AngularKinematics", "sequence", 0, ["sequence = 0"]),
    ("AngularKinematics", "sequence", 2 ** 63 - 1, ["sequence = 9.2233720368547758e+18"]),
    ("EulerRates", "frame", 3, ["frame = 3", "Enumeration Frame"]),
    ("EulerRates", "tolerance", 2.0, ["tolerance = 2", "outside [0, 1]"]),
    ("EulerRates", "tolerance", math.nan, ["tolerance[1]", "nan"]),
])
def test_bad_parameter_refused_before_initialization(model, name, value, words):
    instance = Instance3(model)
    try:
        before = instance.snapshot()
        status = (instance.set_int({name: value}) if name != "tolerance"
                  else instance.set({name: [value]}))
        assert status == ERROR
        message = instance.errors()[-1]
        assert message.startswith("fmi3SetInt64" if name != "tolerance" else "fmi3SetFloat64")
        for word in words:
            assert word.replace("tolerance[1]", "tolerance") in message, (word, message)
        assert instance.snapshot() == before
        instance.initialize()
        ints = (I64 * 1)()
        assert instance.call("fmi3GetInt64", vrs([instance.vr["sequence"]]), 1, ints, 1) == OK
        assert ints[0] == 1  # the start value: nothing was set
    finally:
        instance.free()


def messages_of_failed_instantiation(function, args):
    instance = Instance3("AngularKinematics")  # only for its loaded library
    messages = []

    from fmpy.fmi3 import fmi3LogMessageCallback
    callback = fmi3LogMessageCallback(lambda env, status, category, message:
                                      messages.append(message.decode()))
    try:
        result = instance.fmu._functions[function](*args(callback))
        assert not result
    finally:
        instance.free()
    return messages


@pytest.mark.parametrize("case, words", [
    ("token", ["fmi3InstantiateCoSimulation", "instantiationToken = \"{wrong}\""]),
    ("event mode", ["fmi3InstantiateCoSimulation", "eventModeUsed = true"]),
    ("intermediate", ["fmi3InstantiateCoSimulation", "nRequiredIntermediateVariables = 1"]),
    ("empty name", ["fmi3InstantiateModelExchange", "instanceName"]),
    ("scheduled", ["fmi3InstantiateScheduledExecution", "not supported"]),
])
def test_instantiation_refused_with_message(case, words):
    token = unzipped("AngularKinematics")[1].guid.encode()

    def arguments(callback):
        if case == "empty name":
            return (b"", token, b"", False, False, None, callback)
        from fmpy.fmi3 import (fmi3ClockUpdateCallback, fmi3IntermediateUpdateCallback,
                               fmi3LockPreemptionCallback, fmi3UnlockPreemptionCallback)
        if case == "scheduled":
            return (b"x", token, b"", False, False, None, callback, fmi3ClockUpdateCallback(),
                    fmi3LockPreemptionCallback(), fmi3UnlockPreemptionCallback())
        return (b"x", b"{wrong}" if case == "token" else token, b"", False, False,
                case == "event mode", False, vrs([0]), 1 if case == "intermediate" else 0, None,
                callback, fmi3IntermediateUpdateCallback())

    function = words[0]
    messages = messages_of_failed_instantiation(function, arguments)
    assert len(messages) == 1 and all(word in messages[0] for word in words), messages
