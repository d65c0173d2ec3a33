"""FMI 3 co-simulation and model exchange behaviour: variable communication steps (each step's
size its own, lastSuccessfulTime the end of the step, the outputs those of the held inputs);
EulerRates discards a step ending at its singular configuration (fmi3Discard, lastSuccessfulTime
= the step's start, the time stays) and recovers through an FMU state; model exchange with no
continuous states and no event indicators; fmpy's simulate_fmu with array inputs."""
import ctypes

import numpy as np
import pytest
from fmpy import simulate_fmu

from fmi3_support import DISCARD, ERROR, OK, Instance3, fmu3_path, vrs


def test_variable_communication_steps():
    instance = Instance3("AngularKinematics")
    try:
        instance.initialize(parameters={"sequence": 6}, stop_time=10.0)
        t = 0.0
        rng = np.random.default_rng(5)
        for h in [0.1, 0.013, 1e-6, 2.5, 0.37, 1.0 / 3.0]:
            u = rng.uniform(-2, 2, 9)
            assert instance.set({"theta": u[:3], "theta_dot": u[3:6], "theta_ddot": u[6:]}) == OK
            before = instance.get(["omega_body", "R"])
            status, last = instance.do_step(t, h)
            assert status == OK and last == t + h
            t = last
            after = instance.get(["omega_body", "R"])
            assert all(np.array_equal(before[k], after[k]) for k in before)  # inputs held
        time = (ctypes.c_double * 1)()
        assert instance.call("fmi3GetFloat64", vrs([1000]), 1, time, 1) == OK
        assert time[0] == t
    finally:
        instance.free()


def test_euler_rates_discards_a_step_at_the_singularity_and_recovers():
    instance = Instance3("EulerRates", logging_on=True)  # a discard is logged only then
    try:
        instance.initialize(inputs={"theta": [0.1, 0.2, 0.3], "omega": [1.0, 0.5, -0.5]})
        assert instance.do_step(0.0, 0.1) == (OK, 0.1)
        valid = instance.get(["theta_dot", "theta_ddot"])
        state = ctypes.c_void_p()
        assert instance.call("fmi3GetFMUState", ctypes.byref(state)) == OK
        assert instance.set({"theta": [0.1, np.pi / 2, 0.3]}) == OK
        assert instance.do_step(0.1, 0.1) == (DISCARD, 0.1)
        assert any("fmi3DoStep: the step from 0.10000000000000001 to 0.20000000000000001 is "
                   "discarded" in m for s, c, m in instance.messages if s == "Discard")
        status, kept = instance.get_raw(["theta_dot", "theta_ddot"])
        assert status == DISCARD
        assert all(np.array_equal(kept[k], valid[k]) for k in kept)
        assert instance.call("fmi3SetFMUState", state) == OK
        assert instance.do_step(0.1, 0.1) == (OK, 0.2)
        assert instance.call("fmi3FreeFMUState", ctypes.byref(state)) == OK
    finally:
        instance.free()


def test_model_exchange_has_no_states_and_no_event_indicators():
    instance = Instance3("AngularKinematics", fmi_type="ModelExchange")
    try:
        n = ctypes.c_size_t(99)
        assert instance.call("fmi3GetNumberOfContinuousStates", ctypes.byref(n)) == OK and n.value == 0
        assert instance.call("fmi3GetNumberOfEventIndicators", ctypes.byref(n)) == OK and n.value == 0
        instance.initialize()
        flags = [ctypes.c_bool(True) for _ in range(5)]
        next_time = ctypes.c_double()
        assert instance.call("fmi3UpdateDiscreteStates", *[ctypes.byref(f) for f in flags],
                             ctypes.byref(next_time)) == OK
        assert not any(f.value for f in flags)
        assert instance.call("fmi3EnterContinuousTimeMode") == OK
        assert instance.call("fmi3SetTime", ctypes.c_double(0.5)) == OK
        x = (ctypes.c_double * 1)()
        for function in ("fmi3GetContinuousStates", "fmi3GetContinuousStateDerivatives",
                         "fmi3GetNominalsOfContinuousStates", "fmi3SetContinuousStates"):
            assert instance.call(function, x, 0) == OK
            assert instance.call(function, x, 1) == ERROR
            assert instance.errors()[-1].startswith(function)
            assert "nContinuousStates = 1" in instance.errors()[-1]
        assert instance.call("fmi3GetEventIndicators", x, 1) == ERROR
        assert instance.set({"theta": [0.1, 0.2, 0.3]}) == OK
        assert instance.get(["omega_fixed"])["omega_fixed"].tolist() == [0.0, 0.0, 0.0]
    finally:
        instance.free()


def test_simulate_fmu_with_array_inputs(report):
    """fmpy's input table: a structured array with one field per array input, of shape (3,)."""
    times = np.linspace(0.0, 1.0, 11)
    signals = np.zeros(len(times), dtype=[("time", float), ("theta", float, (3,)),
                                          ("theta_dot", float, (3,)), ("theta_ddot", float, (3,))])
    signals["time"] = times
    signals["theta"] = np.stack([0.5 * times, 0.25 * times ** 2, -times], axis=1)
    signals["theta_dot"] = np.stack([0.5 + 0 * times, 0.5 * times, -1 + 0 * times], axis=1)
    signals["theta_ddot"] = np.stack([0 * times, 0.5 + 0 * times, 0 * times], axis=1)
    result = simulate_fmu(str(fmu3_path("AngularKinematics")), stop_time=1.0,
                          output_interval=0.1, input=signals, start_values={"sequence": 1},
                          output=["omega_fixed", "q"])
    # At t = 1: the outputs of the step from 0.9, whose inputs fmpy set at t = 0.9 (held).
    instance = Instance3("AngularKinematics")
    try:
        instance.initialize(inputs={k: signals[k][-2] for k in ("theta", "theta_dot", "theta_ddot")})
        direct = instance.get(["omega_fixed", "q"])
    finally:
        instance.free()
    assert np.array_equal(result["omega_fixed"][-1], direct["omega_fixed"])
    assert np.array_equal(result["q"][-1], direct["q"])
    report(f"simulate_fmu with (11, 3) array inputs: {len(result)} rows")
