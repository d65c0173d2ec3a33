"""Output derivatives (maxOutputDerivativeOrder = 1): d(omega)/dt is alpha in both frames'
components; d(alpha)/dt is exact when the derivative of theta_ddot is given through
fmi2SetRealInputDerivatives, and is the value with theta_dddot = 0 otherwise (docs/capabilities.md)."""
import ctypes

import numpy as np
import pytest

from codegen import reference
from demo import trajectories

INPUTS = dict(zip(reference.INPUT_NAMES, [0.3, -0.7, 1.1, 0.5, -1.5, 2.0, 3.0, -0.25, 0.8]))
OMEGA = reference.OUTPUT_NAMES[:6]
ALPHA = reference.OUTPUT_NAMES[6:]


def theta_dddot(times):
    t = np.asarray(times, dtype=float)[:, None]
    argument = trajectories.FREQUENCY * t + trajectories.PHASE
    return -trajectories.AMPLITUDE * trajectories.FREQUENCY ** 3 * np.cos(argument)


def set_derivatives(instance, entries):
    vr = (ctypes.c_uint * len(entries))(*[instance.vr[n] for n, _, _ in entries])
    order = (ctypes.c_int * len(entries))(*[o for _, o, _ in entries])
    value = (ctypes.c_double * len(entries))(*[v for _, _, v in entries])
    return instance.call("fmi2SetRealInputDerivatives", vr, len(entries), order, value)


def output_derivatives(instance, names, order=1):
    """(status, values) of fmi2GetRealOutputDerivatives."""
    vr = (ctypes.c_uint * len(names))(*[instance.vr[n] for n in names])
    orders = (ctypes.c_int * len(names))(*([order] * len(names)))
    value = (ctypes.c_double * len(names))(*([-7.0] * len(names)))
    status = instance.call("fmi2GetRealOutputDerivatives", vr, len(names), orders, value)
    return status, np.array(value)


def test_derivatives_match_finite_differences_of_a_simulation(make_instance, report):
    """A co-simulation on the tumbling trajectory; the master sets the exact inputs of each
    communication point and the derivative of theta_ddot, then reads outputs and derivatives."""
    h = 1e-3
    times = np.arange(0.0, 1.0, h)
    inputs = np.hstack(trajectories.tumbling(times))
    jerk_input = theta_dddot(times)
    instance = make_instance()
    instance.initialize(inputs=dict(zip(reference.INPUT_NAMES, inputs[0])))
    outputs, derivatives = [], []
    for k, t in enumerate(times):
        if k > 0:
            assert instance.call("fmi2DoStep", times[k - 1], t - times[k - 1], 1) == 0
        assert instance.set(dict(zip(reference.INPUT_NAMES, inputs[k]))) == 0
        assert set_derivatives(instance, [(f"theta_ddot[{i + 1}]", 1, jerk_input[k, i])
                                          for i in range(3)]) == 0
        outputs.append(instance.get(reference.OUTPUT_NAMES))
        status, values = output_derivatives(instance, reference.OUTPUT_NAMES)
        assert status == 0
        derivatives.append(values)
    y, dy = np.array(outputs), np.array(derivatives)
    central = (y[:-4] - 8 * y[1:-3] + 8 * y[3:-1] - y[4:]) / (12 * h)  # fourth order
    error = np.abs(central - dy[2:-2]).max(axis=0) / np.abs(dy).max(axis=0)
    report(f"{len(times)} points, h = {h:g}: largest |finite difference - derivative| / max|derivative|"
           f" omega {error[:6].max():.1e}, alpha {error[6:].max():.1e}")
    assert error.max() < 1e-9
    # d(omega)/dt is alpha itself, component by component in both frames.
    assert np.array_equal(dy[:, :6], y[:, 6:])


@pytest.mark.parametrize("given", [False, True])
def test_alpha_derivative_against_reference(given, make_instance):
    instance = make_instance(logging_on=True)
    instance.initialize(inputs=INPUTS)
    third = [0.7, -1.3, 2.2] if given else [0.0, 0.0, 0.0]
    if given:
        assert set_derivatives(instance, [(f"theta_ddot[{i + 1}]", 1, third[i]) for i in range(3)]) == 0
    status, got = output_derivatives(instance, ALPHA)
    assert status == 0
    expected = reference.jerk(list(INPUTS.values()), third)
    assert np.allclose(got, expected, rtol=1e-14, atol=1e-14)
    notes = [m for _, _, m in instance.messages if "uses theta_dddot = 0" in m]
    assert len(notes) == (0 if given else 6)
    if not given:
        assert notes[0] == ("fmi2GetRealOutputDerivatives: d(alpha_fixed[1])/dt uses theta_dddot = 0 "
                            "(no nonzero derivative of theta_ddot was given)")
        # theta_dddot = 0 is what is assumed without it; a given one changes the answer.
        assert not np.allclose(got, reference.jerk(list(INPUTS.values()), [0.7, -1.3, 2.2]))


def test_theta_dddot_moves_with_its_own_derivative_over_a_step(make_instance):
    instance = make_instance()
    instance.initialize(inputs=INPUTS)
    assert set_derivatives(instance, [("theta_ddot[2]", 1, 1.0), ("theta_ddot[2]", 2, 4.0)]) == 0
    assert instance.call("fmi2DoStep", 0.0, 0.5, 1) == 0
    moved = instance.get(reference.INPUT_NAMES)
    status, got = output_derivatives(instance, ALPHA)
    assert status == 0
    # theta_ddot[2] moved by 0.5 * 1 + 0.125 * 4 and its derivative is now 1 + 0.5 * 4 = 3.
    assert moved[7] == INPUTS["theta_ddot[2]"] + 1.0
    assert np.allclose(got, reference.jerk(moved, [0.0, 3.0, 0.0]), rtol=1e-14, atol=1e-14)


def test_any_subset_in_any_order(make_instance):
    instance = make_instance()
    instance.initialize(inputs=INPUTS)
    names = ["alpha_body[2]", "omega_fixed[3]", "alpha_body[2]", "omega_body[1]"]
    status, got = output_derivatives(instance, names)
    assert status == 0
    alpha = dict(zip(ALPHA, instance.get(ALPHA)))
    jerk = dict(zip(ALPHA, reference.jerk(list(INPUTS.values()), [0, 0, 0])))
    assert got[1] == alpha["alpha_fixed[3]"] and got[3] == alpha["alpha_body[1]"]
    assert got[0] == got[2] and np.isclose(got[0], jerk["alpha_body[2]"], rtol=1e-14)


@pytest.mark.parametrize("names,order,message", [
    (["omega_fixed[1]", "theta[1]"], 1, "fmi2GetRealOutputDerivatives: vr[1] = 0 is theta[1], an "
                                        "input; expected an output"),
    (["omega_fixed[1]"], 2, "fmi2GetRealOutputDerivatives: order[0] = 2 for omega_fixed[1]: this FMU "
                            "gives order 1 only (maxOutputDerivativeOrder)"),
    (["alpha_body[3]"], 0, "fmi2GetRealOutputDerivatives: order[0] = 0 for alpha_body[3]: this FMU "
                           "gives order 1 only (maxOutputDerivativeOrder)"),
])
def test_bad_requests_are_refused_and_write_nothing(names, order, message, make_instance):
    instance = make_instance()
    instance.initialize(inputs=INPUTS)
    status, got = output_derivatives(instance, names, order)
    assert status == 3
    assert instance.errors() == [message]
    assert np.all(got == -7.0)


def test_null_arrays_and_states(make_instance):
    instance = make_instance()
    instance.fmu.setupExperiment(startTime=0.0)
    instance.fmu.enterInitializationMode()
    status, _ = output_derivatives(instance, ["omega_fixed[1]"])
    assert status == 3
    instance.fmu.exitInitializationMode()
    vr = (ctypes.c_uint * 1)(9)
    order = (ctypes.c_int * 1)(1)
    assert instance.call("fmi2GetRealOutputDerivatives", vr, 1, order, None) == 3
    assert instance.call("fmi2GetRealOutputDerivatives", None, 0, None, None) == 0
    instance.fmu.terminate()
    status, _ = output_derivatives(instance, ["omega_fixed[1]"])
    assert status == 0  # still readable after fmi2Terminate
    assert instance.errors() == [
        "fmi2GetRealOutputDerivatives: illegal call in state InitializationMode",
        "fmi2GetRealOutputDerivatives: value is NULL with nvr = 1"]
