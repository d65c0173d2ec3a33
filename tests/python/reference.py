"""Independent reference for the kinematics, derived by sympy.physics.vector.

The body B is oriented in N with ``orient_body_fixed(N, (q1, q2, q3), '123')``; sympy computes
the angular velocity and acceleration (``ang_vel_in``, ``ang_acc_in``) itself, and the direction
cosines n_i . b_j. Nothing here is re-typed from the course note or from the C core. The
expressions are evaluated with mpmath at 40 significant digits, so that the reference's own
rounding is negligible against the FMU's.
"""
import functools

import mpmath
import numpy as np
import sympy as sp
from sympy.physics.vector import ReferenceFrame, dynamicsymbols

INPUT_NAMES = [f"{base}[{i}]" for base in ("theta", "theta_dot", "theta_ddot") for i in (1, 2, 3)]
OUTPUT_NAMES = [f"{base}[{i}]" for base in ("omega_fixed", "omega_body", "alpha_fixed", "alpha_body")
                for i in (1, 2, 3)]


@functools.lru_cache(maxsize=None)
def _expressions():
    t = dynamicsymbols._t
    q = dynamicsymbols("q1:4")
    theta = sp.symbols("theta1:4")
    theta_dot = sp.symbols("theta_dot1:4")
    theta_ddot = sp.symbols("theta_ddot1:4")

    N = ReferenceFrame("N")
    B = ReferenceFrame("B")
    B.orient_body_fixed(N, q, "123")
    omega = B.ang_vel_in(N)
    alpha = B.ang_acc_in(N)

    # Second derivatives first, so that the first-derivative substitution does not eat them.
    substitutions = {}
    for k in range(3):
        substitutions[q[k].diff(t, 2)] = theta_ddot[k]
    for k in range(3):
        substitutions[q[k].diff(t)] = theta_dot[k]
    for k in range(3):
        substitutions[q[k]] = theta[k]

    def components(vector, frame):
        return [sp.simplify(vector.dot(axis).subs(substitutions)) for axis in (frame.x, frame.y, frame.z)]

    outputs = (components(omega, N) + components(omega, B) +
               components(alpha, N) + components(alpha, B))
    rotation = [[sp.simplify(n.dot(b).subs(substitutions)) for b in (B.x, B.y, B.z)]
                for n in (N.x, N.y, N.z)]
    symbols = list(theta) + list(theta_dot) + list(theta_ddot)
    return symbols, outputs, rotation


@functools.lru_cache(maxsize=None)
def _functions():
    symbols, outputs, rotation = _expressions()
    outputs_mp = sp.lambdify(symbols, outputs, modules="mpmath")
    rotation_np = sp.lambdify(symbols[:3], rotation, modules="numpy")
    return outputs_mp, rotation_np


def outputs(inputs):
    """The 12 outputs (OUTPUT_NAMES order) for the 9 inputs (INPUT_NAMES order), as floats
    rounded from a 40-digit evaluation."""
    outputs_mp, _ = _functions()
    with mpmath.workdps(40):
        exact = outputs_mp(*[mpmath.mpf(float(x)) for x in inputs])
        return np.array([float(value) for value in exact])


def rotation_matrix(theta):
    """R with R[i][j] = n_i . b_j: maps body components to fixed components."""
    _, rotation_np = _functions()
    return np.array(rotation_np(*theta), dtype=float)


def output_dependencies():
    """For each output name, the set of input names its sympy expression contains."""
    symbols, outputs_expr, _ = _expressions()
    names = dict(zip(symbols, INPUT_NAMES))
    return {OUTPUT_NAMES[k]: {names[s] for s in expr.free_symbols}
            for k, expr in enumerate(outputs_expr)}


def jacobian(inputs):
    """d output_i / d input_j (12 x 9) by central differences of the 40-digit reference at
    60 digits with steps of 1e-20: truncation ~1e-40, rounding ~1e-40, far below double rounding."""
    outputs_mp, _ = _functions()
    with mpmath.workdps(60):
        u = [mpmath.mpf(float(x)) for x in inputs]
        h = mpmath.mpf("1e-20")
        columns = []
        for j in range(9):
            up, down = list(u), list(u)
            up[j] += h
            down[j] -= h
            f_up, f_down = outputs_mp(*up), outputs_mp(*down)
            columns.append([float((a - b) / (2 * h)) for a, b in zip(f_up, f_down)])
    return np.array(columns).T


def jerk(inputs, theta_dddot):
    """d alpha / dt (fixed then body components) along the motion whose theta derivatives are
    theta_dot, theta_ddot and theta_dddot: a central difference in time at 60 digits of the
    reference along the cubic theta(t)."""
    outputs_mp, _ = _functions()
    with mpmath.workdps(60):
        u = [mpmath.mpf(float(x)) for x in inputs]
        d3 = [mpmath.mpf(float(x)) for x in theta_dddot]
        h = mpmath.mpf("1e-20")

        def along(t):
            theta = [u[k] + u[3 + k] * t + u[6 + k] * t**2 / 2 + d3[k] * t**3 / 6 for k in range(3)]
            theta_dot = [u[3 + k] + u[6 + k] * t + d3[k] * t**2 / 2 for k in range(3)]
            theta_ddot = [u[6 + k] + d3[k] * t for k in range(3)]
            return outputs_mp(*(theta + theta_dot + theta_ddot))

        f_up, f_down = along(h), along(-h)
        return np.array([float((f_up[i] - f_down[i]) / (2 * h)) for i in range(6, 12)])
