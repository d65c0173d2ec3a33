"""Simulations through fmpy with smooth, consistent inputs theta(t) and their exact derivatives."""
import numpy as np
import pytest
from fmpy import simulate_fmu

from codegen import reference
from demo import trajectories

STEP = 1e-3
STOP = 4.0


@pytest.fixture(scope="module")
def simulation(fmu_path):
    times = np.arange(0.0, STOP + STEP / 2, STEP)
    result = simulate_fmu(fmu_path, stop_time=STOP, output_interval=STEP,
                          input=trajectories.input_signals(times),
                          output=reference.INPUT_NAMES + reference.OUTPUT_NAMES)
    return times, result


def vectors(result, name):
    return np.column_stack([result[f"{name}[{i}]"] for i in (1, 2, 3)])


def test_result_grid_and_zero_order_hold(simulation):
    times, result = simulation
    assert np.allclose(result["time"], times, atol=1e-12)
    theta, _, _ = trajectories.tumbling(times)
    # fmpy sets the inputs of t, then steps to t + h: each row after the first holds the previous
    # grid point's inputs, and the outputs of those inputs.
    assert np.array_equal(vectors(result, "theta")[0], theta[0])
    assert np.array_equal(vectors(result, "theta")[1:], theta[:-1])


def test_outputs_match_reference(simulation, report):
    _, result = simulation
    worst = 0.0
    for row in result[::20]:
        inputs = np.array([row[n] for n in reference.INPUT_NAMES])
        got = np.array([row[n] for n in reference.OUTPUT_NAMES])
        scale_w = np.abs(inputs[3:6]).sum()
        scale = np.array([scale_w] * 6 + [np.abs(inputs[6:9]).sum() + scale_w ** 2] * 6)
        worst = max(worst, (np.abs(got - reference.outputs(inputs)) / scale).max())
    report(f"{len(result[::20])} rows, worst scaled error {worst:.2e}")
    assert worst <= 1e-14


def test_alpha_is_the_time_derivative_of_omega(simulation, report):
    _, result = simulation
    # Rows from the second on are the kinematics at the grid times 0, h, 2h, ... (see above).
    rows = result[1:]
    for frame in ("fixed", "body"):
        omega, alpha = vectors(rows, f"omega_{frame}"), vectors(rows, f"alpha_{frame}")
        # Fourth-order central difference.
        derivative = (omega[:-4] - 8 * omega[1:-3] + 8 * omega[3:-1] - omega[4:]) / (12 * STEP)
        error = np.abs(derivative - alpha[2:-2]).max() / np.abs(alpha).max()
        report(f"{frame}: largest |d(omega)/dt - alpha| / max|alpha| = {error:.1e}")
        assert error < 1e-9


def test_body_components_are_fixed_components_rotated(simulation, report):
    _, result = simulation
    theta = vectors(result, "theta")
    worst = 0.0
    for k in range(0, len(result), 10):
        R = reference.rotation_matrix(theta[k])
        assert np.allclose(R @ R.T, np.eye(3), atol=1e-14)
        for name in ("omega", "alpha"):
            fixed, body = vectors(result[k:k + 1], f"{name}_fixed")[0], vectors(result[k:k + 1], f"{name}_body")[0]
            error = np.abs(R.T @ fixed - body).max() / max(np.abs(fixed).max(), 1e-300)
            worst = max(worst, error)
    report(f"largest |R^T v_fixed - v_body| / |v| = {worst:.1e}")
    assert worst < 1e-14


def test_master_that_sets_inputs_before_reading_has_no_lag(make_instance):
    """A master that sets the inputs of t + h before reading at t + h gets the kinematics of t + h."""
    times = np.arange(0.0, 1.0, 0.01)
    theta, theta_dot, theta_ddot = trajectories.tumbling(times)
    inputs = np.hstack([theta, theta_dot, theta_ddot])
    instance = make_instance()
    instance.initialize(inputs=dict(zip(reference.INPUT_NAMES, inputs[0])))
    for k in range(1, len(times)):
        instance.fmu.doStep(times[k - 1], times[k] - times[k - 1])
        assert instance.set(dict(zip(reference.INPUT_NAMES, inputs[k]))) == 0
        got = instance.get(reference.OUTPUT_NAMES)
        assert np.allclose(got, reference.outputs(inputs[k]), rtol=1e-13, atol=1e-13)
