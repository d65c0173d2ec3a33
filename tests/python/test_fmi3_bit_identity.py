"""Same numbers: every output of the FMI 3 FMUs is bit-identical to the FMI 2 FMU's for the same
inputs, over all 24 sequences (and both frames of EulerRates), through co-simulation steps; for
AngularKinematics also the directional derivatives of every output and the output derivatives."""
import ctypes

import numpy as np
import pytest

from conftest import Instance
from fmi3_support import Instance3, doubles, vrs

STEPS = 12


def bits(values):
    return np.asarray(values, dtype=np.float64).view(np.uint64)


def random_inputs(rng, model):
    u = rng.uniform(-3.0, 3.0, 9)
    if model == "EulerRates" and rng.random() < 0.1:
        u[1] = np.pi / 2  # at or near the singularity of the Tait-Bryan sequences: warnings too
    return u


@pytest.fixture
def pair(request, unzipdir, model_description, euler_unzipdir, euler_model_description):
    model = request.param
    folder, md = ((unzipdir, model_description) if model == "AngularKinematics"
                  else (euler_unzipdir, euler_model_description))
    fmi2 = Instance(folder, md, name="fmi2")
    fmi3 = Instance3(model, name="fmi3")
    yield model, fmi2, fmi3
    fmi2.free()
    fmi3.free()


@pytest.mark.parametrize("pair", ["AngularKinematics", "EulerRates"], indirect=True)
def test_fmi3_outputs_bit_identical_to_fmi2(pair, report):
    model, fmi2, fmi3 = pair
    outputs = fmi3.outputs()
    output_vrs = [vr for name in outputs for vr in range(fmi3.vr[name], fmi3.vr[name] + fmi3.size[name])]
    frames = (1, 2) if model == "EulerRates" else (None,)
    rng = np.random.default_rng(12)
    compared = 0
    for sequence in range(1, 25):
        for frame in frames:
            parameters = {"sequence": sequence} | ({"frame": frame} if frame else {})
            assert fmi2.call("fmi2Reset") == 0 and fmi3.call("fmi3Reset") == 0
            fmi2.initialize(parameters=parameters)
            fmi3.initialize(parameters=parameters)
            t = 0.0
            for _ in range(STEPS):
                u = random_inputs(rng, model)
                assert fmi2.call("fmi2SetReal", vrs(range(9)), 9, doubles(u)) == 0
                assert fmi3.set({"theta": u[0:3], fmi3.inputs()[1]: u[3:6], fmi3.inputs()[2]: u[6:9]}) == 0
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
                if model == "AngularKinematics":
                    check_derivatives(fmi2, fmi3, outputs, output_vrs, rng)
    report(f"{model}: {compared} output values over 24 sequences{' x 2 frames' if model == 'EulerRates' else ''}, "
           "all bit-identical to the FMI 2 FMU")


def check_derivatives(fmi2, fmi3, outputs, output_vrs, rng):
    seed = rng.uniform(-1.0, 1.0, 9)
    d2 = (ctypes.c_double * len(output_vrs))()
    assert fmi2.call("fmi2GetDirectionalDerivative", vrs(output_vrs), len(output_vrs),
                     vrs(range(9)), 9, doubles(seed), d2) == 0
    d3 = (ctypes.c_double * len(output_vrs))()
    assert fmi3.call("fmi3GetDirectionalDerivative", vrs(fmi3.vr[n] for n in outputs), len(outputs),
                     vrs([0, 3, 6]), 3, doubles(seed), 9, d3, len(output_vrs)) == 0
    assert np.array_equal(bits(list(d2)), bits(list(d3)))
    omega_alpha = output_vrs[:12]
    orders = (ctypes.c_int * 12)(*[1] * 12)
    o2 = (ctypes.c_double * 12)()
    assert fmi2.call("fmi2GetRealOutputDerivatives", vrs(omega_alpha), 12, orders, o2) == 0
    o3 = (ctypes.c_double * 12)()
    assert fmi3.call("fmi3GetOutputDerivatives", vrs(fmi3.vr[n] for n in outputs[:4]), 4,
                     (ctypes.c_int32 * 4)(1, 1, 1, 1), o3, 12) == 0
    assert np.array_equal(bits(list(o2)), bits(list(o3)))


def test_signed_zero_inputs_give_the_fmi2_bits(unzipdir, model_description):
    """A -0.0 set over 0.0 differs in its bits: both layers store it and evaluate from it, so the
    input reads back as set and the outputs carry the same bits in both (signs of zero included)."""
    fmi2 = Instance(unzipdir, model_description, name="fmi2")
    fmi3 = Instance3("AngularKinematics", name="fmi3")
    output_vrs = sorted(v.valueReference for v in model_description.modelVariables
                        if v.causality == "output")
    try:
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
    finally:
        fmi2.free()
        fmi3.free()
