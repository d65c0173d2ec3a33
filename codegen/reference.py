"""The one independent reference for the kinematics, all 24 rotation sequences, derived by
sympy.physics.vector: the tests check the FMUs against it, and python -m codegen finds the
dependency tables of docs/sequences.md on it. Self-contained (examples/dask_sweep.py ships this
file alone to its workers).

For a sequence "bodyIJK" the body B is oriented in N with ``orient_body_fixed(N, (q1, q2, q3),
'IJK')``, for "spaceIJK" with ``orient_space_fixed(N, (q1, q2, q3), 'IJK')``. sympy then gives:
the angular velocity and acceleration (``ang_vel_in``, ``ang_acc_in``), the direction cosines
R[i][j] = n_i . b_j (``N.dcm(B)``), the partial angular velocities (``partial_velocity``, the
columns of W_fixed and W_body) and, by differentiating their components in time, W_fixed_dot and
W_body_dot. The quaternion comes from R by Shepperd's method, the inverse map from solving the
linear systems with mpmath. Nothing is taken from the C core. Everything is evaluated with mpmath
at 40 significant digits, so that the reference's own rounding is negligible.
The general functions take the sequence name first; at the end, the 1-2-3 tests' short forms
(outputs, rotation_matrix, jacobian, jerk, ...) call them with "body123", the FMUs' default.
"""
import functools

import mpmath
import numpy as np
import sympy as sp
from sympy.physics.vector import ReferenceFrame, dynamicsymbols, partial_velocity

DIGITS = 40


@functools.lru_cache(maxsize=None)
def _expressions(name):
    kind, order = name[:-3], name[-3:]
    t = dynamicsymbols._t
    q = dynamicsymbols("q1:4")
    qd = [x.diff(t) for x in q]
    theta = sp.symbols("theta1:4")
    theta_dot = sp.symbols("theta_dot1:4")
    theta_ddot = sp.symbols("theta_ddot1:4")

    N = ReferenceFrame("N")
    B = ReferenceFrame("B")
    if kind == "body":
        B.orient_body_fixed(N, q, order)
    elif kind == "space":
        B.orient_space_fixed(N, q, order)
    else:
        raise ValueError(name)
    omega = B.ang_vel_in(N)
    alpha = B.ang_acc_in(N)

    # Second derivatives first, so that the first-derivative substitution does not eat them.
    substitutions = {}
    for k in range(3):
        substitutions[q[k].diff(t, 2)] = theta_ddot[k]
    for k in range(3):
        substitutions[qd[k]] = theta_dot[k]
    for k in range(3):
        substitutions[q[k]] = theta[k]

    def components(vector, frame):
        return [vector.dot(axis) for axis in (frame.x, frame.y, frame.z)]

    def substituted(expressions):
        return [sp.sympify(e).subs(substitutions) for e in expressions]

    kinematics = substituted(components(omega, N) + components(omega, B) +
                             components(alpha, N) + components(alpha, B))
    rotation = substituted([N.dcm(B)[i, j] for i in range(3) for j in range(3)])
    partials = partial_velocity([omega], qd, N)[0]          # one vector per theta_dot_k
    w_fixed = [[components(partials[k], N)[i] for k in range(3)] for i in range(3)]
    w_body = [[components(partials[k], B)[i] for k in range(3)] for i in range(3)]
    flat = lambda m: [m[i][k] for i in range(3) for k in range(3)]
    partial_terms = substituted(flat(w_fixed) + flat(w_body) +
                                [e.diff(t) for e in flat(w_fixed) + flat(w_body)])

    symbols = list(theta) + list(theta_dot) + list(theta_ddot)
    return symbols, kinematics, rotation, partial_terms


@functools.lru_cache(maxsize=None)
def _functions(name):
    """The expressions as mpmath functions, common subexpressions computed once (cse: faster)."""
    symbols, kinematics, rotation, partial_terms = _expressions(name)
    return (sp.lambdify(symbols, kinematics, modules="mpmath", cse=True),
            sp.lambdify(symbols[:3], rotation, modules="mpmath", cse=True),
            sp.lambdify(symbols[:6], partial_terms, modules="mpmath", cse=True))


def _mp(values):
    return [mpmath.mpf(float(x)) for x in values]


def _matrix(values):
    """3 x 3 mpmath matrix of 9 row-major values."""
    return mpmath.matrix([list(values[3 * i:3 * i + 3]) for i in range(3)])


def kinematics(name, inputs):
    """omega_fixed, omega_body, alpha_fixed, alpha_body (12) for theta, theta_dot, theta_ddot."""
    with mpmath.workdps(DIGITS):
        return np.array([float(v) for v in _functions(name)[0](*_mp(inputs))])


def _rotation_mp(name, theta):
    return _matrix(_functions(name)[1](*_mp(theta)))


def rotation(name, theta):
    """R (3 x 3) with R[i][j] = n_i . b_j: maps body components to fixed components."""
    with mpmath.workdps(DIGITS):
        R = _rotation_mp(name, theta)
        return np.array([[float(R[i, j]) for j in range(3)] for i in range(3)])


def quaternion(name, theta):
    """Unit quaternion of R, scalar first, v_fixed = q v_body q*, by Shepperd's method (the
    largest of the four squares first), sign chosen so that q0 >= 0."""
    with mpmath.workdps(DIGITS):
        return np.array([float(x) for x in _quaternion_mp(_rotation_mp(name, theta))])


def _quaternion_mp(R):
    trace = R[0, 0] + R[1, 1] + R[2, 2]
    squares = [1 + trace, 1 + 2 * R[0, 0] - trace, 1 + 2 * R[1, 1] - trace, 1 + 2 * R[2, 2] - trace]
    big = max(range(4), key=lambda k: squares[k])
    q = [mpmath.mpf(0)] * 4
    q[big] = mpmath.sqrt(squares[big]) / 2
    f = 1 / (4 * q[big])
    if big == 0:
        q[1], q[2], q[3] = (R[2, 1] - R[1, 2]) * f, (R[0, 2] - R[2, 0]) * f, (R[1, 0] - R[0, 1]) * f
    elif big == 1:
        q[0], q[2], q[3] = (R[2, 1] - R[1, 2]) * f, (R[0, 1] + R[1, 0]) * f, (R[0, 2] + R[2, 0]) * f
    elif big == 2:
        q[0], q[1], q[3] = (R[0, 2] - R[2, 0]) * f, (R[0, 1] + R[1, 0]) * f, (R[1, 2] + R[2, 1]) * f
    else:
        q[0], q[1], q[2] = (R[1, 0] - R[0, 1]) * f, (R[0, 2] + R[2, 0]) * f, (R[1, 2] + R[2, 1]) * f
    if q[0] < 0:
        q = [-x for x in q]
    return q


def _partials_mp(name, theta, theta_dot):
    values = _functions(name)[2](*_mp(list(theta) + list(theta_dot)))
    return [_matrix(values[9 * n:9 * n + 9]) for n in range(4)]


def partials(name, theta, theta_dot):
    """W_fixed, W_body, W_fixed_dot, W_body_dot (each 3 x 3, column k belongs to theta_dot_k)."""
    with mpmath.workdps(DIGITS):
        return [np.array([[float(M[i, j]) for j in range(3)] for i in range(3)])
                for M in _partials_mp(name, theta, theta_dot)]


def euler_rates(name, frame, theta, omega, omega_dot):
    """theta_dot, theta_ddot from theta and omega, omega_dot in the components of frame ("fixed"
    or "body"): W theta_dot = omega, and omega_dot = W theta_ddot + (the rest of sympy's alpha at
    theta_ddot = 0), solved with mpmath."""
    column = {"fixed": 0, "body": 1}[frame]
    with mpmath.workdps(DIGITS):
        W = _partials_mp(name, theta, [0, 0, 0])[column]
        theta_dot = mpmath.lu_solve(W, mpmath.matrix(_mp(omega)))
        rest = _functions(name)[0](*(_mp(theta) + list(theta_dot) + [mpmath.mpf(0)] * 3))
        rest = rest[6:9] if frame == "fixed" else rest[9:12]
        rhs = mpmath.matrix([mpmath.mpf(float(x)) for x in omega_dot]) - mpmath.matrix(rest)
        theta_ddot = mpmath.lu_solve(W, rhs)
        return np.array([float(x) for x in theta_dot]), np.array([float(x) for x in theta_ddot])


# --- Which inputs each output depends on --------------------------------------------------------
# Found numerically on the 40-digit reference: an input is a dependency when changing it changes the
# output by more than 1e-25 relative to the output's scale; sums that cancel to zero mathematically
# stay below 1e-35. Done at a few generic states, so that no dependency hides at a special value.

KINEMATICS_INPUTS = [f"{b}[{i}]" for b in ("theta", "theta_dot", "theta_ddot") for i in (1, 2, 3)]
KINEMATICS_OUTPUTS = ([f"{b}[{i}]" for b in ("omega_fixed", "omega_body", "alpha_fixed", "alpha_body")
                       for i in (1, 2, 3)] +
                      [f"R[{i},{j}]" for i in (1, 2, 3) for j in (1, 2, 3)] +
                      [f"{b}[{i},{j}]" for b in ("W_fixed", "W_body", "W_fixed_dot", "W_body_dot")
                       for i in (1, 2, 3) for j in (1, 2, 3)])
# AngularKinematics' outputs that the FMU computes from its other outputs (computed_by in its
# description), here each from the reference's R by a formula of its own.
DERIVED_OUTPUTS = ["rotation_angle"]


def derived_values(rotation):
    """The DERIVED_OUTPUTS for R (9 mpmath values, row-major): the rotation angle from the trace,
    trace R = 1 + 2 cos(angle)."""
    return [mpmath.acos((rotation[0] + rotation[4] + rotation[8] - 1) / 2)]


RATES_INPUTS = [f"{b}[{i}]" for b in ("theta", "omega", "omega_dot") for i in (1, 2, 3)]
RATES_OUTPUTS = [f"{b}[{i}]" for b in ("theta_dot", "theta_ddot", "alpha_fixed", "alpha_body")
                 for i in (1, 2, 3)]


def kinematics_values(name, inputs):
    """The outputs of KINEMATICS_OUTPUTS (12 + 9 + 36) for the 9 inputs, as mpmath numbers."""
    values = list(_functions(name)[0](*_mp(inputs)))
    values += list(_functions(name)[1](*_mp(inputs[:3])))
    values += list(_functions(name)[2](*_mp(inputs[:6])))
    return values


def kinematics_and_derived_values(name, inputs):
    """kinematics_values, then the DERIVED_OUTPUTS."""
    values = kinematics_values(name, inputs)
    return values + derived_values(values[12:21])


def rates_values(name, frame, inputs):
    """The outputs of RATES_OUTPUTS for the 9 inputs theta, omega, omega_dot in frame, as mpmath
    numbers: theta_dot, theta_ddot, and alpha in both sets of components."""
    theta, omega, omega_dot = inputs[:3], inputs[3:6], inputs[6:9]
    W = _partials_mp(name, theta, [0, 0, 0])[0 if frame == "fixed" else 1]
    theta_dot = mpmath.lu_solve(W, mpmath.matrix(_mp(omega)))
    rest = _functions(name)[0](*(_mp(theta) + list(theta_dot) + [mpmath.mpf(0)] * 3))
    rest = rest[6:9] if frame == "fixed" else rest[9:12]
    given = mpmath.matrix(_mp(omega_dot))
    theta_ddot = mpmath.lu_solve(W, given - mpmath.matrix(rest))
    R = _rotation_mp(name, theta)
    other = R.T * given if frame == "fixed" else R * given
    alpha_fixed, alpha_body = (given, other) if frame == "fixed" else (other, given)
    return list(theta_dot) + list(theta_ddot) + list(alpha_fixed) + list(alpha_body)


def dependencies(evaluate, inputs_names, output_names, states, step=0.25):
    """{output name: set of input names} for evaluate(inputs) -> list of mpmath numbers."""
    found = {name: set() for name in output_names}
    with mpmath.workdps(DIGITS):
        for state in states:
            base = evaluate(list(state))
            scale = max(abs(v) for v in base) + 1
            for k, input_name in enumerate(inputs_names):
                moved = list(state)
                moved[k] += step
                for output_name, b, a in zip(output_names, base, evaluate(moved)):
                    if abs(a - b) > mpmath.mpf("1e-25") * scale:
                        found[output_name].add(input_name)
    return found


# --- The FMU's outputs in its value-reference order, and their exact derivatives --------------------
# AngularKinematics' outputs: omega_fixed, omega_body, alpha_fixed, alpha_body (12), R (9, row-major),
# q (4, scalar first), W_fixed, W_body, W_fixed_dot, W_body_dot (36), then the DERIVED_OUTPUTS.
FMU_OUTPUTS = (KINEMATICS_OUTPUTS[:21] + [f"q[{k}]" for k in (1, 2, 3, 4)] + KINEMATICS_OUTPUTS[21:] +
               DERIVED_OUTPUTS)

def fmu_outputs_mp(name, inputs):
    """The FMU_OUTPUTS for 9 mpmath inputs (theta, theta_dot, theta_ddot), as mpmath numbers."""
    kinematics_fn, rotation_fn, partials_fn = _functions(name)
    rotation = list(rotation_fn(*inputs[:3]))
    return (list(kinematics_fn(*inputs)) + rotation + list(_quaternion_mp(_matrix(rotation))) +
            list(partials_fn(*inputs[:6])) + derived_values(rotation))


def fmu_outputs(name, inputs):
    with mpmath.workdps(DIGITS):
        return np.array([float(v) for v in fmu_outputs_mp(name, _mp(inputs))])


def fmu_jacobian(name, inputs):
    """d output / d input (one row per FMU_OUTPUTS, 9 columns) by central differences on the 40-digit reference with a step of
    1e-12: truncation ~1e-24, rounding ~1e-28, far below double precision. (Near q0 = 0 the sign
    choice of q jumps; callers keep away from it.)"""
    with mpmath.workdps(DIGITS):
        x = _mp(inputs)
        h = mpmath.mpf("1e-12")
        columns = []
        for k in range(9):
            up, down = list(x), list(x)
            up[k] += h
            down[k] -= h
            columns.append([(a - b) / (2 * h) for a, b in zip(fmu_outputs_mp(name, up),
                                                               fmu_outputs_mp(name, down))])
        return np.array([[float(columns[k][i]) for k in range(9)] for i in range(len(columns[0]))])


# --- Time derivatives of the kinematics at 60 digits ----------------------------------------------

def kinematics_jacobian(name, inputs):
    """d output_i / d input_j (12 x 9) of kinematics() by central differences at 60 digits with
    steps of 1e-20: truncation ~1e-40, rounding ~1e-40, far below double rounding."""
    evaluate = _functions(name)[0]
    with mpmath.workdps(60):
        u = _mp(inputs)
        h = mpmath.mpf("1e-20")
        columns = []
        for j in range(9):
            up, down = list(u), list(u)
            up[j] += h
            down[j] -= h
            columns.append([float((a - b) / (2 * h)) for a, b in zip(evaluate(*up), evaluate(*down))])
    return np.array(columns).T


def kinematics_jerk(name, inputs, theta_dddot):
    """d alpha / dt (fixed then body components) along the motion whose theta derivatives are
    theta_dot, theta_ddot and theta_dddot: a central difference in time at 60 digits along the
    cubic theta(t)."""
    evaluate = _functions(name)[0]
    with mpmath.workdps(60):
        u = _mp(inputs)
        d3 = _mp(theta_dddot)
        h = mpmath.mpf("1e-20")

        def along(t):
            theta = [u[k] + u[3 + k] * t + u[6 + k] * t**2 / 2 + d3[k] * t**3 / 6 for k in range(3)]
            theta_dot = [u[3 + k] + u[6 + k] * t + d3[k] * t**2 / 2 for k in range(3)]
            theta_ddot = [u[6 + k] + d3[k] * t for k in range(3)]
            return evaluate(*(theta + theta_dot + theta_ddot))

        f_up, f_down = along(h), along(-h)
        return np.array([float((f_up[i] - f_down[i]) / (2 * h)) for i in range(6, 12)])


def symbolic_dependencies(name):
    """For each of the 12 kinematics outputs, the input names its simplified sympy expression
    contains."""
    symbols, kinematics_expressions, _, _ = _expressions(name)
    names = dict(zip(symbols, KINEMATICS_INPUTS))
    return {KINEMATICS_OUTPUTS[k]: {names[s] for s in sp.simplify(e).free_symbols}
            for k, e in enumerate(kinematics_expressions)}


# --- The 1-2-3 tests' short forms: the general functions for body123 -------------------------------

BODY123 = "body123"
INPUT_NAMES = KINEMATICS_INPUTS
OUTPUT_NAMES = KINEMATICS_OUTPUTS[:12]  # omega_fixed, omega_body, alpha_fixed, alpha_body


def outputs(inputs):
    """The 12 outputs (OUTPUT_NAMES order) for the 9 inputs (INPUT_NAMES order)."""
    return kinematics(BODY123, inputs)


def rotation_matrix(theta):
    """R with R[i][j] = n_i . b_j: maps body components to fixed components."""
    return rotation(BODY123, theta)


def jacobian(inputs):
    return kinematics_jacobian(BODY123, inputs)


def jerk(inputs, theta_dddot):
    return kinematics_jerk(BODY123, inputs, theta_dddot)


def output_dependencies():
    return symbolic_dependencies(BODY123)
