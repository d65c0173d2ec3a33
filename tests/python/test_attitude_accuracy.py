"""AttitudePropagator accuracy against closed forms (docs/attitude_propagator.md quotes the figures
these tests report): constant rotation (exact to rounding, variable steps, both frames), coning
motion at h = 1e-3 over 100 s with and without input derivatives, the order of convergence
measured log-log over h, and the round trip AngularKinematics -> AttitudePropagator that recovers
the angles of a smooth trajectory through gimbal lock."""
import numpy as np
import pytest

from attitude_support import (FRAME, OMEGA, OMEGA_DOT, Q, THETA, attitude_error,  # noqa: F401
                              attitude_model_description, attitude_unzipdir, coning,
                              make_attitude_instance, qconj, qexp, qmul, run_cs)


@pytest.mark.parametrize("frame", ["body", "fixed"])
def test_constant_rotation_is_exact_to_rounding_with_variable_steps(frame, make_attitude_instance,
                                                                     report):
    omega = np.array([0.3, -1.1, 2.0])
    q0 = np.array([0.5, 0.5, -0.5, 0.5])
    instance = make_attitude_instance()
    instance.fmu.setupExperiment(startTime=0.0)
    instance.fmu.enterInitializationMode()
    instance.set_integer({"frame": FRAME[frame]})
    instance.set({f"q0[{k + 1}]": q0[k] for k in range(4)} | dict(zip(OMEGA, omega)))
    instance.fmu.exitInitializationMode()
    steps = np.random.default_rng(1).uniform(1e-3, 5e-2, 400)
    t, worst = 0.0, 0.0
    for h in steps:
        instance.fmu.doStep(t, h)
        t += h
        e = qexp(omega * t / 2)
        exact = qmul(q0, e) if frame == "body" else qmul(e, q0)
        worst = max(worst, np.max(np.abs(instance.get(Q) - exact)))
    report(f"{frame} frame, 400 random steps over {t:.2f} s: largest |q - q_exact| = {worst:.2e}")
    # A truncation error of any method that is not exact for constant omega would be orders
    # above rounding here (|omega| h up to 0.1 rad per step).
    assert worst < 1e-13


@pytest.fixture(scope="module")
def coning_motion():
    return coning(beta=0.2, rate=2 * np.pi)


@pytest.mark.slow
def test_coning_motion_100_s(coning_motion, make_attitude_instance, report):
    q_of, omega_of, omega_dot_of, omega_ddot_of = coning_motion
    errors = {}
    for mode in ("held", "derivatives", "omega_dot", "derivatives2"):
        instance = make_attitude_instance(name=mode)
        errors[mode] = run_cs(instance, q_of, omega_of, omega_dot_of, 1e-3, 100.0, mode,
                              samples=1000, omega_ddot_of=omega_ddot_of)
        report(f"coning (beta 0.2 rad, 1 Hz), h = 1e-3, 100 s, inputs {mode}: largest attitude "
               f"error {errors[mode][0]:.2e} rad, at 100 s {errors[mode][1]:.2e} rad")
    # With derivatives the method is 3rd/4th order (test_convergence_order): orders of magnitude
    # below the held inputs, which are first order.
    assert errors["derivatives"][0] < 1e-8
    assert errors["omega_dot"] == errors["derivatives"]  # the same information, the same step
    assert errors["held"][0] > 1e4 * errors["derivatives"][0]
    # Both 4th order; order 2 also makes the first communication point so.
    assert errors["derivatives2"][0] < 1e-8


def order(hs, errors):
    return np.polyfit(np.log(hs), np.log(errors), 1)[0]


def test_convergence_order(coning_motion, make_attitude_instance, report):
    """Attitude error over 2 s of coning, for h = 0.04 .. 0.005, fitted log-log: the largest over
    the run, and at its end (with order-1 derivatives only the first communication point keeps the
    O(h^3) error of a step taken without history; the retaken step makes every later one 4th
    order)."""
    q_of, omega_of, omega_dot_of, omega_ddot_of = coning_motion
    hs = [0.04, 0.02, 0.01, 0.005]
    expected = {("derivatives2", "largest"): 4.0, ("derivatives", "at 2 s"): 4.0,
                ("held", "largest"): 1.0}
    for (mode, which), target in expected.items():
        errors = []
        for h in hs:
            instance = make_attitude_instance(name=f"{mode}{h}")
            largest, end = run_cs(instance, q_of, omega_of, omega_dot_of, h, 2.0, mode,
                                  omega_ddot_of=omega_ddot_of)
            errors.append(largest if which == "largest" else end)
        p = order(hs, errors)
        report(f"inputs {mode}, error {which}: {', '.join(f'{e:.2e}' for e in errors)} at h = "
               f"{', '.join(map(str, hs))}: order {p:.2f}")
        assert abs(p - target) < 0.15, (mode, p, errors)


def test_convergence_order_in_fixed_components(coning_motion, make_attitude_instance, report):
    """The same coning in fixed components (the other sign of the Magnus commutator):
    omega_f = R omega_b, its derivative R omega_b_dot, the next R (omega_b x omega_b_dot +
    omega_b_ddot)."""
    q_of, omega_of, omega_dot_of, omega_ddot_of = coning_motion

    def rotate(t, v):
        q = np.array(q_of(t), dtype=float)
        return qmul(qmul(q, np.concatenate([[0.0], v])), qconj(q))[1:]

    def body(f, t):
        return np.array(f(t), dtype=float)

    def omega_f(t):
        return rotate(t, body(omega_of, t))

    def omega_dot_f(t):
        return rotate(t, body(omega_dot_of, t))

    def omega_ddot_f(t):
        return rotate(t, np.cross(body(omega_of, t), body(omega_dot_of, t)) + body(omega_ddot_of, t))

    hs = [0.04, 0.02, 0.01, 0.005]
    errors = []
    for h in hs:
        instance = make_attitude_instance(name=f"fixed{h}")
        assert instance.set_integer({"frame": FRAME["fixed"]}) == 0
        errors.append(run_cs(instance, q_of, omega_f, omega_dot_f, h, 2.0, "derivatives2",
                             omega_ddot_of=omega_ddot_f)[0])
    p = order(hs, errors)
    report(f"fixed frame, derivatives orders 1 and 2: errors {', '.join(f'{e:.2e}' for e in errors)}: "
           f"order {p:.2f}")
    assert abs(p - 4.0) < 0.15, errors


def test_round_trip_through_gimbal_lock(make_instance, make_attitude_instance, report):
    """theta(t) of body123 crosses theta2 = pi/2 at t = 1 s; AngularKinematics turns it into
    omega_body and alpha_body, AttitudePropagator integrates them and gives theta back."""
    def theta_of(t):
        return np.array([0.4 + 0.7 * t, np.pi / 2 - 0.6 + 0.6 * t, -0.3 + 0.5 * t * t])

    def rates_of(t):
        return np.array([0.7, 0.6, t]), np.array([0.0, 0.0, 1.0])

    kinematics = make_instance()
    kinematics.initialize()
    propagator = make_attitude_instance()
    names = ([f"theta[{k}]" for k in (1, 2, 3)] + [f"theta_dot[{k}]" for k in (1, 2, 3)]
             + [f"theta_ddot[{k}]" for k in (1, 2, 3)])

    def body_rates(t):
        rates, accelerations = rates_of(t)
        kinematics.set(dict(zip(names, np.concatenate([theta_of(t), rates, accelerations]))))
        return (kinematics.get([f"omega_body[{k}]" for k in (1, 2, 3)]),
                kinematics.get([f"alpha_body[{k}]" for k in (1, 2, 3)]),
                kinematics.get([f"q[{k}]" for k in (1, 2, 3, 4)]))

    omega, alpha, q0 = body_rates(0.0)
    propagator.initialize(parameters={f"q0[{k + 1}]": q0[k] for k in range(4)},
                          inputs=dict(zip(OMEGA, omega)) | dict(zip(OMEGA_DOT, alpha)))
    h, worst_middle, worst_ends, smallest_distance = 1e-3, 0.0, 0.0, 1.0
    previous = propagator.get(THETA)
    for n in range(2000):
        t = n * h
        omega, alpha, _ = body_rates(t)
        propagator.set(dict(zip(OMEGA, omega)) | dict(zip(OMEGA_DOT, alpha)))
        propagator.fmu.doStep(t, h)
        theta = propagator.get(THETA)
        distance = propagator.get(["singularity_distance"])[0]
        smallest_distance = min(smallest_distance, distance)
        error = np.abs(theta - theta_of(t + h))
        worst_middle = max(worst_middle, error[1])
        # theta1 and theta3 are defined only to (attitude error) / distance near the singularity.
        worst_ends = max(worst_ends, max(error[0], error[2]) * distance)
        assert np.max(np.abs(theta - previous)) < 0.01, f"a jump at t = {t + h}"
        previous = theta
    report(f"body123 through gimbal lock (theta2 crosses pi/2, smallest singularity_distance "
           f"{smallest_distance:.1e}), h = 1e-3, 2 s: largest theta2 error {worst_middle:.1e} "
           f"rad; largest theta1/theta3 error x distance {worst_ends:.1e} rad")
    assert smallest_distance < 1e-3  # the trajectory does pass next to the singular angle
    assert previous[1] > np.pi / 2 + 0.5  # came out on the far side, not bounced back
    assert worst_middle < 1e-9
    assert worst_ends < 1e-9
