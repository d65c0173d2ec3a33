"""FMI 3 instances driven through fmpy 0.3.32 (FMU3Slave, FMU3Model), keeping their log messages.

fmpy's FMI 3 wrappers size some buffers per value reference, not per array element
(getOutputDerivatives, and getFloat64/getDirectionalDerivative/getAdjointDerivative when nValues
or nSensitivity is not given): this module passes nValues explicitly to getFloat64 and calls the
raw functions (fmu._functions[...]) for output, directional and adjoint derivatives and for every
call whose status a test checks (fmpy raises on fmi3Error)."""
import atexit
import ctypes
import os
import pathlib
import shutil
import tempfile

import numpy as np
from fmpy import extract, read_model_description
from fmpy.fmi3 import FMU3Model, FMU3Slave

from codegen import project
from fmi_layers import Layer

ROOT = pathlib.Path(__file__).resolve().parents[2]
STATUS = {0: "OK", 1: "Warning", 2: "Discard", 3: "Error", 4: "Fatal"}
OK, WARNING, DISCARD, ERROR = 0, 1, 2, 3
MODELS = project.FMI3_MODELS
_unzipped = {}


def fmu3_path(model):
    """dist/fmi3/<model>.fmu, or AK_FMU3_DIR/<model>.fmu (e.g. a sanitizer build's)."""
    folder = pathlib.Path(os.environ.get("AK_FMU3_DIR", ROOT / "dist" / "fmi3"))
    path = folder / f"{model}.fmu"
    assert path.is_file(), f"{path} is missing: build it first (bash scripts/build.sh)"
    return path


def unzipped(model):
    if model not in _unzipped:
        path = fmu3_path(model)
        folder = tempfile.mkdtemp(prefix=f"{model}3_")
        atexit.register(shutil.rmtree, folder, ignore_errors=True)
        _unzipped[model] = (extract(str(path), unzipdir=folder), read_model_description(str(path)))
    return _unzipped[model]


def doubles(values):
    values = list(values)
    return (ctypes.c_double * max(len(values), 1))(*values)


def vrs(values):
    values = list(values)
    return (ctypes.c_uint32 * max(len(values), 1))(*values)


class Instance3:
    """One FMI 3 instance; `call` returns the raw status of any FMI 3 function."""

    def __init__(self, model, fmi_type="CoSimulation", name="instance", logging_on=False):
        self.model = model
        unzipdir, md = unzipped(model)
        self.md = md
        self.variables = {v.name: v for v in md.modelVariables}
        self.vr = {v.name: v.valueReference for v in md.modelVariables}
        self.size = {v.name: int(np.prod([int(d.start) for d in v.dimensions])) if v.dimensions
                     else 1 for v in md.modelVariables}
        self.messages = []
        cls, interface = ((FMU3Model, md.modelExchange) if fmi_type == "ModelExchange"
                          else (FMU3Slave, md.coSimulation))
        self.fmu = cls(guid=md.guid, unzipDirectory=unzipdir,
                       modelIdentifier=interface.modelIdentifier, instanceName=name)
        self.fmu.instantiate(loggingOn=logging_on, logMessage=self._log)
        self.component = self.fmu.component

    def _log(self, env, status, category, message):
        self.messages.append((STATUS.get(status, str(status)), category.decode(), message.decode()))

    def call(self, function, *args):
        return self.fmu._functions[function](self.component, *args)

    def errors(self):
        return [m for s, c, m in self.messages if s == "Error"]

    def set(self, values):
        """fmi3SetFloat64 of whole arrays by name ({name: sequence}); returns the status."""
        names = list(values)
        flat = np.concatenate([np.ravel(np.asarray(values[n], dtype=float)) for n in names])
        return self.call("fmi3SetFloat64", vrs(self.vr[n] for n in names), len(names),
                         doubles(flat), len(flat))

    def set_int(self, values):
        names = list(values)
        array = (ctypes.c_int64 * len(names))(*[values[n] for n in names])
        return self.call("fmi3SetInt64", vrs(self.vr[n] for n in names), len(names), array,
                         len(names))

    def get_raw(self, names):
        """(status, {name: flat numpy array}) of one fmi3GetFloat64 call."""
        n = sum(self.size[name] for name in names)
        out = (ctypes.c_double * max(n, 1))()
        status = self.call("fmi3GetFloat64", vrs(self.vr[name] for name in names), len(names),
                           out, n)
        values, k = {}, 0
        for name in names:
            values[name] = np.array(out[k:k + self.size[name]])
            k += self.size[name]
        return status, values

    def get(self, names):
        status, values = self.get_raw(names)
        assert status in (OK, WARNING), (status, self.messages[-3:])
        return values

    def initialize(self, parameters=None, inputs=None, start_time=0.0, stop_time=None):
        """parameters: {name: value}; Enumerations through fmi3SetInt64."""
        stop = stop_time is not None
        assert self.call("fmi3EnterInitializationMode", False, 0.0, start_time, stop,
                         stop_time or 0.0) == OK
        for name, value in (parameters or {}).items():
            if self.variables[name].type == "Enumeration":
                assert self.set_int({name: value}) == OK
            else:
                assert self.set({name: [value]}) == OK
        if inputs:
            assert self.set(inputs) == OK
        assert self.call("fmi3ExitInitializationMode") == OK

    def do_step(self, t, h):
        """(status, lastSuccessfulTime) of fmi3DoStep."""
        flags = [ctypes.c_bool() for _ in range(3)]
        last = ctypes.c_double()
        status = self.call("fmi3DoStep", ctypes.c_double(t), ctypes.c_double(h), True,
                           *[ctypes.byref(f) for f in flags], ctypes.byref(last))
        return status, last.value

    def snapshot(self):
        """What a refused call must leave as it was: the bits of every variable read through
        fmi3GetFloat64 and fmi3GetInt64 (with the statuses), and the serialized FMU state."""
        n_messages = len(self.messages)
        floats = [n for n, v in self.variables.items() if v.type == "Float64"]
        status, values = self.get_raw(floats)
        bits = np.concatenate([values[n] for n in floats]).view(np.uint64).tolist()
        enums = [n for n, v in self.variables.items() if v.type == "Enumeration"]
        ints = (ctypes.c_int64 * max(len(enums), 1))()
        int_status = self.call("fmi3GetInt64", vrs(self.vr[n] for n in enums), len(enums), ints,
                               len(enums))
        image = Layer(3).state_image(self)
        del self.messages[n_messages:]
        return status, bits, int_status, list(ints), image

    def free(self):
        if self.component is not None:
            self.fmu.freeInstance()
            self.component = None

    def outputs(self):
        return [v.name for v in self.md.modelVariables if v.causality == "output"]

    def inputs(self):
        return [v.name for v in self.md.modelVariables if v.causality == "input"]
