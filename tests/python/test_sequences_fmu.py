"""AngularKinematics for all 24 rotation sequences, through the FMU (fmpy), against the independent
sympy reference (codegen/reference.py): every output, the dependencies <ModelStructure> lists,
the exact directional derivatives and the output derivatives.

Errors are scaled by the natural size of the terms an output sums: sum|theta_dot| for omega and
W_dot, sum|theta_ddot| + (sum|theta_dot|)^2 for alpha, 1 for R, q and W."""
import ctypes

import numpy as np
import pytest

from codegen import reference
from conftest import sequence_cases
from codegen.project import SEQUENCES

INPUTS = reference.KINEMATICS_INPUTS
OUTPUTS = reference.FMU_OUTPUTS
TOLERANCE = 1e-14
RNG_SEED = 20261121


def scales(inputs):
    theta_dot, theta_ddot = np.asarray(inputs[3:6]), np.asarray(inputs[6:9])
    omega = np.abs(theta_dot).sum()
    alpha = np.abs(theta_ddot).sum() + omega ** 2
    # omega, alpha, R, q, W_fixed and W_body, their derivatives, then outputs computed from these
    # (an angle for rotation_angle).
    return np.array([omega] * 6 + [alpha] * 6 + [1.0] * 9 + [1.0] * 4 + [1.0] * 18 + [omega] * 18 +
                    [1.0] * len(reference.DERIVED_OUTPUTS))


def singular_value(name):
    return 0.0 if name[-3] == name[-1] else np.pi / 2


def states(name, count, rng):
    """Random states: a third generic, a third near the sequence's singular theta2, a third at it."""
    theta = rng.uniform(-np.pi, np.pi, (count, 3))
    third = count // 3
    offsets = 10.0 ** rng.uniform(-12, -1, third) * rng.choice([-1, 1], third)
    theta[third:2 * third, 1] = rng.choice([-1, 1], third) * singular_value(name) + offsets
    theta[2 * third:, 1] = rng.choice([-1, 1], count - 2 * third) * singular_value(name)
    rates = 10.0 ** rng.uniform(-3, 3, (count, 6)) * rng.uniform(-1, 1, (count, 6))
    return np.hstack([theta, rates])


def instance_for(make_instance, name, **kwargs):
    instance = make_instance(**kwargs)
    instance.initialize(parameters={"sequence": SEQUENCES.index(name) + 1})
    return instance


@pytest.mark.parametrize("name", sequence_cases())
def test_outputs_match_reference(name, make_instance, report):
    rng = np.random.default_rng([RNG_SEED, SEQUENCES.index(name)])
    instance = instance_for(make_instance, name)
    assert instance.get_integer(["sequence"]) == [SEQUENCES.index(name) + 1]
    worst = np.zeros(len(OUTPUTS))
    for inputs in states(name, 30, rng):
        assert instance.set(dict(zip(INPUTS, inputs))) == 0
        got = instance.get(OUTPUTS)
        expected = reference.fmu_outputs(name, inputs)
        worst = np.maximum(worst, np.abs(got - expected) / scales(inputs))
    groups = {"omega": worst[:6], "alpha": worst[6:12], "R": worst[12:21], "q": worst[21:25],
              "W": worst[25:43], "W_dot": worst[43:]}
    report(f"30 states: worst scaled error " +
           ", ".join(f"{k} {v.max():.1e}" for k, v in groups.items()))
    for output, error in zip(OUTPUTS, worst):
        assert error <= TOLERANCE, f"{name} {output}: scaled error {error:.3e}"


def test_body123_fast_path_equals_the_general_core_bit_for_bit(make_instance, report):
    """body123 (the default) runs the hand-written core ak_angular_kinematics_123; every other
    sequence the general core. space321 with the angles (and rates) in reverse order is the same
    rotation chain R1 R2 R3, computed by the general core: the two paths must give the same bits
    for omega and alpha, and the same rotation outputs up to the column order of W."""
    rng = np.random.default_rng([RNG_SEED, 123])
    fast = instance_for(make_instance, "body123")
    general = instance_for(make_instance, "space321")
    reverse = [2, 1, 0, 5, 4, 3, 8, 7, 6]
    for _ in range(200):
        x = np.hstack([rng.uniform(-4, 4, 3), rng.uniform(-50, 50, 6)])
        fast.set(dict(zip(INPUTS, x)))
        general.set(dict(zip(INPUTS, x[reverse])))
        assert np.array_equal(fast.get(OUTPUTS[:25]), general.get(OUTPUTS[:25]))  # omega, alpha, R, q
    report("200 states: body123 (hand-written) and space321 with reversed angles (general core) "
           "bit-identical in omega, alpha, R and q")


def test_each_output_moves_only_with_its_listed_inputs_and_the_union_is_exact(make_instance,
                                                                          model_description):
    """For every sequence, changing an input changes only outputs that list it; over all sequences,
    every listed dependency is exercised by some sequence (the union is exact). Any change of the
    double counts, so no dependency can hide in rounding."""
    listed = {u.variable.name: {d.name for d in u.dependencies} for u in model_description.outputs}
    rng = np.random.default_rng(RNG_SEED)
    seen = {output: set() for output in OUTPUTS}
    for name in SEQUENCES:
        instance = instance_for(make_instance, name)
        for _ in range(2):
            base = dict(zip(INPUTS, rng.uniform(-2, 2, 9)))
            instance.set(base)
            before = instance.get(OUTPUTS)
            for input_name in INPUTS:
                instance.set({input_name: base[input_name] + 0.25})
                after = instance.get(OUTPUTS)
                instance.set({input_name: base[input_name]})
                for output, b, a in zip(OUTPUTS, before, after):
                    if a != b:
                        assert input_name in listed[output], f"{name}: {output} moves with {input_name}"
                        seen[output].add(input_name)
        instance.free()
    assert seen == listed


def directional(instance, unknowns, knowns, seed):
    n, m = len(unknowns), len(knowns)
    result = (ctypes.c_double * n)()
    status = instance.call("fmi2GetDirectionalDerivative", (ctypes.c_uint * n)(*unknowns), n,
                           (ctypes.c_uint * m)(*knowns), m, (ctypes.c_double * m)(*seed), result)
    return status, np.array(result)


@pytest.mark.parametrize("name", sequence_cases())
def test_directional_derivatives_are_the_exact_jacobian(name, make_instance, report):
    """Every entry of d output / d input, every output x 9 inputs, against central differences on
    the 40-digit reference; scaled by the output's scale (per unit of input)."""
    rng = np.random.default_rng([RNG_SEED, 7, SEQUENCES.index(name)])
    instance = instance_for(make_instance, name)
    outputs = [instance.vr[o] for o in OUTPUTS]
    worst = 0.0
    for _ in range(2):
        inputs = np.hstack([rng.uniform(-np.pi, np.pi, 3), rng.uniform(-2, 2, 6)])
        instance.set(dict(zip(INPUTS, inputs)))
        expected = reference.fmu_jacobian(name, inputs)
        got = np.empty_like(expected)
        for k in range(9):
            status, got[:, k] = directional(instance, outputs, [k], [1.0])
            assert status == 0
        scale = np.maximum(scales(inputs), 1.0)[:, None] * (1 + np.abs(inputs).max())
        worst = max(worst, (np.abs(got - expected) / scale).max())
        # A seed combines the columns linearly.
        seed = rng.uniform(-1, 1, 9)
        status, combined = directional(instance, outputs, list(range(9)), list(seed))
        assert status == 0 and np.allclose(combined, got @ seed, rtol=1e-13, atol=1e-13)
    report(f"2 states x {len(OUTPUTS)} x 9 entries: worst scaled error {worst:.1e}")
    assert worst <= TOLERANCE


@pytest.mark.parametrize("name", sequence_cases())
def test_output_derivatives_are_the_chain_rule_of_the_reference(name, make_instance):
    """d y / dt = J (theta_dot, theta_ddot, theta_dddot) for every output, theta_dddot given as the
    first derivative of theta_ddot; d omega / dt is alpha itself."""
    instance = instance_for(make_instance, name)
    inputs = np.array([0.4, 1.1, -2.0, 0.7, -0.3, 1.9, 0.2, -1.2, 0.6])
    third = np.array([0.9, -0.4, 1.3])
    instance.set(dict(zip(INPUTS, inputs)))
    vr = (ctypes.c_uint * 3)(*[instance.vr[f"theta_ddot[{k}]"] for k in (1, 2, 3)])
    assert instance.call("fmi2SetRealInputDerivatives", vr, 3, (ctypes.c_int * 3)(1, 1, 1),
                         (ctypes.c_double * 3)(*third)) == 0
    outputs = [instance.vr[o] for o in OUTPUTS]
    got = (ctypes.c_double * len(outputs))()
    assert instance.call("fmi2GetRealOutputDerivatives", (ctypes.c_uint * len(outputs))(*outputs),
                         len(outputs), (ctypes.c_int * len(outputs))(*[1] * len(outputs)), got) == 0
    expected = reference.fmu_jacobian(name, inputs) @ np.hstack([inputs[3:], third])
    scale = np.maximum(scales(inputs), 1.0) * 10
    assert (np.abs(np.array(got) - expected) / scale).max() <= TOLERANCE
    assert np.array_equal(np.array(got)[:6], instance.get(OUTPUTS[6:12]))


def test_sequence_parameter_values_and_states(make_instance):
    instance = make_instance()
    assert instance.set_integer({"sequence": 25}) == 3  # in Instantiated: checked all the same
    instance.fmu.setupExperiment(startTime=0.0)
    instance.fmu.enterInitializationMode()
    assert instance.get_integer(["sequence"]) == [1]  # the default, body123
    assert instance.set_integer({"sequence": 0}) == 3
    assert instance.set_integer({"sequence": -2147483648}) == 3
    assert instance.set({"sequence": 2.0}) == 3  # an Integer (Enumeration), not a Real
    assert instance.errors() == [
        "fmi2SetInteger: sequence = 25 (vr[0] = 70) is not an item of the Enumeration Sequence "
        "(1 body123 .. 24 space323); no value set",
        "fmi2SetInteger: sequence = 0 (vr[0] = 70) is not an item of the Enumeration Sequence "
        "(1 body123 .. 24 space323); no value set",
        "fmi2SetInteger: sequence = -2147483648 (vr[0] = 70) is not an item of the Enumeration "
        "Sequence (1 body123 .. 24 space323); no value set",
        "fmi2SetReal: vr[0] = 70 is sequence, of type Integer, not Real"]
    assert instance.get_integer(["sequence"]) == [1]
    assert instance.set_integer({"sequence": SEQUENCES.index("space313") + 1}) == 0
    instance.fmu.exitInitializationMode()
    assert instance.set_integer({"sequence": 1}) == 3
    assert instance.errors()[-1] == (
        "fmi2SetInteger: sequence (vr[0] = 70) is a parameter of variability fixed: it can be set "
        "only in Instantiated and InitializationMode, not in StepComplete; no value set")
    assert instance.get_integer(["sequence"]) == [SEQUENCES.index("space313") + 1]
    inputs = [0.3, -0.7, 1.1, 0.5, -1.5, 2.0, 3.0, -0.25, 0.8]
    instance.set(dict(zip(INPUTS, inputs)))
    assert np.allclose(instance.get(OUTPUTS), reference.fmu_outputs("space313", inputs), atol=1e-14)
    instance.fmu.reset()
    instance.fmu.setupExperiment(startTime=0.0)
    instance.fmu.enterInitializationMode()
    assert instance.get_integer(["sequence"]) == [1]


def test_rotation_outputs_are_computed_only_when_read(make_instance):
    """The 49 rotation outputs are a lazy group: reading omega and alpha never computes them; the
    first read of one of them after an input changed computes them once."""
    instance = make_instance(logging_on=True)
    instance.initialize(parameters={"sequence": 6})

    def lazy():
        return sum(m == "lazy outputs evaluated" for _, _, m in instance.messages)

    inputs = dict(zip(INPUTS, [0.3, -0.7, 1.1, 0.5, -1.5, 2.0, 3.0, -0.25, 0.8]))
    for k in range(3):
        instance.set({**inputs, "theta[1]": 0.1 * k})
        instance.get(OUTPUTS[:12])
        instance.fmu.doStep(0.1 * k, 0.1)
    assert lazy() == 0
    instance.get(["q[1]"])
    instance.get(["R[2,3]", "W_body_dot[3,3]"])
    assert lazy() == 1
    instance.set({"theta_dot[2]": 9.0})
    instance.get(OUTPUTS[:12])
    assert lazy() == 1
    assert instance.get(["W_fixed_dot[1,1]"]) is not None and lazy() == 2


def test_every_output_at_once_after_an_input_change(make_instance):
    """A read of a lazy output right after an input changed evaluates both groups in one pass
    (one evaluation, no separate lazy one); the values are bit for bit those of the two-step
    path (main group read first, then the lazy group), for every sequence."""
    rng = np.random.default_rng(RNG_SEED)
    for name in SEQUENCES:
        two_steps = instance_for(make_instance, name)
        one_pass = instance_for(make_instance, name, logging_on=True)  # last: gets the messages
        for inputs in states(name, 6, rng):
            for instance in (one_pass, two_steps):
                instance.set(dict(zip(INPUTS, inputs)))
            before = len(one_pass.messages)
            got = np.array(one_pass.get(OUTPUTS[12:] + OUTPUTS[:12]))
            new = [m for _, _, m in one_pass.messages[before:]]
            assert sum("with the lazy outputs" in m for m in new) == 1, new
            assert not any(m == "lazy outputs evaluated" for m in new), new
            main = np.array(two_steps.get(OUTPUTS[:12]))
            lazy = np.array(two_steps.get(OUTPUTS[12:]))
            expected = np.concatenate([lazy, main])
            assert np.array_equal(got.view(np.int64), expected.view(np.int64)), name
