"""QuaternionKinematics through its FMUs: the outputs against an independent high-precision
reference (u = q / |q| along q(t) = q + q_dot t + q_ddot t^2 / 2, differentiated by sympy and
evaluated with mpmath; the angular velocity and acceleration from the quaternion products of their
definition, R from u v u*), the angles through the rotations they compose and through
AngularKinematics, AngularKinematics' quaternion along angle trajectories, the invariances (-q,
2^k q, 3.7 q), the refusals and their recovery, ModelStructure against the reference's
dependencies, and direct feedthrough with FMI 3's arrays against FMI 2's scalars."""
import ctypes
import functools
import math

import mpmath as mp
import numpy as np
import pytest
import sympy as sp
from fmpy import read_model_description

from conftest import QUICK_SEQUENCES, fmu_path_of, sequence_cases
from codegen import project

MODEL = "QuaternionKinematics"
SHAPES = {"q": 4, "q_dot": 4, "q_ddot": 4, "omega_fixed": 3, "omega_body": 3, "alpha_fixed": 3,
          "alpha_body": 3, "R": 9, "q_norm": 1, "theta": 3, "theta_dot": 3, "theta_ddot": 3,
          "singularity_distance": 1}
VECTORS_IN = ["q", "q_dot", "q_ddot"]
VECTORS_OUT = ["omega_fixed", "omega_body", "alpha_fixed", "alpha_body", "R", "q_norm", "theta",
               "theta_dot", "theta_ddot", "singularity_distance"]
DIGITS = 40  # mpmath's working precision of the reference


def names(vector):
    """The FMI 2 scalar names of a vector (R: row-major R[i,j])."""
    if vector == "R":
        return [f"R[{i},{j}]" for i in (1, 2, 3) for j in (1, 2, 3)]
    if SHAPES[vector] == 1:
        return [vector]
    return [f"{vector}[{i}]" for i in range(1, SHAPES[vector] + 1)]


INPUT_NAMES = [n for v in VECTORS_IN for n in names(v)]
OUTPUT_NAMES = [n for v in VECTORS_OUT for n in names(v)]


def is_fmi3(instance):
    return hasattr(instance, "inputs")


def set_inputs(instance, q, q_dot, q_ddot):
    if is_fmi3(instance):
        return instance.set({"q": q, "q_dot": q_dot, "q_ddot": q_ddot})
    return instance.set(dict(zip(INPUT_NAMES, np.concatenate([q, q_dot, q_ddot]))))


def read_raw(instance, vectors=VECTORS_OUT):
    """(status, {vector: values}) of one read of the vectors, without raising: after a refusal
    the FMU still writes the values it keeps."""
    if is_fmi3(instance):
        return instance.get_raw(vectors)
    flat = [n for v in vectors for n in names(v)]
    values = (ctypes.c_double * len(flat))()
    status = instance.call("fmi2GetReal", (ctypes.c_uint * len(flat))(*[instance.vr[n] for n in flat]),
                           len(flat), values)
    got, k = {}, 0
    for v in vectors:
        got[v] = np.array(values[k:k + SHAPES[v]])
        k += SHAPES[v]
    return status, got


def outputs(instance, vectors=VECTORS_OUT, allowed=(0,)):
    status, got = read_raw(instance, vectors)
    assert status in allowed, (status, instance.messages[-3:])
    return got


def bits(got):
    return {v: np.asarray(x, dtype=float).view(np.uint64).tolist() for v, x in got.items()}


def sequence_index(name):
    return project.SEQUENCES.index(name) + 1


def start(new_instance, model=MODEL, fmi_version=2, sequence="body123", **more):
    instance = new_instance(model, fmi_version=fmi_version, logging_on=True, **more)
    instance.initialize(parameters={"sequence": sequence_index(sequence)})
    return instance


@pytest.fixture(params=[2, 3], ids=["fmi2", "fmi3"])
def fmi_version(request):
    return request.param


# --- the reference -------------------------------------------------------------------------------

def hamilton(a, b):
    """a b, scalar first (works on sympy and mpmath numbers alike)."""
    return [a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
            a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
            a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
            a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0]]


def conjugate(a):
    return [a[0], -a[1], -a[2], -a[3]]


@functools.lru_cache(maxsize=1)
def _symbols():
    """t, the 12 input symbols (q, q_dot, q_ddot) and u(t) = q(t) / |q(t)| along
    q(t) = q + q_dot t + q_ddot t^2 / 2."""
    t = sp.symbols("t")
    x = sp.symbols("q0:4 d0:4 e0:4", real=True)
    q, d, e = x[0:4], x[4:8], x[8:12]
    curve = [q[k] + d[k] * t + e[k] * t ** 2 / 2 for k in range(4)]
    norm = sp.sqrt(sum(c ** 2 for c in curve))
    return t, x, [c / norm for c in curve], norm


@functools.lru_cache(maxsize=1)
def _u_and_derivatives():
    """An mpmath function of the 12 inputs: u, u', u'' at t = 0 (12 values) and |q|."""
    t, x, u, norm = _symbols()
    at0 = [e.subs(t, 0) for e in u] + [sp.diff(e, t).subs(t, 0) for e in u] + \
          [sp.diff(e, t, 2).subs(t, 0) for e in u] + [norm.subs(t, 0)]
    return sp.lambdify(x, at0, "mpmath", cse=True)


def rotate(u, v):
    """vec(u (0, v) u*) in mpmath: the definition of R(u) v."""
    return hamilton(hamilton(u, [0] + list(v)), conjugate(u))[1:]


def reference(q, q_dot, q_ddot):
    """The exact outputs (mpmath, DIGITS digits) of the inputs (doubles, taken exactly), and the
    sizes of the terms that make them."""
    with mp.workdps(DIGITS):
        values = _u_and_derivatives()(*[mp.mpf(float(v)) for v in (*q, *q_dot, *q_ddot)])
        u, u1, u2, n = values[0:4], values[4:8], values[8:12], values[12]
        columns = [rotate(u, e) for e in ([1, 0, 0], [0, 1, 0], [0, 0, 1])]
        exact = {"omega_body": [2 * c for c in hamilton(conjugate(u), u1)[1:]],
                 "omega_fixed": [2 * c for c in hamilton(u1, conjugate(u))[1:]],
                 "alpha_body": [2 * c for c in hamilton(conjugate(u), u2)[1:]],
                 "alpha_fixed": [2 * c for c in hamilton(u2, conjugate(u))[1:]],
                 "R": [columns[j][i] for i in range(3) for j in range(3)],
                 "q_norm": [n]}
    size_q = float(np.linalg.norm(q))
    omega = 2 * float(np.linalg.norm(q_dot)) / size_q
    alpha = 2 * float(np.linalg.norm(q_ddot)) / size_q + omega ** 2
    sizes = {"omega_body": omega, "omega_fixed": omega, "alpha_body": alpha,
             "alpha_fixed": alpha, "R": 1.0, "q_norm": size_q}
    return exact, u, sizes


def tolerance(name):
    """What the checks beyond the accuracy test allow: 1e-15 of the terms' size."""
    return 1e-15


def error(got, exact, size):
    """The largest difference of got (doubles) from exact (mpmath), relative to max(1, size)."""
    with mp.workdps(DIGITS):
        return float(max(abs(mp.mpf(float(g)) - e) for g, e in zip(got, exact))) / max(1.0, size)


def random_motions(rng, n):
    """n (q, q_dot, q_ddot): random directions, lengths each 1e-3 to 1e3, log-uniform and
    independent."""
    def vectors():
        v = rng.normal(size=(n, 4))
        return v / np.linalg.norm(v, axis=1)[:, None] * 10.0 ** rng.uniform(-3, 3, (n, 1))
    return list(zip(vectors(), vectors(), vectors()))


# --- the rotations the angles compose ------------------------------------------------------------

def chain(sequence):
    """(axes, index of theta per chain place) of the chain R = R_a1(phi1) R_a2(phi2) R_a3(phi3):
    body-fixed I-J-K is R_I(theta1) R_J(theta2) R_K(theta3); space-fixed I-J-K is
    R_K(theta3) R_J(theta2) R_I(theta1)."""
    axes = [a - 1 for a in project.sequence_axes(sequence)]
    if sequence.startswith("body"):
        return axes, [0, 1, 2]
    return axes[::-1], [2, 1, 0]


def elementary(axis, angle):
    """The rotation by angle about the coordinate axis (0, 1, 2), right-handed, as an mpmath
    matrix: it turns a vector, v_fixed = R v_body."""
    c, s = mp.cos(angle), mp.sin(angle)
    m = mp.eye(3)
    i, j = (axis + 1) % 3, (axis + 2) % 3
    m[i, i], m[i, j], m[j, i], m[j, j] = c, -s, s, c
    return m


def composed(sequence, theta):
    """R of the angles, composed from the sequence's elementary rotations (mpmath)."""
    axes, place = chain(sequence)
    with mp.workdps(DIGITS):
        m = mp.eye(3)
        for a, k in zip(axes, place):
            m = m * elementary(a, mp.mpf(float(theta[k])))
        return [m[i, j] for i in range(3) for j in range(3)]


def exact_distance(sequence, u):
    """|cos theta2| (Tait-Bryan) or |sin theta2| (proper Euler) of the attitude u: e_a1 . R e_a3
    is +-sin theta2 (Tait-Bryan) or cos theta2 (proper Euler), for the chain's first and last
    axes."""
    axes, _ = chain(sequence)
    with mp.workdps(DIGITS):
        e = [0, 0, 0]
        e[axes[2]] = 1
        x = rotate(u, e)[axes[0]]
        return mp.sqrt(1 - x * x)


def principal(sequence, theta, slack=0.0):
    """Whether theta is the principal set of the sequence."""
    low = 0.0 if project.sequence_is_proper_euler(sequence) else -math.pi / 2
    return (low - slack <= theta[1] <= low + math.pi + slack and
            -math.pi - slack <= theta[0] <= math.pi + slack and
            -math.pi - slack <= theta[2] <= math.pi + slack)


# --- 1. accuracy ---------------------------------------------------------------------------------

ACCURACY_SAMPLES = 4000


@functools.lru_cache(maxsize=1)
def accuracy_errors():
    """{output: worst error} of ACCURACY_SAMPLES random motions (|q|, |q_dot|, |q_ddot| each 1e-3
    to 1e3, random directions) against the mpmath reference, relative to max(1, size of the terms
    that make the output): omega 2 |q_dot| / |q|, alpha 2 |q_ddot| / |q| + 4 |q_dot|^2 / |q|^2,
    R 1, q_norm |q|; and the number of samples whose R is off by more than 1e-15."""
    from conftest import Instance, fmu_files
    unzipdir, description = fmu_files(MODEL)
    instance = Instance(unzipdir, description)
    try:
        instance.initialize()
        rng = np.random.default_rng(20261127)
        worst = {v: 0.0 for v in ("omega_fixed", "omega_body", "alpha_fixed", "alpha_body", "R",
                                  "q_norm")}
        r_above = 0
        for q, q_dot, q_ddot in random_motions(rng, ACCURACY_SAMPLES):
            assert set_inputs(instance, q, q_dot, q_ddot) == 0
            got = outputs(instance, list(worst), allowed=(0, 1))
            exact, _, sizes = reference(q, q_dot, q_ddot)
            for name in worst:
                e = error(got[name], exact[name], sizes[name])
                worst[name] = max(worst[name], e)
                r_above += name == "R" and e > 1e-15
        return worst, r_above
    finally:
        instance.free()


@pytest.mark.xdist_group("quaternion_accuracy")  # one worker computes accuracy_errors once
def test_every_output_within_1e_15_of_the_exact_value(report):
    """omega (both frames), alpha (both frames), R and q_norm within 1e-15 of the terms' size (see
    accuracy_errors).
    Planted: a reference with alpha_body = 2 vec(u'' u*) (the fixed-frame product) fails it at
    errors of order 1."""
    worst, r_above = accuracy_errors()
    report(f"{MODEL}: {ACCURACY_SAMPLES} random motions (|q|, |q_dot|, |q_ddot| 1e-3 to 1e3), "
           "worst error relative to max(1, size of the terms): " +
           ", ".join(f"{k} {v:.2g}" for k, v in worst.items()) +
           f" ({r_above} R above 1e-15)")
    assert max(worst.values()) <= 1e-15, worst


@pytest.mark.parametrize("sequence", sequence_cases())
def test_the_angles_compose_R_and_give_back_omega_and_alpha(new_instance, sequence, report):
    """For 200 random motions: theta is principal, the sequence's elementary rotations of theta
    compose the exact R of u (within 1e-15 over the distance: theta1 and theta3 are read off
    entries of R of size distance, so R's rounding moves them by that over the distance),
    singularity_distance is the exact one (within 1e-15), and where it is above 1e-2 AngularKinematics (same sequence) turns theta, theta_dot,
    theta_ddot back into QuaternionKinematics' omega_body and alpha_body (within 1e-15 of the
    terms' size over distance, and over distance^2 for alpha). Planted: the space-fixed chain
    taken in body order (axes not reversed) fails the composition at errors of order 1."""
    qk = start(new_instance, sequence=sequence)
    ak = start(new_instance, "AngularKinematics", sequence=sequence)
    rng = np.random.default_rng(sequence_index(sequence))
    worst = dict(R=0.0, distance=0.0, omega=0.0, alpha=0.0)
    largest_R = 0.0  # R(theta)'s error itself, not scaled
    checked = 0
    for q, q_dot, q_ddot in random_motions(rng, 200):
        assert set_inputs(qk, q, q_dot, q_ddot) == 0
        got = outputs(qk, allowed=(0, 1))
        exact, u, sizes = reference(q, q_dot, q_ddot)
        theta = got["theta"]
        assert principal(sequence, theta), theta
        with mp.workdps(DIGITS):
            e = float(max(abs(a - b) for a, b in zip(composed(sequence, theta), exact["R"])))
            d = float(exact_distance(sequence, u))
        largest_R = max(largest_R, e)
        worst["R"] = max(worst["R"], e * d)
        worst["distance"] = max(worst["distance"], abs(got["singularity_distance"][0] - d))
        if d <= 1e-2:
            continue
        checked += 1
        assert ak.set({**dict(zip(names("theta"), theta)),
                       **dict(zip(names("theta_dot"), got["theta_dot"])),
                       **dict(zip(names("theta_ddot"), got["theta_ddot"]))}) == 0
        back = ak.get(names("omega_body") + names("alpha_body"))
        for key, values, power in (("omega", back[:3], 1), ("alpha", back[3:], 2)):
            size = max(1.0, sizes[f"{key}_body"])
            e = float(np.max(np.abs(values - got[f"{key}_body"]))) / size * d ** power
            worst[key] = max(worst[key], e)
    report(f"{MODEL} {sequence}: 200 random motions, {checked} with distance > 1e-2 back through "
           f"AngularKinematics; worst: R(theta) {largest_R:.2g} ({worst['R']:.2g} times distance), distance {worst['distance']:.2g}, "
           f"omega {worst['omega']:.2g} and alpha {worst['alpha']:.2g} (relative to the terms' size "
           "times distance, distance^2)")
    assert checked >= 100
    assert max(worst.values()) <= 1e-15, worst


# --- 2. along angle trajectories, against AngularKinematics ------------------------------------

@functools.lru_cache(maxsize=None)
def _trajectory(sequence):
    """theta(t) = a + b sin(w t + c) (theta1 running past pi, theta2 within 1.2 of the middle of
    its principal range: distance at least cos 1.2 = 0.36), and the sequence's quaternion as the
    product of the three axis quaternions (cos(phi_k/2), sin(phi_k/2) e_ak), with their first and
    second derivatives: one mpmath function of t."""
    t = sp.symbols("t")
    middle = sp.pi / 2 if project.sequence_is_proper_euler(sequence) else 0
    theta = [sp.Rational(5, 2) + sp.sin(sp.Rational(13, 10) * t + sp.Rational(1, 3)),
             middle + sp.Rational(6, 5) * sp.sin(sp.Rational(7, 10) * t - 1),
             -sp.Rational(1, 2) + 2 * sp.sin(sp.Rational(9, 10) * t + 2)]
    axes, place = chain(sequence)
    q = [sp.Integer(1), 0, 0, 0]
    for a, k in zip(axes, place):
        factor = [sp.cos(theta[k] / 2), 0, 0, 0]
        factor[a + 1] = sp.sin(theta[k] / 2)
        q = hamilton(q, factor)
    values = (theta + [sp.diff(x, t) for x in theta] + [sp.diff(x, t, 2) for x in theta] +
              q + [sp.diff(x, t) for x in q] + [sp.diff(x, t, 2) for x in q])
    return sp.lambdify(t, values, "mpmath", cse=True)


@pytest.mark.parametrize("sequence", sequence_cases())
def test_along_angle_trajectories_as_angular_kinematics(new_instance, sequence, report):
    """At 60 instants of a smooth angle trajectory AngularKinematics gives q (its unit quaternion
    output, q[1] >= 0) and omega, alpha; q_dot and q_ddot come from the sympy derivative of the
    product of the axis quaternions, their sign taken with q's. QuaternionKinematics fed q, q_dot,
    q_ddot gives AngularKinematics' omega and alpha (within 1e-14 of their size), theta equal to
    the trajectory's where that is principal (else up to 2 pi), and the trajectory's theta_dot
    and theta_ddot. Planted: q_ddot's sign not flipped with q fails alpha at errors of order 1."""
    f = _trajectory(sequence)
    ak = start(new_instance, "AngularKinematics", sequence=sequence)
    qk = start(new_instance, sequence=sequence)
    worst = dict(q=0.0, omega=0.0, alpha=0.0, theta=0.0, theta_dot=0.0, theta_ddot=0.0)
    seen = {True: 0, False: 0}
    for time in np.linspace(0.0, 9.0, 60):
        with mp.workdps(DIGITS):
            values = [float(v) for v in f(mp.mpf(time))]
        theta, theta_dot, theta_ddot = (np.array(values[3 * k:3 * k + 3]) for k in range(3))
        q_exact, q_dot, q_ddot = (np.array(values[9 + 4 * k:13 + 4 * k]) for k in range(3))
        assert ak.set({**dict(zip(names("theta"), theta)),
                       **dict(zip(names("theta_dot"), theta_dot)),
                       **dict(zip(names("theta_ddot"), theta_ddot))}) == 0
        kinematics = ["omega_fixed", "omega_body", "alpha_fixed", "alpha_body"]
        a = dict(zip(["q"] + kinematics,
                     np.split(ak.get(names("q") + [n for v in kinematics for n in names(v)]),
                              [4, 7, 10, 13, 16])))
        sign = 1.0 if q_exact[0] >= 0 else -1.0  # AngularKinematics' q has q[1] >= 0
        worst["q"] = max(worst["q"], float(np.max(np.abs(a["q"] - sign * q_exact))))
        assert set_inputs(qk, a["q"], sign * q_dot, sign * q_ddot) == 0
        got = outputs(qk, allowed=(0, 1))
        omega_size = max(1.0, float(np.linalg.norm(a["omega_body"])))
        alpha_size = max(1.0, float(np.linalg.norm(a["alpha_body"])), omega_size ** 2)
        for name in kinematics:
            size = omega_size if name.startswith("omega") else alpha_size
            key = name.split("_")[0]
            worst[key] = max(worst[key], float(np.max(np.abs(got[name] - a[name]))) / size)
        is_principal = principal(sequence, theta)
        seen[is_principal] += 1
        difference = got["theta"] - theta
        if not is_principal:  # theta1 past pi: the same attitude 2 pi away
            difference = (difference + np.pi) % (2 * np.pi) - np.pi
        worst["theta"] = max(worst["theta"], float(np.max(np.abs(difference))))
        for name, exact in (("theta_dot", theta_dot), ("theta_ddot", theta_ddot)):
            size = max(1.0, float(np.max(np.abs(exact))))
            worst[name] = max(worst[name], float(np.max(np.abs(got[name] - exact))) / size)
    report(f"{MODEL} {sequence}: 60 instants of an angle trajectory ({seen[True]} principal) "
           "against AngularKinematics and the trajectory, worst: " +
           ", ".join(f"{k} {v:.2g}" for k, v in worst.items()))
    assert seen[True] >= 10 and seen[False] >= 10, seen
    assert worst["q"] <= 1e-15, worst
    assert max(worst["omega"], worst["alpha"]) <= 1e-14, worst
    assert max(worst["theta"], worst["theta_dot"], worst["theta_ddot"]) <= 1e-14, worst


# --- 3. invariances ------------------------------------------------------------------------------

def test_minus_q_and_powers_of_two_give_the_same_bits_and_3_7_q_the_same_values(new_instance,
                                                                                report):
    """300 random motions: (-q, -q_dot, -q_ddot) and 2^k (q, q_dot, q_ddot) for k = -10, 10 give
    the same bits in every output (q_norm: 2^k |q| exactly); 3.7 (q, q_dot, q_ddot) gives omega,
    alpha, q_norm / 3.7 and singularity_distance within 1e-15 of the terms' size, theta within
    1e-15 over the distance, and R within 2e-15 (two results each within 1e-15 of the exact
    R). Planted: -q with q_dot kept fails the bits at once."""
    instance = start(new_instance)
    worst = {}
    for q, q_dot, q_ddot in random_motions(np.random.default_rng(3), 300):
        assert set_inputs(instance, q, q_dot, q_ddot) == 0
        base = outputs(instance, allowed=(0, 1))
        assert set_inputs(instance, -q, -q_dot, -q_ddot) == 0
        assert bits(outputs(instance, allowed=(0, 1))) == bits(base)
        for k in (-10, 10):
            s = 2.0 ** k
            assert set_inputs(instance, s * q, s * q_dot, s * q_ddot) == 0
            scaled = outputs(instance, allowed=(0, 1))
            assert scaled["q_norm"][0] == s * base["q_norm"][0]
            scaled["q_norm"] = base["q_norm"]
            assert bits(scaled) == bits(base), k
        assert set_inputs(instance, 3.7 * q, 3.7 * q_dot, 3.7 * q_ddot) == 0
        other = outputs(instance, allowed=(0, 1))
        other["q_norm"] = other["q_norm"] / 3.7
        _, _, sizes = reference(q, q_dot, q_ddot)
        sizes["singularity_distance"] = 1.0
        # theta1 and theta3 are known to the rounding of R over the distance
        sizes["theta"] = 1.0 / base["singularity_distance"][0]
        for name, size in sizes.items():
            e = float(np.max(np.abs(other[name] - base[name]))) / max(1.0, size)
            worst[name] = max(worst.get(name, 0.0), e)
    report(f"{MODEL}: 300 random motions, -q and 2^+-10 q bit for bit; 3.7 q worst difference "
           "relative to the terms' size: " + ", ".join(f"{k} {v:.2g}" for k, v in worst.items()))
    assert max(v for k, v in worst.items() if k != "R") <= 1e-15, worst
    assert worst["R"] <= 2e-15, worst


# --- 4. refusals and recovery --------------------------------------------------------------------

FIRST = (np.array([0.9, -0.2, 0.3, 0.1]), np.array([0.5, 1.5, -0.7, 0.2]),
         np.array([-2.0, 0.4, 1.1, 3.0]))
OTHER = (np.array([0.2, 0.8, -0.5, 0.6]), np.array([-1.0, 0.3, 0.9, 0.4]),
         np.array([0.7, -1.3, 0.2, 2.5]))


def do_step(instance, t, h):
    if is_fmi3(instance):
        return instance.do_step(t, h)[0]
    return instance.call("fmi2DoStep", ctypes.c_double(t), ctypes.c_double(h), 1)


def refused(instance, inputs, message):
    """Sets finite inputs that the evaluation refuses: reads return Discard, a message contains
    `message`, every output keeps its bits; the next valid set works; a step with the refused
    inputs returns Discard."""
    assert set_inputs(instance, *FIRST) == 0
    before = outputs(instance)
    assert set_inputs(instance, *inputs) == 0  # finite inputs are taken
    n = len(instance.messages)
    status, kept = read_raw(instance)
    assert status == 2  # Discard
    assert any(message in m for _, _, m in instance.messages[n:]), instance.messages[n:]
    calls = [m for _, _, m in instance.messages[n:] if "kinematics evaluat" in m]
    assert len(calls) == 1 and "refused: the outputs keep their last valid values" in calls[0]
    assert bits(kept) == bits(before)
    assert set_inputs(instance, *OTHER) == 0
    after = outputs(instance)
    exact, _, sizes = reference(*OTHER)
    for name in exact:
        assert error(after[name], exact[name], sizes[name]) <= tolerance(name), name
    messages = instance.messages[n:]
    assert set_inputs(instance, *inputs) == 0
    assert do_step(instance, 0.0, 0.1) == 2  # last: FMI 2 takes no input after a failed step
    return messages


def test_q_zero_is_refused_naming_q_and_the_next_valid_set_works(new_instance, fmi_version):
    """Planted: a message check for "q = (0, 0, 0, 1)" fails on the FMU's "q = (0, 0, 0, 0)"."""
    zero = np.zeros(4)
    refused(start(new_instance, fmi_version=fmi_version), (zero, FIRST[1], FIRST[2]),
            "q = (0, 0, 0, 0) is not an attitude")
    tiny = np.array([1e-310, 0.0, -1e-310, 0.0])  # below the smallest normal double
    refused(start(new_instance, fmi_version=fmi_version), (tiny, FIRST[1], FIRST[2]),
            "q = (1e-310, 0, -1e-310, 0) is not an attitude")


def test_an_overflow_is_refused_naming_the_output(new_instance, fmi_version):
    """q = (1e-300, 0, 0, 0), q_dot = (0, 1e10, 0, 0): q_dot / |q| = 1e310 overflows; the message
    names an angular velocity or acceleration output."""
    instance = start(new_instance, fmi_version=fmi_version)
    messages = refused(instance, (np.array([1e-300, 0, 0, 0]), np.array([0, 1e10, 0, 0]),
                                  np.zeros(4)), "overflows")
    named = [m for _, _, m in messages if "overflows" in m]
    outputs_named = [n for v in VECTORS_OUT for n in names(v) if f": {n} = " in named[0]]
    assert outputs_named and outputs_named[0].split("[")[0] in ("omega_fixed", "omega_body",
                                                                 "alpha_fixed", "alpha_body"), named


def test_a_non_finite_input_is_refused_by_the_setter(new_instance, fmi_version):
    instance = start(new_instance, fmi_version=fmi_version)
    assert set_inputs(instance, *FIRST) == 0
    before = instance.snapshot()
    for k, vector in enumerate(VECTORS_IN):
        for bad in (math.nan, math.inf):
            inputs = [x.copy() for x in OTHER]
            inputs[k][2] = bad
            n = len(instance.messages)
            assert set_inputs(instance, *inputs) == 3  # Error
            assert any("is not finite; no value set" in m and f"{vector}[3]" in m
                       for _, _, m in instance.messages[n:]), instance.messages[n:]
            assert instance.snapshot() == before
    assert set_inputs(instance, *OTHER) == 0
    assert outputs(instance)


def test_the_singular_configuration_keeps_the_rates_and_gives_the_rest(new_instance, fmi_version):
    """q = (1, 0, 1, 0): theta[2] = pi/2 for body123. The read returns Discard naming theta[2];
    theta_dot and theta_ddot keep their last bits; omega, alpha, R and theta are those of the new
    inputs. Then near it (distance 1e-6 < tolerance 1e-4): a warning, every output computed."""
    instance = start(new_instance, fmi_version=fmi_version)
    assert set_inputs(instance, *FIRST) == 0
    before = outputs(instance)
    q, q_dot, q_ddot = np.array([1.0, 0.0, 1.0, 0.0]), OTHER[1], OTHER[2]
    assert set_inputs(instance, q, q_dot, q_ddot) == 0
    n = len(instance.messages)
    status, got = read_raw(instance)
    assert status == 2
    assert any("theta[2] = " in m and "singular configuration of body123" in m
               for _, _, m in instance.messages[n:]), instance.messages[n:]
    for name in ("theta_dot", "theta_ddot"):
        assert bits({name: got[name]}) == bits({name: before[name]}), name
    exact, _, sizes = reference(q, q_dot, q_ddot)
    for name in exact:
        assert error(got[name], exact[name], sizes[name]) <= tolerance(name), name
    assert abs(got["theta"][1] - math.pi / 2) <= 1e-7
    assert got["singularity_distance"][0] <= 1e-15
    assert not np.array_equal(got["omega_body"], before["omega_body"])

    angle = math.pi / 2 - 1e-6  # about y: theta = (0, angle, 0), distance sin(1e-6)
    near = np.array([math.cos(angle / 2), 0.0, math.sin(angle / 2), 0.0])
    assert set_inputs(instance, near, q_dot, q_ddot) == 0
    n = len(instance.messages)
    status, got = read_raw(instance)
    assert status == 1  # Warning
    assert any("near the singular configuration of body123" in m
               for _, _, m in instance.messages[n:]), instance.messages[n:]
    assert abs(got["singularity_distance"][0] - 1e-6) <= 1e-12
    assert abs(got["theta"][1] - angle) <= 1e-12
    assert all(np.all(np.isfinite(v)) for v in got.values())
    assert not np.array_equal(got["theta_dot"], before["theta_dot"])
    ak = start(new_instance, "AngularKinematics")  # the rates give omega back
    assert ak.set({**dict(zip(names("theta"), got["theta"])),
                   **dict(zip(names("theta_dot"), got["theta_dot"]))}) == 0
    omega = ak.get(names("omega_body"))
    assert np.max(np.abs(omega - got["omega_body"])) <= 1e-9 * max(1.0, np.max(np.abs(omega)))


# --- 5. ModelStructure ---------------------------------------------------------------------------

@functools.lru_cache(maxsize=1)
def _every_output():
    """Every output element (FMI 2 names) as sympy expressions of t and the 12 inputs along q(t),
    lambdified to mpmath, for body123 (the start value of sequence): omega and alpha as the
    quaternion products of their definition, R from u v u*, |q|, the angles of R = R_1(theta1)
    R_2(theta2) R_3(theta3) (theta2 = atan2(R13, sqrt(R11^2 + R12^2)), theta1 = atan2(-R23, R33),
    theta3 = atan2(-R12, R11)) and the distance cos theta2. Returns (f, angles): f(t, *x) the
    outputs but the angles' rates; angles(t, *x) theta, whose time derivatives at t = 0 are
    theta_dot and theta_ddot."""
    t, x, u, norm = _symbols()
    u1, u2 = [sp.diff(e, t) for e in u], [sp.diff(e, t, 2) for e in u]
    columns = [rotate(u, e) for e in ([1, 0, 0], [0, 1, 0], [0, 0, 1])]
    R = [[columns[j][i] for j in range(3)] for i in range(3)]
    distance = sp.sqrt(R[0][0] ** 2 + R[0][1] ** 2)
    theta = [sp.atan2(-R[1][2], R[2][2]), sp.atan2(R[0][2], distance), sp.atan2(-R[0][1], R[0][0])]
    expressions = ([2 * c for c in hamilton(u1, conjugate(u))[1:]] +
                   [2 * c for c in hamilton(conjugate(u), u1)[1:]] +
                   [2 * c for c in hamilton(u2, conjugate(u))[1:]] +
                   [2 * c for c in hamilton(conjugate(u), u2)[1:]] +
                   [R[i][j] for i in range(3) for j in range(3)] + [norm] + theta + [distance])
    return (sp.lambdify([t, *x], expressions, "mpmath", cse=True),
            sp.lambdify([t, *x], theta, "mpmath", cse=True))


def every_output(x):
    """The outputs (OUTPUT_NAMES' order) at the inputs x (mpmath numbers): theta_dot and
    theta_ddot by mpmath's differentiation of theta(t) at t = 0."""
    f, angles = _every_output()
    values = f(0, *x)
    rates = [[mp.diff(lambda t: angles(t, *x)[k], 0, n) for k in range(3)] for n in (1, 2)]
    return values[:-1] + rates[0] + rates[1] + values[-1:]


def reference_dependencies():
    """{output element: the inputs (FMI 2 names) whose partial derivative is not zero}, from
    central differences (step 1e-20, 60 digits) of the reference at a random point, where a zero
    derivative comes out below 1e-30 and the others above 1e-3."""
    point = [mp.mpf(float(v)) for v in np.random.default_rng(7).uniform(-1.0, 1.0, 12)]
    needed = {name: set() for name in OUTPUT_NAMES}
    with mp.workdps(60):
        h = mp.mpf("1e-20")
        for k, input_name in enumerate(INPUT_NAMES):
            up, down = list(point), list(point)
            up[k] += h
            down[k] -= h
            for name, a, b in zip(OUTPUT_NAMES, every_output(up), every_output(down)):
                derivative = abs(a - b) / (2 * h)
                assert derivative <= 1e-30 or derivative >= 1e-3, (name, input_name, derivative)
                if derivative > 1e-30:
                    needed[name].add(input_name)
    return needed


def test_model_structure_lists_exactly_the_references_dependencies():
    """FMI 2 per element, FMI 3 per array (every element of an output depends on whole input
    arrays, so the array listing loses nothing). Planted: a reference without the q_ddot terms
    (q(t) = q + q_dot t) fails alpha and theta_ddot."""
    needed = reference_dependencies()
    md = read_model_description(str(fmu_path_of(MODEL)))
    listed = {u.variable.name: {d.name for d in (u.dependencies or [])} for u in md.outputs}
    assert listed == needed
    from fmi3_support import fmu3_path
    md3 = read_model_description(str(fmu3_path(MODEL)))
    listed3 = {u.variable.name: {d.name for d in (u.dependencies or [])} for u in md3.outputs}
    arrays = {}
    for vector in VECTORS_OUT:
        elements = [needed[n] for n in names(vector)]
        union = {n.split("[")[0] for e in elements for n in e}
        assert all(e == {n for v in union for n in names(v)} for e in elements), vector
        arrays[vector] = union
    assert listed3 == arrays


# --- 6. direct feedthrough, FMI 3 against FMI 2 --------------------------------------------------

def test_outputs_follow_the_inputs_before_and_between_steps_fmi3_as_fmi2(new_instance):
    """Five input sets, the first before any step, the others each after a step: every output read
    right after the set is that of the new inputs (omega, alpha, R, q_norm within 1e-15 of the
    reference) and FMI 3's arrays give the bits of FMI 2's scalars. Planted: FMI 3's last set
    left out (its outputs those of the inputs before the step) fails the bits."""
    two = start(new_instance, fmi_version=2)
    three = start(new_instance, fmi_version=3)
    t = 0.0
    for k, (q, q_dot, q_ddot) in enumerate(random_motions(np.random.default_rng(11), 5)):
        if k:
            assert do_step(two, t, 0.25) == 0 and do_step(three, t, 0.25) == 0
            t += 0.25
        assert set_inputs(two, q, q_dot, q_ddot) == 0 and set_inputs(three, q, q_dot, q_ddot) == 0
        got = outputs(two, allowed=(0, 1))
        exact, _, sizes = reference(q, q_dot, q_ddot)
        for name in exact:
            assert error(got[name], exact[name], sizes[name]) <= tolerance(name), (k, name)
        assert bits(outputs(three, allowed=(0, 1))) == bits(got), k
