"""FMI 3 derivatives of AngularKinematics: fmi3GetDirectionalDerivative and
fmi3GetAdjointDerivative are the same exact Jacobian (the adjoint is its transpose, its zeros are
exactly those of the per-element dependencies, which fmi3GetVariableDependencies gives as the
description states them); fmi3GetOutputDerivatives gives d omega/dt = alpha bit for bit and
d alpha/dt consistent with a finite difference. What a model does not declare it refuses:
test_undeclared_capabilities.py, both layers."""
import ctypes

import numpy as np

from codegen.models import load
from fmi3_support import OK, Instance3, doubles, vrs

INPUTS = ["theta", "theta_dot", "theta_ddot"]


def started(sequence=14, theta=(0.4, -0.7, 1.2), rates=(0.5, -1.5, 2.0), accelerations=(1.0, 0.25, -0.5)):
    instance = Instance3("AngularKinematics")
    instance.initialize(parameters={"sequence": sequence},
                        inputs={"theta": theta, "theta_dot": rates, "theta_ddot": accelerations})
    return instance


def jacobian(instance, outputs):
    """Full J (rows: output elements, columns: the 9 input elements) by unit seeds."""
    n = sum(instance.size[o] for o in outputs)
    columns = []
    for k in range(9):
        seed = np.zeros(9)
        seed[k] = 1.0
        out = (ctypes.c_double * n)()
        assert instance.call("fmi3GetDirectionalDerivative", vrs(instance.vr[o] for o in outputs),
                             len(outputs), vrs([0, 3, 6]), 3, doubles(seed), 9, out, n) == OK
        columns.append(list(out))
    return np.array(columns).T


def test_adjoint_is_the_transpose_and_zeros_are_the_dependencies():
    instance = started()
    try:
        outputs = instance.outputs()
        J = jacobian(instance, outputs)
        rng = np.random.default_rng(3)
        seed = rng.uniform(-1, 1, J.shape[0])
        out = (ctypes.c_double * 9)()
        assert instance.call("fmi3GetAdjointDerivative", vrs(instance.vr[o] for o in outputs),
                             len(outputs), vrs([0, 3, 6]), 3, doubles(seed), len(seed), out, 9) == OK
        assert np.allclose(list(out), J.T @ seed, rtol=1e-14, atol=1e-14)
        # A directional derivative with a general seed is J seed.
        direction = rng.uniform(-1, 1, 9)
        d = (ctypes.c_double * J.shape[0])()
        assert instance.call("fmi3GetDirectionalDerivative", vrs(instance.vr[o] for o in outputs),
                             len(outputs), vrs([0, 3, 6]), 3, doubles(direction), 9, d,
                             J.shape[0]) == OK
        assert np.allclose(list(d), J @ direction, rtol=1e-14, atol=1e-14)
        # Sparsity = the description's per-element dependencies, from the FMU.
        m = load("AngularKinematics")
        row = 0
        for name in outputs:
            n = ctypes.c_size_t()
            assert instance.call("fmi3GetNumberOfVariableDependencies", instance.vr[name],
                                 ctypes.byref(n)) == OK
            k = n.value
            dependent = (ctypes.c_size_t * k)()
            independents = (ctypes.c_uint32 * k)()
            elements = (ctypes.c_size_t * k)()
            kinds = (ctypes.c_int * k)()
            assert instance.call("fmi3GetVariableDependencies", instance.vr[name], dependent,
                                 independents, elements, kinds, k) == OK
            scalars = [s for s in m.scalars if s.base == name]
            # Element indices 1-based, row-major; 0 for a scalar.
            expected = sorted((e + 1 if s.indices else 0, d) for e, s in enumerate(scalars)
                              for d in s.depends)
            got = sorted((dependent[i], independents[i] + elements[i] - 1) for i in range(k))
            assert got == expected, name
            assert set(kinds) <= {5}  # fmi3Dependent
            for e in range(len(scalars)):
                structural = np.zeros(9, dtype=bool)
                structural[scalars[e].depends] = True
                assert np.all(J[row + e][~structural] == 0.0), (name, e)
            row += len(scalars)
    finally:
        instance.free()


def test_d_omega_dt_is_alpha_and_d_alpha_dt_matches_finite_differences():
    theta, rates, acc = np.array([0.4, -0.7, 1.2]), np.array([0.5, -1.5, 2.0]), np.array([1.0, 0.25, -0.5])
    instance = started(theta=theta, rates=rates, accelerations=acc)
    try:
        names = ["omega_fixed", "omega_body", "alpha_fixed", "alpha_body"]
        out = (ctypes.c_double * 12)()
        assert instance.call("fmi3GetOutputDerivatives", vrs(instance.vr[n] for n in names), 4,
                             (ctypes.c_int32 * 4)(1, 1, 1, 1), out, 12) == OK
        values = instance.get(names)
        derivative = np.array(list(out))
        assert np.array_equal(derivative[:6].view(np.uint64),
                              np.concatenate([values["alpha_fixed"], values["alpha_body"]]).view(np.uint64))
        # d alpha / dt with theta_dddot = 0: a central difference along the trajectory.
        h = 1e-5

        def alpha_at(t):
            assert instance.set({"theta": theta + rates * t + acc * t * t / 2,
                                 "theta_dot": rates + acc * t, "theta_ddot": acc}) == OK
            v = instance.get(["alpha_fixed", "alpha_body"])
            return np.concatenate([v["alpha_fixed"], v["alpha_body"]])

        difference = (alpha_at(h) - alpha_at(-h)) / (2 * h)
        assert np.allclose(derivative[6:], difference, rtol=1e-7, atol=1e-7)
    finally:
        instance.free()
