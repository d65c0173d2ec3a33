"""Demonstration: a tumbling body whose body 1-2-3 angles pass through gimbal lock (theta2 =
pi/2) three times, propagated on quaternions by dist/AttitudePropagator.fmu with fmpy.

The motion is given in closed form by its angles, theta(t) = (0.4 + 0.7 t, pi/2 + 0.8 sin(0.9
(t - 1)), -0.3 + 0.25 t^2); its body angular velocity and acceleration (derived with sympy from
the attitude quaternion) are the FMU's only inputs. The FMU never sees an angle: it integrates q
and reports the angles of the sequence, unwrapped and continued through the singular attitude.

Writes results/gimbal_lock.png (theta against the closed form, q, the attitude error and the
singularity distance over time) and prints the largest errors. Run:
    .venv/bin/python demo/gimbal_lock.py [--stop-time 8] [--step 1e-3] [--output PATH]"""
import argparse
import pathlib

import matplotlib
import numpy as np
import sympy as sp
from fmpy import simulate_fmu

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402 (after the backend choice)

ROOT = pathlib.Path(__file__).resolve().parent.parent


def closed_form():
    """numpy functions of t: theta, q (scalar first), omega_body, omega_body_dot."""
    t = sp.symbols("t", real=True)
    theta = sp.Matrix([0.4 + 0.7 * t, sp.pi / 2 + 0.8 * sp.sin(0.9 * (t - 1)), -0.3 + 0.25 * t**2])

    def axis_quaternion(axis, angle):
        q = [sp.cos(angle / 2), 0, 0, 0]
        q[axis] = sp.sin(angle / 2)
        return sp.Quaternion(*q)

    q = axis_quaternion(1, theta[0]) * axis_quaternion(2, theta[1]) * axis_quaternion(3, theta[2])
    q_dot = q.diff(t)
    rate = q.inverse() * q_dot  # q* (x) dq/dt for a unit q
    omega = sp.Matrix([2 * rate.b, 2 * rate.c, 2 * rate.d])
    components = [q.a, q.b, q.c, q.d]
    return tuple(sp.lambdify(t, list(f), "numpy")
                 for f in (theta, components, omega, omega.diff(t)))


def attitude_error(q, reference):
    """Rotation angle (rad) between attitudes, rows of (w, x, y, z); q and -q are the same. From
    d = reference* (x) q as 2 atan2(|vec d|, |scalar d|): arccos of the scalar would lose half the
    digits near 0."""
    w0, x0, y0, z0 = reference.T
    w, x, y, z = q.T
    scalar = w0 * w + x0 * x + y0 * y + z0 * z
    vector = np.column_stack([w0 * x - x0 * w - y0 * z + z0 * y,
                              w0 * y + x0 * z - y0 * w - z0 * x,
                              w0 * z - x0 * y + y0 * x - z0 * w])
    return 2.0 * np.arctan2(np.linalg.norm(vector, axis=1), np.abs(scalar))


def run(fmu, stop_time, step):
    theta_of, q_of, omega_of, omega_dot_of = closed_form()
    times = np.arange(0.0, stop_time + step / 2, step)
    omega = np.array(omega_of(times), dtype=float).reshape(3, -1)
    omega_dot = np.array(omega_dot_of(times), dtype=float).reshape(3, -1)
    names = [f"omega[{k}]" for k in (1, 2, 3)] + [f"omega_dot[{k}]" for k in (1, 2, 3)]
    signals = np.zeros(len(times), dtype=[("time", float)] + [(n, float) for n in names])
    signals["time"] = times
    for k, name in enumerate(names):
        signals[name] = omega[k] if k < 3 else omega_dot[k - 3]
    q0 = np.array(q_of(0.0), dtype=float)
    outputs = ([f"q[{k}]" for k in (1, 2, 3, 4)] + [f"theta[{k}]" for k in (1, 2, 3)]
               + ["singularity_distance"])
    result = simulate_fmu(fmu, stop_time=stop_time, output_interval=step, input=signals,
                          start_values={f"q0[{k + 1}]": q0[k] for k in range(4)}, output=outputs)
    t = result["time"]
    q = np.column_stack([result[f"q[{k}]"] for k in (1, 2, 3, 4)])
    theta = np.column_stack([result[f"theta[{k}]"] for k in (1, 2, 3)])
    theta_exact = np.array(theta_of(t), dtype=float).reshape(3, -1).T
    q_exact = np.array(q_of(t), dtype=float).reshape(4, -1).T
    return t, q, theta, theta_exact, attitude_error(q, q_exact), result["singularity_distance"]


def plot(t, q, theta, theta_exact, error, distance, path):
    figure, axes = plt.subplots(4, 1, figsize=(9, 11), sharex=True)
    for k in range(3):
        axes[0].plot(t, theta[:, k], label=f"theta[{k + 1}] (FMU)")
        axes[0].plot(t, theta_exact[:, k], "k--", linewidth=0.8)
    axes[0].axhline(np.pi / 2, color="grey", linewidth=0.5)
    axes[0].set_ylabel("body123 angles (rad)")
    axes[0].legend(loc="upper left", fontsize=8)
    axes[0].set_title("Through gimbal lock: angles continuous (dashed: closed form)")
    for k in range(4):
        axes[1].plot(t, q[:, k], label=f"q[{k + 1}]")
    axes[1].set_ylabel("quaternion")
    axes[1].legend(loc="upper left", fontsize=8)
    axes[2].semilogy(t, np.maximum(error, 1e-17))
    axes[2].set_ylabel("attitude error (rad)")
    axes[3].semilogy(t, np.maximum(distance, 1e-17))
    axes[3].set_ylabel("singularity_distance")
    axes[3].set_xlabel("time (s)")
    figure.tight_layout()
    path.parent.mkdir(parents=True, exist_ok=True)
    figure.savefig(path, dpi=110)
    plt.close(figure)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--fmu", default=str(ROOT / "dist" / "AttitudePropagator.fmu"))
    parser.add_argument("--stop-time", type=float, default=8.0)
    parser.add_argument("--step", type=float, default=1e-3)
    parser.add_argument("--output", type=pathlib.Path, default=ROOT / "results" / "gimbal_lock.png")
    args = parser.parse_args(argv)
    t, q, theta, theta_exact, error, distance = run(args.fmu, args.stop_time, args.step)
    plot(t, q, theta, theta_exact, error, distance, args.output)
    far = distance > 1e-3
    print(f"{len(t) - 1} steps of {args.step} s: largest attitude error {error.max():.2e} rad; "
          f"largest theta2 error {np.abs(theta[:, 1] - theta_exact[:, 1]).max():.2e} rad; "
          f"largest theta1, theta3 error where singularity_distance > 1e-3 "
          f"{np.abs(theta[far][:, [0, 2]] - theta_exact[far][:, [0, 2]]).max():.2e} rad; "
          f"smallest singularity_distance {distance.min():.1e}; plot: {args.output}")
    return error.max()


if __name__ == "__main__":
    main()
