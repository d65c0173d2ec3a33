"""What FMI 3.0.3 (fmi-standard's main branch after v3.0.2) changed in what an FMU must do, one
test per change; docs/fmi3.md#fmi-303 quotes the sentences. Error logging whatever the logging
settings (2_2_common_mechanisms.adoc), instanceEnvironment NULL (2_3_common_states.adoc),
outputs that are continuous states and their self-dependency (2_4_common_schema.adoc), partial
derivatives with respect to every known that can appear in dependencies, non-inputs included
(2_2_common_mechanisms.adoc). Instances in parallel threads: tests/c/fmi3_abuse.c (instances)."""
import ctypes

import numpy as np
import pytest

from fmi3_support import DISCARD, ERROR, MODELS, OK, Instance3, doubles, unzipped, vrs

LOG_MESSAGE = ctypes.CFUNCTYPE(None, ctypes.c_void_p, ctypes.c_int, ctypes.c_char_p,
                               ctypes.c_char_p)
UNKNOWN_VR = 999  # no variable of any model has it


def library(model):
    """The FMU's x86_64-linux binary, with the argument types of the calls made here."""
    unzipdir, md = unzipped(model)
    lib = ctypes.CDLL(f"{unzipdir}/binaries/x86_64-linux/{md.coSimulation.modelIdentifier}.so")
    lib.fmi3InstantiateCoSimulation.restype = ctypes.c_void_p
    lib.fmi3InstantiateCoSimulation.argtypes = [
        ctypes.c_char_p, ctypes.c_char_p, ctypes.c_char_p, ctypes.c_bool, ctypes.c_bool,
        ctypes.c_bool, ctypes.c_bool, ctypes.c_void_p, ctypes.c_size_t, ctypes.c_void_p,
        LOG_MESSAGE, ctypes.c_void_p]
    lib.fmi3SetFloat64.argtypes = [ctypes.c_void_p, ctypes.c_void_p, ctypes.c_size_t,
                                   ctypes.c_void_p, ctypes.c_size_t]
    lib.fmi3FreeInstance.argtypes = [ctypes.c_void_p]
    return lib, md


def instantiate(lib, md, environment, log_message, token=None, logging_on=False):
    return lib.fmi3InstantiateCoSimulation(b"raw", (token or md.guid).encode(), None, False,
                                           logging_on, False, False, None, 0, environment,
                                           log_message, None)


def set_unknown(lib, instance):
    return lib.fmi3SetFloat64(instance, vrs([UNKNOWN_VR]), 1, doubles([0.0]), 1)


# --- Error and Fatal reach logMessage whatever loggingOn and the categories say ---------------
# "If loggingOn is false, or debug logging has been disabled in a call to fmi3SetDebugLogging,
# the FMU must not call logMessage, except for fmi3Error and fmi3Fatal return statuses and
# equivalent error situations, where it should call logMessage" (2_2_common_mechanisms.adoc).

SWITCHED_OFF = {
    "loggingOn false": lambda i: None,
    "fmi3SetDebugLogging(false) for all": lambda i: i.call("fmi3SetDebugLogging", False, 0, None),
    "logStatusError switched off": lambda i: i.call(
        "fmi3SetDebugLogging", False, 1, (ctypes.c_char_p * 1)(b"logStatusError")),
}


@pytest.mark.parametrize("fmi_type", ["CoSimulation", "ModelExchange"])
@pytest.mark.parametrize("setting", SWITCHED_OFF)
@pytest.mark.parametrize("model", MODELS)
def test_error_reaches_log_message_whatever_the_logging_settings(model, setting, fmi_type):
    instance = Instance3(model, fmi_type=fmi_type, logging_on=False)
    try:
        assert SWITCHED_OFF[setting](instance) in (None, OK)
        first = instance.inputs()[0]  # 3 elements, or 4 (a quaternion)
        assert instance.set({first: [0.1 * (k + 1) for k in range(instance.size[first])]}) == OK
        assert instance.messages == []  # nothing but errors with logging off
        status = instance.call("fmi3SetFloat64", vrs([UNKNOWN_VR]), 1, doubles([0.0]), 1)
        assert status == ERROR
        assert len(instance.messages) == 1
        level, category, message = instance.messages[0]
        assert (level, category) == ("Error", "logStatusError")
        assert message.startswith("fmi3SetFloat64: ") and str(UNKNOWN_VR) in message
    finally:
        instance.free()


@pytest.mark.parametrize("logging_on", [False, True])
def test_discard_logged_only_with_logging_on(logging_on):
    """Not an error: with loggingOn false the FMU "must not call logMessage"."""
    instance = Instance3("EulerRates", logging_on=logging_on)
    try:
        instance.initialize(inputs={"theta": [0.1, np.pi / 2, 0.3], "omega": [1.0, 0.5, -0.5]})
        assert instance.do_step(0.0, 0.1) == (DISCARD, 0.0)
        discards = [m for s, c, m in instance.messages if s == "Discard"]
        assert any("is discarded" in m for m in discards) == logging_on
        assert len(instance.messages) == 0 or logging_on
    finally:
        instance.free()


@pytest.mark.parametrize("model", MODELS)
def test_refused_instantiation_logged_with_logging_off(model):
    """A NULL return of fmi3Instantiate* counts as fmi3Error for logging."""
    lib, md = library(model)
    messages = []
    log = LOG_MESSAGE(lambda env, status, category, message: messages.append((status, message)))
    assert instantiate(lib, md, None, log, token="{not-this-fmu}") is None
    assert len(messages) == 1 and messages[0][0] == ERROR
    assert b"fmi3InstantiateCoSimulation: instantiationToken" in messages[0][1]


@pytest.mark.parametrize("model", MODELS)
def test_no_log_message_callback_is_never_called(model):
    """"If no logMessage callback function pointer was provided (i.e. it is NULL), the FMU must
    not attempt to call logMessage": the error is returned, nothing crashes."""
    lib, md = library(model)
    instance = instantiate(lib, md, None, LOG_MESSAGE())
    assert instance is not None
    try:
        assert set_unknown(lib, instance) == ERROR
    finally:
        lib.fmi3FreeInstance(instance)
    assert instantiate(lib, md, None, LOG_MESSAGE(), token="{not-this-fmu}") is None


def test_fmi2_still_logs_only_the_enabled_categories(make_instance):
    """FMI 2.0.4: "logger should only be called for log categories that were enabled by a call
    to fmi2SetDebugLogging (see below) or via loggingOn = fmi2True in fmi2Instantiate"."""
    instance = make_instance()
    assert instance.call("fmi2SetReal", (ctypes.c_uint * 1)(UNKNOWN_VR), 1,
                         (ctypes.c_double * 1)(0.0)) == ERROR
    assert len(instance.errors()) == 1  # on by default
    assert instance.call("fmi2SetDebugLogging", False, 0, None) == OK
    assert instance.call("fmi2SetReal", (ctypes.c_uint * 1)(UNKNOWN_VR), 1,
                         (ctypes.c_double * 1)(0.0)) == ERROR
    assert len(instance.errors()) == 1


# --- instanceEnvironment may be NULL ------------------------------------------------------------
# "instanceEnvironment is a pointer that must be passed to fmi3IntermediateUpdateCallback,
# fmi3ClockUpdateCallback, and fmi3LogMessageCallback [...]. This pointer may be NULL."
# (2_3_common_states.adoc)

@pytest.mark.parametrize("environment", [None, 0x5EED])
@pytest.mark.parametrize("model", MODELS)
def test_instance_environment_passed_to_log_message_as_given(model, environment):
    lib, md = library(model)
    seen = []
    log = LOG_MESSAGE(lambda env, status, category, message: seen.append(env))
    assert instantiate(lib, md, environment, log, token="{not-this-fmu}") is None
    instance = instantiate(lib, md, environment, log, logging_on=True)
    assert instance is not None
    try:
        assert set_unknown(lib, instance) == ERROR
    finally:
        lib.fmi3FreeInstance(instance)
    assert len(seen) >= 3  # the refusal, the call trace, the error
    assert set(seen) == {environment}


# --- Self-dependencies: an output that is a continuous state -----------------------------------
# "The importer should not rely on self-dependencies to be explicitly listed, e.g., Outputs that
# are continuous state(s) have an implicit self-dependency." (2_4_common_schema.adoc) The FMU
# lists it, and its partial derivative is the identity.

def test_output_that_is_a_state_lists_and_derives_itself():
    instance = Instance3("AttitudePropagator", fmi_type="ModelExchange")
    try:
        md = instance.md
        states = [u.variable.derivative for u in md.derivatives]
        assert [s.name for s in states] == ["q"]
        q = {u.variable.name: u for u in md.outputs}["q"]
        assert q.variable in [d for d in q.dependencies]
        instance.initialize(inputs={"omega": [0.7, -0.2, 1.5]})
        assert instance.call("fmi3EnterContinuousTimeMode") == OK
        x = doubles([0.5, 0.5, -0.5, 0.5])
        assert instance.call("fmi3SetContinuousStates", x, 4) == OK
        columns = []
        for k in range(4):
            d = (ctypes.c_double * 4)()
            assert instance.call("fmi3GetDirectionalDerivative", vrs([instance.vr["q"]]), 1,
                                 vrs([instance.vr["q"]]), 1, doubles(np.eye(4)[k]), 4, d, 4) == OK
            columns.append(list(d))
        assert np.array_equal(np.array(columns).T, np.eye(4))
    finally:
        instance.free()


# --- Partial derivatives with respect to the knowns that can appear in dependencies ------------
# "v_known is the vector of arguments of function f that could appear in dependencies (see the
# description there) in ModelStructure of the unknown variables v_unknown." (2_2_common_mechanisms
# .adoc) Not only inputs: the continuous states too. Each known of each unknown's dependencies is
# accepted and its column matches a central difference.

def value_of(instance, name, x):
    """The unknown `name` after setting the states to x (model exchange)."""
    assert instance.call("fmi3SetContinuousStates", doubles(x), len(x)) == OK
    return instance.get([name])[name]


def test_derivative_with_respect_to_every_known_in_dependencies():
    instance = Instance3("AttitudePropagator", fmi_type="ModelExchange")
    try:
        instance.initialize(inputs={"omega": [0.7, -0.2, 1.5], "omega_dot": [0.3, 0.1, -0.4]})
        assert instance.call("fmi3EnterContinuousTimeMode") == OK
        x0 = np.array([0.6, 0.4, -0.5, 0.48])
        x0 /= np.linalg.norm(x0)
        unknowns = list(instance.md.outputs) + list(instance.md.derivatives)
        checked_states = 0
        for unknown in unknowns:
            name = unknown.variable.name
            for known in unknown.dependencies:
                if known.causality == "input":
                    continue  # inputs: test_fmi3_attitude.py
                assert known.name == "q"  # the one non-input known of this model
                n_out, h = instance.size[name], 1e-6
                d = (ctypes.c_double * n_out)()
                for k in range(4):
                    assert instance.call("fmi3SetContinuousStates", doubles(x0), 4) == OK
                    assert instance.call("fmi3GetDirectionalDerivative",
                                         vrs([instance.vr[name]]), 1, vrs([instance.vr["q"]]), 1,
                                         doubles(np.eye(4)[k]), 4, d, n_out) == OK, \
                        instance.messages[-1:]
                    step = h * np.eye(4)[k]
                    numeric = (value_of(instance, name, x0 + step)
                               - value_of(instance, name, x0 - step)) / (2 * h)
                    assert np.allclose(list(d), numeric, rtol=1e-6, atol=1e-6), (name, k)
                checked_states += 1
        assert checked_states >= 2  # q itself and der(q) at least
    finally:
        instance.free()
