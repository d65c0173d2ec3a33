"""EulerRates (dist/EulerRates.fmu), the inverse map, through fmpy: the round trip
EulerRates(AngularKinematics(x)) = x for every sequence and both frames, agreement with the
independent reference, the behaviour near and at the singular configuration (warning, fmi2Discard,
last valid values kept, recovery, co-simulation step status, model exchange), its parameters and
bad values, and the capabilities it claims (what it refuses: test_undeclared_capabilities.py)."""
import ctypes

import numpy as np
import pytest

from codegen import reference
from codegen.project import SEQUENCES

ER_INPUTS = reference.RATES_INPUTS
ER_OUTPUTS = reference.RATES_OUTPUTS + ["singularity_distance"]
AK_INPUTS = reference.KINEMATICS_INPUTS
RNG_SEED = 20261122


def proper(name):
    return name[-3] == name[-1]


def singular_value(name):
    return 0.0 if proper(name) else np.pi / 2


def distance(name, theta2):
    return abs(np.sin(theta2)) if proper(name) else abs(np.cos(theta2))


def euler(make_euler_instance, name="body123", frame=1, tolerance=None, fmi_type="CoSimulation",
          inputs=None, logging_on=False):
    instance = make_euler_instance(fmi_type=fmi_type, logging_on=logging_on)
    parameters = {"sequence": SEQUENCES.index(name) + 1, "frame": frame}
    if tolerance is not None:
        parameters["tolerance"] = tolerance
    instance.initialize(parameters=parameters, inputs=inputs)
    return instance


def get_raw(instance, names):
    vrs = [instance.vr[n] for n in names]
    values = (ctypes.c_double * len(vrs))(*([-7.0] * len(vrs)))
    status = instance.call("fmi2GetReal", (ctypes.c_uint * len(vrs))(*vrs), len(vrs), values)
    return status, np.array(values)


def generic_states(name, count, rng, minimum_distance=0.2):
    states = []
    while len(states) < count:
        x = np.hstack([rng.uniform(-np.pi, np.pi, 3), rng.uniform(-3, 3, 6)])
        if distance(name, x[1]) >= minimum_distance:
            states.append(x)
    return np.array(states)


@pytest.mark.parametrize("name", SEQUENCES)
def test_round_trip_through_both_fmus(name, make_instance, make_euler_instance, report):
    """x = (theta, theta_dot, theta_ddot) -> AngularKinematics -> omega, alpha in one frame ->
    EulerRates -> theta_dot, theta_ddot: x again, in both frames; alpha in the other frame too."""
    rng = np.random.default_rng([RNG_SEED, SEQUENCES.index(name)])
    forward = make_instance()
    forward.initialize(parameters={"sequence": SEQUENCES.index(name) + 1})
    inverse = {frame: euler(make_euler_instance, name, code) for frame, code in (("fixed", 1), ("body", 2))}
    worst = 0.0
    for x in generic_states(name, 12, rng):
        assert forward.set(dict(zip(AK_INPUTS, x))) == 0
        for frame, instance in inverse.items():
            omega = forward.get([f"omega_{frame}[{i}]" for i in (1, 2, 3)])
            alpha = forward.get([f"alpha_{frame}[{i}]" for i in (1, 2, 3)])
            assert instance.set(dict(zip(ER_INPUTS, np.hstack([x[:3], omega, alpha])))) == 0
            status, back = get_raw(instance, ER_OUTPUTS)
            assert status == 0
            # Conditioning: the inverse amplifies by up to 1/singularity_distance.
            d = distance(name, x[1])
            omega_scale = np.abs(x[3:6]).sum() / d
            alpha_scale = (np.abs(x[6:9]).sum() + np.abs(x[3:6]).sum() ** 2) / d ** 2
            error = max(np.abs(back[0:3] - x[3:6]).max() / omega_scale,
                        np.abs(back[3:6] - x[6:9]).max() / alpha_scale)
            worst = max(worst, error)
            both = forward.get([f"alpha_{f}[{i}]" for f in ("fixed", "body") for i in (1, 2, 3)])
            assert np.allclose(back[6:12], both, rtol=0, atol=1e-13 * (1 + np.abs(both).max()))
            assert back[12] == pytest.approx(d, rel=1e-15, abs=1e-16)
    report(f"12 states x 2 frames: worst conditioned scaled round-trip error {worst:.1e}")
    assert worst <= 1e-14


@pytest.mark.parametrize("name", ["body123", "body321", "body313", "space132", "space212"])
@pytest.mark.parametrize("frame", ["fixed", "body"])
def test_matches_the_independent_reference(name, frame, make_euler_instance):
    rng = np.random.default_rng([RNG_SEED, 99, SEQUENCES.index(name)])
    instance = euler(make_euler_instance, name, 1 if frame == "fixed" else 2)
    for x in generic_states(name, 4, rng, minimum_distance=0.3):
        assert instance.set(dict(zip(ER_INPUTS, x))) == 0
        status, got = get_raw(instance, ER_OUTPUTS)
        assert status == 0
        theta_dot, theta_ddot = reference.euler_rates(name, frame, x[:3], x[3:6], x[6:9])
        scale = 1 + np.abs(theta_dot).max() + np.abs(theta_ddot).max()
        assert np.abs(got[:6] - np.hstack([theta_dot, theta_ddot])).max() / scale <= 1e-14


SINGULAR_INPUTS = {"theta[1]": 0.3, "theta[2]": np.pi / 2, "theta[3]": -0.4, "omega[1]": 0.5,
                   "omega[2]": -0.2, "omega[3]": 0.9, "omega_dot[1]": 0.1, "omega_dot[2]": 0.2,
                   "omega_dot[3]": -0.3}
GOOD_INPUTS = dict(SINGULAR_INPUTS, **{"theta[2]": 0.4})


def test_near_the_singularity_a_warning_inside_the_tolerance(make_euler_instance):
    instance = euler(make_euler_instance, "body123", tolerance=1e-3, inputs=GOOD_INPUTS)
    assert get_raw(instance, ER_OUTPUTS)[0] == 0
    near = np.pi / 2 - 5e-4  # distance sin(5e-4) < 1e-3
    assert instance.set({"theta[2]": near}) == 0
    status, values = get_raw(instance, ER_OUTPUTS)
    assert status == 1  # fmi2Warning: the outputs are valid
    assert values[12] == pytest.approx(np.sin(5e-4), rel=1e-9)
    theta_dot, _ = reference.euler_rates("body123", "fixed", [0.3, near, -0.4], [0.5, -0.2, 0.9],
                                         [0.1, 0.2, -0.3])
    assert np.allclose(values[:3], theta_dot, rtol=1e-10)
    warnings = [m for s, c, m in instance.messages if s == "Warning"]
    assert warnings == [
        f"EulerRates: theta[2] = {'%.17g' % near} is near the singular configuration of body123 (theta[2] = "
        f"+-pi/2): singularity_distance = {values[12]:g} < tolerance = 0.001; theta_dot[1] and "
        "theta_dot[3] grow as 1/singularity_distance"]
    # Outside the tolerance: no warning.
    assert instance.set({"theta[2]": np.pi / 2 - 2e-3}) == 0
    assert get_raw(instance, ER_OUTPUTS)[0] == 0


@pytest.mark.parametrize("name", ["body123", "space321", "body313", "space121"])
def test_at_the_singularity_discard_keeps_the_last_valid_values_and_recovers(name, make_euler_instance):
    good = dict(GOOD_INPUTS)
    singular = dict(GOOD_INPUTS, **{"theta[2]": singular_value(name)})
    instance = euler(make_euler_instance, name, inputs=good)
    status, valid = get_raw(instance, ER_OUTPUTS)
    assert status == 0
    assert instance.set(singular) == 0  # a valid number: accepted
    status, kept = get_raw(instance, ER_OUTPUTS)
    assert status == 2  # fmi2Discard
    assert np.array_equal(kept[:12], valid[:12])  # nothing garbage, nothing lost
    assert kept[12] == 0.0 or kept[12] < 1e-15  # the current distance
    message = [m for s, c, m in instance.messages if s == "Discard"][-1]
    shown = "0 or pi" if proper(name) else "+-pi/2"
    assert message == (
        f"EulerRates: theta[2] = {'%.17g' % singular['theta[2]']} is at the singular configuration of {name} "
        f"(theta[2] = {shown}): singularity_distance = {kept[12]:g}; theta_dot and theta_ddot are not "
        "defined there; the outputs keep their last valid values")
    assert instance.get(["theta[2]"])[0] == singular["theta[2]"]
    # Recovery: a later input away from the singularity.
    assert instance.set(good) == 0
    status, again = get_raw(instance, ER_OUTPUTS)
    assert status == 0 and np.array_equal(again, valid)


def test_do_step_discards_a_step_ending_at_the_singularity(make_euler_instance):
    instance = euler(make_euler_instance, "body123", inputs=GOOD_INPUTS)
    assert instance.call("fmi2DoStep", 0.0, 0.1, 1) == 0
    status, valid = get_raw(instance, ER_OUTPUTS)
    state = instance.fmu.getFMUstate()
    assert instance.set({"theta[2]": np.pi / 2}) == 0
    assert instance.call("fmi2DoStep", 0.1, 0.1, 1) == 2  # fmi2Discard
    assert any("fmi2DoStep: the step from 0.10000000000000001 to 0.20000000000000001 is discarded"
               in m for s, c, m in instance.messages if s == "Discard")
    last = ctypes.c_double()
    assert instance.call("fmi2GetRealStatus", 2, ctypes.byref(last)) == 0  # fmi2LastSuccessfulTime
    assert last.value == 0.1
    terminated = ctypes.c_int(1)
    assert instance.call("fmi2GetBooleanStatus", 3, ctypes.byref(terminated)) == 0  # fmi2Terminated
    assert terminated.value == 0
    status, kept = get_raw(instance, ER_OUTPUTS[:12])
    assert status == 2 and np.array_equal(kept, valid[:12])
    # StepFailed: no further step, no input; going back with the FMU state works.
    assert instance.call("fmi2DoStep", 0.1, 0.1, 1) == 3
    instance.fmu.setFMUstate(state)
    assert instance.call("fmi2DoStep", 0.1, 0.1, 1) == 0
    assert get_raw(instance, ER_OUTPUTS) [0] == 0
    instance.fmu.freeFMUstate(state)


def test_model_exchange_discards_at_the_singularity_and_recovers(make_euler_instance):
    instance = euler(make_euler_instance, "body123", fmi_type="ModelExchange", inputs=GOOD_INPUTS)
    instance.fmu.enterContinuousTimeMode()
    status, valid = get_raw(instance, ER_OUTPUTS)
    assert status == 0
    instance.fmu.setTime(0.5)
    assert instance.set({"theta[2]": -np.pi / 2}) == 0
    status, kept = get_raw(instance, ER_OUTPUTS)
    assert status == 2 and np.array_equal(kept[:12], valid[:12])
    assert instance.set({"theta[2]": 0.4}) == 0
    assert get_raw(instance, ER_OUTPUTS)[0] == 0


def test_parameters_and_their_bad_values(make_euler_instance):
    instance = make_euler_instance()
    # Bad values in Instantiated are refused as in InitializationMode.
    assert instance.set_integer({"frame": 0}) == 3
    instance.fmu.setupExperiment(startTime=0.0)
    instance.fmu.enterInitializationMode()
    assert instance.get_integer(["sequence", "frame"]) == [1, 1]
    assert instance.get(["tolerance"])[0] == 1e-4
    assert instance.set_integer({"frame": 3}) == 3
    assert instance.set_integer({"sequence": 0}) == 3
    assert instance.set({"tolerance": 1.5}) == 3
    assert instance.set({"tolerance": float("nan")}) == 3
    assert instance.errors() == [
        "fmi2SetInteger: frame = 0 (vr[0] = 23) is not an item of the Enumeration Frame (1 fixed, 2 "
        "body); no value set",
        "fmi2SetInteger: frame = 3 (vr[0] = 23) is not an item of the Enumeration Frame (1 fixed, 2 "
        "body); no value set",
        "fmi2SetInteger: sequence = 0 (vr[0] = 22) is not an item of the Enumeration Sequence (1 "
        "body123 .. 24 space323); no value set",
        "fmi2SetReal: tolerance = 1.5 (vr[0] = 24) is outside [0, 1], the range of "
        "singularity_distance; no value set",
        "fmi2SetReal: tolerance = nan (vr[0] = 24) is not finite; no value set"]
    assert instance.get_integer(["sequence", "frame"]) == [1, 1]
    assert instance.set_integer({"frame": 2, "sequence": 24}) == 0
    assert instance.set({"tolerance": 0.25}) == 0
    assert instance.set(GOOD_INPUTS) == 0
    instance.fmu.exitInitializationMode()
    assert instance.get_integer(["sequence", "frame"]) == [24, 2]
    # Variability fixed: refused after initialization.
    assert instance.set_integer({"frame": 1}) == 3
    assert instance.set({"tolerance": 0.5}) == 3
    assert instance.errors()[-2:] == [
        "fmi2SetInteger: frame (vr[0] = 23) is a parameter of variability fixed: it can be set only "
        "in Instantiated and InitializationMode, not in StepComplete; no value set",
        "fmi2SetReal: tolerance (vr[0] = 24) is a parameter of variability fixed: it can be set only "
        "in Instantiated and InitializationMode, not in StepComplete; no value set"]
    assert instance.get_integer(["frame"]) == [2] and instance.get(["tolerance"])[0] == 0.25
    # A proper Euler sequence (space323) in body components, distance |sin 0.4| > 0.25: no warning.
    assert get_raw(instance, ER_OUTPUTS)[0] == 0
    instance.fmu.reset()
    instance.fmu.setupExperiment(startTime=0.0)
    instance.fmu.enterInitializationMode()
    assert instance.get_integer(["sequence", "frame"]) == [1, 1]


def test_fmu_state_round_trip_with_parameters(make_euler_instance):
    first = euler(make_euler_instance, "space231", frame=2, tolerance=0.01, inputs=GOOD_INPUTS)
    data = first.fmu.serializeFMUstate(first.fmu.getFMUstate())
    assert len(data) == 436
    second = make_euler_instance()
    second.fmu.setFMUstate(second.fmu.deSerializeFMUstate(data))
    assert second.get_integer(["sequence", "frame"]) == [SEQUENCES.index("space231") + 1, 2]
    assert second.get(["tolerance"])[0] == 0.01
    assert np.array_equal(get_raw(second, ER_OUTPUTS)[1], get_raw(first, ER_OUTPUTS)[1])


def test_interpolated_inputs_and_variable_steps(make_euler_instance):
    """canInterpolateInputs and canHandleVariableCommunicationStepSize: the inputs follow their
    polynomials over steps of any size, and the outputs are those of the inputs at the step end."""
    instance = euler(make_euler_instance, "body321", inputs=GOOD_INPUTS)
    vr = (ctypes.c_uint * 2)(instance.vr["theta[1]"], instance.vr["omega[2]"])
    assert instance.call("fmi2SetRealInputDerivatives", vr, 2, (ctypes.c_int * 2)(1, 1),
                         (ctypes.c_double * 2)(0.5, -1.0)) == 0
    t = 0.0
    for h in (0.01, 0.2, 0.003):
        assert instance.call("fmi2DoStep", t, h, 1) == 0
        t += h
    theta1, omega2 = instance.get(["theta[1]", "omega[2]"])
    assert theta1 == pytest.approx(0.3 + 0.5 * t, abs=1e-15)
    assert omega2 == pytest.approx(-0.2 - 1.0 * t, abs=1e-15)
    x = dict(GOOD_INPUTS, **{"theta[1]": theta1, "omega[2]": omega2})
    theta_dot, _ = reference.euler_rates("body321", "fixed", [x[n] for n in ER_INPUTS[:3]],
                                         [x[n] for n in ER_INPUTS[3:6]], [x[n] for n in ER_INPUTS[6:]])
    assert np.allclose(get_raw(instance, ER_OUTPUTS)[1][:3], theta_dot, rtol=1e-14, atol=1e-15)
