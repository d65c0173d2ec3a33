"""FMI 2.0 behaviour through fmpy: state machine, direct feedthrough, stepping, reset, logging,
refused capabilities, and instances side by side. The concerns every model shares run for each
model (the `model` fixture); where the values themselves matter, AngularKinematics' outputs are
checked against the sympy reference, and any model's against a fresh instance of itself."""
import ctypes

import numpy as np
import pytest

from codegen import reference

INPUTS = dict(zip(reference.INPUT_NAMES, [0.3, -0.7, 1.1, 0.5, -1.5, 2.0, 3.0, -0.25, 0.8]))


def evaluations(instance):
    return sum("kinematics evaluated" in m for _, _, m in instance.messages)


def expected_outputs(inputs):
    return reference.outputs([inputs[n] for n in reference.INPUT_NAMES])


def fresh_outputs(make_model_instance, model, inputs=None):
    """The outputs of a new instance of the model initialized with inputs: what an instance must
    give after any detour. Call it before creating the instance whose messages are checked (fmpy
    sends every message to the newest instance)."""
    fresh = make_model_instance("fresh")
    fresh.initialize(inputs=inputs)
    outputs = fresh.get(model.outputs)
    fresh.free()
    return outputs


# --- State machine -------------------------------------------------------------------------------

ILLEGAL_IN_INSTANTIATED = [
    ("fmi2ExitInitializationMode", ()),
    ("fmi2DoStep", (0.0, 0.1, 1)),
    ("fmi2Terminate", ()),
    ("fmi2GetReal", ((ctypes.c_uint * 1)(0), 1, (ctypes.c_double * 1)())),
    ("fmi2CancelStep", ()),
]


@pytest.mark.parametrize("function,args", ILLEGAL_IN_INSTANTIATED)
def test_illegal_call_in_instantiated_state(function, args, model, make_model_instance):
    expected = fresh_outputs(make_model_instance, model, model.valid_inputs)
    instance = make_model_instance()
    before = instance.snapshot()
    assert instance.call(function, *args) == 3
    assert instance.errors() == [f"{function}: illegal call in state Instantiated"]
    assert instance.snapshot() == before
    # Nothing was lost: the instance goes on as if the call had not been made.
    instance.initialize(inputs=model.valid_inputs)
    assert np.array_equal(instance.get(model.outputs), expected)


def test_illegal_calls_after_initialization_and_termination(model, make_model_instance):
    expected = fresh_outputs(make_model_instance, model)
    instance = make_model_instance()
    instance.initialize()
    refused = [("fmi2SetupExperiment", (0, 0.0, 0.0, 0, 0.0)), ("fmi2EnterInitializationMode", ()),
               ("fmi2ExitInitializationMode", ())]
    for function, args in refused:
        before = instance.snapshot()
        assert instance.call(function, *args) == 3
        assert instance.snapshot() == before, function
    assert instance.call("fmi2Terminate") == 0
    before = instance.snapshot()
    assert instance.call("fmi2DoStep", 0.0, 0.1, 1) == 3
    assert instance.set({model.inputs[0]: 1.0}) == 3
    assert instance.call("fmi2Terminate") == 3
    assert instance.snapshot() == before
    assert instance.errors() == [
        "fmi2SetupExperiment: illegal call in state StepComplete",
        "fmi2EnterInitializationMode: illegal call in state StepComplete",
        "fmi2ExitInitializationMode: illegal call in state StepComplete",
        "fmi2DoStep: illegal call in state Terminated",
        "fmi2SetReal: illegal call in state Terminated",
        "fmi2Terminate: illegal call in state Terminated",
    ]
    # Outputs can still be read after fmi2Terminate.
    assert np.array_equal(instance.get(model.outputs), expected)


def test_inputs_settable_before_initialization(model, make_model_instance):
    expected = fresh_outputs(make_model_instance, model, model.valid_inputs)
    instance = make_model_instance()
    assert instance.set(model.valid_inputs) == 0
    instance.initialize()
    assert np.array_equal(instance.get(model.outputs), expected)


def test_inputs_settable_before_initialization_give_the_reference(make_instance):
    instance = make_instance()
    assert instance.set(INPUTS) == 0
    instance.initialize()
    assert np.allclose(instance.get(reference.OUTPUT_NAMES), expected_outputs(INPUTS), rtol=1e-14)


def test_null_instance_is_refused_without_crash(make_model_instance):
    instance = make_model_instance()
    functions = instance.fmu._functions
    assert functions["fmi2DoStep"](None, 0.0, 0.1, 1) == 3
    assert functions["fmi2SetReal"](None, None, 0, None) == 3
    assert functions["fmi2Reset"](None) == 3
    functions["fmi2FreeInstance"](None)  # ignored, as the standard says


# --- Direct feedthrough and lazy evaluation ------------------------------------------------------

def test_outputs_valid_right_after_initialization(make_instance):
    instance = make_instance()
    instance.initialize(inputs=INPUTS)
    assert np.allclose(instance.get(reference.OUTPUT_NAMES), expected_outputs(INPUTS), rtol=1e-14)


def test_get_after_set_at_same_communication_point_follows_new_inputs(make_instance):
    instance = make_instance(logging_on=True)
    instance.initialize(inputs=INPUTS)
    instance.fmu.doStep(0.0, 0.1)
    changed = dict(INPUTS, **{"theta[2]": 1.4, "theta_dot[1]": -3.0})
    for _ in range(3):  # a master iterating an algebraic loop at t = 0.1
        assert instance.set(changed) == 0
        assert np.allclose(instance.get(reference.OUTPUT_NAMES), expected_outputs(changed), rtol=1e-14)
        changed["theta_ddot[3]"] += 1.0


def test_outputs_computed_once_and_only_when_an_input_changed(model, make_model_instance):
    instance = make_model_instance(logging_on=True)
    instance.initialize(inputs=model.valid_inputs)
    assert evaluations(instance) == 1
    # A step changes nothing of a stateless model; it moves the states of a model with some, and
    # its outputs are then evaluated once at the end of the step.
    per_step = 1 if model.description.numberOfContinuousStates else 0
    for _ in range(5):
        instance.get(model.outputs)
        instance.fmu.doStep(instance.fmu.getRealStatus(2), 0.1)
    instance.set(model.valid_inputs)  # the same values again: nothing changed
    instance.get(model.outputs)
    assert evaluations(instance) == 1 + 5 * per_step
    instance.set({model.inputs[2]: 0.0})
    instance.set({model.inputs[5]: 0.0})
    assert evaluations(instance) == 1 + 5 * per_step  # setting alone computes nothing
    instance.get(model.outputs[-1:])
    instance.get(model.outputs)
    assert evaluations(instance) == 2 + 5 * per_step


# --- Stepping ------------------------------------------------------------------------------------

def test_variable_steps_and_stop_time(model, make_model_instance):
    instance = make_model_instance()
    instance.initialize(stop_time=1.0, inputs=model.valid_inputs)
    t = 0.0
    for h in (0.1, 0.013, 0.25, 1e-6, 0.3):
        assert instance.call("fmi2DoStep", t, h, 1) == 0
        t += h
        assert instance.fmu.getRealStatus(2) == t  # fmi2LastSuccessfulTime
    assert instance.call("fmi2DoStep", t, 1.0 - t, 1) == 0  # lands on the stop time
    assert instance.call("fmi2DoStep", 1.0, 0.1, 1) == 3
    assert instance.errors()[-1] == (
        "fmi2DoStep: the step from 1 by communicationStepSize = 0.10000000000000001 ends at "
        "1.1000000000000001, past stopTime = 1")


@pytest.mark.parametrize("t,h,message", [
    (0.0, 0.0, "fmi2DoStep: communicationStepSize = 0 must be > 0"),
    (0.0, -0.1, "fmi2DoStep: communicationStepSize = -0.1 must be > 0"),
    (0.0, float("nan"), "fmi2DoStep: currentCommunicationPoint = 0 and communicationStepSize = nan "
                        "must be finite"),
    (float("inf"), 0.1, "fmi2DoStep: currentCommunicationPoint = inf and communicationStepSize = 0.1 "
                        "must be finite"),
    (0.5, 0.1, "fmi2DoStep: currentCommunicationPoint = 0.5 does not continue from the last "
               "communication point 0.20000000000000001"),
])
def test_bad_step_is_refused_and_changes_nothing(t, h, message, model, make_model_instance):
    instance = make_model_instance()
    instance.initialize(inputs=model.valid_inputs)
    instance.fmu.doStep(0.0, 0.2)
    before = instance.snapshot()
    assert instance.call("fmi2DoStep", t, h, 1) == 3
    assert instance.errors() == [message]
    assert instance.snapshot() == before
    assert instance.fmu.getRealStatus(2) == 0.2
    assert instance.call("fmi2DoStep", 0.2, 0.1, 1) == 0


def test_step_within_relative_tolerance_of_last_point_is_accepted(make_model_instance):
    instance = make_model_instance()
    instance.initialize()
    t = 0.0
    for _ in range(10):
        assert instance.call("fmi2DoStep", t, 0.1, 1) == 0
        t += 0.1
    # A master that computes the time as n * h differs from the sum of its steps in the last bits.
    assert instance.call("fmi2DoStep", 10 * 0.1, 0.1, 1) == 0


@pytest.mark.parametrize("args,message", [
    ((0, 0.0, float("nan"), 0, 0.0), "fmi2SetupExperiment: startTime = nan is not finite"),
    ((0, 0.0, 1.0, 1, 0.5), "fmi2SetupExperiment: stopTime = 0.5 must be finite and >= startTime = 1"),
    ((1, -1e-6, 0.0, 0, 0.0), "fmi2SetupExperiment: tolerance = -1e-06 must be finite and >= 0"),
])
def test_bad_experiment_setup_is_refused(args, message, make_model_instance):
    instance = make_model_instance()
    before = instance.snapshot()
    assert instance.call("fmi2SetupExperiment", *args) == 3
    assert instance.errors() == [message]
    assert instance.snapshot() == before
    assert instance.call("fmi2SetupExperiment", 0, 0.0, 2.0, 1, 3.0) == 0
    instance.fmu.enterInitializationMode()
    instance.fmu.exitInitializationMode()
    assert instance.fmu.getRealStatus(2) == 2.0


def test_status_queries(make_model_instance):
    instance = make_model_instance()
    instance.initialize(start_time=1.5)
    assert instance.fmu.getRealStatus(2) == 1.5
    assert instance.fmu.getBooleanStatus(3) == 0
    status = ctypes.c_int()
    assert instance.call("fmi2GetStatus", 0, ctypes.byref(status)) == 2  # fmi2Discard
    assert instance.call("fmi2GetRealStatus", 2, None) == 3
    assert instance.errors() == ["fmi2GetRealStatus: value is NULL"]


# --- Reset, terminate, free ----------------------------------------------------------------------

def test_reset_returns_to_just_instantiated(model, make_model_instance):
    expected = fresh_outputs(make_model_instance, model)
    starts = [v["start"] for v in model.c_table["variables"] if v["causality"] == "input"]
    instance = make_model_instance()
    instance.initialize(start_time=3.0, stop_time=4.0, inputs=model.valid_inputs)
    instance.fmu.doStep(3.0, 0.5)
    assert instance.call("fmi2Reset") == 0
    # Just instantiated: initialization may start again, inputs are back at their start values.
    assert instance.call("fmi2DoStep", 3.5, 0.1, 1) == 3
    instance.initialize(start_time=0.0)
    assert np.array_equal(instance.get(model.inputs), starts)
    assert np.array_equal(instance.get(model.outputs), expected)
    assert instance.call("fmi2DoStep", 0.0, 10.0, 1) == 0  # no stop time any more


def test_reset_from_every_reachable_state(model, make_model_instance):
    expected = fresh_outputs(make_model_instance, model, model.valid_inputs)
    instance = make_model_instance()
    for setup in ("instantiated", "initialization", "step_complete", "terminated"):
        assert instance.call("fmi2Reset") == 0
        if setup != "instantiated":
            instance.fmu.setupExperiment(startTime=0.0)
            instance.fmu.enterInitializationMode()
        if setup in ("step_complete", "terminated"):
            instance.fmu.exitInitializationMode()
        if setup == "terminated":
            instance.fmu.terminate()
        assert instance.call("fmi2Reset") == 0
        instance.initialize(inputs=model.valid_inputs)
        assert np.array_equal(instance.get(model.outputs), expected)
        assert instance.call("fmi2Reset") == 0


def test_many_instantiate_free_cycles(model, make_model_instance):
    # Each cycle allocates and frees; a leak or double free would show under the sanitizers too.
    # Every cycle's instance steps, terminates and gives the outputs of the first one.
    expected = None
    for n in range(200):
        instance = make_model_instance(name=f"cycle{n}")
        assert instance.component is not None
        instance.initialize(inputs=model.valid_inputs)
        assert instance.call("fmi2DoStep", 0.0, 0.1, 1) == 0
        outputs = instance.get(model.outputs)
        if expected is None:
            expected = outputs
        assert np.array_equal(outputs, expected, equal_nan=True)
        assert instance.call("fmi2Terminate") == 0
        instance.free()


# --- Instances side by side ----------------------------------------------------------------------

def test_two_instances_with_different_inputs(make_instance):
    first, second = make_instance("first"), make_instance("second")
    other = dict(zip(reference.INPUT_NAMES, [-1.0, 1.5, 0.2, 4.0, 0.1, -0.3, 0.0, 9.0, -2.0]))
    first.initialize(inputs=INPUTS)
    second.initialize(inputs=other)
    for t in (0.0, 0.1, 0.2):
        first.fmu.doStep(t, 0.1)
        second.fmu.doStep(t, 0.1)
        assert np.allclose(first.get(reference.OUTPUT_NAMES), expected_outputs(INPUTS), rtol=1e-14)
        assert np.allclose(second.get(reference.OUTPUT_NAMES), expected_outputs(other), rtol=1e-14)
    second.free()
    assert np.allclose(first.get(reference.OUTPUT_NAMES), expected_outputs(INPUTS), rtol=1e-14)


# --- Logging -------------------------------------------------------------------------------------

def test_call_trace_only_when_asked(model, make_model_instance):
    quiet = make_model_instance("quiet")
    quiet.initialize(inputs=model.valid_inputs)
    quiet.get(model.outputs[:1])
    assert quiet.messages == []

    traced = make_model_instance("traced", logging_on=True)
    traced.initialize(inputs=model.valid_inputs)
    categories = {c for _, c, _ in traced.messages}
    assert categories == {"logCalls"}
    calls = [m for _, _, m in traced.messages]
    assert calls[:4] == ['fmi2Instantiate: instance "traced" created', "fmi2SetupExperiment",
                         "fmi2EnterInitializationMode", "fmi2SetReal"]
    assert f"fmi2SetReal: {model.inputs[0]} = 0.29999999999999999" in calls


def test_set_debug_logging_by_category(model, make_model_instance):
    instance = make_model_instance()
    instance.fmu.setDebugLogging(True, ["logCalls"])
    instance.initialize()
    assert "fmi2ExitInitializationMode" in [m for _, _, m in instance.messages]
    instance.fmu.setDebugLogging(False, ["logCalls", "logStatusError"])
    count = len(instance.messages)
    instance.get(model.inputs[:1])
    assert instance.call("fmi2DoStep", 5.0, 0.1, 1) == 3  # an error, logged in a category that is off
    assert len(instance.messages) == count
    instance.fmu.setDebugLogging(True, [])  # every category on
    assert instance.call("fmi2DoStep", 5.0, 0.1, 1) == 3
    assert len(instance.errors()) == 1


def test_set_debug_logging_rejects_unknown_category(make_model_instance):
    instance = make_model_instance()
    categories = (ctypes.c_char_p * 2)(b"logCalls", b"logEverything%s")
    assert instance.call("fmi2SetDebugLogging", 1, 2, categories) == 3
    assert instance.errors() == [
        'fmi2SetDebugLogging: categories[1] = "logEverything%s" is not a log category of this FMU '
        "(logStatusError, logStatusWarning, logCalls)"]
    instance.initialize()
    assert not any(c == "logCalls" for _, c, _ in instance.messages)  # logCalls was not switched on
    assert instance.call("fmi2SetDebugLogging", 1, 1, None) == 3


# --- What this FMU does not offer ---------------------------------------------------------------
# Every capability flag of modelDescription.xml is true and tested in its own file
# (test_model_exchange.py, test_input_interpolation.py, test_output_derivatives.py,
# test_directional_derivatives.py, test_fmu_state.py, test_variable_steps.py). Asynchronous
# stepping (canRunAsynchronuously="false") stays unsupported: no step is ever in progress.

def test_cancel_step_is_refused_because_steps_are_never_asynchronous(model, make_model_instance):
    instance = make_model_instance()
    instance.initialize(inputs=model.valid_inputs)
    assert instance.call("fmi2DoStep", 0.0, 0.1, 1) == 0
    assert instance.call("fmi2CancelStep") == 3
    assert instance.errors() == ["fmi2CancelStep: illegal call in state StepComplete"]
    assert instance.call("fmi2DoStep", 0.1, 0.1, 1) == 0  # nothing was disturbed
