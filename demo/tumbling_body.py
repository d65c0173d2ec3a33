"""Demonstration: a tumbling body simulated with fmpy through AngularKinematics.fmu.

Writes results/tumbling_body.csv with the nine inputs and the four output vectors at every
communication point, results/tumbling_body.png with omega and alpha in both frames, and prints a
short summary. Runs that take more than a moment show a progress bar. `bash scripts/demo.sh` runs
it on an FMU it builds first, build-demo/dist/AngularKinematics.fmu (x86_64-linux binary only);
the default is the seven-platform FMU of `bash scripts/build.sh`."""
import argparse
import pathlib
import sys

import numpy as np
from fmpy import simulate_fmu
from fmpy.util import write_csv
from tqdm import tqdm

from demo import trajectories

ROOT = pathlib.Path(__file__).resolve().parent.parent
VECTORS = ("omega_fixed", "omega_body", "alpha_fixed", "alpha_body")
PROGRESS_DELAY = 1.0  # seconds a run must last before its progress bar appears


def simulate(fmu, stop_time, step, progress=True):
    """The fmpy result: inputs and outputs at every communication point of [0, stop_time]."""
    times = np.arange(0.0, stop_time + step / 2, step)
    # Inputs are recorded beside the outputs: fmpy's co-simulation master holds the inputs of t over
    # the step [t, t + h], so the row at t + h shows the inputs of t and the kinematics they give.
    outputs = trajectories.INPUT_NAMES + [f"{v}[{i}]" for v in VECTORS for i in (1, 2, 3)]
    with tqdm(total=round(stop_time / step), unit="step", delay=PROGRESS_DELAY,
              disable=not progress, file=sys.stderr) as bar:
        def step_finished(time, recorder):
            bar.update(round(time / step) - bar.n)
            return True

        return simulate_fmu(fmu, stop_time=stop_time, output_interval=step, output=outputs,
                            input=trajectories.input_signals(times), step_finished=step_finished)


def vector(result, name):
    return np.column_stack([result[f"{name}[{i}]"] for i in (1, 2, 3)])


def plot(result, step, output):
    """omega and alpha, fixed and body components, against the time of the inputs they belong to."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    # Row k + 1 holds the kinematics of the inputs of time k h (fmpy's zero-order hold).
    rows = result[1:]
    time = result["time"][1:] - step
    figure, axes = plt.subplots(2, 2, figsize=(10, 6.5), sharex=True, layout="constrained")
    titles = {"omega_fixed": "omega, fixed-frame components", "omega_body": "omega, body-frame components",
              "alpha_fixed": "alpha, fixed-frame components", "alpha_body": "alpha, body-frame components"}
    units = {"omega": "rad/s", "alpha": "rad/s$^2$"}
    near_lock = np.abs(vector(rows, "theta")[:, 1]) > np.pi / 2 - 0.1
    for ax, name in zip(axes.ravel(), VECTORS):
        values = vector(rows, name)
        for i, colour in zip(range(3), ("#d62728", "#2ca02c", "#1f77b4")):
            ax.plot(time, values[:, i], color=colour, lw=1.2, label=f"component [{i + 1}]")
        ax.fill_between(time, 0, 1, where=near_lock, transform=ax.get_xaxis_transform(),
                        color="0.85", lw=0, label="|theta[2]| within 0.1 rad of gimbal lock")
        ax.set_title(titles[name], fontsize=10)
        ax.set_ylabel(units[name.split("_")[0]])
        ax.grid(True, lw=0.3)
    for ax in axes[1]:
        ax.set_xlabel("time (s)")
    figure.legend(*axes[0, 0].get_legend_handles_labels(), loc="outside lower center", ncols=4,
                  fontsize=8, frameon=False)
    figure.suptitle("Tumbling body: AngularKinematics.fmu simulated with fmpy", fontsize=11)
    figure.savefig(output, dpi=90, metadata={"Software": None})
    plt.close(figure)


def main():
    summary, details = __doc__.split("\n\n", 1)
    parser = argparse.ArgumentParser(description=" ".join(summary.split()), epilog=details,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--fmu", default=str(ROOT / "dist" / "AngularKinematics.fmu"),
                        help="the FMU to simulate (default: %(default)s)")
    parser.add_argument("--stop-time", type=float, default=10.0, help="seconds (default: 10)")
    parser.add_argument("--step", type=float, default=0.01,
                        help="communication step in seconds (default: 0.01)")
    parser.add_argument("--output", default=str(ROOT / "results" / "tumbling_body.csv"),
                        help="the CSV; the plot goes beside it with the suffix .png")
    parser.add_argument("--no-progress", action="store_true", help="never show a progress bar")
    args = parser.parse_args()

    result = simulate(args.fmu, args.stop_time, args.step, progress=not args.no_progress)
    output = pathlib.Path(args.output)
    output.parent.mkdir(parents=True, exist_ok=True)
    write_csv(str(output), result)
    picture = output.with_suffix(".png")
    plot(result, args.step, picture)

    speed_fixed = np.linalg.norm(vector(result, "omega_fixed"), axis=1)
    speed_body = np.linalg.norm(vector(result, "omega_body"), axis=1)
    print(f"simulated {len(result) - 1} steps of {args.step} s to t = {result['time'][-1]:g} s")
    print(f"|omega| from {speed_fixed.min():.3f} to {speed_fixed.max():.3f} rad/s, "
          f"|alpha| up to {np.linalg.norm(vector(result, 'alpha_fixed'), axis=1).max():.3f} rad/s2")
    print(f"largest difference between |omega_fixed| and |omega_body|: "
          f"{np.abs(speed_fixed - speed_body).max():.1e} rad/s")
    print(f"wrote {output} and {picture}")
    print(f"note: the CSV row at time t holds the outputs of the inputs of t - {args.step:g} s (fmpy's "
          f"co-simulation master records after each step, the inputs held over it); the input "
          f"columns beside them are those inputs, and the plot is drawn against their time")
    return 0


if __name__ == "__main__":
    sys.exit(main())
