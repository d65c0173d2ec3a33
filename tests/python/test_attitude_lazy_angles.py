"""AttitudePropagator's lazy angles (model.c, step_angles): in co-simulation the angles are
computed when read, from the last ones computed, and by the step itself when a later read could
differ. Reading them rarely must give the bits of reading them at every communication point:
for every sequence and both frames, through fast tumbling, the singular configuration, steps
that turn by more than a radian, input derivatives (the retaken first step) and an FMU state
taken while the angles wait. And the bound a step adds covers how far each angle moves along
it, near the singular attitude and away from it."""
import ctypes

import numpy as np
import pytest

from attitude_support import FRAME, OMEGA, Q, THETA, make_attitude_instance, qmul  # noqa: F401
from codegen import project

ANGLE_OUTPUTS = THETA + ["theta_dot[1]", "theta_dot[3]", "R[1,3]", "singularity_distance"]


def omega_at(n, kind):
    """Inputs at communication point n: a fast tumble; a body whose body123 angles swing to
    within 0.05 rad of the singular attitude while it spins about body axis 3; a spin about body
    axis 2 through the singular attitude of the Tait-Bryan sequences whose middle axis is 2; or
    jumps of up to 40 rad/s (several radians per step)."""
    t = 0.05 * n
    if kind == "tumble":
        return [3.0 * np.sin(0.7 * t) + 1.0, 2.0 * np.cos(1.3 * t), 4.0 * np.sin(0.4 * t + 1.0)]
    if kind == "swing":  # omega_body = W_body(theta) theta_dot of these body123 angles
        w, a2 = 2.0, np.pi / 2 - 0.05
        theta2 = a2 * np.sin(w * t + 0.4)
        theta3 = w * t + 0.5 * np.sin(w * t + 1.0)
        rates = [0.8 * w * np.cos(w * t), a2 * w * np.cos(w * t + 0.4),
                 w + 0.5 * w * np.cos(w * t + 1.0)]
        s2, c2, s3, c3 = np.sin(theta2), np.cos(theta2), np.sin(theta3), np.cos(theta3)
        return [c2 * c3 * rates[0] + s3 * rates[1], -c2 * s3 * rates[0] + c3 * rates[1],
                s2 * rates[0] + rates[2]]
    if kind == "through_singular":
        return [1e-9 * np.sin(t), np.pi / 2 / 0.05 / 20, 0.0]  # pi/2 in 20 steps
    return [40.0 * np.sin(1.7 * n), 25.0 * np.cos(2.3 * n), 30.0 * np.sin(0.9 * n + 0.5)]


def drive(instance, steps, kind, read_every, with_derivatives, first=0, record=None):
    """Steps first .. steps - 1; after each, q is read, and every read_every-th step the angle
    outputs too: {step: values} into record."""
    record = {} if record is None else record
    vrs = (ctypes.c_uint * 3)(*[instance.vr[n] for n in OMEGA])
    for n in range(first, steps):
        instance.set(dict(zip(OMEGA, omega_at(n, kind))))
        if with_derivatives:
            slopes = (ctypes.c_double * 3)(*omega_at(n + 0.5, kind))
            instance.call("fmi2SetRealInputDerivatives", vrs, 3, (ctypes.c_int * 3)(1, 1, 1), slopes)
        instance.fmu.doStep(0.05 * n, 0.05)  # raises unless fmi2OK
        names = Q + ANGLE_OUTPUTS if (n + 1) % read_every == 0 else Q
        record[n] = dict(zip(names, instance.get(names)))
    return record


def started(make, sequence, frame):
    instance = make()
    instance.initialize(parameters={"sequence": sequence, "frame": FRAME[frame]},
                        inputs={"omega_dot[1]": 0.0})
    return instance


def assert_same_bits(dense, sparse):
    """Every value the sparse run read equals the dense run's, bit for bit."""
    for n, values in sparse.items():
        for name, value in values.items():
            assert np.float64(value).tobytes() == np.float64(dense[n][name]).tobytes(), (n, name)


@pytest.mark.parametrize("sequence", range(1, 25))
@pytest.mark.parametrize("frame", ["body", "fixed"])
def test_angles_read_rarely_are_those_read_at_every_step(sequence, frame, make_attitude_instance):
    for kind, with_derivatives in [("tumble", False), ("swing", False),
                                   ("through_singular", False), ("jumps", False),
                                   ("tumble", True)]:
        steps = 120
        dense = drive(started(make_attitude_instance, sequence, frame), steps, kind, 1,
                      with_derivatives)
        for read_every in (3, 40):
            sparse = drive(started(make_attitude_instance, sequence, frame), steps, kind,
                           read_every, with_derivatives)
            assert_same_bits(dense, sparse)


def test_a_state_taken_while_the_angles_wait_replays_the_same_bits(make_attitude_instance):
    """A state taken after steps without a read of the angles, restored into a fresh instance and
    into the same one: reading the angles from there gives the bits of the run read throughout."""
    dense = drive(started(make_attitude_instance, 1, "body"), 90, "tumble", 1, True)
    first = started(make_attitude_instance, 1, "body")
    drive(first, 45, "tumble", 1000, True)
    drive(first, 50, "tumble", 1000, True, first=45)
    state = first.fmu.getFMUState()
    serialized = first.fmu.serializeFMUState(state)
    assert_same_bits(dense, drive(first, 90, "tumble", 7, True, first=50))
    first.fmu.setFMUState(state)
    assert_same_bits(dense, drive(first, 90, "tumble", 1, True, first=50))
    second = started(make_attitude_instance, 1, "body")
    second.fmu.setFMUState(second.fmu.deserializeFMUState(serialized))
    assert_same_bits(dense, drive(second, 90, "tumble", 13, True, first=50))
    first.fmu.freeFMUState(state)


def image_value(instance, name):
    """A value as an FMU state holds it (values by value reference after the 88-byte header,
    docs/capabilities.md#fmu-state), read without a get (a get of a local evaluates)."""
    state = instance.fmu.getFMUState()
    image = instance.fmu.serializeFMUState(state)
    instance.fmu.freeFMUState(state)
    offset = 88 + 8 * instance.vr[name]
    return np.frombuffer(bytes(image[offset:offset + 8]), dtype="<f8")[0]


def test_the_step_computes_the_angles_only_when_a_read_could_differ(make_attitude_instance):
    """A slow rotation: the angles wait for a read over all 30 steps; jumps of several radians
    per step: the step computes them at every step, before it moves the state."""
    for kind, age in [("slow", 30.0), ("jumps", 1.0)]:
        instance = started(make_attitude_instance, 1, "body")
        for n in range(30):
            omega = [0.1, 0.05, -0.02] if kind == "slow" else omega_at(n, "jumps")
            instance.set(dict(zip(OMEGA, omega)))
            instance.fmu.doStep(0.05 * n, 0.05)
            instance.get(Q)  # a state: read without an evaluation
        assert image_value(instance, "angles_age") == age
        assert (image_value(instance, "angles_change_bound") <= 0.6) == (kind == "slow")
        instance.get(THETA)
        assert image_value(instance, "angles_age") == 0.0


def test_q_follows_q0_until_initialization_ends_in_both_layers(make_attitude_instance):
    """A get of q alone evaluates only while the states follow the parameters: in Initialization
    Mode it gives the normalized q0 just set (FMI 2 and FMI 3); after it, the stepped q."""
    fmi2 = make_attitude_instance()
    fmi2.fmu.setupExperiment(startTime=0.0)
    fmi2.fmu.enterInitializationMode()
    assert fmi2.set({"q0[1]": 0.0, "q0[2]": 3.0, "q0[4]": -4.0}) == 0
    assert list(fmi2.get(Q)) == [0.0, 0.6, 0.0, -0.8]
    fmi2.fmu.exitInitializationMode()
    fmi2.set({"omega[1]": 2.0})
    fmi2.fmu.doStep(0.0, 0.5)
    assert list(fmi2.get(Q)) != [0.0, 0.6, 0.0, -0.8]

    fmi3 = make_attitude_instance(fmi_version=3)
    assert fmi3.call("fmi3EnterInitializationMode", False, 0.0, 0.0, False, 0.0) == 0
    assert fmi3.set({"q0": [0.0, 3.0, 0.0, -4.0]}) == 0
    assert list(fmi3.get(["q"])["q"]) == [0.0, 0.6, 0.0, -0.8]
    assert fmi3.call("fmi3ExitInitializationMode") == 0
    assert fmi3.set({"omega": [2.0, 0.0, 0.0]}) == 0
    assert fmi3.do_step(0.0, 0.5)[0] == 0
    q3 = list(fmi3.get(["q"])["q"])
    assert q3 != [0.0, 0.6, 0.0, -0.8] and q3 == list(fmi2.get(Q))


@pytest.mark.parametrize("sequence", [1, 6, 7, 13, 18, 24])
def test_fmi3_angles_read_rarely_are_fmi2_angles_read_at_every_step(sequence,
                                                                     make_attitude_instance):
    """The FMI 3 layer reads q without an evaluation too: its angles, read every 5th or 40th
    step, are the FMI 2 FMU's read at every step, bit for bit."""
    names = ["q", "theta", "R", "singularity_distance"]
    for frame in ["body", "fixed"]:
        for kind in ["tumble", "through_singular", "jumps"]:
            dense = drive(started(make_attitude_instance, sequence, frame), 120, kind, 1, False)
            for read_every in (5, 40):
                fmi3 = make_attitude_instance(fmi_version=3)
                fmi3.initialize(parameters={"sequence": sequence, "frame": FRAME[frame]})
                for n in range(120):
                    assert fmi3.set({"omega": omega_at(n, kind)}) == 0
                    assert fmi3.do_step(0.05 * n, 0.05)[0] == 0
                    read = names if (n + 1) % read_every == 0 else ["q"]
                    values = fmi3.get(read)
                    expected = {"q": [dense[n][name] for name in Q]}
                    if len(read) > 1:
                        expected["theta"] = [dense[n][name] for name in THETA]
                        expected["singularity_distance"] = [dense[n]["singularity_distance"]]
                        assert values["R"][2] == dense[n]["R[1,3]"]
                    for name, value in expected.items():
                        assert np.array(value).tobytes() == values[name].tobytes(), (n, name)


def quaternion_of_sequence(name, theta):
    """q of the angles theta of sequence name (numpy, independent of the C core): body-fixed
    a1-a2-a3 is R_a1(theta1) R_a2(theta2) R_a3(theta3), space-fixed R_a3(theta3) R_a2(theta2)
    R_a1(theta1)."""
    factors = []
    for axis, angle in zip(project.sequence_axes(name), theta):
        factor = np.zeros(4)
        factor[0], factor[axis] = np.cos(angle / 2), np.sin(angle / 2)
        factors.append(factor)
    if name.startswith("space"):
        factors.reverse()
    return qmul(qmul(factors[0], factors[1]), factors[2])


@pytest.mark.parametrize("sequence", range(1, 25))
@pytest.mark.parametrize("frame", ["body", "fixed"])
def test_the_bound_of_a_step_covers_how_far_each_angle_moves(sequence, frame, make_attitude_instance):
    """The bound one step adds (angles_change_bound after a step from computed angles) is at least
    how far each angle moves along the step: the angles read at 100 substeps of the same rotation
    (omega held, so the substeps turn about the same axis), from attitudes 0.03 and 0.3 rad from
    the singular one, turning by 0.01 and 0.1 rad about random axes."""
    name = project.SEQUENCES[sequence - 1]
    rng = np.random.default_rng(sequence * 2 + FRAME[frame])
    h, substeps, checked = 0.1, 100, 0
    for offset in (0.03, 0.3):
        middle = offset if project.sequence_is_proper_euler(name) else np.pi / 2 - offset
        q0 = quaternion_of_sequence(name, [rng.uniform(-3, 3), middle, rng.uniform(-3, 3)])
        for turn in (0.01, 0.1):
            axis = rng.normal(size=3)
            omega = dict(zip(OMEGA, turn / h * axis / np.linalg.norm(axis)))
            parameters = {"sequence": sequence, "frame": FRAME[frame],
                          **{f"q0[{k + 1}]": q0[k] for k in range(4)}}
            whole = make_attitude_instance()
            whole.initialize(parameters=parameters, inputs={"omega_dot[1]": 0.0})
            assert abs(whole.get(["singularity_distance"])[0] - np.sin(offset)) < 1e-9
            whole.set(omega)
            whole.fmu.doStep(0.0, h)
            bound = image_value(whole, "angles_change_bound")
            parts = make_attitude_instance()
            parts.initialize(parameters=parameters, inputs={"omega_dot[1]": 0.0})
            start = np.array(parts.get(THETA))
            moved = np.zeros(3)
            for k in range(substeps):
                parts.set(omega)
                parts.fmu.doStep(k * h / substeps, h / substeps)
                moved = np.maximum(moved, np.abs(np.array(parts.get(THETA)) - start))
            if bound <= 1.3:  # above it, the next step computes the angles
                checked += 1
                assert moved.max() <= bound * (1 + 1e-9), (offset, turn, moved, bound)
    assert checked >= 3
