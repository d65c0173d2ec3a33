"""fmpy side of the benchmark: seconds per 100,000 steps of fmpy.simulate_fmu with AngularKinematics
next to the pass-through FMU, fmpy's floor for this interface, timed alternately in one run.

The pass-through FMU (bench/passthrough/) has the same 9 inputs and 12 outputs, same names and
value references, and copies inputs to outputs: whatever fmpy spends on it is fmpy's own cost.
This script packages it from the binary of the benchmark build into a temporary .fmu, extracts
both FMUs once, and runs the same simulation (same input table, same recorded outputs) on each.

Usage: python bench/fmpy_bench.py --fmu AngularKinematics.fmu --passthrough PassThrough.so
                                  [--steps 100000] [--repeats 5]
"""
import argparse
import pathlib
import statistics
import sys
import tempfile
import time
import zipfile

import numpy as np
from fmpy import extract, simulate_fmu

HERE = pathlib.Path(__file__).resolve().parent
INPUT_NAMES = [f"{name}[{i}]" for name in ("theta", "theta_dot", "theta_ddot") for i in (1, 2, 3)]
OUTPUT_NAMES = [f"{name}[{i}]" for name in ("omega_fixed", "omega_body", "alpha_fixed", "alpha_body")
                for i in (1, 2, 3)]
STEP_SIZE = 1e-3


def package_passthrough(binary, directory):
    """The pass-through .fmu: its modelDescription.xml and the binary of the benchmark build."""
    fmu = pathlib.Path(directory) / "PassThrough.fmu"
    with zipfile.ZipFile(fmu, "w") as archive:
        archive.write(HERE / "passthrough" / "modelDescription.xml", "modelDescription.xml")
        archive.write(binary, "binaries/linux64/PassThrough.so")
    return fmu


def input_signals(steps):
    """A smooth tumbling motion sampled at every communication point, so that fmpy interpolates
    and sets new values at each step."""
    times = np.arange(steps + 1) * STEP_SIZE
    signals = np.zeros(times.size, dtype=[("time", np.float64)] + [(n, np.float64) for n in INPUT_NAMES])
    signals["time"] = times
    rates = (0.7, -1.3, 2.1)
    for k, rate in enumerate(rates):
        signals[INPUT_NAMES[k]] = np.sin(rate * times + k)
        signals[INPUT_NAMES[3 + k]] = rate * np.cos(rate * times + k)
        signals[INPUT_NAMES[6 + k]] = -rate * rate * np.sin(rate * times + k)
    return signals


def simulate(directory, signals, steps):
    """CPU seconds of this process for one fmpy.simulate_fmu of `steps` steps, recording the 12
    outputs. CPU time, not wall time: on a machine shared with other jobs, the time this process
    waits for a core is nobody's cost."""
    start = time.process_time()
    result = simulate_fmu(str(directory), stop_time=steps * STEP_SIZE, output_interval=STEP_SIZE,
                          input=signals, output=OUTPUT_NAMES)
    elapsed = time.process_time() - start
    if len(result) != steps + 1:
        sys.exit(f"fmpy_bench: expected {steps + 1} result rows, got {len(result)}")
    return elapsed


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--fmu", required=True, help="AngularKinematics.fmu of the benchmark build")
    parser.add_argument("--passthrough", required=True, help="PassThrough.so of the benchmark build")
    parser.add_argument("--steps", type=int, default=100_000, help="steps per simulation")
    parser.add_argument("--repeats", type=int, default=5, help="simulations per FMU, median quoted")
    args = parser.parse_args()

    signals = input_signals(args.steps)
    with tempfile.TemporaryDirectory(prefix="ak-bench-") as temporary:
        fmus = {
            "AngularKinematics": extract(args.fmu, unzipdir=pathlib.Path(temporary) / "ak"),
            "PassThrough": extract(package_passthrough(args.passthrough, temporary),
                                   unzipdir=pathlib.Path(temporary) / "pt"),
        }
        for directory in fmus.values():  # warm-up: first loads, caches
            simulate(directory, signals, min(args.steps, 1000))
        seconds = {name: [] for name in fmus}
        for _ in range(args.repeats):
            for name, directory in fmus.items():  # alternately, so both see the same machine
                seconds[name].append(simulate(directory, signals, args.steps))

    per_100k = {name: statistics.median(values) * 100_000 / args.steps for name, values in seconds.items()}
    ratio = statistics.median(a / p for a, p in zip(seconds["AngularKinematics"], seconds["PassThrough"]))
    print(f"fmpy.simulate_fmu, {args.steps} steps of {STEP_SIZE} s, 9 inputs set and 12 outputs recorded "
          f"per step, {args.repeats} repeats alternating (median); ratio = median of the per-repeat ratios:\n")
    print("| FMU | CPU s per 100,000 steps | / pass-through |")
    print("|---|---:|---:|")
    print(f"| PassThrough (fmpy's floor) | {per_100k['PassThrough']:.2f} | 1.00 |")
    print(f"| AngularKinematics | {per_100k['AngularKinematics']:.2f} | {ratio:.3f} |")


if __name__ == "__main__":
    main()
