"""Outputs of the FMUs over seeded random states, as SHA-256 digests per sequence (and frame):
the record that proves a rebuilt FMU computes bit for bit what the released one did.

    .venv/bin/python tests/python/golden_outputs.py record DIR_WITH_FMUS tests/python/data/golden_0.2.json

The record holds, per model, the names of the outputs the recorded FMU had ("outputs", in
value-reference order) and the digests of those outputs ("digests"). test_bit_identity.py
recomputes the digests of the same outputs with the FMUs of dist/ and compares: an output added
since does not enter them."""
import hashlib
import json
import sys

import numpy as np
from fmpy import extract, read_model_description
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


def digests(fmu_path, output_names=None):
    """(model identifier, the output names digested, {sequence[/frame]: digest}); output_names:
    the outputs to digest, in that order (default: every output of the FMU)."""
    md = read_model_description(fmu_path)
    model = md.coSimulation.modelIdentifier
    vr = {v.name: v.valueReference for v in md.modelVariables}
    inputs = [v.valueReference for v in md.modelVariables if v.causality == "input"]
    if output_names is None:
        output_names = [v.name for v in md.modelVariables if v.causality == "output"]
    outputs = [vr[name] for name in output_names]
    unzipdir = extract(fmu_path)
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
        h = hashlib.sha256()
        for u in states(1000 + n):
            fmu.setReal(inputs, list(u))
            try:
                y = fmu.getReal(outputs)
                status = "ok"
            except Exception as e:  # fmi2Discard at a singular angle: record that it happened
                y, status = [], type(e).__name__
            h.update(np.asarray(y, dtype="<f8").tobytes() + status.encode())
        key = f"{sequence}" if frame is None else f"{sequence}/{frame}"
        result[key] = h.hexdigest()
    fmu.terminate()
    fmu.freeInstance()
    return model, output_names, result


# Outputs whose bits changed on purpose since 0.2, each recorded in CHANGELOG.md: left out of the
# digests (their accuracy is tested against the reference, test_sequences_fmu.py).
CHANGED_SINCE_0_2 = {
    "AngularKinematics": ["q[1]", "q[2]", "q[3]", "q[4]"],  # 0.3.0: q from the angles' sines
}


def main():
    if len(sys.argv) != 4 or sys.argv[1] != "record":
        sys.exit(__doc__)
    import pathlib
    record = {}
    for name in ("AngularKinematics", "EulerRates"):  # the models of 0.2
        path = str(pathlib.Path(sys.argv[2]) / f"{name}.fmu")
        every = [v.name for v in read_model_description(path).modelVariables
                 if v.causality == "output"]
        kept = [n for n in every if n not in CHANGED_SINCE_0_2.get(name, [])]
        model, outputs, result = digests(path, kept)
        record[model] = {"outputs": outputs, "left_out": [n for n in every if n not in kept],
                         "digests": result}
    pathlib.Path(sys.argv[3]).write_text(json.dumps(record, indent=1, sort_keys=True) + "\n")


if __name__ == "__main__":
    main()
