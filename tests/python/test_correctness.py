"""The FMU's outputs against the independent sympy reference, over many random states.

The error of an output is measured against the natural size of the terms it sums:
sum|theta_dot| for omega, sum|theta_ddot| + (sum|theta_dot|)^2 for alpha. A plain relative error
would mean little near gimbal lock, where the outputs cancel far below their terms."""
import numpy as np
import pytest

from codegen import reference

TOLERANCE = 1e-14
RNG_SEED = 20261121


def random_states(kind, count, rng):
    """Inputs (count x 9) of one kind of state."""
    theta = rng.uniform(-np.pi, np.pi, (count, 3))
    if kind == "beyond_pi":
        theta = rng.uniform(-60.0, 60.0, (count, 3))
    elif kind == "near_gimbal_lock":
        offsets = 10.0 ** rng.uniform(-12, -1, count) * rng.choice([-1, 1], count)
        theta[:, 1] = rng.choice([-np.pi / 2, np.pi / 2], count) + offsets
    elif kind == "at_gimbal_lock":
        theta[:, 1] = rng.choice([-np.pi / 2, np.pi / 2], count)
    # Every component its own magnitude, from 1e-6 to 1e6, so that small terms sit beside big ones.
    theta_dot = 10.0 ** rng.uniform(-6, 6, (count, 3)) * rng.uniform(-1, 1, (count, 3))
    theta_ddot = 10.0 ** rng.uniform(-6, 6, (count, 3)) * rng.uniform(-1, 1, (count, 3))
    return np.hstack([theta, theta_dot, theta_ddot])


def scaled_errors(got, expected, inputs):
    theta_dot, theta_ddot = inputs[3:6], inputs[6:9]
    omega_scale = np.abs(theta_dot).sum()
    alpha_scale = np.abs(theta_ddot).sum() + omega_scale ** 2
    scale = np.array([omega_scale] * 6 + [alpha_scale] * 6)
    return np.abs(got - expected) / scale


@pytest.mark.parametrize("kind", ["in_pi", "beyond_pi", "near_gimbal_lock", "at_gimbal_lock"])
def test_outputs_match_reference(kind, make_instance, report):
    rng = np.random.default_rng([RNG_SEED, len(kind)])
    states = random_states(kind, 1500, rng)
    instance = make_instance()
    instance.initialize()
    worst = np.zeros(12)
    for inputs in states:
        assert instance.set(dict(zip(reference.INPUT_NAMES, inputs))) == 0
        got = instance.get(reference.OUTPUT_NAMES)
        worst = np.maximum(worst, scaled_errors(got, reference.outputs(inputs), inputs))
    report(f"{len(states)} states, worst scaled error omega {worst[:6].max():.2e}, "
           f"alpha {worst[6:].max():.2e} (tolerance {TOLERANCE:g})")
    for name, error in zip(reference.OUTPUT_NAMES, worst):
        assert error <= TOLERANCE, f"{name}: scaled error {error:.3e}"

# The dependency check of <ModelStructure> covers every sequence: test_sequences_fmu.py.
