"""Outputs of the FMUs over seeded random states, as SHA-256 digests per sequence (and frame):
the record that proves a rebuilt FMU computes bit for bit what the released one did.

    .venv/bin/python tests/python/golden_outputs.py record DIR_WITH_FMUS tests/python/data/golden_0.4.json
    .venv/bin/python tests/python/golden_outputs.py compare DIR_WITH_FMUS DIR_WITH_OLD_BINARIES

The record holds, per model, the names of the outputs the recorded FMU had ("outputs", in
value-reference order) and the digests of those outputs ("digests"). test_bit_identity.py
recomputes the digests of the same outputs with the FMUs of dist/ and compares: an output added
since does not enter them."""
import hashlib
import json
import pathlib
import shutil
import sys

import numpy as np
from fmpy import extract, platform as fmpy_platform, read_model_description
import ctypes

from fmpy.fmi2 import (FMU2Slave, calloc, fmi2CallbackAllocateMemoryTYPE, fmi2CallbackFreeMemoryTYPE,
                       fmi2CallbackFunctions, fmi2CallbackLoggerTYPE, free)
from fmpy.logging import addLoggerProxy

STATES_PER_CASE = 120  # x 24 sequences (x 2 frames for EulerRates): 2,880 and 5,760 states


def states(seed):
    """Inputs of 9 components: angles in [-pi, pi], rates and accelerations of mixed magnitude."""
    rng = np.random.default_rng(seed)
    angles = rng.uniform(-np.pi, np.pi, (STATES_PER_CASE, 3))
    rates = rng.uniform(-1, 1, (STATES_PER_CASE, 6)) * 10.0 ** rng.integers(-3, 4, (STATES_PER_CASE, 6))
    return np.hstack([angles, rates])


def cases(md):
    """(sequence, frame) pairs: every sequence, times every value of the `frame` parameter's
    enumeration for a model that has one."""
    frame = next((v for v in md.modelVariables if v.name == "frame"), None)
    frames = tuple(int(item.value) for item in frame.declaredType.items) if frame else (None,)
    return [(sequence, frame) for sequence in range(1, 25) for frame in frames]


def outputs_over_states(fmu_path, output_names=None, binary=None):
    """(model identifier, output names, {sequence[/frame]: (values, statuses)}) over the seeded
    states; values: float64 array (states x outputs), NaN rows where the FMU refused a state.
    binary: another build's library to run in place of the FMU's own (same GUID and value
    references), e.g. the previous release's."""
    md = read_model_description(fmu_path)
    model = md.coSimulation.modelIdentifier
    vr = {v.name: v.valueReference for v in md.modelVariables}
    inputs = [v.valueReference for v in md.modelVariables if v.causality == "input"]
    if output_names is None:
        output_names = [v.name for v in md.modelVariables if v.causality == "output"]
    outputs = [vr[name] for name in output_names]
    unzipdir = extract(fmu_path)
    if binary is not None:
        own = pathlib.Path(unzipdir) / "binaries" / fmpy_platform / pathlib.Path(binary).name
        shutil.copyfile(binary, own)
    fmu = FMU2Slave(guid=md.guid, unzipDirectory=unzipdir, modelIdentifier=model,
                    instanceName="golden")
    # fmpy's native logger proxy holds one logger for the process: register ours (it ignores the
    # messages) so that it never calls a logger of an instance that is gone.
    callbacks = fmi2CallbackFunctions()
    callbacks.logger = fmi2CallbackLoggerTYPE(lambda *args: None)
    callbacks.allocateMemory = fmi2CallbackAllocateMemoryTYPE(calloc)
    callbacks.freeMemory = fmi2CallbackFreeMemoryTYPE(free)
    addLoggerProxy(ctypes.byref(callbacks))
    fmu.instantiate(callbacks=callbacks)
    result = {}
    for n, (sequence, frame) in enumerate(cases(md)):
        fmu.reset()
        fmu.setInteger([vr["sequence"]], [sequence])
        if frame is not None:
            fmu.setInteger([vr["frame"]], [frame])
        fmu.enterInitializationMode()
        fmu.exitInitializationMode()
        values = np.full((STATES_PER_CASE, len(outputs)), np.nan)
        statuses = []
        for row, u in enumerate(states(1000 + n)):
            fmu.setReal(inputs, list(u))
            try:
                values[row] = fmu.getReal(outputs)
                statuses.append("ok")
            except Exception as e:  # fmi2Discard at a singular angle: record that it happened
                statuses.append(type(e).__name__)
        key = f"{sequence}" if frame is None else f"{sequence}/{frame}"
        result[key] = (values, statuses)
    fmu.terminate()
    fmu.freeInstance()
    shutil.rmtree(unzipdir, ignore_errors=True)
    return model, output_names, result


def digest(values, statuses):
    h = hashlib.sha256()
    for row, status in zip(values, statuses):
        y = row if status == "ok" else np.zeros(0)
        h.update(np.asarray(y, dtype="<f8").tobytes() + status.encode())
    return h.hexdigest()


def digests(fmu_path, output_names=None, binary=None):
    """(model identifier, the output names digested, {sequence[/frame]: digest}); output_names:
    the outputs to digest, in that order (default: every output of the FMU)."""
    model, names, result = outputs_over_states(fmu_path, output_names, binary)
    return model, names, {key: digest(*pair) for key, pair in result.items()}


def ulps_apart(a, b):
    """Distance in units in the last place between float64 arrays (0 where bit-identical)."""
    def ordered(x):
        i = np.asarray(x, dtype="<f8").view("<i8")
        return np.where(i < 0, np.int64(-(2**63)) - i, i)
    return np.abs(ordered(a) - ordered(b)).astype(float)


def compare(fmu_path, old_binary, output_names=None):
    """How the FMU's outputs differ from another build's (old_binary): per output name, the values
    compared, how many differ and the largest distance in ulp; and the cases whose digest moved."""
    model, names, new = outputs_over_states(fmu_path, output_names)
    _, _, old = outputs_over_states(fmu_path, names, old_binary)
    per_output = {name: [0, 0, 0.0] for name in names}
    moved = []
    for key in new:
        (a, sa), (b, sb) = new[key], old[key]
        assert sa == sb, f"{model} {key}: the refused states differ"
        if digest(a, sa) != digest(b, sb):
            moved.append(key)
        ok = np.array([s == "ok" for s in sa])
        d = ulps_apart(a[ok], b[ok])
        for j, name in enumerate(names):
            per_output[name][0] += int(ok.sum())
            per_output[name][1] += int((d[:, j] > 0).sum())
            per_output[name][2] = max(per_output[name][2], float(d[:, j].max(initial=0.0)))
    return model, per_output, moved, len(new)


# The models whose outputs are pure functions of the inputs (no states), recorded whole.
MODELS_RECORDED = ("AngularKinematics", "EulerRates")


def main():
    """record DIR_WITH_FMUS RECORD.json | compare DIR_WITH_FMUS DIR_WITH_OLD_BINARIES"""
    if len(sys.argv) != 4 or sys.argv[1] not in ("record", "compare"):
        sys.exit(__doc__)
    record = {}
    for name in MODELS_RECORDED:
        path = str(pathlib.Path(sys.argv[2]) / f"{name}.fmu")
        if sys.argv[1] == "compare":
            old = pathlib.Path(sys.argv[3]) / f"{name}.so"
            model, per_output, moved, cases_run = compare(path, str(old))
            print(f"{model}: {len(moved)} of {cases_run} case digests move")
            for output, (compared, differ, worst) in per_output.items():
                if differ:
                    print(f"  {output}: {differ} of {compared} values differ, at most {worst:.0f} ulp")
            continue
        every = [v.name for v in read_model_description(path).modelVariables
                 if v.causality == "output"]
        model, outputs, result = digests(path, every)
        record[model] = {"outputs": outputs, "digests": result}
    if sys.argv[1] == "record":
        pathlib.Path(sys.argv[3]).write_text(json.dumps(record, indent=1, sort_keys=True) + "\n")


if __name__ == "__main__":
    main()
