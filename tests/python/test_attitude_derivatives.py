"""AttitudePropagator's directional derivatives (analytic, model.c) against central differences of
the FMU's own outputs, for every unknown (der(q) and the outputs) and every known (the states q
and the inputs), in model exchange, both frames, four sequences, at random points away from the
singular configuration; and their zero pattern against <ModelStructure>."""
import ctypes

import numpy as np
import pytest

from attitude_support import (FRAME, OMEGA, OMEGA_DOT, Q, attitude_model_description,  # noqa: F401
                              attitude_unzipdir, make_attitude_instance)

STEP = 1e-6


def doubles(values):
    return (ctypes.c_double * len(values))(*values)


@pytest.mark.parametrize("sequence", [1, 11, 13, 24])
@pytest.mark.parametrize("frame", ["body", "fixed"])
def test_directional_derivatives_are_the_jacobian(sequence, frame, make_attitude_instance,
                                                  attitude_model_description, report):
    md = attitude_model_description
    unknowns = [d.variable for d in md.derivatives] + [u.variable for u in md.outputs]
    knowns = Q + OMEGA + OMEGA_DOT
    listed = {u.variable.name: {d.name for d in u.dependencies} for u in md.outputs + md.derivatives}
    instance = make_attitude_instance(fmi_type="ModelExchange")
    instance.fmu.setupExperiment(startTime=0.0)
    instance.fmu.enterInitializationMode()
    instance.set_integer({"frame": FRAME[frame], "sequence": sequence})
    instance.fmu.exitInitializationMode()
    instance.fmu.enterContinuousTimeMode()
    unknown_vrs = (ctypes.c_uint * len(unknowns))(*[v.valueReference for v in unknowns])
    names = [v.name for v in unknowns]
    rng = np.random.default_rng(sequence)
    worst = 0.0
    for _ in range(5):
        point = np.concatenate([rng.normal(size=4) * 0.7, rng.normal(size=6)])

        def values_at(p):
            instance.call("fmi2SetContinuousStates", doubles(p[:4]), 4)
            instance.set(dict(zip(OMEGA + OMEGA_DOT, p[4:])))
            return instance.get(names)

        base = values_at(point)
        if base[names.index("singularity_distance")] < 0.05:
            continue  # theta1, theta3 and their rates are not differentiable at the singularity
        for k, known in enumerate(knowns):
            up, down = point.copy(), point.copy()
            up[k] += STEP
            down[k] -= STEP
            numeric = (values_at(up) - values_at(down)) / (2 * STEP)
            values_at(point)  # the unwrapping reference back at the point
            seed = doubles([1.0])
            out = (ctypes.c_double * len(unknowns))()
            known_vr = (ctypes.c_uint * 1)(instance.vr[known])
            assert instance.call("fmi2GetDirectionalDerivative", unknown_vrs, len(unknowns),
                                 known_vr, 1, seed, out) == 0
            analytic = np.array(out)
            scale = 1.0 + np.abs(numeric)
            worst = max(worst, np.max(np.abs(analytic - numeric) / scale))
            assert np.allclose(analytic, numeric, rtol=1e-6, atol=1e-6), (known, [
                (n, a, b) for n, a, b in zip(names, analytic, numeric) if abs(a - b) > 1e-6 * (1 + abs(b))])
            for name, value in zip(names, analytic):
                if value != 0.0:  # a nonzero derivative is a listed dependency
                    assert known in listed[name], (name, known)
    report(f"{frame} frame, sequence {sequence}: {len(unknowns)} unknowns x {len(knowns)} knowns, "
           f"largest |analytic - central difference| / (1 + |difference|) = {worst:.1e}")
