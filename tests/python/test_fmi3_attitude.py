"""dist/fmi3/AttitudePropagator.fmu against dist/AttitudePropagator.fmu (FMI 2), the same
description, model folder and core behind another FMI layer:

- co-simulation: every output (and der(q)) bit-identical to the FMI 2 FMU for the same omega and
  omega_dot inputs and the same, varying, communication step sizes, over several sequences and
  both frames; the steps with omega_dot zero (held omega) and not zero (the cubic of omega with
  its history) both exercised;
- model exchange: a hand explicit-Euler loop over the continuous-state functions gives the FMI 2
  FMU's states, derivatives and outputs bit for bit, and fmpy's simulate_fmu gives the FMI 2
  result;
- FMU state: a rollback and replay, and a serialized state restored in another instance, give
  bit-identical results, in both interfaces;
- directional and adjoint derivatives with the states as knowns and der(q) as unknown: the FMI 2
  layer's bits (directional), the transpose (adjoint);
- bad input (NaN omega, zero q0, wrong nValues, setting q or der(q), unknown value references,
  calls in the wrong state or with the wrong number of states) refused with fmi3Error and a
  message naming function, variable and value; nothing changes."""
import ctypes
import math

import numpy as np
import pytest
from fmpy import simulate_fmu

from attitude_support import (ATTITUDE_FMU_PATH, attitude_model_description,  # noqa: F401
                              attitude_unzipdir, make_attitude_instance)
from fmi3_support import DISCARD, ERROR, OK, Instance3, doubles, fmu3_path, vrs

MODEL = "AttitudePropagator"
SEQUENCES = (1, 4, 6, 7, 12, 13, 19, 24)  # Tait-Bryan and proper Euler, body and space
STEP_SIZES = (0.01, 0.05, 0.002, 0.1, 0.03)
Q0 = [0.9, 0.2, -0.3, 0.1]  # not unit: normalized at initialization


def bits(values):
    return np.asarray(values, dtype=np.float64).view(np.uint64)


def fmi2_initialize(fmi2, sequence, frame, q0=Q0):
    fmi2.initialize(parameters={"sequence": sequence, "frame": frame} |
                    {f"q0[{k + 1}]": v for k, v in enumerate(q0)})


def fmi3_initialize(fmi3, sequence, frame, q0=Q0):
    assert fmi3.call("fmi3EnterInitializationMode", False, 0.0, 0.0, False, 0.0) == OK
    assert fmi3.set_int({"sequence": sequence, "frame": frame}) == OK
    assert fmi3.set({"q0": q0}) == OK
    assert fmi3.call("fmi3ExitInitializationMode") == OK


def unknown_names(fmi3):
    """The outputs and der(q): every value the model computes."""
    return fmi3.outputs() + ["der(q)"]


def fmi2_values(fmi2, fmi3, names):
    """(status, values) of one fmi2GetReal of the FMI 2 elements of the FMI 3 arrays `names`."""
    elements = [vr for n in names for vr in range(fmi3.vr[n], fmi3.vr[n] + fmi3.size[n])]
    out = (ctypes.c_double * len(elements))()
    status = fmi2.call("fmi2GetReal", vrs(elements), len(elements), out)
    return status, np.array(list(out))


def fmi3_values(fmi3, names):
    status, values = fmi3.get_raw(names)
    return status, np.concatenate([values[n] for n in names])


def random_inputs(rng, step):
    omega = rng.uniform(-3.0, 3.0, 3)
    omega_dot = np.zeros(3) if step % 3 == 2 else rng.uniform(-2.0, 2.0, 3)
    return omega, omega_dot


def test_cosimulation_bit_identical_to_fmi2(make_attitude_instance, report):
    fmi2 = make_attitude_instance(name="fmi2")
    fmi3 = Instance3(MODEL, name="fmi3")
    rng = np.random.default_rng(14)
    names = unknown_names(fmi3)
    compared = steps = 0
    try:
        for sequence in SEQUENCES:
            for frame in (1, 2):
                assert fmi2.call("fmi2Reset") == 0 and fmi3.call("fmi3Reset") == OK
                fmi2_initialize(fmi2, sequence, frame)
                fmi3_initialize(fmi3, sequence, frame)
                s2, y2 = fmi2_values(fmi2, fmi3, names)
                s3, y3 = fmi3_values(fmi3, names)
                assert s2 == s3 == OK and np.array_equal(bits(y2), bits(y3))
                t = 0.0
                for k in range(24):
                    h = STEP_SIZES[k % len(STEP_SIZES)]
                    omega, omega_dot = random_inputs(rng, k)
                    u = np.concatenate([omega, omega_dot])
                    assert fmi2.call("fmi2SetReal", vrs(range(6)), 6, doubles(u)) == 0
                    assert fmi3.set({"omega": omega, "omega_dot": omega_dot}) == OK
                    assert fmi2.call("fmi2DoStep", ctypes.c_double(t), ctypes.c_double(h),
                                     True) == 0
                    status, last = fmi3.do_step(t, h)
                    assert status == OK and last == t + h
                    t += h
                    s2, y2 = fmi2_values(fmi2, fmi3, names)
                    s3, y3 = fmi3_values(fmi3, names)
                    assert s2 == s3 == OK
                    assert np.array_equal(bits(y2), bits(y3)), (sequence, frame, k)
                    compared += y3.size
                    steps += 1
    finally:
        fmi3.free()
    report(f"{MODEL}: co-simulation, {steps} steps ({len(SEQUENCES)} sequences x 2 frames, step "
           f"sizes {STEP_SIZES}): {compared} values of the outputs and der(q) bit-identical to "
           "the FMI 2 FMU")


def me_instances(make_attitude_instance, sequence, frame):
    fmi2 = make_attitude_instance(name="fmi2", fmi_type="ModelExchange")
    fmi3 = Instance3(MODEL, fmi_type="ModelExchange", name="fmi3")
    fmi2_initialize(fmi2, sequence, frame)
    fmi3_initialize(fmi3, sequence, frame)
    assert fmi2.call("fmi2EnterContinuousTimeMode") == 0
    assert fmi3.call("fmi3EnterContinuousTimeMode") == OK
    return fmi2, fmi3


def euler_step(fmi3, t, h, omega, x=None):
    """One explicit Euler step of the FMI 3 instance from its states; returns them after."""
    n = 4
    states, derivatives = (ctypes.c_double * n)(), (ctypes.c_double * n)()
    assert fmi3.call("fmi3SetTime", ctypes.c_double(t)) == OK
    assert fmi3.set({"omega": omega}) == OK
    assert fmi3.call("fmi3GetContinuousStates", states, n) == OK
    assert fmi3.call("fmi3GetContinuousStateDerivatives", derivatives, n) == OK
    x = np.array(list(states)) + h * np.array(list(derivatives))
    assert fmi3.call("fmi3SetContinuousStates", doubles(x), n) == OK
    flags = [ctypes.c_bool(True), ctypes.c_bool(True)]
    assert fmi3.call("fmi3CompletedIntegratorStep", True, ctypes.byref(flags[0]),
                     ctypes.byref(flags[1])) == OK
    assert not flags[0].value and not flags[1].value
    return x


@pytest.mark.parametrize("sequence, frame", [(1, 2), (13, 1), (24, 2)])
def test_model_exchange_hand_loop_bit_identical_to_fmi2(make_attitude_instance, sequence, frame,
                                                        report):
    fmi2, fmi3 = me_instances(make_attitude_instance, sequence, frame)
    try:
        n = ctypes.c_size_t()
        assert fmi3.call("fmi3GetNumberOfContinuousStates", ctypes.byref(n)) == OK and n.value == 4
        nominals = (ctypes.c_double * 4)()
        assert fmi3.call("fmi3GetNominalsOfContinuousStates", nominals, 4) == OK
        assert list(nominals) == [1.0] * 4
        names = unknown_names(fmi3)
        rng = np.random.default_rng(sequence)
        compared, t, h = 0, 0.0, 0.01
        for k in range(200):
            omega = rng.uniform(-3.0, 3.0, 3) if k % 20 == 0 else omega
            # FMI 2, by hand the same way
            x2, d2 = (ctypes.c_double * 4)(), (ctypes.c_double * 4)()
            assert fmi2.call("fmi2SetTime", ctypes.c_double(t)) == 0
            assert fmi2.call("fmi2SetReal", vrs(range(3)), 3, doubles(omega)) == 0
            assert fmi2.call("fmi2GetContinuousStates", x2, 4) == 0
            assert fmi2.call("fmi2GetDerivatives", d2, 4) == 0
            next2 = np.array(list(x2)) + h * np.array(list(d2))
            assert fmi2.call("fmi2SetContinuousStates", doubles(next2), 4) == 0
            b = [ctypes.c_int(), ctypes.c_int()]
            assert fmi2.call("fmi2CompletedIntegratorStep", 1, ctypes.byref(b[0]),
                             ctypes.byref(b[1])) == 0
            next3 = euler_step(fmi3, t, h, omega)
            assert np.array_equal(bits(next2), bits(next3))
            t += h
            s2, y2 = fmi2_values(fmi2, fmi3, names)
            s3, y3 = fmi3_values(fmi3, names)
            assert s2 == s3 == OK and np.array_equal(bits(y2), bits(y3)), k
            compared += y3.size + 4
        assert not np.allclose(next3, fmi3_values(fmi3, ["q"])[1] * 0)  # the states moved
    finally:
        fmi3.free()
    report(f"{MODEL}: model exchange, sequence {sequence} frame {frame}: 200 explicit Euler "
           f"steps, {compared} states and values bit-identical to the FMI 2 FMU")


def test_simulate_fmu_model_exchange_matches_fmi2(report):
    common = dict(fmi_type="ModelExchange", solver="Euler", step_size=0.01, output_interval=0.01,
                  stop_time=2.0)
    r3 = simulate_fmu(str(fmu3_path(MODEL)), start_values={
        "omega": [0.5, -1.0, 2.0], "q0": Q0, "sequence": 5, "frame": 1},
        output=["q", "theta", "R"], **common)
    start2 = {"sequence": 5, "frame": 1} | {f"omega[{k + 1}]": v for k, v in
                                            enumerate([0.5, -1.0, 2.0])}
    start2 |= {f"q0[{k + 1}]": v for k, v in enumerate(Q0)}
    out2 = [f"q[{k}]" for k in range(1, 5)] + [f"theta[{k}]" for k in range(1, 4)]
    r2 = simulate_fmu(str(ATTITUDE_FMU_PATH), start_values=start2, output=out2, **common)
    assert len(r3) == len(r2) == 201
    q2 = np.column_stack([r2[f"q[{k}]"] for k in range(1, 5)])
    theta2 = np.column_stack([r2[f"theta[{k}]"] for k in range(1, 4)])
    assert np.array_equal(bits(r3["q"]), bits(q2)) and np.array_equal(bits(r3["theta"]), bits(theta2))
    assert not np.allclose(r3["q"][-1], r3["q"][0])
    report(f"{MODEL}: fmpy simulate_fmu model exchange (Euler, 0.01 s, 2 s): {len(r3)} rows of q "
           "and theta bit-identical to the FMI 2 FMU")


def run_cs(fmi3, t, inputs):
    names = unknown_names(fmi3)
    out = []
    for h, omega, omega_dot in inputs:
        assert fmi3.set({"omega": omega, "omega_dot": omega_dot}) == OK
        assert fmi3.do_step(t, h) == (OK, t + h)
        t += h
        out.append(fmi3_values(fmi3, names)[1])
    return t, bits(np.concatenate(out))


def serialized(fmi3, state):
    size = ctypes.c_size_t()
    assert fmi3.call("fmi3SerializedFMUStateSize", state, ctypes.byref(size)) == OK
    data = (ctypes.c_ubyte * size.value)()
    assert fmi3.call("fmi3SerializeFMUState", state, data, size.value) == OK
    return data, size.value


def test_cosimulation_rollback_and_replay_bit_identical(report):
    rng = np.random.default_rng(3)
    inputs = [(STEP_SIZES[k % 5], *random_inputs(rng, k)) for k in range(30)]
    fmi3 = Instance3(MODEL, name="first")
    other = Instance3(MODEL, name="second")
    try:
        fmi3_initialize(fmi3, 7, 2)
        t, _ = run_cs(fmi3, 0.0, inputs[:10])  # a history (omega_previous, h_previous) to carry
        state = ctypes.c_void_p()
        assert fmi3.call("fmi3GetFMUState", ctypes.byref(state)) == OK
        t_end, first = run_cs(fmi3, t, inputs[10:])
        assert fmi3.call("fmi3SetFMUState", state) == OK
        _, replay = run_cs(fmi3, t, inputs[10:])
        assert np.array_equal(first, replay)
        data, size = serialized(fmi3, state)
        fmi3_initialize(other, 7, 2)
        copy = ctypes.c_void_p()
        assert other.call("fmi3DeserializeFMUState", data, size, ctypes.byref(copy)) == OK
        assert other.call("fmi3SetFMUState", copy) == OK
        _, restored = run_cs(other, t, inputs[10:])
        assert np.array_equal(first, restored)
        assert fmi3.call("fmi3FreeFMUState", ctypes.byref(state)) == OK
        assert other.call("fmi3FreeFMUState", ctypes.byref(copy)) == OK
    finally:
        fmi3.free()
        other.free()
    report(f"{MODEL}: co-simulation rollback over 20 steps and a {size}-byte serialized state "
           f"in another instance: {first.size} values replayed bit for bit, twice")


def test_model_exchange_rollback_and_replay_bit_identical():
    fmi3 = Instance3(MODEL, fmi_type="ModelExchange")
    try:
        fmi3_initialize(fmi3, 19, 1)
        assert fmi3.call("fmi3EnterContinuousTimeMode") == OK
        for k in range(5):
            euler_step(fmi3, 0.01 * k, 0.01, [1.0, -0.5, 0.25])
        state = ctypes.c_void_p()
        assert fmi3.call("fmi3GetFMUState", ctypes.byref(state)) == OK

        def run():
            out = [euler_step(fmi3, 0.05 + 0.01 * k, 0.01, [0.3, 2.0, -1.0]) for k in range(20)]
            return bits(np.concatenate(out + [fmi3_values(fmi3, unknown_names(fmi3))[1]]))

        first = run()
        assert fmi3.call("fmi3SetFMUState", state) == OK
        assert np.array_equal(run(), first)
        assert fmi3.call("fmi3FreeFMUState", ctypes.byref(state)) == OK
    finally:
        fmi3.free()


def test_directional_and_adjoint_derivatives_with_states(make_attitude_instance, report):
    fmi2, fmi3 = me_instances(make_attitude_instance, 4, 2)
    try:
        euler_step(fmi3, 0.0, 0.1, [0.7, -0.2, 1.5])
        x = (ctypes.c_double * 4)()
        assert fmi3.call("fmi3GetContinuousStates", x, 4) == OK
        assert fmi2.call("fmi2SetReal", vrs(range(3)), 3, doubles([0.7, -0.2, 1.5])) == 0
        assert fmi2.call("fmi2SetContinuousStates", x, 4) == 0
        assert fmi2.set({"omega_dot[1]": 0.5}) == 0 and fmi3.set({"omega_dot": [0.5, 0, 0]}) == OK
        names = unknown_names(fmi3)
        fmi2_values(fmi2, fmi3, names), fmi3_values(fmi3, names)  # both evaluated alike
        rows = [vr for n in names for vr in range(fmi3.vr[n], fmi3.vr[n] + fmi3.size[n])]
        seed = np.random.default_rng(5).uniform(-1.0, 1.0, 10)
        d2 = (ctypes.c_double * len(rows))()
        assert fmi2.call("fmi2GetDirectionalDerivative", vrs(rows), len(rows), vrs(range(10)),
                         10, doubles(seed), d2) == 0
        knowns = [fmi3.vr["omega"], fmi3.vr["omega_dot"], fmi3.vr["q"]]
        d3 = (ctypes.c_double * len(rows))()
        assert fmi3.call("fmi3GetDirectionalDerivative", vrs(fmi3.vr[n] for n in names),
                         len(names), vrs(knowns), 3, doubles(seed), 10, d3, len(rows)) == OK
        assert np.array_equal(bits(list(d2)), bits(list(d3)))
        assert np.any(np.array(list(d3)) != 0.0)
        weights = np.random.default_rng(6).uniform(-1.0, 1.0, len(rows))
        a3 = (ctypes.c_double * 10)()
        assert fmi3.call("fmi3GetAdjointDerivative", vrs(fmi3.vr[n] for n in names), len(names),
                         vrs(knowns), 3, doubles(weights), len(rows), a3, 10) == OK
        assert float(weights @ np.array(list(d3))) == pytest.approx(float(np.array(list(a3)) @ seed),
                                                                    rel=1e-12, abs=1e-12)
    finally:
        fmi3.free()
    report(f"{MODEL}: directional derivative of {len(rows)} unknowns (outputs, der(q)) over 10 "
           "knowns (omega, omega_dot, q) bit-identical to the FMI 2 FMU; adjoint its transpose")


def test_per_element_dependencies_not_provided():
    fmi3 = Instance3(MODEL)
    try:
        n = ctypes.c_size_t()
        assert fmi3.call("fmi3GetNumberOfVariableDependencies", fmi3.vr["R"],
                         ctypes.byref(n)) == ERROR
        assert "providesPerElementDependencies" in fmi3.errors()[-1]
        assert fmi3.errors()[-1].startswith("fmi3GetNumberOfVariableDependencies")
    finally:
        fmi3.free()


# --- bad input ----------------------------------------------------------------------------------

def f64(instance, vr_list, values, n=None):
    values = list(values)
    return instance.call("fmi3SetFloat64", vrs(vr_list), len(vr_list), doubles(values),
                         len(values) if n is None else n)


def snapshot(instance):
    names = [v.name for v in instance.md.modelVariables
             if v.type == "Float64" and v.name != "time"]
    values = instance.get(names)
    ints = (ctypes.c_int64 * 2)()
    assert instance.call("fmi3GetInt64", vrs([instance.vr["frame"], instance.vr["sequence"]]), 2,
                         ints, 2) == OK
    return np.concatenate([values[n] for n in names]).view(np.uint64).tolist() + list(ints)


def states_call(function, values, n):
    return lambda i: i.call(function, doubles(values), n)


# (name, interface, call on an initialized instance, words the message must hold)
CASES = [
    ("NaN omega", "CoSimulation", lambda i: f64(i, [0], [0.1, math.nan, 0.3]),
     ["fmi3SetFloat64", "omega[2]", "nan"]),
    ("too few values", "CoSimulation", lambda i: f64(i, [0, 3], [0.1] * 5),
     ["fmi3SetFloat64", "nValues = 5", "omega .. omega_dot", "6 elements", "too few"]),
    ("too many values to get", "CoSimulation",
     lambda i: i.call("fmi3GetFloat64", vrs([6]), 1, doubles([0] * 9), 9),
     ["fmi3GetFloat64", "nValues = 9", "q", "4 elements", "too many"]),
    ("set the state q", "CoSimulation", lambda i: f64(i, [6], [1.0, 0, 0, 0]),
     ["fmi3SetFloat64", "= 6 is q, an output and a continuous state", "fmi3SetContinuousStates"]),
    ("set der(q)", "ModelExchange", lambda i: f64(i, [10], [0.0] * 4),
     ["fmi3SetFloat64", "= 10 is der(q), a local"]),
    ("set a co-simulation memory", "CoSimulation", lambda i: f64(i, [54], [0.5]),
     ["fmi3SetFloat64", "= 54 is h_previous, a local"]),
    ("unknown value reference", "CoSimulation", lambda i: f64(i, [61], [1.0]),
     ["fmi3SetFloat64", "valueReferences[0] = 61 is not"]),
    ("inner element of q", "CoSimulation",
     lambda i: i.call("fmi3GetFloat64", vrs([7]), 1, doubles([0] * 3), 3),
     ["fmi3GetFloat64", "valueReferences[0] = 7 is not"]),
    ("q0 after initialization", "CoSimulation", lambda i: f64(i, [44], [0.0, 1.0, 0.0, 0.0]),
     ["fmi3SetFloat64", "q0[1]", "variability fixed", "Step Mode"]),
    ("frame out of range", "ModelExchange",
     lambda i: i.call("fmi3SetInt64", vrs([42]), 1, (ctypes.c_int64 * 1)(3), 1),
     ["fmi3SetInt64", "frame", "Continuous-Time Mode"]),
    ("continuous states in co-simulation", "CoSimulation",
     states_call("fmi3SetContinuousStates", [1, 0, 0, 0], 4),
     ["fmi3SetContinuousStates", "not available", "fmi3InstantiateCoSimulation"]),
    ("step in model exchange", "ModelExchange",
     lambda i: i.call("fmi3DoStep", ctypes.c_double(0.0), ctypes.c_double(0.1), True,
                      *[ctypes.byref(ctypes.c_bool()) for _ in range(3)],
                      ctypes.byref(ctypes.c_double())),
     ["fmi3DoStep"]),
    ("wrong nContinuousStates", "ModelExchange",
     states_call("fmi3SetContinuousStates", [1, 0, 0], 3),
     ["fmi3SetContinuousStates", "nContinuousStates = 3", "4 continuous states"]),
    ("NaN state", "ModelExchange", states_call("fmi3SetContinuousStates", [1, math.nan, 0, 0], 4),
     ["fmi3SetContinuousStates", "continuousStates[1] = nan", "q[2]"]),
    ("wrong number of derivatives", "ModelExchange",
     states_call("fmi3GetContinuousStateDerivatives", [0] * 5, 5),
     ["fmi3GetContinuousStateDerivatives", "nContinuousStates = 5"]),
    ("wrong number of nominals", "ModelExchange",
     states_call("fmi3GetNominalsOfContinuousStates", [0] * 2, 2),
     ["fmi3GetNominalsOfContinuousStates", "nContinuousStates = 2"]),
    ("derivative w.r.t. an output", "CoSimulation",
     lambda i: i.call("fmi3GetDirectionalDerivative", vrs([14]), 1, vrs([23]), 1,
                      doubles([1, 0, 0]), 3, doubles([0] * 9), 9),
     ["fmi3GetDirectionalDerivative", "knowns[0] = 23", "theta"]),
]


@pytest.mark.parametrize("name, interface, bad_call, words", CASES, ids=[c[0] for c in CASES])
def test_bad_input_refused_with_message_and_nothing_changed(name, interface, bad_call, words):
    instance = Instance3(MODEL, fmi_type=interface)
    try:
        fmi3_initialize(instance, 9, 1)
        assert instance.set({"omega": [0.5, -1.0, 0.25], "omega_dot": [0.0, 0.1, 0.0]}) == OK
        if interface == "ModelExchange":
            assert instance.call("fmi3EnterContinuousTimeMode") == OK
        else:
            assert instance.do_step(0.0, 0.1)[0] == OK
        before = snapshot(instance)
        n_errors = len(instance.errors())
        assert bad_call(instance) == ERROR
        errors = instance.errors()[n_errors:]
        assert len(errors) == 1, errors
        for word in words:
            assert word in errors[0], (word, errors[0])
        assert snapshot(instance) == before
    finally:
        instance.free()


def test_zero_q0_refused_at_initialization_and_correctable():
    instance = Instance3(MODEL)
    try:
        assert instance.call("fmi3EnterInitializationMode", False, 0.0, 0.0, False, 0.0) == OK
        assert instance.set({"q0": [0.0, 0.0, 0.0, 0.0]}) == OK  # the norm needs all four
        status, _ = instance.get_raw(["q"])
        assert status == DISCARD
        assert instance.call("fmi3ExitInitializationMode") == ERROR
        errors = instance.errors()
        assert "q0 = (0, 0, 0, 0) is not an attitude" in errors[-2]
        assert errors[-1].startswith("fmi3ExitInitializationMode: the parameters give no initial "
                                     "state")
        assert instance.set({"q0": [0.0, 0.0, 2.0, 0.0]}) == OK  # still in Initialization Mode
        assert instance.call("fmi3ExitInitializationMode") == OK
        assert instance.get(["q"])["q"].tolist() == [0.0, 0.0, 1.0, 0.0]
        assert instance.set({"q0": [math.nan] * 4}) == ERROR
        assert "fmi3SetFloat64: q0[1] = nan" in instance.errors()[-1]
    finally:
        instance.free()


def test_step_that_cannot_be_taken_is_discarded_and_changes_nothing(make_attitude_instance):
    """omega so large that the rotation over the step is not finite: fmi3Discard, the model's
    message and the layer's, lastSuccessfulTime the step's start, every value as before; the
    FMI 2 FMU discards the same step. A step with a sane omega then goes on from there."""
    fmi2 = make_attitude_instance(name="fmi2")
    fmi3 = Instance3(MODEL, logging_on=True)  # a discard is logged only then
    try:
        fmi2_initialize(fmi2, 3, 2)
        fmi3_initialize(fmi3, 3, 2)
        assert fmi3.set({"omega": [1.0, 2.0, 3.0]}) == OK and fmi3.do_step(0.0, 0.5) == (OK, 0.5)
        before = snapshot(fmi3)
        assert fmi3.set({"omega": [1e308, -1e308, 1e308]}) == OK
        kept = snapshot(fmi3)
        assert fmi3.do_step(0.5, 10.0) == (DISCARD, 0.5)
        warnings = [m for s, c, m in fmi3.messages if s in ("Error", "Discard")][-2:]
        assert warnings[0].startswith("AttitudePropagator: omega = (1e+308, -1e+308, 1e+308) over "
                                      "the communication step size 10")
        assert warnings[1].startswith("fmi3DoStep: the step from 0.5 to 10.5 is discarded: the "
                                      "states cannot be advanced over it")
        assert snapshot(fmi3) == kept and kept != before
        assert fmi2.set({"omega[1]": 1.0, "omega[2]": 2.0, "omega[3]": 3.0}) == 0
        assert fmi2.call("fmi2DoStep", ctypes.c_double(0.0), ctypes.c_double(0.5), True) == 0
        assert fmi2.set({"omega[1]": 1e308, "omega[2]": -1e308, "omega[3]": 1e308}) == 0
        assert fmi2.call("fmi2DoStep", ctypes.c_double(0.5), ctypes.c_double(10.0), True) == DISCARD
        assert fmi3.set({"omega": [1.0, 2.0, 3.0]}) == OK
        assert fmi3.do_step(0.5, 0.5) == (OK, 1.0)
    finally:
        fmi3.free()
