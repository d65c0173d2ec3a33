"""Runs dist/ssp/RoundTrip.ssp (built first from dist/*.fmu when missing) with fmpy's SSP master
over the tumbling body of demo/trajectories.py, and checks that EulerRates gives back the
trajectory's theta_dot and theta_ddot:

    .venv/bin/python examples/ssp/round_trip.py [--ssp FILE] [--stop-time 4] [--step 0.01]

Error per row: |recovered - true| / |true| with the Euclidean norm over the three components, for
theta_dot and for theta_ddot. Rows where singularity_distance (|cos theta[2]|) is below
--min-distance (default 0.1) are near the singular angle and left out; the result must be within
--tolerance (default 1e-10) everywhere else. Exit status 0 within, 1 beyond.

fmpy's master (fmpy.ssp.simulation.simulate_ssp) is a Jacobi master: every connection passes a
value on one communication step later. EulerRates gets theta straight from the system's inputs
(one step late) and omega through AngularKinematics (two steps late), so the trajectory is held
for two steps: on every even row k >= 2 both came from the sample at row k - 2, and those rows are
compared with the true values of row k - 2."""
import argparse
import pathlib
import sys

import numpy as np
from fmpy.ssp.simulation import simulate_ssp

from demo.trajectories import tumbling
from examples.ssp.make_ssp import make_ssp

ROOT = pathlib.Path(__file__).resolve().parents[2]

HOLD = 2  # communication steps each sample of the trajectory is held


def held_inputs(step):
    """{system input connector: function of time}: the tumbling body, sampled every HOLD steps."""
    def signal(kind, i):
        def value(time):
            sample = (int(round(time / step)) // HOLD) * HOLD * step
            return float(tumbling(np.array([sample]))[kind][0, i])
        return value
    return {f"{name}[{i + 1}]": signal(kind, i)
            for kind, name in enumerate(["theta", "theta_dot", "theta_ddot"]) for i in range(3)}


def run(ssp, stop_time=4.0, step=0.01):
    """The result of simulate_ssp and, for each compared row, the relative errors."""
    result = simulate_ssp(str(ssp), stop_time=stop_time, step_size=step, input=held_inputs(step))

    def vector(name, rows):
        return np.column_stack([result[f"{name}[{i}]"][rows] for i in (1, 2, 3)])

    rows = np.arange(HOLD, len(result), HOLD)  # even rows: theta and omega from row k - 2
    errors = {}
    for name in ("theta_dot", "theta_ddot"):
        true = vector(name, rows - HOLD)  # the system input: the trajectory
        recovered = vector(f"{name}_recovered", rows)
        errors[name] = np.linalg.norm(recovered - true, axis=1) / np.linalg.norm(true, axis=1)
    return result, rows, errors


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--ssp", default=str(ROOT / "dist" / "ssp" / "RoundTrip.ssp"))
    parser.add_argument("--stop-time", type=float, default=4.0)
    parser.add_argument("--step", type=float, default=0.01)
    parser.add_argument("--tolerance", type=float, default=1e-10)
    parser.add_argument("--min-distance", type=float, default=0.1)
    args = parser.parse_args(argv)
    ssp = pathlib.Path(args.ssp)
    if not ssp.is_file():
        make_ssp(ROOT / "dist", ssp)
    result, rows, errors = run(ssp, args.stop_time, args.step)
    away = result["singularity_distance"][rows] >= args.min_distance
    status = 0
    for name, error in errors.items():
        worst = float(error[away].max())
        near = float(error[~away].max()) if (~away).any() else float("nan")
        verdict = "ok" if worst <= args.tolerance else "BEYOND"
        print(f"{verdict:>6} {name}: largest relative error {worst:.2e} over {int(away.sum())} rows "
              f"(singularity_distance >= {args.min_distance:g}); {near:.2e} over the "
              f"{int((~away).sum())} rows nearer the singular angle")
        status |= worst > args.tolerance
    print(f"{ssp}: {len(result)} communication points of {args.step:g} s; "
          f"{'PASSED' if status == 0 else 'FAILED'} at {args.tolerance:g}")
    return int(status)


if __name__ == "__main__":
    sys.exit(main())
