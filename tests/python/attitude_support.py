"""What the AttitudePropagator tests share: the FMU and its instances (conftest.new_instance), the
closed-form references (constant rotation, coning motion; derived here with sympy, independently
of the C core) and a co-simulation driver through fmpy.

Quaternions are numpy arrays (w, x, y, z), scalar first, Hamilton product."""
import ctypes
import functools

import numpy as np
import pytest
import sympy as sp

from conftest import fmu_files, fmu_path_of

ATTITUDE_FMU_PATH = fmu_path_of("AttitudePropagator")
OMEGA = ["omega[1]", "omega[2]", "omega[3]"]
OMEGA_DOT = ["omega_dot[1]", "omega_dot[2]", "omega_dot[3]"]
Q = ["q[1]", "q[2]", "q[3]", "q[4]"]
THETA = ["theta[1]", "theta[2]", "theta[3]"]
FRAME = {"fixed": 1, "body": 2}


@pytest.fixture(scope="session")
def attitude_model_description():
    return fmu_files("AttitudePropagator")[1]


@pytest.fixture(scope="session")
def attitude_unzipdir():
    return fmu_files("AttitudePropagator")[0]


@pytest.fixture
def make_attitude_instance(new_instance):
    """FMI 2 instances of AttitudePropagator (conftest's new_instance)."""
    return functools.partial(new_instance, "AttitudePropagator")


# --- quaternions (numpy, independent of the C core) ----------------------------------------------

def qmul(a, b):
    w1, x1, y1, z1 = a
    w2, x2, y2, z2 = b
    return np.array([w1 * w2 - x1 * x2 - y1 * y2 - z1 * z2,
                     w1 * x2 + x1 * w2 + y1 * z2 - z1 * y2,
                     w1 * y2 - x1 * z2 + y1 * w2 + z1 * x2,
                     w1 * z2 + x1 * y2 - y1 * x2 + z1 * w2])


def qconj(q):
    return np.array([q[0], -q[1], -q[2], -q[3]])


def qexp(v):
    angle = np.linalg.norm(v)
    if angle == 0.0:
        return np.array([1.0, 0.0, 0.0, 0.0])
    return np.concatenate([[np.cos(angle)], np.sin(angle) / angle * np.asarray(v)])


def attitude_error(q, reference):
    """The rotation angle (rad) between two attitudes; q and -q are the same attitude."""
    d = qmul(qconj(reference), q)
    return 2.0 * np.arctan2(np.linalg.norm(d[1:]), abs(d[0]))


# --- coning motion (closed form) -----------------------------------------------------------------

def coning(beta=0.2, rate=2 * np.pi):
    """Classic coning: the body axis turned by the half-cone angle beta about a horizontal axis
    that sweeps around n3 at `rate`:  q(t) = (cos beta/2, sin beta/2 cos rate t,
    sin beta/2 sin rate t, 0). Returns numpy functions q(t), omega_body(t) and its first and
    second derivatives, derived symbolically from omega_body = 2 vec(q* (x) dq/dt)."""
    t = sp.symbols("t", real=True)
    b, w = sp.Float(beta, 30), sp.Float(rate, 30)
    q = sp.Matrix([sp.cos(b / 2), sp.sin(b / 2) * sp.cos(w * t), sp.sin(b / 2) * sp.sin(w * t), 0])
    dq = q.diff(t)
    conj = [q[0], -q[1], -q[2], -q[3]]
    product = qmul(conj, list(dq))
    omega = sp.Matrix([sp.simplify(2 * product[k]) for k in (1, 2, 3)])
    omega_dot = omega.diff(t)
    return tuple(sp.lambdify(t, list(f), "numpy") for f in (q, omega, omega_dot, omega_dot.diff(t)))


def run_cs(instance, q_of, omega_of, omega_dot_of, h, stop, mode, samples=100,
           omega_ddot_of=None):
    """Co-simulates from 0 to stop with step h, the inputs set at every communication point.
    mode: "held" (omega only), "derivatives" (fmi2SetRealInputDerivatives, order 1),
    "derivatives2" (orders 1 and 2, omega_ddot_of needed) or "omega_dot" (the omega_dot inputs).
    Returns (largest attitude error over `samples` evenly
    spread points and the end, the error at the end)."""
    fmu = instance.fmu
    vr = instance.vr
    omega_vr = [vr[n] for n in OMEGA]
    omega_dot_vr = [vr[n] for n in OMEGA_DOT]
    q_vr = [vr[n] for n in Q]
    q0 = np.array(q_of(0.0), dtype=float)
    instance.initialize(parameters={f"q0[{k + 1}]": q0[k] for k in range(4)},
                        inputs={n: float(x) for n, x in zip(OMEGA, omega_of(0.0))})
    steps = int(round(stop / h))
    every = max(1, steps // samples)
    orders = (ctypes.c_int * 3)(1, 1, 1)
    orders2 = (ctypes.c_int * 3)(2, 2, 2)
    vrs = (ctypes.c_uint * 3)(*omega_vr)
    worst = 0.0
    for n in range(steps):
        t = n * h
        fmu.setReal(omega_vr, [float(x) for x in omega_of(t)])
        if mode in ("derivatives", "derivatives2"):
            values = (ctypes.c_double * 3)(*[float(x) for x in omega_dot_of(t)])
            assert instance.call("fmi2SetRealInputDerivatives", vrs, 3, orders, values) == 0
        if mode == "derivatives2":
            values = (ctypes.c_double * 3)(*[float(x) for x in omega_ddot_of(t)])
            assert instance.call("fmi2SetRealInputDerivatives", vrs, 3, orders2, values) == 0
        elif mode == "omega_dot":
            fmu.setReal(omega_dot_vr, [float(x) for x in omega_dot_of(t)])
        fmu.doStep(currentCommunicationPoint=t, communicationStepSize=h)
        if (n + 1) % every == 0 or n + 1 == steps:
            error = attitude_error(np.array(fmu.getReal(q_vr)), np.array(q_of((n + 1) * h)))
            worst = max(worst, error)
    return worst, error
