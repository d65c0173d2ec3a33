"""Large sweeps on Dask: many fmpy simulations of AngularKinematics.fmu, checked against the reference.

Each simulation is one task on a dask.distributed cluster: a tumbling trajectory of its own
(theta_i(t) = rate_i t + amplitude_i sin(frequency_i t + phase_i), parameters drawn from a seeded
generator), simulated with fmpy, and checked on the worker against the project's independent sympy
reference (codegen/reference.py): the worst error over the checked rows, scaled as in the tests, must
not exceed --tolerance. The client collects every case's figures, writes them to a CSV and exits
with status 1 if any case fails.

By default the sweep runs on a LocalCluster of worker processes that listen on 127.0.0.1 only.
--scheduler ADDRESS (e.g. tcp://10.0.0.5:8786) uses an existing cluster instead: the FMU's bytes,
the reference module and the trajectory module (demo/trajectories.py) are sent to its workers, which need the packages of requirements.txt (fmpy,
numpy, sympy, mpmath) but no shared file system.

    .venv/bin/python examples/dask_sweep.py --count 200             # local cluster, 2 workers
    .venv/bin/python examples/dask_sweep.py --scheduler tcp://HOST:8786 --count 10000
"""
import argparse
import csv
import hashlib
import os
import pathlib
import sys
import tempfile
import time

import numpy as np
from dask.distributed import Client, LocalCluster, as_completed
from tqdm import tqdm

ROOT = pathlib.Path(__file__).resolve().parent.parent
INPUT_NAMES = [f"{base}[{i}]" for base in ("theta", "theta_dot", "theta_ddot") for i in (1, 2, 3)]
OUTPUT_NAMES = [f"{base}[{i}]" for base in ("omega_fixed", "omega_body", "alpha_fixed", "alpha_body")
                for i in (1, 2, 3)]


def sweep_cases(count, seed):
    """count parameter sets (each 3 rates, amplitudes, frequencies, phases) from a seeded generator."""
    generator = np.random.default_rng(seed)
    return [{"case": k,
             "rate": generator.uniform(-3.0, 3.0, 3),
             "amplitude": generator.uniform(0.0, 1.6, 3),
             "frequency": generator.uniform(0.2, 3.0, 3),
             "phase": generator.uniform(0.0, 2 * np.pi, 3)} for k in range(count)]


def input_signals(case, times):
    """The nine inputs of a case, exact derivatives included, as fmpy's structured input array."""
    import trajectories  # demo/trajectories.py, sent to the workers by Client.upload_file
    return trajectories.as_input_signals(times, *trajectories.sinusoidal(
        times, case["rate"], case["amplitude"], case["frequency"], case["phase"]))


def unpacked_fmu(fmu_bytes):
    """The FMU extracted once per worker machine, in a folder named after its SHA-256."""
    from fmpy import extract
    digest = hashlib.sha256(fmu_bytes).hexdigest()[:16]
    folder = pathlib.Path(tempfile.gettempdir()) / f"AngularKinematics-{digest}"
    if not (folder / "modelDescription.xml").is_file():
        staging = pathlib.Path(tempfile.mkdtemp(prefix=folder.name + "-"))
        archive = staging / "AngularKinematics.fmu"
        archive.write_bytes(fmu_bytes)
        extract(str(archive), unzipdir=str(staging / "fmu"))
        try:
            os.rename(staging / "fmu", folder)  # atomic: a concurrent worker's copy wins or ours does
        except OSError:
            pass
    return str(folder)


def run_case(case, fmu_bytes, stop_time, step, check_every):
    """Runs on a worker: simulates one case and measures its worst scaled error against the reference."""
    import reference  # sent to the workers by Client.upload_file
    from fmpy import simulate_fmu

    started = time.perf_counter()
    times = np.arange(0.0, stop_time + step / 2, step)
    result = simulate_fmu(unpacked_fmu(fmu_bytes), stop_time=stop_time, output_interval=step,
                          input=input_signals(case, times), output=INPUT_NAMES + OUTPUT_NAMES)
    simulated = time.perf_counter() - started
    worst = 0.0
    # Each row holds the inputs the FMU computed its outputs from (fmpy holds inputs over a step).
    for row in result[::check_every]:
        inputs = np.array([row[n] for n in INPUT_NAMES])
        got = np.array([row[n] for n in OUTPUT_NAMES])
        scale_w = max(np.abs(inputs[3:6]).sum(), 1e-300)
        scale = np.array([scale_w] * 6 + [np.abs(inputs[6:9]).sum() + scale_w ** 2] * 6)
        worst = max(worst, float((np.abs(got - reference.outputs(inputs)) / scale).max()))
    return {"case": case["case"], "rows": len(result), "checked_rows": len(result[::check_every]),
            "worst_scaled_error": worst, "simulation_seconds": simulated,
            "worker": os.getpid()}


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scheduler", metavar="ADDRESS",
                        help="an existing Dask scheduler (default: a local cluster on 127.0.0.1)")
    parser.add_argument("--workers", type=int, default=2, help="worker processes of the local cluster")
    parser.add_argument("--count", type=int, default=64, help="number of simulations")
    parser.add_argument("--seed", type=int, default=2026)
    parser.add_argument("--stop-time", type=float, default=5.0)
    parser.add_argument("--step", type=float, default=0.01)
    parser.add_argument("--check-every", type=int, default=10, help="check every n-th row")
    parser.add_argument("--tolerance", type=float, default=1e-14,
                        help="largest allowed |FMU - reference| / scale (scale: sum|theta_dot| for "
                             "omega, sum|theta_ddot| + sum|theta_dot|^2 for alpha)")
    parser.add_argument("--fmu", default=str(ROOT / "dist" / "AngularKinematics.fmu"))
    parser.add_argument("--output", default=str(ROOT / "results" / "dask_sweep.csv"))
    parser.add_argument("--no-progress", action="store_true")
    args = parser.parse_args(argv)

    fmu_bytes = pathlib.Path(args.fmu).read_bytes()
    cluster = None
    if args.scheduler:
        client = Client(args.scheduler)
    else:
        cluster = LocalCluster(n_workers=args.workers, threads_per_worker=1, processes=True,
                               host="127.0.0.1", dashboard_address=None)
        client = Client(cluster)
    started = time.perf_counter()
    try:
        client.upload_file(str(ROOT / "codegen" / "reference.py"))
        client.upload_file(str(ROOT / "demo" / "trajectories.py"))
        fmu_future = client.scatter(fmu_bytes, broadcast=True)
        futures = [client.submit(run_case, case, fmu_future, args.stop_time, args.step,
                                 args.check_every, pure=False)
                   for case in sweep_cases(args.count, args.seed)]
        outcomes = []
        with tqdm(total=len(futures), unit="sim", disable=args.no_progress, file=sys.stderr) as bar:
            for future in as_completed(futures):
                outcomes.append(future.result())
                bar.update(1)
        workers = len(client.scheduler_info()["workers"])
    finally:
        client.close()
        if cluster is not None:
            cluster.close()
    elapsed = time.perf_counter() - started

    outcomes.sort(key=lambda o: o["case"])
    output = pathlib.Path(args.output)
    output.parent.mkdir(parents=True, exist_ok=True)
    with output.open("w", newline="") as file:
        writer = csv.DictWriter(file, fieldnames=list(outcomes[0]))
        writer.writeheader()
        writer.writerows(outcomes)

    failed = [o for o in outcomes if not o["worst_scaled_error"] <= args.tolerance]
    worst = max(o["worst_scaled_error"] for o in outcomes)
    rows = sum(o["rows"] for o in outcomes)
    median = float(np.median([o["simulation_seconds"] for o in outcomes]))
    print(f"{len(outcomes)} simulations ({rows} rows, {sum(o['checked_rows'] for o in outcomes)} "
          f"checked against the reference) on {workers} workers in {elapsed:.1f} s; "
          f"median simulation {median * 1e3:.0f} ms")
    print(f"worst scaled error {worst:.2e} (tolerance {args.tolerance:g}); wrote {output}")
    for o in failed:
        print(f"FAILED case {o['case']}: worst scaled error {o['worst_scaled_error']:.2e}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
