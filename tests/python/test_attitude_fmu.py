"""AttitudePropagator through its FMI 2 interface: model exchange with real continuous states
(<Derivatives>, <InitialUnknowns>, fmi2Get/SetContinuousStates, fmi2GetDerivatives, nominals),
initialization from q0, the angle outputs (unwrapped, finite at the singular angle), bad input
(nothing changed, a message naming function, variable and value), rollback and replay
bit-identical through FMU states, and the norm kept over many steps."""
import ctypes

import numpy as np
import pytest
from fmpy import simulate_fmu
from fmpy.validation import validate_fmu

from attitude_support import (ATTITUDE_FMU_PATH, FRAME, OMEGA, OMEGA_DOT, Q, THETA,  # noqa: F401
                              attitude_model_description, attitude_unzipdir,
                              make_attitude_instance, qexp, qmul)

DER_Q = [f"der(q[{k}])" for k in (1, 2, 3, 4)]


def doubles(values):
    return (ctypes.c_double * len(values))(*values)


PROTOTYPES = {
    "fmi2DoStep": (ctypes.c_void_p, ctypes.c_double, ctypes.c_double, ctypes.c_int),
    "fmi2GetContinuousStates": (ctypes.c_void_p, ctypes.c_void_p, ctypes.c_size_t),
}


def call_other_interface(instance, function, *args):
    """An FMI function the fmpy class of the instance's interface does not load."""
    prototype = ctypes.CFUNCTYPE(ctypes.c_int, *PROTOTYPES[function])
    return prototype((function, instance.fmu.dll))(instance.component, *args)


def test_model_description_declares_four_states_and_no_event_indicators(attitude_model_description):
    md = attitude_model_description
    assert validate_fmu(str(ATTITUDE_FMU_PATH)) == []
    assert md.numberOfContinuousStates == 4
    assert md.numberOfEventIndicators == 0
    assert [d.variable.name for d in md.derivatives] == DER_Q
    assert [d.variable.derivative.name for d in md.derivatives] == Q
    assert md.coSimulation.canInterpolateInputs is True
    assert md.coSimulation.canHandleVariableCommunicationStepSize is True
    assert md.modelExchange.providesDirectionalDerivative is True  # test_attitude_derivatives.py
    initial = {u.variable.name: {d.name for d in u.dependencies} for u in md.initialUnknowns}
    q0 = {f"q0[{k}]" for k in (1, 2, 3, 4)}
    assert initial["q[1]"] == q0 and initial["der(q[2])"] == q0 | set(OMEGA)
    assert set(Q + DER_Q) <= set(initial)


@pytest.mark.parametrize("frame", ["body", "fixed"])
def test_derivatives_are_the_quaternion_kinematics_and_their_listed_dependencies(
        frame, make_attitude_instance, attitude_model_description):
    """der(q) = q (x) (0, omega)/2 (body) or (0, omega) (x) q/2 (fixed), for states that are not
    unit (an integrator's); every derivative changes with exactly the states and inputs that
    <Derivatives> lists."""
    instance = make_attitude_instance(fmi_type="ModelExchange")
    instance.fmu.setupExperiment(startTime=0.0)
    instance.fmu.enterInitializationMode()
    instance.set_integer({"frame": FRAME[frame]})
    instance.fmu.exitInitializationMode()
    instance.fmu.enterContinuousTimeMode()
    rng = np.random.default_rng(7)
    listed = {u.variable.name: {d.name for d in u.dependencies}
              for u in attitude_model_description.derivatives}
    for _ in range(20):
        x, omega = rng.normal(size=4), rng.normal(size=3)
        assert instance.call("fmi2SetContinuousStates", doubles(x), 4) == 0
        assert instance.set(dict(zip(OMEGA, omega))) == 0
        dx = (ctypes.c_double * 4)()
        assert instance.call("fmi2GetDerivatives", dx, 4) == 0
        w = np.concatenate([[0.0], omega])
        expected = (qmul(x, w) if frame == "body" else qmul(w, x)) / 2
        assert np.allclose(np.array(dx), expected, rtol=0, atol=1e-15)
        assert np.array_equal(instance.get(DER_Q), np.array(dx))
    knowns = Q + OMEGA + OMEGA_DOT
    for k, name in enumerate(knowns):
        base = np.concatenate([x, omega, [0.0, 0.0, 0.0]])
        moved = base.copy()
        moved[k] += 0.5
        values = []
        for point in (base, moved):
            instance.call("fmi2SetContinuousStates", doubles(point[:4]), 4)
            instance.set(dict(zip(OMEGA + OMEGA_DOT, point[4:])))
            values.append(instance.get(DER_Q))
        changed = {DER_Q[i] for i in range(4) if values[0][i] != values[1][i]}
        assert changed == {d for d in DER_Q if name in listed[d]}, name


def test_model_exchange_with_cvode_follows_the_closed_form(attitude_model_description, report):
    omega = np.array([0.4, -0.3, 1.2])
    result = simulate_fmu(str(ATTITUDE_FMU_PATH), fmi_type="ModelExchange", stop_time=5.0,
                          output_interval=0.1, relative_tolerance=1e-10,
                          start_values=dict(zip(OMEGA, omega)), output=Q + THETA)
    worst = 0.0
    for row in result:
        exact = qexp(omega * row["time"] / 2)
        q = np.array([row[n] for n in Q])
        worst = max(worst, np.max(np.abs(q / np.linalg.norm(q) - exact)))
    report(f"model exchange, CVode rtol 1e-10, 5 s of constant rotation: |q - q_exact| <= {worst:.1e}")
    assert worst < 1e-7


def test_states_and_nominals_in_model_exchange(make_attitude_instance):
    instance = make_attitude_instance(fmi_type="ModelExchange")
    instance.fmu.setupExperiment(startTime=0.0)
    instance.fmu.enterInitializationMode()
    instance.set({"q0[1]": 1.0, "q0[2]": 1.0, "q0[3]": 1.0, "q0[4]": 1.0})
    x = (ctypes.c_double * 4)()
    assert instance.call("fmi2GetContinuousStates", x, 4) == 0
    assert list(x) == [0.5, 0.5, 0.5, 0.5]  # q0 normalized, already in InitializationMode
    instance.fmu.exitInitializationMode()
    nominal = (ctypes.c_double * 4)()
    assert instance.call("fmi2GetNominalsOfContinuousStates", nominal, 4) == 0
    assert list(nominal) == [1.0] * 4
    instance.fmu.enterContinuousTimeMode()
    assert instance.call("fmi2SetContinuousStates", doubles([0.0, 0.0, 0.0, 2.0]), 4) == 0
    assert list(instance.get(Q)) == [0.0, 0.0, 0.0, 2.0]
    # R and the angles are those of the attitude q / |q|: a rotation by pi about n3.
    assert np.allclose(instance.get(["R[1,1]", "R[2,2]", "R[3,3]"]), [-1.0, -1.0, 1.0], atol=1e-15)


def start(instance, parameters=None, inputs=None):
    instance.initialize(parameters=parameters, inputs=inputs)


def test_q0_is_normalized_and_a_zero_q0_is_refused_until_corrected(make_attitude_instance):
    instance = make_attitude_instance()
    instance.fmu.setupExperiment(startTime=0.0)
    instance.fmu.enterInitializationMode()
    assert instance.set({"q0[1]": 0.0}) == 0
    assert instance.call("fmi2ExitInitializationMode") == 3
    assert instance.errors() == ["AttitudePropagator: q0 = (0, 0, 0, 0) is not an attitude: the "
                                 "initial quaternion must be finite and not zero; q0[1] = 1 and "
                                 "the rest 0 is the identity",
                                 "fmi2ExitInitializationMode: the parameters give no initial "
                                 "state (see the message before); the instance stays in "
                                 "InitializationMode"]
    assert instance.call("fmi2DoStep", ctypes.c_double(0.0), ctypes.c_double(0.1), 1) == 3
    assert instance.set({"q0[3]": -1e300}) == 0  # still InitializationMode: settable
    assert instance.call("fmi2ExitInitializationMode") == 0
    assert list(instance.get(Q)) == [0.0, 0.0, -1.0, 0.0]


def test_angles_unwrap_across_pi(make_attitude_instance):
    """A steady turn about b3 at 1 rad/s: body123 theta3 = t, on past pi and 2 pi."""
    instance = make_attitude_instance()
    start(instance, inputs={"omega[3]": 1.0})
    for n in range(100):
        instance.fmu.doStep(n * 0.1, 0.1)
        theta = instance.get(THETA)
        assert abs(theta[2] - (n + 1) * 0.1) < 1e-12 and abs(theta[0]) < 1e-15


@pytest.mark.parametrize("sequence", [1, 11, 13, 24])  # body123, body313, space123, space323
def test_angle_outputs_finite_at_the_singular_angle(sequence, make_attitude_instance):
    """Start exactly at the singular attitude (theta2 = pi/2 or 0) of the sequence and turn about
    a body axis: the angles, their rates and the distance stay finite, theta1 is held while the
    distance is below the threshold."""
    instance = make_attitude_instance()
    # A quaternion at the singular attitude of each sequence.
    q_of = {1: qexp(np.array([0.0, np.pi / 4, 0.0])),  # R_2(pi/2): body123 theta2 = pi/2
            11: np.array([1.0, 0.0, 0.0, 0.0]),        # identity: body313 theta2 = 0
            13: qexp(np.array([0.0, np.pi / 4, 0.0])),  # space123 theta2 = pi/2
            24: np.array([1.0, 0.0, 0.0, 0.0])}         # space323 theta2 = 0
    q0 = q_of[sequence]
    start(instance, parameters={"sequence": sequence} | {f"q0[{k + 1}]": q0[k] for k in range(4)},
          inputs={"omega[1]": 0.3, "omega[2]": -0.2, "omega[3]": 0.5})
    names = THETA + ["theta_dot[1]", "theta_dot[2]", "theta_dot[3]", "singularity_distance"]
    values = instance.get(names)
    assert np.all(np.isfinite(values)) and values[-1] < 1e-8
    for n in range(20):
        instance.fmu.doStep(n * 0.05, 0.05)
        assert np.all(np.isfinite(instance.get(names)))


def test_alpha_and_omega_in_both_frames(make_attitude_instance):
    instance = make_attitude_instance()
    omega, omega_dot = np.array([0.2, 0.5, -0.4]), np.array([1.0, -2.0, 0.5])
    start(instance, parameters={"q0[1]": 0.9, "q0[2]": 0.1, "q0[3]": -0.3, "q0[4]": 0.2},
          inputs=dict(zip(OMEGA, omega)) | dict(zip(OMEGA_DOT, omega_dot)))
    R = instance.get([f"R[{i},{j}]" for i in (1, 2, 3) for j in (1, 2, 3)]).reshape(3, 3)
    assert np.allclose(R @ R.T, np.eye(3), atol=1e-15)
    assert np.array_equal(instance.get([f"omega_body[{k}]" for k in (1, 2, 3)]), omega)
    assert np.allclose(instance.get([f"omega_fixed[{k}]" for k in (1, 2, 3)]), R @ omega, atol=1e-15)
    assert np.array_equal(instance.get([f"alpha_body[{k}]" for k in (1, 2, 3)]), omega_dot)
    assert np.allclose(instance.get([f"alpha_fixed[{k}]" for k in (1, 2, 3)]), R @ omega_dot,
                       atol=1e-15)


def snapshot(instance):
    return instance.get(Q + THETA + ["theta_dot[1]", "R[1,2]", "singularity_distance"])


def test_rollback_and_replay_are_bit_identical(make_attitude_instance):
    """Steps with input derivatives (so the step's history matters), a state taken at step 20,
    serialized and restored into a fresh instance: the replay from there gives the same bits."""
    def drive(instance, first, last, record):
        vrs = (ctypes.c_uint * 3)(*[instance.vr[n] for n in OMEGA])
        for n in range(first, last):
            t = 0.01 * n
            instance.set(dict(zip(OMEGA, [np.sin(3 * t), 0.5, np.cos(t)])))
            slopes = doubles([3 * np.cos(3 * t), 0.0, -np.sin(t)])
            instance.call("fmi2SetRealInputDerivatives", vrs, 3, (ctypes.c_int * 3)(1, 1, 1), slopes)
            instance.fmu.doStep(t, 0.01)  # raises unless fmi2OK
            record.append(snapshot(instance))

    first = make_attitude_instance(name="first")
    start(first, parameters={"sequence": 13})
    original, replay, again = [], [], []
    drive(first, 0, 20, original)
    state = first.fmu.getFMUState()
    serialized = first.fmu.serializeFMUState(state)
    drive(first, 20, 60, original)
    first.fmu.setFMUState(state)  # rollback in the same instance
    drive(first, 20, 60, again)
    second = make_attitude_instance(name="second")
    start(second, parameters={"sequence": 13})
    second.fmu.setFMUState(second.fmu.deserializeFMUState(serialized))
    drive(second, 20, 60, replay)
    assert all(np.array_equal(a, b) for a, b in zip(original[20:], again))
    assert all(np.array_equal(a, b) for a, b in zip(original[20:], replay))
    first.fmu.freeFMUState(state)


def test_bad_input_is_refused_and_changes_nothing(make_attitude_instance):
    instance = make_attitude_instance()
    start(instance, inputs={"omega[1]": 0.5})
    instance.fmu.doStep(0.0, 0.1)
    before = snapshot(instance)
    checks = [
        (lambda: instance.set({"omega[2]": float("nan")}),
         "fmi2SetReal: omega[2] = nan (vr[0] = 1) is not finite; no value set"),
        (lambda: instance.set({"omega_dot[3]": float("inf")}),
         "fmi2SetReal: omega_dot[3] = inf (vr[0] = 5) is not finite; no value set"),
        (lambda: instance.set({"q[2]": 0.5}),
         "fmi2SetReal: vr[0] = 7 is q[2], an output and a continuous state "
         "(fmi2SetContinuousStates sets states in model exchange): only inputs and parameters "
         "can be set; no value set"),
        (lambda: instance.set({"der(q[1])": 0.5}),
         "fmi2SetReal: vr[0] = 10 is der(q[1]), a local: only inputs and parameters can be "
         "set; no value set"),
        (lambda: instance.set({"q0[1]": 2.0}),
         "fmi2SetReal: q0[1] (vr[0] = 44) is a parameter of variability fixed: it can be set "
         "only in Instantiated and InitializationMode, not in StepComplete; no value set"),
        (lambda: instance.call("fmi2GetReal", (ctypes.c_uint * 1)(99), 1, (ctypes.c_double * 1)()),
         "fmi2GetReal: vr[0] = 99 is not a value reference of this FMU (0 to 60)"),
        (lambda: call_other_interface(instance, "fmi2GetContinuousStates", (ctypes.c_double * 4)(), 4),
         "fmi2GetContinuousStates: a model-exchange function, but this instance was created "
         "for co-simulation (fmi2CoSimulation)"),
        (lambda: instance.call("fmi2DoStep", ctypes.c_double(0.1), ctypes.c_double(-1.0), 1),
         "fmi2DoStep: communicationStepSize = -1 must be > 0"),
    ]
    for call, message in checks:
        count = len(instance.errors())
        assert call() == 3, message
        assert instance.errors()[count:] == [message]
        assert np.array_equal(snapshot(instance), before)


def test_bad_state_arrays_in_model_exchange(make_attitude_instance):
    instance = make_attitude_instance(fmi_type="ModelExchange")
    instance.fmu.setupExperiment(startTime=0.0)
    instance.fmu.enterInitializationMode()
    instance.fmu.exitInitializationMode()
    instance.fmu.enterContinuousTimeMode()
    before = instance.get(Q)
    assert instance.call("fmi2SetContinuousStates", doubles([1.0, float("nan"), 0.0, 0.0]), 4) == 3
    assert instance.call("fmi2SetContinuousStates", doubles([1.0, 0.0, 0.0]), 3) == 3
    assert instance.call("fmi2GetDerivatives", (ctypes.c_double * 5)(), 5) == 3
    assert instance.call("fmi2GetEventIndicators", (ctypes.c_double * 1)(), 1) == 3
    assert call_other_interface(instance, "fmi2DoStep", 0.0, 0.1, 1) == 3
    assert instance.errors() == [
        "fmi2SetContinuousStates: x[1] = nan (q[2]) is not finite; no state set",
        "fmi2SetContinuousStates: nx = 3, but this FMU has 4 continuous states "
        "(numberOfContinuousStates)",
        "fmi2GetDerivatives: nx = 5, but this FMU has 4 continuous states (numberOfContinuousStates)",
        "fmi2GetEventIndicators: ni = 1, but this FMU has no event indicators (ni must be 0)",
        "fmi2DoStep: a co-simulation function, but this instance was created for model exchange "
        "(fmi2ModelExchange)"]
    assert np.array_equal(instance.get(Q), before)
    # A zero state is not an attitude: the outputs keep their values and the read says Discard.
    assert instance.call("fmi2SetContinuousStates", doubles([0.0] * 4), 4) == 0
    values = (ctypes.c_double * 1)()
    assert instance.call("fmi2GetReal", (ctypes.c_uint * 1)(instance.vr["theta[1]"]), 1, values) == 2


def test_norm_kept_over_many_steps_of_a_tumbling_body(make_attitude_instance, report):
    """The bounded version of the 1e7-step run (build/test_attitude 10000000): 2e4 FMU steps."""
    instance = make_attitude_instance()
    start(instance, inputs={"omega[1]": 1.0})
    vrs = [instance.vr[n] for n in OMEGA + OMEGA_DOT]
    q_vr = [instance.vr[n] for n in Q]
    worst = 0.0
    for n in range(20000):
        t = 1e-3 * n
        instance.fmu.setReal(vrs, [np.cos(t), 0.5 * np.sin(2 * t), 0.3, -np.sin(t), np.cos(2 * t), 0.0])
        instance.fmu.doStep(t, 1e-3)
        if n % 100 == 99:
            worst = max(worst, abs(np.linalg.norm(instance.fmu.getReal(q_vr)) - 1.0))
    report(f"tumbling body, 2e4 steps of 1e-3: largest | |q| - 1 | = {worst:.1e}")
    assert worst < 1e-15


@pytest.mark.slow
def test_source_fmu_compiles_with_fmpy_and_simulates_identically(attitude_unzipdir, tmp_path):
    """sources/ of AttitudePropagator.fmu (its own list: attitude.c and its variable table) rebuilt
    by fmpy into a binary that computes the same bits as the packaged one."""
    import pathlib
    import shutil

    from fmpy import read_model_description
    from fmpy.build import build_platform_binary

    listed = (pathlib.Path(__file__).resolve().parents[2] / "build"
              / "fmu_sources_AttitudePropagator.txt").read_text().split()
    assert {"attitude.c", "AttitudePropagator_variables.c", "model.c"} <= set(listed)
    assert not any("EulerRates" in n or "AngularKinematics_variables" in n for n in listed)
    description = read_model_description(str(ATTITUDE_FMU_PATH))
    assert description.buildConfigurations[0].sourceFileSets[0].sourceFiles == listed
    copy = tmp_path / "fmu"
    shutil.copytree(attitude_unzipdir, copy)
    shutil.rmtree(copy / "binaries")
    build_platform_binary(copy, build_dir=tmp_path, all_warnings=True,
                          cmake_options={"CMAKE_COMPILE_WARNING_AS_ERROR:BOOL": "ON"})
    names = Q + THETA + ["theta_dot[2]", "alpha_fixed[1]", "singularity_distance"]
    start = {"sequence": 11, "frame": 1, "omega[1]": 1.5, "omega[3]": -0.5, "omega_dot[2]": 2.0,
             "q0[2]": 0.3}

    def simulate(fmu):
        return simulate_fmu(fmu, stop_time=0.5, output_interval=0.01, output=names,
                            start_values=start)

    ours, rebuilt = simulate(str(ATTITUDE_FMU_PATH)), simulate(str(copy))
    for name in ["time"] + names:
        assert np.array_equal(ours[name], rebuilt[name]), name
