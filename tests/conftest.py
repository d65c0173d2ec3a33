"""Shared fixtures: the built FMU, its model description, and instances driven through fmpy with
their log messages captured."""
import ctypes
import json
import os
import pathlib
import subprocess
import sys

import numpy as np
import pytest
from fmpy import extract, read_model_description
from fmpy.fmi2 import (FMU2Slave, calloc, fmi2CallbackAllocateMemoryTYPE, fmi2CallbackFreeMemoryTYPE,
                       fmi2CallbackFunctions, fmi2CallbackLoggerTYPE, free)
from fmpy.logging import addLoggerProxy

ROOT = pathlib.Path(__file__).resolve().parent.parent
# AK_FMU: another build of the FMU to test (scripts/check_sanitizers.sh passes its ASan build).
FMU_PATH = pathlib.Path(os.environ.get("AK_FMU", ROOT / "dist" / "AngularKinematics.fmu"))
BUILD_DIR = ROOT / "build"
sys.path.insert(0, str(ROOT / "demo"))  # the demo's trajectories serve as test signals too

STATUS = {0: "OK", 1: "Warning", 2: "Discard", 3: "Error", 4: "Fatal", 5: "Pending"}
FIGURES = pytest.StashKey[list]()


def pytest_configure(config):
    config.stash[FIGURES] = []


def pytest_terminal_summary(terminalreporter, exitstatus, config):
    figures = config.stash[FIGURES]
    if figures:
        terminalreporter.section("measured figures")
        for line in figures:
            terminalreporter.write_line(line)


@pytest.fixture
def report(request):
    """Records a measured figure, printed at the end of the run."""
    def record(line):
        request.config.stash[FIGURES].append(f"{request.node.name}: {line}")
    return record


@pytest.fixture(scope="session")
def root():
    return ROOT


@pytest.fixture(scope="session")
def fmu_path():
    assert FMU_PATH.is_file(), f"{FMU_PATH} is missing: build it first (bash scripts/build.sh)"
    return str(FMU_PATH)


@pytest.fixture(scope="session")
def model_description(fmu_path):
    return read_model_description(fmu_path)


@pytest.fixture(scope="session")
def unzipdir(fmu_path, tmp_path_factory):
    return extract(fmu_path, unzipdir=str(tmp_path_factory.mktemp("fmu")))


@pytest.fixture(scope="session")
def c_table():
    """The variable table the binary is built from, printed by the model_info tool."""
    tool = BUILD_DIR / "model_info"
    assert tool.is_file(), f"{tool} is missing: build it first (bash scripts/build.sh)"
    return json.loads(subprocess.run([str(tool)], check=True, capture_output=True, text=True).stdout)


class Instance:
    """One FMU instance, created through fmpy's FMU2Slave with a logger that keeps every message.

    ``call`` invokes an FMI function and returns its status without raising, so that tests can
    check the status of calls that are meant to fail."""

    def __init__(self, unzipdir, model_description, name="instance", logging_on=False):
        self.model_description = model_description
        self.vr = {v.name: v.valueReference for v in model_description.modelVariables}
        self.messages = []  # (status name, category, message)
        self.callbacks = fmi2CallbackFunctions()
        self._logger = fmi2CallbackLoggerTYPE(self._log)
        self.callbacks.logger = self._logger
        self.callbacks.allocateMemory = fmi2CallbackAllocateMemoryTYPE(calloc)
        self.callbacks.freeMemory = fmi2CallbackFreeMemoryTYPE(free)
        addLoggerProxy(ctypes.byref(self.callbacks))
        self.fmu = FMU2Slave(guid=model_description.guid, unzipDirectory=unzipdir,
                             modelIdentifier=model_description.coSimulation.modelIdentifier,
                             instanceName=name)
        self.fmu.instantiate(callbacks=self.callbacks, loggingOn=logging_on)
        self.component = self.fmu.component

    def _log(self, env, instance_name, status, category, message):
        self.messages.append((STATUS.get(status, str(status)), category.decode(), message.decode()))

    def call(self, function, *args):
        """The raw status of an FMI function called on this instance."""
        return self.fmu._functions[function](self.component, *args)

    def errors(self):
        return [m for s, c, m in self.messages if s == "Error"]

    def set(self, values):
        """fmi2SetReal by variable name; returns the status."""
        names = list(values)
        vr = (ctypes.c_uint * len(names))(*[self.vr[n] for n in names])
        array = (ctypes.c_double * len(names))(*[values[n] for n in names])
        return self.call("fmi2SetReal", vr, len(names), array)

    def get(self, names):
        """fmi2GetReal by variable name; returns the values as a numpy array (raises on error)."""
        return np.array(self.fmu.getReal([self.vr[n] for n in names]))

    def initialize(self, start_time=0.0, stop_time=None, inputs=None):
        self.fmu.setupExperiment(startTime=start_time, stopTime=stop_time)
        self.fmu.enterInitializationMode()
        if inputs:
            assert self.set(inputs) == 0
        self.fmu.exitInitializationMode()

    def free(self):
        if self.component is not None:
            self.fmu.freeInstance()
            self.component = None


@pytest.fixture
def make_instance(unzipdir, model_description):
    """Creates instances, all freed at the end of the test."""
    created = []

    def make(name="instance", logging_on=False):
        instance = Instance(unzipdir, model_description, name=name, logging_on=logging_on)
        created.append(instance)
        return instance

    yield make
    for instance in created:
        instance.free()
