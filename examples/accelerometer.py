"""An accelerometer at a lever arm on the demonstration's tumbling body, through two FMUs:
AngularKinematics turns the body's angles and their derivatives (demo/trajectories.py) into
omega_body, alpha_body and R; PointKinematics turns those, the lever arm r and gravity in body
components (R^T g) into what the accelerometer reads, specific_force = a_P - g, with its
tangential, centripetal and Coriolis parts. The body's centre is at rest; the sensor is fixed on
the body (r_dot = r_ddot = 0).

Both models follow their inputs at once (direct feedthrough), so running AngularKinematics over the
whole time grid and then PointKinematics over its outputs is the chain a co-simulation master runs
step by step. Writes results/accelerometer.csv and results/accelerometer.png.

    .venv/bin/python -m examples.accelerometer [--dist DIR] [--stop 10] [--step 0.01]"""
import argparse
import pathlib
import sys

import numpy as np

from demo import trajectories
from examples.cross_check import simulate

ROOT = pathlib.Path(__file__).resolve().parent.parent
LEVER_ARM = np.array([0.3, -0.1, 0.2])  # m, the sensor relative to the body's centre
G_FIXED = np.array([0.0, 0.0, -9.81])  # m/s2, gravity in fixed components
VECTOR = (1, 2, 3)


def names(vector):
    return [f"{vector}[{i}]" for i in VECTOR]


def accelerometer(dist, times):
    """{name: len(times) x 3}: the body's omega and alpha, the reading and its parts."""
    theta, theta_dot, theta_ddot = trajectories.tumbling(times)
    body = ["omega_body", "alpha_body"]
    out, y = simulate(str(dist / "AngularKinematics.fmu"), "cs", times, trajectories.INPUT_NAMES,
                      np.hstack([theta, theta_dot, theta_ddot]),
                      [n for v in body for n in names(v)] + [f"R[{i},{j}]" for i in VECTOR
                                                              for j in VECTOR])
    omega, alpha, R = y[:, 0:3], y[:, 3:6], y[:, 6:15].reshape(-1, 3, 3)
    g_body = np.einsum("kji,j->ki", R, G_FIXED)  # R^T g
    zero = np.zeros_like(omega)
    inputs = {"omega": omega, "alpha": alpha, "v_O": zero, "a_O": zero,
              "r": np.broadcast_to(LEVER_ARM, omega.shape), "r_dot": zero, "r_ddot": zero,
              "g": g_body}
    parts = ["specific_force", "a_tangential", "a_centripetal", "a_coriolis"]
    _, z = simulate(str(dist / "PointKinematics.fmu"), "cs", times,
                    [n for v in inputs for n in names(v)], np.hstack(list(inputs.values())),
                    [n for v in parts for n in names(v)])
    result = {"omega_body": omega, "alpha_body": alpha, "g_body": g_body}
    result.update({part: z[:, 3 * k:3 * k + 3] for k, part in enumerate(parts)})
    return result


def plot(times, result, output):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    figure, axes = plt.subplots(2, 1, figsize=(10, 6.5), sharex=True, layout="constrained")
    colours = ("#d62728", "#2ca02c", "#1f77b4")
    for i, colour in enumerate(colours):
        axes[0].plot(times, result["specific_force"][:, i], color=colour,
                     label=f"specific_force[{i + 1}]")
        axes[0].plot(times, -result["g_body"][:, i], color=colour, linestyle=":", linewidth=1,
                     label="dotted: -g_body, the reading at rest" if i == 0 else None)
    axes[0].set_ylabel("m/s$^2$")
    axes[0].set_title(f"what an accelerometer at r = {LEVER_ARM.tolist()} m reads, body components")
    axes[0].legend(loc="upper right", ncol=2, fontsize="small")
    for part, style in (("a_tangential", "-"), ("a_centripetal", "--")):
        size = np.linalg.norm(result[part], axis=1)
        axes[1].plot(times, size, linestyle=style, label=f"|{part}|")
    axes[1].set_ylabel("m/s$^2$")
    axes[1].set_xlabel("time (s)")
    axes[1].set_title("the rotation's parts of the reading (alpha x r, omega x (omega x r))")
    axes[1].legend(loc="upper right", fontsize="small")
    figure.savefig(output, dpi=110)
    plt.close(figure)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--dist", default=str(ROOT / "dist"), help="folder of the built FMUs")
    parser.add_argument("--stop", type=float, default=10.0)
    parser.add_argument("--step", type=float, default=0.01)
    parser.add_argument("--out", default=str(ROOT / "results"))
    args = parser.parse_args(argv)
    times = np.arange(0.0, args.stop + args.step / 2, args.step)
    result = accelerometer(pathlib.Path(args.dist), times)
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    columns = ["time"] + [n for key in result for n in names(key)]
    table = np.column_stack([times] + list(result.values()))
    np.savetxt(out / "accelerometer.csv", table, delimiter=",", fmt="%.17g",
               header=",".join(columns), comments="")
    plot(times, result, out / "accelerometer.png")
    reading = np.linalg.norm(result["specific_force"], axis=1)
    print(f"wrote {out / 'accelerometer.csv'} and {out / 'accelerometer.png'}: |specific_force| "
          f"from {reading.min():.3f} to {reading.max():.3f} m/s2 (9.81 at rest)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
