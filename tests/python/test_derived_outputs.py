"""Outputs that a core function computes from other outputs (`computed_by` in a description,
fmu_src/models/model_derived.c), AngularKinematics' rotation_angle today: computed only when one
of them is read, and their derivatives by the chain rule are the same whether asked alone, among
other outputs, or in a request longer than the FMU's value table. Values, dependencies and
derivatives against the sympy reference: test_sequences_fmu.py."""
import ctypes

import numpy as np

from codegen.models import load
from fmi3_support import doubles, vrs

DERIVED = [s.name for s in load("AngularKinematics").scalars if s.computed_by]
INPUTS = dict(zip([f"{b}[{i}]" for b in ("theta", "theta_dot", "theta_ddot") for i in (1, 2, 3)],
                  [0.3, -1.1, 2.0, 0.7, -0.4, 1.9, 3.0, -2.5, 0.25]))


def output_derivatives(instance, requested):
    got = (ctypes.c_double * len(requested))()
    status = instance.call("fmi2GetRealOutputDerivatives", vrs(requested), len(requested),
                           (ctypes.c_int * len(requested))(*[1] * len(requested)), got)
    assert status == 0
    return np.array(got)


def directional(instance, unknowns, seed):
    got = (ctypes.c_double * len(unknowns))()
    status = instance.call("fmi2GetDirectionalDerivative", vrs(unknowns), len(unknowns),
                           vrs(range(9)), 9, doubles(seed), got)
    assert status == 0
    return np.array(got)


def test_the_model_has_derived_outputs():
    assert DERIVED == ["rotation_angle"]


def test_computed_only_when_one_of_them_is_read(make_instance):
    instance = make_instance(logging_on=True)
    instance.initialize(inputs=INPUTS)

    def evaluations():
        return sum(m == "derived outputs evaluated" for _, _, m in instance.messages)

    instance.get(["R[1,1]", "q[1]", "W_body_dot[3,3]"])
    assert evaluations() == 0
    first = instance.get(DERIVED)
    assert evaluations() == 1
    assert np.array_equal(instance.get(DERIVED), first)
    assert evaluations() == 1  # nothing changed since
    assert instance.set({"theta[1]": 0.9}) == 0
    instance.get(["omega_fixed[1]", "R[2,2]"])
    assert evaluations() == 1
    assert not np.array_equal(instance.get(DERIVED), first)
    assert evaluations() == 2


def test_derivatives_alone_among_others_and_in_a_long_request(make_instance):
    instance = make_instance()
    instance.initialize(inputs=INPUTS)
    outputs = [v.valueReference for v in instance.model_description.modelVariables
               if v.causality == "output"]
    derived = [instance.vr[n] for n in DERIVED]
    alone = {vr: output_derivatives(instance, [vr])[0] for vr in outputs}
    # More value references than the FMU has variables, derived ones among them.
    long = outputs + derived * 20 + outputs[::-1]
    assert len(long) > 80
    assert np.array_equal(output_derivatives(instance, long), [alone[vr] for vr in long])
    seed = np.linspace(-1.0, 1.0, 9)
    each = {vr: directional(instance, [vr], seed)[0] for vr in outputs}
    mixed = derived + outputs[:5] + derived
    assert np.array_equal(directional(instance, mixed, seed), [each[vr] for vr in mixed])
    assert all(np.isfinite(alone[vr]) and alone[vr] != 0.0 for vr in derived)


def test_no_rotation_gives_angle_zero_and_derivative_zero(make_instance):
    """At theta = 0 the rotation angle has a kink (it is |x| of the rotation vector): its value is
    0 and its derivatives are taken as 0, never NaN."""
    instance = make_instance()
    instance.initialize(inputs={**INPUTS, "theta[1]": 0.0, "theta[2]": 0.0, "theta[3]": 0.0})
    derived = [instance.vr[n] for n in DERIVED]
    assert np.array_equal(instance.get(DERIVED), [0.0])
    assert np.array_equal(output_derivatives(instance, derived), [0.0])
    assert np.array_equal(directional(instance, derived, np.ones(9)), [0.0])
