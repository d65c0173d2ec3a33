"""Same numbers: every output of the FMI 3 FMUs is bit-identical to the FMI 2 FMU's for the same
inputs, over all 24 sequences (and every frame of a model with a `frame` parameter), through
co-simulation steps; for a model that provides them also the directional derivatives of every
output and the output derivatives."""
import ctypes

import numpy as np
import pytest

from fmi3_support import doubles, vrs

STEPS = 12


def bits(values):
    return np.asarray(values, dtype=np.float64).view(np.uint64)


def random_inputs(rng, count):
    u = rng.uniform(-3.0, 3.0, count)
    if rng.random() < 0.1:
        u[1] = np.pi / 2  # at or near the singularity of the Tait-Bryan sequences: warnings too
    return u


def frames(instance):
    """The values of the `frame` parameter's enumeration, (None,) for a model without one."""
    frame = instance.variables.get("frame")
    return tuple(int(item.value) for item in frame.declaredType.items) if frame else (None,)


@pytest.fixture
def pair(model, make_model_instance):
    """The model's FMI 2 instance (conftest's `model`: each of codegen.project.MODELS) and its
    FMI 3 instance."""
    fmi2 = make_model_instance("fmi2")
    fmi3 = make_model_instance("fmi3", fmi_version=3)
    return model.name, fmi2, fmi3


def test_fmi3_outputs_bit_identical_to_fmi2(pair, report):
    model, fmi2, fmi3 = pair
    outputs, inputs = fmi3.outputs(), fmi3.inputs()
    output_vrs = [vr for name in outputs for vr in range(fmi3.vr[name], fmi3.vr[name] + fmi3.size[name])]
    input_vrs = [vr for name in inputs for vr in range(fmi3.vr[name], fmi3.vr[name] + fmi3.size[name])]
    ends = np.cumsum([fmi3.size[name] for name in inputs])
    derivatives = fmi3.md.coSimulation.providesDirectionalDerivative
    rng = np.random.default_rng(12)
    compared = 0
    sequences = range(1, 25) if "sequence" in fmi3.vr else [None]
    for sequence in sequences:
        for frame in frames(fmi3):
            parameters = ({"sequence": sequence} if sequence else {}) | \
                ({"frame": frame} if frame else {})
            assert fmi2.call("fmi2Reset") == 0 and fmi3.call("fmi3Reset") == 0
            fmi2.initialize(parameters=parameters)
            fmi3.initialize(parameters=parameters)
            t = 0.0
            for _ in range(STEPS):
                u = random_inputs(rng, len(input_vrs))
                assert fmi2.call("fmi2SetReal", vrs(input_vrs), len(input_vrs), doubles(u)) == 0
                assert fmi3.set(dict(zip(inputs, np.split(u, ends[:-1])))) == 0
                s2 = fmi2.call("fmi2DoStep", ctypes.c_double(t), ctypes.c_double(0.01), True)
                s3, t3 = fmi3.do_step(t, 0.01)
                assert s2 == s3, (sequence, frame, s2, s3, fmi3.messages[-2:])
                if s3 == 2:  # discarded at the singularity by both (FMI 2 is then in StepFailed)
                    assert t3 == t
                    break
                t += 0.01
                y2 = (ctypes.c_double * len(output_vrs))()
                status2 = fmi2.call("fmi2GetReal", vrs(output_vrs), len(output_vrs), y2)
                status3, y3 = fmi3.get_raw(outputs)
                assert status2 == status3
                flat3 = np.concatenate([y3[name] for name in outputs])
                assert np.array_equal(bits(list(y2)), bits(flat3)), (model, sequence, frame)
                compared += len(output_vrs)
                if derivatives:
                    check_directional_derivatives(fmi2, fmi3, outputs, output_vrs, input_vrs, rng)
                if int(fmi3.md.coSimulation.maxOutputDerivativeOrder or 0) >= 1:
                    check_output_derivatives(fmi2, fmi3, outputs, output_vrs)
    assert compared > 0
    report(f"{model}: {compared} output values over {len(sequences)} sequence(s) x {len(frames(fmi3))} frame(s), "
           "all bit-identical to the FMI 2 FMU")


def check_directional_derivatives(fmi2, fmi3, outputs, output_vrs, input_vrs, rng):
    seed = rng.uniform(-1.0, 1.0, len(input_vrs))
    d2 = (ctypes.c_double * len(output_vrs))()
    assert fmi2.call("fmi2GetDirectionalDerivative", vrs(output_vrs), len(output_vrs),
                     vrs(input_vrs), len(input_vrs), doubles(seed), d2) == 0
    d3 = (ctypes.c_double * len(output_vrs))()
    inputs = fmi3.inputs()
    assert fmi3.call("fmi3GetDirectionalDerivative", vrs(fmi3.vr[n] for n in outputs), len(outputs),
                     vrs(fmi3.vr[n] for n in inputs), len(inputs), doubles(seed), len(input_vrs),
                     d3, len(output_vrs)) == 0
    assert np.array_equal(bits(list(d2)), bits(list(d3)))


def check_output_derivatives(fmi2, fmi3, outputs, output_vrs):
    n = len(output_vrs)
    o2 = (ctypes.c_double * n)()
    assert fmi2.call("fmi2GetRealOutputDerivatives", vrs(output_vrs), n,
                     (ctypes.c_int * n)(*[1] * n), o2) == 0
    o3 = (ctypes.c_double * n)()
    assert fmi3.call("fmi3GetOutputDerivatives", vrs(fmi3.vr[name] for name in outputs), len(outputs),
                     (ctypes.c_int32 * len(outputs))(*[1] * len(outputs)), o3, n) == 0
    assert np.array_equal(bits(list(o2)), bits(list(o3)))


def test_signed_zero_inputs_give_the_fmi2_bits(model_description, new_instance):
    """A -0.0 set over 0.0 differs in its bits: both layers store it and evaluate from it, so the
    input reads back as set and the outputs carry the same bits in both (signs of zero included)."""
    fmi2 = new_instance("AngularKinematics", name="fmi2")
    fmi3 = new_instance("AngularKinematics", name="fmi3", fmi_version=3)
    output_vrs = sorted(v.valueReference for v in model_description.modelVariables
                        if v.causality == "output")
    fmi2.initialize(parameters={"sequence": 3})
    fmi3.initialize(parameters={"sequence": 3})
    for u in ([-0.0] * 9, [0.0, -0.0, 0.5, -0.0, 0.0, 0.0, 0.0, -0.0, 0.0]):
        assert fmi2.call("fmi2SetReal", vrs(range(9)), 9, doubles(u)) == 0
        assert fmi3.set({"theta": u[:3], "theta_dot": u[3:6], "theta_ddot": u[6:]}) == 0
        names = fmi3.outputs()
        y3 = np.concatenate([fmi3.get(names)[n] for n in names])
        y2 = (ctypes.c_double * len(y3))()
        assert fmi2.call("fmi2GetReal", vrs(output_vrs), len(y3), y2) == 0
        assert np.array_equal(bits(list(y2)), bits(y3))
        assert np.array_equal(bits(fmi3.get(["theta"])["theta"]), bits(u[:3]))
        theta2 = (ctypes.c_double * 3)()
        assert fmi2.call("fmi2GetReal", vrs(range(3)), 3, theta2) == 0
        assert np.array_equal(bits(list(theta2)), bits(u[:3]))
