"""Input interpolation (canInterpolateInputs): with fmi2SetRealInputDerivatives the inputs follow
u(t) + (s - t) du/dt (+ (s - t)^2/2 d2u/dt2) over fmi2DoStep(t, h), so the outputs at t + h are
those of the extrapolated inputs; fmpy's set_input_derivatives removes the one-step lag of the
zero-order hold."""
import ctypes

import numpy as np
import pytest
from fmpy import simulate_fmu

from codegen import reference
from demo import trajectories

INPUTS = dict(zip(reference.INPUT_NAMES, [0.3, -0.7, 1.1, 0.5, -1.5, 2.0, 3.0, -0.25, 0.8]))


def set_derivatives(instance, entries):
    """fmi2SetRealInputDerivatives for (name, order, value) entries; returns the status."""
    vr = (ctypes.c_uint * len(entries))(*[instance.vr[n] for n, _, _ in entries])
    order = (ctypes.c_int * len(entries))(*[o for _, o, _ in entries])
    value = (ctypes.c_double * len(entries))(*[v for _, _, v in entries])
    return instance.call("fmi2SetRealInputDerivatives", vr, len(entries), order, value)


def evaluations(instance):
    return sum("kinematics evaluated" in m for _, _, m in instance.messages)


@pytest.mark.parametrize("step", [4e-2, 1e-2])
def test_set_input_derivatives_removes_the_zero_order_hold_lag(step, fmu_path, report):
    stop = 2.0
    times = np.arange(0.0, stop + step / 2, step)
    signals = trajectories.input_signals(times)
    exact = np.array([reference.outputs(row) for row in
                      np.hstack(trajectories.tumbling(times))])
    errors = {}
    for interpolate in (False, True):
        result = simulate_fmu(fmu_path, stop_time=stop, output_interval=step, input=signals,
                              output=reference.OUTPUT_NAMES, set_input_derivatives=interpolate)
        assert np.allclose(result["time"], times, atol=1e-12)
        got = np.column_stack([result[n] for n in reference.OUTPUT_NAMES])
        # Row k is read at t_k: compare with the kinematics of the exact inputs at t_k.
        errors[interpolate] = np.abs(got[2:] - exact[2:]).max() / np.abs(exact).max()
    ratio = errors[False] / errors[True]
    report(f"h = {step:g}: max output error / max|output|: zero-order hold {errors[False]:.2e}, "
           f"input derivatives {errors[True]:.2e}, {ratio:.0f}x smaller")
    # Zero-order hold lags by one step (error ~ h); fmpy's backward-difference slopes make the
    # extrapolation error ~ h^2.
    assert errors[True] < errors[False] / 10
    assert errors[True] < 2 * step ** 2 * 10


def test_inputs_and_outputs_follow_the_polynomial_over_a_step(make_instance):
    instance = make_instance()
    instance.initialize(inputs=INPUTS, start_time=1.0)
    d1 = {"theta[1]": 0.4, "theta[2]": -2.0, "theta_dot[3]": 1.5, "theta_ddot[2]": 10.0}
    d2 = {"theta[2]": 3.0, "theta_ddot[1]": -8.0}
    assert set_derivatives(instance, [(n, 1, v) for n, v in d1.items()] +
                           [(n, 2, v) for n, v in d2.items()]) == 0
    h = 0.125
    assert instance.call("fmi2DoStep", 1.0, h, 1) == 0
    moved = {n: INPUTS[n] + h * (d1.get(n, 0.0) + 0.5 * h * d2.get(n, 0.0)) for n in INPUTS}
    assert np.allclose(instance.get(reference.INPUT_NAMES), list(moved.values()), rtol=1e-15, atol=0)
    assert np.allclose(instance.get(reference.OUTPUT_NAMES),
                       reference.outputs(list(moved.values())), rtol=1e-14, atol=1e-14)
    # Without new values the polynomials go on: the slope moved with the second derivative.
    assert instance.call("fmi2DoStep", 1.0 + h, h, 1) == 0
    two = {n: INPUTS[n] + 2 * h * (d1.get(n, 0.0) + 0.5 * 2 * h * d2.get(n, 0.0)) for n in INPUTS}
    assert np.allclose(instance.get(reference.INPUT_NAMES), list(two.values()), rtol=1e-14, atol=0)


def test_set_real_forgets_that_inputs_derivatives_only(make_instance):
    instance = make_instance()
    instance.initialize(inputs=INPUTS)
    assert set_derivatives(instance, [("theta[1]", 1, 1.0), ("theta[2]", 1, 1.0),
                                      ("theta[2]", 2, 4.0)]) == 0
    assert instance.set({"theta[2]": 0.5}) == 0  # a new value at this point, with no slope
    assert instance.call("fmi2DoStep", 0.0, 0.5, 1) == 0
    got = dict(zip(reference.INPUT_NAMES, instance.get(reference.INPUT_NAMES)))
    assert got["theta[1]"] == INPUTS["theta[1]"] + 0.5
    assert got["theta[2]"] == 0.5  # held
    assert got["theta[3]"] == INPUTS["theta[3]"]


def test_zero_order_hold_steps_cost_no_evaluation(make_instance):
    instance = make_instance(logging_on=True)
    instance.initialize(inputs=INPUTS)
    instance.get(reference.OUTPUT_NAMES)
    assert set_derivatives(instance, [("theta[1]", 1, 0.0), ("theta[1]", 2, 0.0)]) == 0
    for k in range(5):
        assert instance.call("fmi2DoStep", 0.1 * k, 0.1, 1) == 0
        instance.get(reference.OUTPUT_NAMES)
    assert evaluations(instance) == 1  # zero derivatives: nothing moved, nothing recomputed
    assert set_derivatives(instance, [("theta_ddot[3]", 1, 2.0)]) == 0
    assert evaluations(instance) == 1
    assert instance.call("fmi2DoStep", 0.5, 0.1, 1) == 0
    instance.get(reference.OUTPUT_NAMES)
    instance.get(reference.OUTPUT_NAMES)
    assert evaluations(instance) == 2


def test_allowed_before_initialization_and_kept_through_it(make_instance):
    instance = make_instance()
    assert set_derivatives(instance, [("theta[3]", 1, 2.0)]) == 0  # Instantiated
    instance.fmu.setupExperiment(startTime=0.0)
    instance.fmu.enterInitializationMode()
    assert set_derivatives(instance, [("theta[1]", 1, -1.0)]) == 0  # InitializationMode
    instance.fmu.exitInitializationMode()
    assert instance.call("fmi2DoStep", 0.0, 0.25, 1) == 0
    assert np.array_equal(instance.get(["theta[1]", "theta[3]"]), [-0.25, 0.5])
    instance.fmu.terminate()
    assert set_derivatives(instance, [("theta[1]", 1, 1.0)]) == 3
    assert instance.errors() == ["fmi2SetRealInputDerivatives: illegal call in state Terminated"]


@pytest.mark.parametrize("entries,message", [
    ([("theta[1]", 1, 1.0), ("theta[2]", 0, 1.0)],
     "fmi2SetRealInputDerivatives: order[1] = 0 for theta[2]: this FMU takes orders 1 to 2; no "
     "derivative set"),
    ([("theta[1]", 1, 1.0), ("theta[2]", 3, 1.0)],
     "fmi2SetRealInputDerivatives: order[1] = 3 for theta[2]: this FMU takes orders 1 to 2; no "
     "derivative set"),
    ([("theta[1]", 1, 1.0), ("omega_fixed[1]", 1, 1.0)],
     "fmi2SetRealInputDerivatives: vr[1] = 9 is omega_fixed[1], an output; expected an input"),
    ([("theta[1]", 1, 1.0), ("theta_dot[1]", 2, float("inf"))],
     "fmi2SetRealInputDerivatives: derivative of order 2 of theta_dot[1] = inf (vr[1] = 3) is not "
     "finite; no derivative set"),
])
def test_bad_derivatives_are_refused_and_nothing_is_set(entries, message, make_instance):
    instance = make_instance()
    instance.initialize(inputs=INPUTS)
    assert set_derivatives(instance, entries) == 3
    assert instance.errors() == [message]
    assert instance.call("fmi2DoStep", 0.0, 0.5, 1) == 0
    assert np.array_equal(instance.get(reference.INPUT_NAMES), list(INPUTS.values()))  # held


def test_null_arrays_and_overflow(make_instance):
    instance = make_instance()
    instance.initialize(inputs=INPUTS)
    vr = (ctypes.c_uint * 1)(0)
    value = (ctypes.c_double * 1)(1e308)
    assert instance.call("fmi2SetRealInputDerivatives", vr, 1, None, value) == 3
    order = (ctypes.c_int * 1)(1)
    assert instance.call("fmi2SetRealInputDerivatives", vr, 1, order, value) == 0
    assert instance.call("fmi2DoStep", 0.0, 10.0, 1) == 3  # 0.3 + 10 * 1e308 overflows
    assert instance.errors() == [
        "fmi2SetRealInputDerivatives: order is NULL with nvr = 1",
        "fmi2DoStep: extrapolating theta[1] = 0.29999999999999999 with derivatives 1e+308 (order 1) "
        "and 0 (order 2) over communicationStepSize = 10 overflows; step not taken"]
    assert instance.fmu.getRealStatus(2) == 0.0  # the step was not taken
    assert instance.get(["theta[1]"])[0] == 0.3
    assert instance.call("fmi2DoStep", 0.0, 1e-9, 1) == 0


def test_reset_forgets_the_derivatives(make_instance):
    instance = make_instance()
    instance.initialize(inputs=INPUTS)
    assert set_derivatives(instance, [("theta[1]", 1, 1.0), ("theta_dot[2]", 2, 3.0)]) == 0
    assert instance.call("fmi2Reset") == 0
    instance.initialize(inputs=INPUTS)
    assert instance.call("fmi2DoStep", 0.0, 0.5, 1) == 0
    assert np.array_equal(instance.get(reference.INPUT_NAMES), list(INPUTS.values()))
