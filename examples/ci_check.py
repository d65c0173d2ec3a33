"""A simulation check to copy into CI: runs a reference trajectory through an FMU with fmpy and
compares every output with a stored reference result; exits 1 on a regression.

Tolerances (stated here, printed with the result): for each output y and each row,
    |y - y_reference| <= ABSOLUTE + RELATIVE * |y_reference|
with RELATIVE = 1e-12 and ABSOLUTE = 1e-12 (rad/s for omega, rad/s2 for alpha). The FMU computes
in double precision to ~1e-16; the margin leaves room for another compiler or C library, while
any change of the kinematics shows up far above it. The time grid and the recorded inputs must
match the reference's to 1e-13 (the same trajectory went in).

    .venv/bin/python examples/ci_check.py                      # exit 0: no regression
    .venv/bin/python examples/ci_check.py --reference OTHER.csv
    .venv/bin/python examples/ci_check.py --update             # store a new reference (review it!)

Exit status: 0 all outputs within tolerance, 1 regression, 2 the run cannot be compared (no FMU or
an FMU fmpy cannot simulate, no reference, other columns or time grid)."""
import argparse
import pathlib
import sys

import numpy as np
from fmpy import simulate_fmu

ROOT = pathlib.Path(__file__).resolve().parent.parent
INPUT_NAMES = [f"{base}[{i}]" for base in ("theta", "theta_dot", "theta_ddot") for i in (1, 2, 3)]
OUTPUT_NAMES = [f"{base}[{i}]" for base in ("omega_fixed", "omega_body", "alpha_fixed", "alpha_body")
                for i in (1, 2, 3)]
RELATIVE = 1e-12
ABSOLUTE = 1e-12
STOP_TIME = 4.0
STEP = 0.02


def reference_inputs(times):
    """The reference trajectory: a body tumbling about all three axes, theta[2] passing within
    0.05 rad of gimbal lock; exact first and second derivatives."""
    rate = np.array([0.6, 0.0, 2.5])
    amplitude = np.array([0.8, np.pi / 2 - 0.05, 0.5])
    frequency = np.array([1.3, 0.9, 2.1])
    phase = np.array([0.0, 0.4, 1.0])
    t = times[:, None]
    argument = frequency * t + phase
    columns = np.hstack([rate * t + amplitude * np.sin(argument),
                         rate + amplitude * frequency * np.cos(argument),
                         -amplitude * frequency ** 2 * np.sin(argument)])
    signals = np.zeros(len(times), dtype=[("time", float)] + [(n, float) for n in INPUT_NAMES])
    signals["time"] = times
    for k, name in enumerate(INPUT_NAMES):
        signals[name] = columns[:, k]
    return signals


def simulate(fmu):
    times = np.arange(0.0, STOP_TIME + STEP / 2, STEP)
    return simulate_fmu(fmu, stop_time=STOP_TIME, output_interval=STEP,
                        input=reference_inputs(times), output=INPUT_NAMES + OUTPUT_NAMES)


def write_reference(result, path):
    path.parent.mkdir(parents=True, exist_ok=True)
    columns = ["time"] + INPUT_NAMES + OUTPUT_NAMES
    table = np.column_stack([result[name] for name in columns])
    np.savetxt(path, table, delimiter=",", fmt="%.17g", header=",".join(columns), comments="")


def read_reference(path):
    with path.open() as file:
        columns = file.readline().strip().split(",")
    return columns, np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)


def compare(result, path):
    """Prints one line per output and returns the exit status."""
    if not path.is_file():
        print(f"no reference result at {path} (store one with --update)")
        return 2
    columns, table = read_reference(path)
    expected_columns = ["time"] + INPUT_NAMES + OUTPUT_NAMES
    if columns != expected_columns:
        print(f"{path}: columns {columns} are not {expected_columns}")
        return 2
    reference = {name: table[:, k] for k, name in enumerate(columns)}
    # The inputs come from numpy's sin and cos, which may differ in the last bit between machines.
    if len(result) != len(table) or not all(np.allclose(result[n], reference[n], rtol=1e-13, atol=1e-13)
                                            for n in ["time"] + INPUT_NAMES):
        print(f"{path}: the time grid or the inputs differ from this run's: not comparable")
        return 2
    status = 0
    print(f"tolerance per value: {ABSOLUTE:g} + {RELATIVE:g} * |reference|")
    for name in OUTPUT_NAMES:
        deviation = np.abs(result[name] - reference[name])
        ratio = deviation / (ABSOLUTE + RELATIVE * np.abs(reference[name]))
        worst = int(np.argmax(ratio))
        verdict = "ok" if ratio[worst] <= 1 else "REGRESSION"
        print(f"{verdict:>10}  {name:<16} largest deviation {deviation[worst]:.2e} at "
              f"t = {result['time'][worst]:g} s ({ratio[worst]:.2g} of the tolerance)")
        if ratio[worst] > 1:
            status = 1
    return status


def parser():
    summary, details = __doc__.split("\n\n", 1)
    result = argparse.ArgumentParser(description=" ".join(summary.split()), epilog=details,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    result.add_argument("--fmu", default=str(ROOT / "dist" / "AngularKinematics.fmu"),
                        help="the FMU to check (default: %(default)s)")
    result.add_argument("--reference", default=str(ROOT / "examples" / "reference" /
                                                   "tumbling_body_reference.csv"),
                        help="the stored reference result, a CSV file (default: %(default)s)")
    result.add_argument("--update", action="store_true",
                        help="store this run as the new reference instead of comparing")
    result.add_argument("--cross-check", metavar="DIR",
                        help="instead: re-simulate a folder in the FMI Cross-Check layout "
                             "(dist/cross-check/) and fail on a difference beyond its tolerance")
    result.add_argument("--ls-ref", metavar="FMU",
                        help="instead: re-simulate the FMU against the reference result it "
                             "carries (FMI-LS-REF, extra/org.fmi-standard.fmi-ls-ref/)")
    return result


def main(argv=None):
    args = parser().parse_args(argv)
    if args.cross_check:
        return cross_check(args.cross_check)
    if args.ls_ref:
        return carried_reference(args.ls_ref)
    if not pathlib.Path(args.fmu).is_file():
        print(f"no FMU at {args.fmu}: build it with bash scripts/build.sh, or name one with --fmu")
        print("ERROR: not comparable")
        return 2
    try:
        result = simulate(args.fmu)
    except Exception as error:  # fmpy's message names what is wrong with the file
        print(f"{args.fmu} could not be simulated: {error}")
        print("ERROR: not comparable")
        return 2
    path = pathlib.Path(args.reference)
    if args.update:
        write_reference(result, path)
        print(f"stored {len(result)} rows as the reference in {path}")
        return 0
    status = compare(result, path)
    print({0: "PASSED: no regression", 1: "FAILED: regression against the reference",
           2: "ERROR: not comparable"}[status])
    return status


def cross_check(folder):
    """--cross-check DIR: examples/cross_check.py and cross_check3.py (copy them beside this file)
    re-simulate every <Model>_in.csv under DIR, FMI 2.0 and 3.0, and compare with <Model>_ref.csv;
    exit 0 equal, 1 different, 2 empty."""
    if __package__:  # examples.ci_check, in the repository
        from examples.cross_check import check_folder
    else:  # run as a file: cross_check.py beside it (the script's folder is on the path)
        from cross_check import check_folder
    status = check_folder(pathlib.Path(folder))
    print({0: "PASSED: the cross-check results agree", 1: "FAILED: a result differs",
           2: "ERROR: nothing to compare"}[status])
    return status


def carried_reference(fmu):
    """--ls-ref FMU: examples/ls_ref.py (copy it and cross_check*.py beside this file) re-simulates
    the FMU over the inputs it carries; exit 0 equal, 1 different, 2 nothing carried."""
    if __package__:
        from examples.ls_ref import check_carried
    else:
        from ls_ref import check_carried
    status = check_carried(pathlib.Path(fmu))
    print({0: "PASSED: the FMU computes the result it carries", 1: "FAILED: a result differs",
           2: "ERROR: nothing to compare"}[status])
    return status


if __name__ == "__main__":
    sys.exit(main())
