"""The general kinematics core (all 24 rotation sequences) against the independent sympy reference
of codegen/reference.py, reached through the test-only library build/testlib (ctypes), before
any FMI layer uses it.

Errors are measured against the natural size of the terms summed: sum|theta_dot| for omega and
W_dot, sum|theta_ddot| + (sum|theta_dot|)^2 for alpha; R, q, W are of size 1. For the inverse
map the size is multiplied by the conditioning 1/singularity_distance."""
import ctypes
import pathlib
import sys

import numpy as np
import pytest

from codegen import reference
from conftest import sequence_cases
from codegen.project import SEQUENCES

ROOT = pathlib.Path(__file__).resolve().parents[2]
LIBRARY = ROOT / "build" / "testlib" / {"win32": "kinematics_testlib.dll",
                                        "darwin": "libkinematics_testlib.dylib"}.get(
                                            sys.platform, "libkinematics_testlib.so")
TOLERANCE = 1e-14
RNG_SEED = 20261121

RATES_OK, RATES_NEAR_SINGULAR, RATES_SINGULAR, RATES_OVERFLOW = 0, 1, 2, 3

DOUBLES = np.ctypeslib.ndpointer(dtype=np.float64, flags="C_CONTIGUOUS")


@pytest.fixture(scope="module")
def lib():
    assert LIBRARY.is_file(), f"{LIBRARY} is missing: build it first (bash scripts/build.sh)"
    lib = ctypes.CDLL(str(LIBRARY))
    lib.akt_sequence_count.restype = ctypes.c_int
    lib.akt_sequence.restype = ctypes.c_char_p
    lib.akt_sequence.argtypes = [ctypes.c_int, ctypes.POINTER(ctypes.c_int * 3),
                                 ctypes.POINTER(ctypes.c_int), ctypes.POINTER(ctypes.c_int)]
    lib.akt_angular_kinematics.argtypes = [ctypes.c_int, ctypes.c_int, DOUBLES, DOUBLES]
    lib.akt_rotation_terms.argtypes = [ctypes.c_int, ctypes.c_int, DOUBLES, DOUBLES]
    lib.akt_euler_rates.argtypes = [ctypes.c_int, ctypes.c_int, DOUBLES, ctypes.c_double, DOUBLES,
                                    ctypes.POINTER(ctypes.c_double)]
    return lib


def forward(lib, name, states):
    states = np.ascontiguousarray(states, dtype=float)
    out = np.empty((len(states), 12))
    assert lib.akt_angular_kinematics(SEQUENCES.index(name), len(states), states, out) == 0
    return out


def rotation_terms(lib, name, states):
    """R, q, W_fixed, W_body, W_fixed_dot, W_body_dot, distance for states of theta, theta_dot."""
    states = np.ascontiguousarray(states, dtype=float)
    out = np.empty((len(states), 50))
    assert lib.akt_rotation_terms(SEQUENCES.index(name), len(states), states, out) == 0
    return (out[:, 0:9].reshape(-1, 3, 3), out[:, 9:13], out[:, 13:22].reshape(-1, 3, 3),
            out[:, 22:31].reshape(-1, 3, 3), out[:, 31:40].reshape(-1, 3, 3),
            out[:, 40:49].reshape(-1, 3, 3), out[:, 49])


def euler_rates(lib, name, frame, theta, omega, omega_dot, tolerance=0.0):
    """(status, distance, theta_dot, theta_ddot, alpha_fixed, alpha_body); the outputs hold NaN
    where the core wrote nothing."""
    inputs = np.ascontiguousarray(np.concatenate([theta, omega, omega_dot]), dtype=float)
    out = np.full(12, np.nan)
    distance = ctypes.c_double(np.nan)
    status = lib.akt_euler_rates(SEQUENCES.index(name), {"fixed": 0, "body": 1}[frame], inputs,
                                 tolerance, out, ctypes.byref(distance))
    return status, distance.value, out[0:3], out[3:6], out[6:9], out[9:12]


def singular_angles(name):
    return [0.0, np.pi] if name[-3] == name[-1] else [-np.pi / 2, np.pi / 2]


def random_states(name, kind, count, rng):
    """States (count x 9) of theta, theta_dot, theta_ddot of one kind."""
    theta = rng.uniform(-np.pi, np.pi, (count, 3))
    if kind == "beyond_pi":
        theta = rng.uniform(-60.0, 60.0, (count, 3))
    elif kind == "near_singular":
        offsets = 10.0 ** rng.uniform(-12, -1, count) * rng.choice([-1, 1], count)
        theta[:, 1] = rng.choice(singular_angles(name), count) + offsets
    elif kind == "at_singular":
        theta[:, 1] = rng.choice(singular_angles(name), count)
    # Every component its own magnitude, from 1e-6 to 1e6, so that small terms sit beside big ones.
    theta_dot = 10.0 ** rng.uniform(-6, 6, (count, 3)) * rng.uniform(-1, 1, (count, 3))
    theta_ddot = 10.0 ** rng.uniform(-6, 6, (count, 3)) * rng.uniform(-1, 1, (count, 3))
    return np.hstack([theta, theta_dot, theta_ddot])


def test_sequence_table(lib):
    """The core's table is the 24 sequences, in the order of the future Enumeration items."""
    assert lib.akt_sequence_count() == len(SEQUENCES)
    for index, name in enumerate(SEQUENCES):
        axes, kind, proper = (ctypes.c_int * 3)(), ctypes.c_int(), ctypes.c_int()
        assert lib.akt_sequence(index, ctypes.byref(axes), ctypes.byref(kind),
                                ctypes.byref(proper)).decode() == name
        assert "".join(str(a) for a in axes) == name[-3:]
        assert kind.value == (0 if name.startswith("body") else 1)
        assert proper.value == (name[-3] == name[-1])
    assert lib.akt_sequence(len(SEQUENCES), ctypes.byref((ctypes.c_int * 3)()),
                            ctypes.byref(ctypes.c_int()), ctypes.byref(ctypes.c_int())) is None


@pytest.mark.parametrize("name", sequence_cases())
def test_kinematics_match_reference(name, lib, report):
    rng = np.random.default_rng([RNG_SEED, SEQUENCES.index(name)])
    worst = {}
    for kind in ("in_pi", "beyond_pi", "near_singular", "at_singular"):
        states = random_states(name, kind, 60, rng)
        got = forward(lib, name, states)
        omega_scale = np.abs(states[:, 3:6]).sum(axis=1)
        alpha_scale = np.abs(states[:, 6:9]).sum(axis=1) + omega_scale ** 2
        for state, values, ws, as_ in zip(states, got, omega_scale, alpha_scale):
            error = np.abs(values - reference.kinematics(name, state))
            worst["omega"] = max(worst.get("omega", 0.0), error[:6].max() / ws)
            worst["alpha"] = max(worst.get("alpha", 0.0), error[6:].max() / as_)
    report(f"240 states, worst scaled error omega {worst['omega']:.2e}, alpha {worst['alpha']:.2e}")
    assert worst["omega"] <= TOLERANCE and worst["alpha"] <= TOLERANCE, worst


@pytest.mark.parametrize("name", sequence_cases())
def test_rotation_terms_match_reference(name, lib, report):
    rng = np.random.default_rng([RNG_SEED, 100 + SEQUENCES.index(name)])
    states = np.vstack([random_states(name, kind, 25, rng)[:, :6]
                        for kind in ("in_pi", "beyond_pi", "near_singular", "at_singular")])
    R, q, w_fixed, w_body, w_fixed_dot, w_body_dot, distance = rotation_terms(lib, name, states)
    worst = dict.fromkeys(["R", "q", "W", "W_dot", "distance"], 0.0)
    for n, state in enumerate(states):
        theta, theta_dot = state[:3], state[3:6]
        worst["R"] = max(worst["R"], np.abs(R[n] - reference.rotation(name, theta)).max())
        q_ref = reference.quaternion(name, theta)
        assert q[n][0] >= 0.0
        q_error = np.abs(q[n] - q_ref).max()
        if q_ref[0] < 1e-12:   # q and -q both have q0 = 0 to rounding: either is right
            q_error = min(q_error, np.abs(q[n] + q_ref).max())
        worst["q"] = max(worst["q"], q_error)
        ref = reference.partials(name, theta, theta_dot)
        worst["W"] = max(worst["W"], np.abs(w_fixed[n] - ref[0]).max(), np.abs(w_body[n] - ref[1]).max())
        scale = np.abs(theta_dot).sum()
        worst["W_dot"] = max(worst["W_dot"], np.abs(w_fixed_dot[n] - ref[2]).max() / scale,
                             np.abs(w_body_dot[n] - ref[3]).max() / scale)
        # The singularity distance is |det W|, of the reference's W.
        worst["distance"] = max(worst["distance"], abs(distance[n] - abs(np.linalg.det(ref[0]))))
    report(f"{len(states)} states, worst error " + ", ".join(f"{k} {v:.2e}" for k, v in worst.items()))
    assert worst["R"] <= 2e-15 and worst["q"] <= 2e-15 and worst["W"] <= 2e-15, worst
    assert worst["W_dot"] <= TOLERANCE and worst["distance"] <= 2e-15, worst


@pytest.mark.parametrize("name", sequence_cases())
def test_inverse_map_matches_reference(name, lib, report):
    """Any omega, omega_dot (not only consistent ones) at distances from 1 down to 1e-6."""
    rng = np.random.default_rng([RNG_SEED, 200 + SEQUENCES.index(name)])
    worst = {"theta_dot": 0.0, "theta_ddot": 0.0}
    for n in range(40):
        theta = rng.uniform(-np.pi, np.pi, 3)
        if n % 2:
            theta[1] = rng.choice(singular_angles(name)) + 10.0 ** rng.uniform(-6, -2) * rng.choice([-1, 1])
        omega = 10.0 ** rng.uniform(-3, 3, 3) * rng.uniform(-1, 1, 3)
        omega_dot = 10.0 ** rng.uniform(-3, 3, 3) * rng.uniform(-1, 1, 3)
        for frame in ("fixed", "body"):
            status, distance, td, tdd, _, _ = euler_rates(lib, name, frame, theta, omega, omega_dot)
            assert status == RATES_OK
            td_ref, tdd_ref = reference.euler_rates(name, frame, theta, omega, omega_dot)
            td_scale = np.abs(omega).sum() / distance
            tdd_scale = (np.abs(omega_dot).sum() + td_scale ** 2) / distance
            worst["theta_dot"] = max(worst["theta_dot"], np.abs(td - td_ref).max() / td_scale)
            worst["theta_ddot"] = max(worst["theta_ddot"], np.abs(tdd - tdd_ref).max() / tdd_scale)
    report(f"80 solves, worst conditioned scaled error theta_dot {worst['theta_dot']:.2e}, "
           f"theta_ddot {worst['theta_ddot']:.2e}")
    assert max(worst.values()) <= TOLERANCE, worst


@pytest.mark.parametrize("name", sequence_cases())
def test_round_trip_away_from_singularity(name, lib):
    """EulerRates(AngularKinematics(x)) = x, in both frames, at distances 1e-2 and more."""
    rng = np.random.default_rng([RNG_SEED, 300 + SEQUENCES.index(name)])
    states = random_states(name, "in_pi", 200, rng)
    for state, out in zip(states, forward(lib, name, states)):
        theta, td, tdd = state[:3], state[3:6], state[6:9]
        omega_scale = np.abs(td).sum()
        alpha_scale = np.abs(tdd).sum() + omega_scale ** 2
        for frame, omega, alpha in (("fixed", out[0:3], out[6:9]), ("body", out[3:6], out[9:12])):
            status, distance, td_back, tdd_back, af, ab = euler_rates(lib, name, frame, theta, omega, alpha)
            if distance < 1e-2:
                continue
            assert status == RATES_OK
            assert np.abs(td_back - td).max() <= TOLERANCE * omega_scale / distance
            assert np.abs(tdd_back - tdd).max() <= TOLERANCE * alpha_scale / distance ** 2
            assert np.abs(af - out[6:9]).max() <= TOLERANCE * alpha_scale
            assert np.abs(ab - out[9:12]).max() <= TOLERANCE * alpha_scale


@pytest.mark.parametrize("name", sequence_cases())
def test_singular_configuration_is_refused(name, lib):
    """At the singular angle (and its 2 pi multiples): AK_RATES_SINGULAR, nothing written; inside
    the tolerance: AK_RATES_NEAR_SINGULAR with finite results; outside: AK_RATES_OK."""
    omega, omega_dot = np.array([0.3, -0.2, 0.1]), np.array([1.0, 2.0, 3.0])
    for singular in singular_angles(name):
        for wrap in (-3, 0, 3):
            theta = np.array([0.4, singular + 2 * np.pi * wrap, -1.1])
            for frame in ("fixed", "body"):
                status, distance, *outputs = euler_rates(lib, name, frame, theta, omega, omega_dot, 1e-6)
                assert status == RATES_SINGULAR and distance < 1e-14
                assert all(np.isnan(o).all() for o in outputs)
        for offset, tolerance, expected in ((1e-7, 1e-6, RATES_NEAR_SINGULAR), (1e-5, 1e-6, RATES_OK),
                                            (1e-12, 1e-6, RATES_NEAR_SINGULAR)):
            theta = np.array([0.4, singular + offset, -1.1])
            status, distance, *outputs = euler_rates(lib, name, "body", theta, omega, omega_dot, tolerance)
            assert status == expected
            assert distance == pytest.approx(offset, rel=1e-3)
            assert all(np.isfinite(o).all() for o in outputs)


def core_kinematics_values(lib, name, inputs):
    """The core's values in the order of reference.KINEMATICS_OUTPUTS, plus q and the
    singularity distance."""
    inputs = np.asarray(inputs, dtype=float)
    kinematics = forward(lib, name, inputs[None, :])[0]
    R, q, w_fixed, w_body, w_fixed_dot, w_body_dot, distance = rotation_terms(lib, name, inputs[None, :6])
    values = np.concatenate([kinematics, R[0].ravel(), w_fixed[0].ravel(), w_body[0].ravel(),
                             w_fixed_dot[0].ravel(), w_body_dot[0].ravel()])
    return values, q[0], distance[0]


def core_dependencies(evaluate, input_names, output_names, states, step=0.25):
    """Like reference.dependencies, but on the core: any change of the double counts."""
    found = {name: set() for name in output_names}
    for state in states:
        base = evaluate(state)
        for k, input_name in enumerate(input_names):
            moved = np.array(state, dtype=float)
            moved[k] += step
            for output_name, b, a in zip(output_names, base, evaluate(moved)):
                if a != b:
                    found[output_name].add(input_name)
    return found


@pytest.mark.parametrize("name", sequence_cases())
def test_dependencies_match_reference(name, lib):
    """Every output of the core moves with exactly the inputs it depends on in the reference, for
    the forward map (omega, alpha, R, W, W_dot) and the inverse map in both frames; q moves with
    every theta, the singularity distance with theta[2] alone. This is what <ModelStructure> lists
    for each sequence (the modelDescription holds the union over sequences, DEPENDENCY_UNION)."""
    rng = np.random.default_rng([RNG_SEED, 400 + SEQUENCES.index(name)])
    states = rng.uniform(-2, 2, (2, 9))   # generic: no dependency vanishes there
    got = core_dependencies(lambda x: core_kinematics_values(lib, name, x)[0],
                            reference.KINEMATICS_INPUTS, reference.KINEMATICS_OUTPUTS, states)
    expected = reference.dependencies(lambda x: reference.kinematics_values(name, x),
                                      reference.KINEMATICS_INPUTS, reference.KINEMATICS_OUTPUTS, states)
    assert got == expected
    rotation_only = core_dependencies(
        lambda x: np.concatenate(core_kinematics_values(lib, name, x)[1:2] +
                                 ([core_kinematics_values(lib, name, x)[2]],)),
        reference.KINEMATICS_INPUTS, ["q[1]", "q[2]", "q[3]", "q[4]", "singularity_distance"], states)
    assert all(rotation_only[f"q[{i}]"] == {"theta[1]", "theta[2]", "theta[3]"} for i in (1, 2, 3, 4))
    assert rotation_only["singularity_distance"] == {"theta[2]"}

    for frame in ("fixed", "body"):
        def core_rates(x):
            status, _, td, tdd, af, ab = euler_rates(lib, name, frame, x[:3], x[3:6], x[6:9])
            assert status == RATES_OK
            return np.concatenate([td, tdd, af, ab])
        got = core_dependencies(core_rates, reference.RATES_INPUTS, reference.RATES_OUTPUTS, states)
        expected = reference.dependencies(lambda x: reference.rates_values(name, frame, x),
                                          reference.RATES_INPUTS, reference.RATES_OUTPUTS, states)
        assert got == expected, frame
