"""QuaternionKinematics' directional derivatives (fmi2GetDirectionalDerivative and
fmi3GetDirectionalDerivative): every output along every input, for sequences of every kind,
against central differences of the FMU's own outputs (the differences know nothing of the
tangent formulas: the angles' derivatives come from inverting AngularKinematics' Jacobian in the
FMU), and zero exactly where <ModelStructure> lists no dependency."""
import ctypes

import numpy as np
import pytest
from fmpy import read_model_description

from codegen.project import SEQUENCES
from conftest import fmu_path_of

MODEL = "QuaternionKinematics"
N_INPUTS = 12
OUTPUTS = list(range(12, 44))
# A body-fixed and a space-fixed sequence of each family.
CHOSEN = ["body123", "body313", "space231", "space121"]


def point(rng):
    """Random inputs away from the singular configurations: |q| near 1 to 2, rates of order 1."""
    return np.concatenate([rng.uniform(-1.0, 1.0, 4) * rng.uniform(1.0, 2.0),
                           rng.uniform(-1.0, 1.0, 4), rng.uniform(-1.0, 1.0, 4)])


def fmi2_instance(new_instance, **parameters):
    """An initialized FMI 2 instance of the model (value references 0 .. 11 are its inputs)."""
    instance = new_instance(MODEL)
    instance.initialize(parameters=parameters)
    return instance


def outputs_at(instance, x):
    """The outputs after setting the 12 inputs to x."""
    assert instance.fmu.setReal(list(range(N_INPUTS)), list(x)) is None
    return np.array(instance.fmu.getReal(OUTPUTS))


@pytest.mark.parametrize("sequence", CHOSEN)
def test_directional_derivatives_are_the_central_differences(sequence, new_instance, report):
    instance = fmi2_instance(new_instance, sequence=SEQUENCES.index(sequence) + 1)
    rng = np.random.default_rng(17)
    worst, points = 0.0, 0
    while points < 6:
        x = point(rng)
        values = outputs_at(instance, x)
        if values[-1] < 0.2:  # singularity_distance: the angle rates' derivatives grow as 1 / d^2
            continue
        points += 1
        J = np.array([instance.fmu.getDirectionalDerivative(OUTPUTS, [k], [1.0])
                      for k in range(N_INPUTS)]).T
        h = 1e-6
        differences = np.empty_like(J)
        for k in range(N_INPUTS):
            e = np.zeros(N_INPUTS)
            e[k] = h
            differences[:, k] = (outputs_at(instance, x + e) - outputs_at(instance, x - e)) / (2 * h)
        worst = max(worst, float(np.max(np.abs(J - differences) / (1.0 + np.abs(differences)))))
    report(f"{MODEL} {sequence}: 32 x 12 directional derivatives at 6 points against central "
           f"differences (h = 1e-6): largest difference {worst:.2g}")
    assert worst < 1e-6


def test_fmi3_gives_the_bits_of_fmi2(new_instance):
    """The same Jacobian through fmi3GetDirectionalDerivative, bit for bit."""
    x = point(np.random.default_rng(4))
    fmi2 = fmi2_instance(new_instance)
    outputs_at(fmi2, x)
    J2 = np.array([fmi2.fmu.getDirectionalDerivative(OUTPUTS, [k], [1.0])
                   for k in range(N_INPUTS)])
    fmi3 = new_instance(MODEL, fmi_version=3)
    fmi3.initialize()
    fmi3.set({"q": x[0:4], "q_dot": x[4:8], "q_ddot": x[8:12]})
    # FMI 3: each output array by its value reference; the known is the input array q, q_dot or
    # q_ddot (value references 0, 4, 8) with a seed of 4, one element set.
    arrays = sorted({v.valueReference for v in fmi3.md.modelVariables if v.causality == "output"})
    J3 = np.empty((N_INPUTS, len(OUTPUTS)))
    for k in range(N_INPUTS):
        out = (ctypes.c_double * len(OUTPUTS))()
        status = fmi3.call("fmi3GetDirectionalDerivative", (ctypes.c_uint * len(arrays))(*arrays),
                           len(arrays), (ctypes.c_uint * 1)(4 * (k // 4)), 1,
                           (ctypes.c_double * 4)(*np.eye(4)[k % 4]), 4, out, len(OUTPUTS))
        assert status == 0
        J3[k] = np.array(out)
    assert np.array_equal(J2, J3)


def test_zero_where_model_structure_lists_no_dependency(new_instance):
    md = read_model_description(str(fmu_path_of(MODEL)))
    by_name = {v.name: v.valueReference for v in md.modelVariables}
    listed = {by_name[u.variable.name]: {by_name[d.name] for d in (u.dependencies or [])}
              for u in md.outputs}
    instance = fmi2_instance(new_instance)
    outputs_at(instance, point(np.random.default_rng(8)))
    for k in range(N_INPUTS):
        column = instance.fmu.getDirectionalDerivative(OUTPUTS, [k], [1.0])
        for vr, value in zip(OUTPUTS, column):
            if k not in listed[vr]:
                assert value == 0.0, (vr, k)
