"""Variable communication step size (canHandleVariableCommunicationStepSize) and the stop time,
with irregular steps."""
import ctypes

import numpy as np
from fmpy import simulate_fmu

from codegen import reference

RNG = np.random.default_rng(7)
START = dict(zip(reference.INPUT_NAMES, [0.3, -0.7, 1.1, 0.5, -1.5, 2.0, 3.0, -0.25, 0.8]))
SLOPE = dict(zip(reference.INPUT_NAMES, [0.5, -0.2, 1.0, 0.3, 0.0, -0.4, 1.5, 0.0, -2.0]))
CURVATURE = dict(zip(reference.INPUT_NAMES, [0.1, 0.4, -0.3, 0.0, 0.2, 0.0, -1.0, 0.6, 0.0]))


def quadratic(t):
    """Inputs along u(t) = u0 + t du + t^2/2 d2u, which order-2 interpolation follows exactly."""
    return [START[n] + t * SLOPE[n] + 0.5 * t * t * CURVATURE[n] for n in reference.INPUT_NAMES]


def set_derivatives(instance):
    names = reference.INPUT_NAMES
    vr = (ctypes.c_uint * 18)(*[instance.vr[n] for n in names] * 2)
    order = (ctypes.c_int * 18)(*([1] * 9 + [2] * 9))
    value = (ctypes.c_double * 18)(*[SLOPE[n] for n in names] + [CURVATURE[n] for n in names])
    assert instance.call("fmi2SetRealInputDerivatives", vr, 18, order, value) == 0


def test_irregular_steps_up_to_the_stop_time(make_instance, report):
    instance = make_instance()
    stop = 3.0
    instance.initialize(inputs=dict(zip(reference.INPUT_NAMES, quadratic(0.0))), stop_time=stop)
    set_derivatives(instance)  # once: the polynomials carry the inputs through every step
    # Step sizes spread over six decades, in random order.
    sizes = 10.0 ** RNG.uniform(-6, -0.5, 200)
    t, worst, steps = 0.0, 0.0, 0
    for h in sizes:
        if t + h >= stop:
            break
        assert instance.call("fmi2DoStep", t, h, 1) == 0
        t += h
        steps += 1
        assert instance.fmu.getRealStatus(2) == t  # fmi2LastSuccessfulTime
        expected = reference.outputs(quadratic(t))
        got = instance.get(reference.OUTPUT_NAMES)
        worst = max(worst, (np.abs(got - expected) / (1.0 + np.abs(expected))).max())
    # The last step lands on the stop time exactly; none may go past it.
    assert instance.call("fmi2DoStep", t, stop - t, 1) == 0
    assert np.allclose(instance.get(reference.INPUT_NAMES), quadratic(stop), rtol=1e-12)
    assert instance.call("fmi2DoStep", stop, 1e-6, 1) == 3
    assert instance.errors()[-1].startswith(f"fmi2DoStep: the step from {stop:g} by communicationStepSize")
    report(f"{steps + 1} steps from {sizes.min():.1e} to {sizes.max():.1e}, worst scaled output "
           f"error against the quadratic inputs {worst:.1e}")
    assert worst < 1e-12


def test_a_step_past_the_stop_time_is_refused_and_changes_nothing(make_instance):
    instance = make_instance()
    instance.initialize(inputs=START, stop_time=1.0)
    assert instance.call("fmi2DoStep", 0.0, 0.7, 1) == 0
    before = instance.get(reference.INPUT_NAMES + reference.OUTPUT_NAMES)
    assert instance.call("fmi2DoStep", 0.7, 0.31, 1) == 3
    assert instance.errors() == ["fmi2DoStep: the step from 0.69999999999999996 by communicationStepSize "
                                 "= 0.31 ends at 1.01, past stopTime = 1"]
    assert instance.fmu.getRealStatus(2) == 0.7
    assert np.array_equal(instance.get(reference.INPUT_NAMES + reference.OUTPUT_NAMES), before)
    # Landing on the stop time within fmpy's relative tolerance of 1e-9 is accepted.
    assert instance.call("fmi2DoStep", 0.7, 0.3 + 1e-10, 1) == 0


def test_fmpy_shortens_the_last_step_to_the_stop_time(fmu_path):
    # 0.3 does not divide 1.0: fmpy, told the FMU handles variable steps, ends with a step of 0.1.
    times = np.array([0.0, 1.0])
    signals = np.zeros(2, dtype=[("time", float)] + [(n, float) for n in reference.INPUT_NAMES])
    signals["time"] = times
    for n in reference.INPUT_NAMES:
        signals[n] = [START[n], START[n] + SLOPE[n]]
    result = simulate_fmu(fmu_path, stop_time=1.0, output_interval=0.3, input=signals,
                          output=reference.INPUT_NAMES + reference.OUTPUT_NAMES,
                          set_input_derivatives=True)
    assert np.allclose(result["time"], [0.0, 0.3, 0.6, 0.9, 1.0])
    last = result[-1]
    inputs = [last[n] for n in reference.INPUT_NAMES]
    # Linear inputs with their slopes: the extrapolated inputs at the stop time are exact.
    assert np.allclose(inputs, [START[n] + SLOPE[n] for n in reference.INPUT_NAMES], rtol=1e-14)
    assert np.allclose([last[n] for n in reference.OUTPUT_NAMES], reference.outputs(inputs), rtol=1e-14)
