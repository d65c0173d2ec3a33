"""PointKinematics through its FMUs: the outputs against a sympy derivation of the motion of a
point of a rotating body (independent of the C formulas: positions differentiated in the fixed
frame), the accuracy on random inputs against exact rational arithmetic, direct feedthrough, the
overflow refusal, and ModelStructure against the derivation's dependencies."""
import ctypes
import functools
from fractions import Fraction

import numpy as np
import pytest
import sympy as sp
from fmpy import read_model_description

from conftest import fmu_path_of

MODEL = "PointKinematics"
VECTORS_IN = ["omega", "alpha", "v_O", "a_O", "r", "r_dot", "r_ddot", "g"]
VECTORS_OUT = ["v_P", "a_P", "specific_force", "a_tangential", "a_centripetal", "a_coriolis"]


def names(vector):
    return [f"{vector}[{i}]" for i in (1, 2, 3)]


INPUT_NAMES = [n for v in VECTORS_IN for n in names(v)]
OUTPUT_NAMES = [n for v in VECTORS_OUT for n in names(v)]


def _derivation():
    """The body's attitude R(t) = Rz(psi) Ry(th) Rx(phi) (any smooth one), O's path p_O(t) in the
    fixed frame, P's body coordinates r(t): p_P = p_O + R r, differentiated twice in the fixed
    frame and expressed in body components. omega, alpha from R^T R' (no cross products)."""
    t = sp.symbols("t")
    phi, th, psi = (sp.Function(n)(t) for n in ("phi", "th", "psi"))
    r = sp.Matrix([sp.Function(f"r{i}")(t) for i in (1, 2, 3)])
    p_O = sp.Matrix([sp.Function(f"o{i}")(t) for i in (1, 2, 3)])
    R = sp.rot_axis3(-psi) * sp.rot_axis2(-th) * sp.rot_axis1(-phi)  # sympy's rot_axis: passive
    skew = R.T * R.diff(t)
    omega = sp.Matrix([skew[2, 1], skew[0, 2], skew[1, 0]])
    alpha = omega.diff(t)  # d/dt of body components: equal to the fixed-frame derivative's
    p_P = p_O + R * r
    v_P = R.T * p_P.diff(t)
    a_P = R.T * p_P.diff(t, 2)
    symbols = {"t": t, "angles": (phi, th, psi), "r": r, "p_O": p_O}
    return symbols, R, omega, alpha, v_P, a_P


@functools.lru_cache(maxsize=1)
def _derivation_at_an_instant():
    """The derivation's outputs as numpy functions of the functions' values and first and second
    derivatives at one instant (each Derivative replaced by a symbol), and their order."""
    s, R, omega, alpha, v_P, a_P = _derivation()
    t = s["t"]
    functions = list(s["angles"]) + list(s["r"]) + list(s["p_O"])
    plain = sp.symbols(f"f0:{3 * len(functions)}")
    replace = {}
    for k, f in enumerate(functions):  # second derivatives first: they contain the first
        replace[f.diff(t, 2)] = plain[3 * k + 2]
    for k, f in enumerate(functions):
        replace[f.diff(t)] = plain[3 * k + 1]
    for k, f in enumerate(functions):
        replace[f] = plain[3 * k]

    def at(e):
        return sp.lambdify(plain, e.subs(replace), "numpy")
    p_O = s["p_O"]
    return {name: at(e) for name, e in (("R", R), ("omega", omega), ("alpha", alpha),
                                        ("v_P", v_P), ("a_P", a_P), ("v_O", p_O.diff(t)),
                                        ("a_O", p_O.diff(t, 2)), ("r", s["r"]),
                                        ("r_dot", s["r"].diff(t)), ("r_ddot", s["r"].diff(t, 2)))}


def sympy_cases(n):
    """n random motions: the FMU's inputs and the outputs of the derivation at one instant."""
    f = _derivation_at_an_instant()
    rng = np.random.default_rng(5)
    g_fixed = np.array([0.0, 0.0, -9.81])
    cases = []
    for _ in range(n):
        x = rng.uniform(-2, 2, 27)  # of the 9 functions: value, first, second derivative

        def ev(name):
            return np.array(f[name](*x), dtype=float).ravel()
        R0 = ev("R").reshape(3, 3)
        inputs = np.concatenate([ev("omega"), ev("alpha"), R0.T @ ev("v_O"), R0.T @ ev("a_O"),
                                 ev("r"), ev("r_dot"), ev("r_ddot"), R0.T @ g_fixed])
        a = ev("a_P")
        cases.append((inputs, {"v_P": ev("v_P"), "a_P": a, "specific_force": a - R0.T @ g_fixed}))
    return cases


@pytest.fixture(params=[2, 3], ids=["fmi2", "fmi3"])
def instance(request, new_instance):
    i = new_instance(MODEL, fmi_version=request.param, logging_on=True)  # FMI 3: warnings too
    i.initialize()
    return i


def set_inputs(instance, flat):
    if hasattr(instance, "inputs"):  # FMI 3: arrays
        return instance.set({v: flat[3 * k:3 * k + 3] for k, v in enumerate(VECTORS_IN)})
    return instance.set(dict(zip(INPUT_NAMES, flat)))


def read_status(instance):
    """The status of reading every output."""
    if hasattr(instance, "inputs"):
        return instance.get_raw(VECTORS_OUT)[0]
    vr = (ctypes.c_uint * 18)(*[instance.vr[n] for n in OUTPUT_NAMES])
    return instance.call("fmi2GetReal", vr, 18, (ctypes.c_double * 18)())


def outputs(instance):
    if hasattr(instance, "inputs"):
        got = instance.get(VECTORS_OUT)
        return {v: np.asarray(got[v]) for v in VECTORS_OUT}
    flat = instance.get(OUTPUT_NAMES)
    return {v: flat[3 * k:3 * k + 3] for k, v in enumerate(VECTORS_OUT)}


def test_outputs_are_the_derivative_of_the_position_in_the_fixed_frame(instance, report):
    worst = 0.0
    for inputs, expected in sympy_cases(20):
        assert set_inputs(instance, inputs) == 0
        got = outputs(instance)  # before any step: direct feedthrough
        for name, value in expected.items():
            error = np.max(np.abs(got[name] - value)) / max(1.0, np.max(np.abs(value)))
            worst = max(worst, error)
            assert error < 1e-13, (name, got[name], value)
    report(f"{MODEL}: v_P, a_P, specific_force of 20 random motions against the sympy derivation "
           f"(p_P = p_O + R r differentiated in the fixed frame): largest error {worst:.2g}")


def random_inputs(rng, n):
    """Components of sizes 1e-3 to 1e3 (log-uniform), either sign."""
    return rng.choice([-1.0, 1.0], (n, 24)) * 10.0 ** rng.uniform(-3, 3, (n, 24))


def exact(u):
    """The outputs and the sizes of their terms, in exact rational arithmetic."""
    F = [Fraction(x) for x in u]
    omega, alpha, v_O, a_O, r, r_dot, r_ddot, g = (F[3 * k:3 * k + 3] for k in range(8))

    def cross(a, b):
        return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]

    def size(a):
        return float(sum(x * x for x in a)) ** 0.5

    w_r = cross(omega, r)
    tangential, centripetal = cross(alpha, r), cross(omega, w_r)
    coriolis = [2 * x for x in cross(omega, r_dot)]
    v_P = [v_O[k] + w_r[k] + r_dot[k] for k in range(3)]
    a_P = [a_O[k] + tangential[k] + centripetal[k] + coriolis[k] + r_ddot[k] for k in range(3)]
    W, A, Rr = size(omega), size(alpha), size(r)
    a_terms = size(a_O) + A * Rr + W * W * Rr + 2 * W * size(r_dot) + size(r_ddot)
    return {"v_P": (v_P, size(v_O) + W * Rr + size(r_dot)),
            "a_P": (a_P, a_terms),
            "specific_force": ([a_P[k] - g[k] for k in range(3)], a_terms + size(g)),
            "a_tangential": (tangential, A * Rr),
            "a_centripetal": (centripetal, W * W * Rr),
            "a_coriolis": (coriolis, 2 * W * size(r_dot))}


@pytest.mark.parametrize("n", [5000])
def test_every_output_within_1e_15_of_the_exact_value(new_instance, n, report):
    """Relative to max(1, the size of the terms that make the output)."""
    instance = new_instance(MODEL)
    instance.initialize()
    rng = np.random.default_rng(1)
    worst = {v: 0.0 for v in VECTORS_OUT}
    for u in random_inputs(rng, n):
        assert set_inputs(instance, u) == 0
        got = outputs(instance)
        for name, (value, terms) in exact(u).items():
            scale = max(1.0, terms)
            error = max(abs(float(Fraction(got[name][k]) - value[k])) for k in range(3)) / scale
            worst[name] = max(worst[name], error)
    assert max(worst.values()) <= 1e-15, worst
    report(f"{MODEL}: {n} random inputs (components 1e-3 to 1e3), worst error relative to "
           "max(1, size of the terms): " + ", ".join(f"{k} {v:.2g}" for k, v in worst.items()))


def test_an_overflow_is_refused_and_the_next_valid_set_works(instance):
    first = np.linspace(-1.0, 1.0, 24)
    assert set_inputs(instance, first) == 0
    before = outputs(instance)
    huge = first.copy()
    huge[0:3] = [1e200, 0.0, 0.0]  # omega
    huge[12:15] = [0.0, 1e200, 0.0]  # r: omega x r overflows
    assert set_inputs(instance, huge) == 0  # finite inputs are taken
    assert read_status(instance) == 2  # Discard
    assert any("v_P[3] = inf: a product of the inputs overflows" in m[2]
               for m in instance.messages[-3:])
    assert set_inputs(instance, first) == 0
    after = outputs(instance)
    for name in VECTORS_OUT:
        assert np.array_equal(after[name], before[name]), name


def sympy_outputs():
    """The 24 input symbols and the outputs as sympy expressions of them (the issue's formulas)."""
    x = sp.symbols(" ".join(f"x{k}" for k in range(24)))
    omega, alpha, v_O, a_O, r, r_dot, r_ddot, g = (sp.Matrix(x[3 * k:3 * k + 3]) for k in range(8))
    a_P = a_O + alpha.cross(r) + omega.cross(omega.cross(r)) + 2 * omega.cross(r_dot) + r_ddot
    return x, {"v_P": v_O + omega.cross(r) + r_dot, "a_P": a_P, "specific_force": a_P - g,
               "a_tangential": alpha.cross(r), "a_centripetal": omega.cross(omega.cross(r)),
               "a_coriolis": 2 * omega.cross(r_dot)}


def test_directional_derivatives_are_the_jacobian(new_instance, report):
    """fmi2GetDirectionalDerivative along each input, every output, against sympy's Jacobian."""
    instance = new_instance(MODEL)
    instance.initialize()
    u = np.random.default_rng(3).uniform(-2.0, 2.0, 24)
    assert set_inputs(instance, u) == 0
    x, formulas = sympy_outputs()
    outputs_all = sp.Matrix([e for vector in VECTORS_OUT for e in formulas[vector]])
    J = np.array(outputs_all.jacobian(x).subs(dict(zip(x, u))).evalf(30), dtype=float)
    out_vrs = [instance.vr[n] for n in OUTPUT_NAMES]
    worst = 0.0
    for k in range(24):
        column = np.array(instance.fmu.getDirectionalDerivative(out_vrs, [k], [1.0]))
        worst = max(worst, float(np.max(np.abs(column - J[:, k]) / (1.0 + np.abs(J[:, k])))))
    report(f"{MODEL}: 18 x 24 directional derivatives against sympy's Jacobian: largest error "
           f"{worst:.2g}")
    assert worst <= 1e-14


def test_model_structure_lists_exactly_the_derivations_dependencies():
    md = read_model_description(str(fmu_path_of(MODEL)))
    by_vr = {v.valueReference: v.name for v in md.modelVariables}
    listed = {u.variable.name: {d.name for d in (u.dependencies or [])}
              for u in md.outputs}
    x, formulas = sympy_outputs()
    for vector, formula in formulas.items():
        for i in range(3):
            expression = sp.expand(formula[i])
            needed = {by_vr[k] for k in range(24) if expression.has(x[k])}
            assert listed[f"{vector}[{i + 1}]"] == needed, (vector, i)
