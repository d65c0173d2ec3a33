"""fmi2GetDirectionalDerivative: the exact Jacobian of every output with respect to every input,
for any seed and any subset of unknowns and knowns, checked against 60-digit central differences
of the independent sympy reference; its zero pattern is the <ModelStructure> dependencies. Bad
arguments are refused in both layers (fmi3GetDirectionalDerivative too: `layer`)."""
import ctypes

import numpy as np
import pytest

from codegen import reference
from conftest import Model, value_references_of

# The first value reference past AngularKinematics' last (a new variable takes it).
PAST = len(value_references_of("AngularKinematics"))

RNG = np.random.default_rng(20261121)
POINTS = [RNG.uniform(-4, 4, 9) for _ in range(6)] + [
    np.array([0.3, np.pi / 2, -1.0, 0.7, -1.1, 2.0, 0.5, 3.0, -2.0]),  # gimbal lock: nothing special
    np.array([0.0] * 3 + [1.5, -0.5, 0.25] + [0.0] * 3),
]


def directional(instance, unknowns, knowns, seed):
    """Raw call by value references; returns (status, result)."""
    vu = (ctypes.c_uint * len(unknowns))(*unknowns)
    vk = (ctypes.c_uint * len(knowns))(*knowns)
    dv = (ctypes.c_double * len(knowns))(*seed)
    out = (ctypes.c_double * len(unknowns))(*([-7.0] * len(unknowns)))
    status = instance.call("fmi2GetDirectionalDerivative", vu, len(unknowns), vk, len(knowns), dv, out)
    return status, np.array(out)


def instance_at(make_instance, point, fmi_type="CoSimulation"):
    instance = make_instance(fmi_type=fmi_type)
    instance.initialize(inputs=dict(zip(reference.INPUT_NAMES, point)))
    return instance


def scaled_error(got, expected):
    return np.abs(got - expected) / (1.0 + np.abs(expected))


@pytest.mark.parametrize("fmi_type", ["CoSimulation", "ModelExchange"])
def test_full_jacobian_column_by_column_matches_reference(fmi_type, make_instance, report):
    worst = 0.0
    outputs = list(range(9, 21))
    for point in POINTS:
        instance = instance_at(make_instance, point, fmi_type)
        expected = reference.jacobian(point)
        J = np.zeros((12, 9))
        for j in range(9):
            status, J[:, j] = directional(instance, outputs, [j], [1.0])
            assert status == 0
        worst = max(worst, scaled_error(J, expected).max())
    report(f"{fmi_type}: {len(POINTS)} points, worst |J - J_ref| / (1 + |J_ref|) = {worst:.1e}")
    assert worst < 1e-14


def test_any_seed_and_any_subset_of_unknowns_and_knowns(make_instance):
    for point in POINTS[:4]:
        instance = instance_at(make_instance, point)
        expected = reference.jacobian(point)
        for _ in range(20):
            unknowns = list(RNG.choice(range(9, 21), size=RNG.integers(1, 13), replace=False))
            knowns = list(RNG.choice(range(9), size=RNG.integers(1, 10), replace=False))
            seed = RNG.normal(size=len(knowns))
            status, got = directional(instance, unknowns, knowns, seed)
            assert status == 0
            want = expected[np.array(unknowns) - 9][:, knowns] @ seed
            assert scaled_error(got, want).max() < 1e-13


def test_repeated_knowns_add_up_and_empty_requests_are_fine(make_instance):
    instance = instance_at(make_instance, POINTS[0])
    expected = reference.jacobian(POINTS[0])
    status, got = directional(instance, [16, 20], [4, 4, 0], [0.5, 0.25, 2.0])
    assert status == 0
    want = expected[[7, 11]][:, [4, 4, 0]] @ np.array([0.5, 0.25, 2.0])
    assert scaled_error(got, want).max() < 1e-14
    status, got = directional(instance, [9, 10], [], [])
    assert status == 0 and np.array_equal(got, [0.0, 0.0])  # no known: zero change
    assert instance.call("fmi2GetDirectionalDerivative", None, 0, None, 0, None, None) == 0


def test_zero_pattern_is_the_model_structure(make_instance, model_description):
    dependencies = {u.variable.valueReference: {d.valueReference for d in u.dependencies}
                    for u in model_description.outputs}
    for point in POINTS[:6]:  # generic points: no accidental zero
        instance = instance_at(make_instance, point)
        for output in range(9, 21):
            row = [directional(instance, [output], [j], [1.0])[1][0] for j in range(9)]
            nonzero = {j for j in range(9) if row[j] != 0.0}
            # ModelStructure lists the union over the sequences: body123 needs a subset of it
            # (test_sequences_fmu.py checks every sequence).
            assert nonzero <= dependencies[output], reference.OUTPUT_NAMES[output - 9]


def test_follows_the_current_inputs(make_instance):
    instance = instance_at(make_instance, POINTS[0])
    instance.fmu.doStep(0.0, 0.1)
    assert instance.set(dict(zip(reference.INPUT_NAMES, POINTS[1]))) == 0
    status, got = directional(instance, list(range(9, 21)), [1], [1.0])
    assert status == 0
    assert scaled_error(got, reference.jacobian(POINTS[1])[:, 1]).max() < 1e-14


# Bad arguments, per layer: FMI 2 (unknowns, knowns, seed, message) by scalar value references;
# FMI 3 (unknowns, knowns, seed, nSensitivity, message) by array value references.
BAD_ARGUMENTS = {
    "unknown is an input": {
        2: ([9, 3], [0], [1.0], "fmi2GetDirectionalDerivative: vUnknown_ref[1] = 3 is theta_dot[1], "
                                "an input; expected an output"),
        3: ([9, 3], [0], [1.0, 0.0, 0.0], 6, "fmi3GetDirectionalDerivative: unknowns[1] = 3 is "
                                             "theta_dot, an input; expected an output")},
    "known is an output": {
        2: ([9], [0, 12], [1.0, 1.0], "fmi2GetDirectionalDerivative: vKnown_ref[1] = 12 is "
                                      "omega_body[1], an output; expected an input"),
        3: ([9], [12], [1.0, 0.0, 0.0], 3, "fmi3GetDirectionalDerivative: knowns[0] = 12 is "
                                           "omega_body, an output; expected an input")},
    "known is a parameter": {
        2: ([9], [70], [1.0], "fmi2GetDirectionalDerivative: vKnown_ref[0] = 70 is sequence, a "
                              "parameter; expected an input"),
        3: ([9], [70], [1.0], 3, "fmi3GetDirectionalDerivative: knowns[0] = 70 is sequence, a "
                                 "parameter; expected an input")},
    "past the last value reference": {
        2: ([PAST], [0], [1.0], f"fmi2GetDirectionalDerivative: vUnknown_ref[0] = {PAST} is not a "
                                f"value reference of this FMU (0 to {PAST - 1})"),
        3: ([PAST], [0], [1.0, 0.0, 0.0], 3, f"fmi3GetDirectionalDerivative: unknowns[0] = {PAST} is "
                                             "not a value reference of this FMU's FMI 3 variables")},
    "NaN seed": {
        2: ([9], [0], [float("nan")], "fmi2GetDirectionalDerivative: dvKnown[0] = nan (seed of "
                                      "theta[1]) is not finite"),
        3: ([9], [0], [1.0, float("nan"), 0.0], 3, "fmi3GetDirectionalDerivative: seed[1] = nan is "
                                                   "not finite")},
}


def directional3(instance, unknowns, knowns, seed, n_sensitivity):
    """Raw fmi3GetDirectionalDerivative by array value references; (status, result)."""
    out = (ctypes.c_double * n_sensitivity)(*([-7.0] * n_sensitivity))
    status = instance.call("fmi3GetDirectionalDerivative", (ctypes.c_uint32 * len(unknowns))(*unknowns),
                           len(unknowns), (ctypes.c_uint32 * len(knowns))(*knowns), len(knowns),
                           (ctypes.c_double * len(seed))(*seed), len(seed), out, n_sensitivity)
    return status, np.array(out)


@pytest.mark.parametrize("kind", list(BAD_ARGUMENTS))
def test_bad_arguments_are_refused_and_write_nothing(kind, layer, new_instance):
    """Both layers: fmi2Error/fmi3Error, exactly one message naming the argument, nothing written,
    nothing changed, and the instance goes on."""
    instance = layer.started(new_instance, Model("AngularKinematics"), "target")
    before = layer.values(instance)
    *arguments, message = BAD_ARGUMENTS[kind][layer.version]
    status, got = (directional if layer.version == 2 else directional3)(instance, *arguments)
    assert status == 3
    assert instance.errors() == [message]
    assert np.all(got == -7.0)
    assert layer.values(instance) == before
    assert layer.step(instance, 0.25, 0.1) == (0, 0.35)


def test_null_arrays_are_refused(make_instance):
    instance = instance_at(make_instance, POINTS[0])
    vr = (ctypes.c_uint * 1)(9)
    dv = (ctypes.c_double * 1)(1.0)
    assert instance.call("fmi2GetDirectionalDerivative", vr, 1, vr, 1, dv, None) == 3
    assert instance.call("fmi2GetDirectionalDerivative", vr, 1, None, 1, dv, dv) == 3
    assert instance.errors() == [
        "fmi2GetDirectionalDerivative: dvUnknown is NULL with nUnknown = 1",
        "fmi2GetDirectionalDerivative: vKnown_ref is NULL with nKnown = 1"]


def test_refused_before_initialization(make_instance):
    instance = make_instance()
    status, _ = directional(instance, [9], [0], [1.0])
    assert status == 3
    assert instance.errors() == ["fmi2GetDirectionalDerivative: illegal call in state Instantiated"]
