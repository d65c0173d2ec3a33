"""Shared fixtures: the built FMU, its model description, and instances driven through fmpy with
their log messages captured."""
import atexit
import ctypes
import functools
import json
import os
import pathlib
import shutil
import subprocess
import tempfile
import xml.etree.ElementTree as ET

import numpy as np
import pytest
from fmpy import extract, read_model_description
from fmpy.fmi2 import (FMU2Model, FMU2Slave, calloc, fmi2CallbackAllocateMemoryTYPE, fmi2CallbackFreeMemoryTYPE,
                       fmi2CallbackFunctions, fmi2CallbackLoggerTYPE, free)
from fmpy.logging import addLoggerProxy

ROOT = pathlib.Path(__file__).resolve().parents[2]
BUILD_DIR = ROOT / "build"

from codegen import models, project

# The sequences a quick run (pytest -m "not slow") checks: one body-fixed Tait-Bryan, one
# space-fixed proper Euler; the other 22 cases of each per-sequence test are marked slow.
QUICK_SEQUENCES = ("body123", "space313")


def sequence_cases():
    """codegen.project.SEQUENCES as pytest parameters, all but QUICK_SEQUENCES marked slow."""
    return [pytest.param(name, marks=() if name in QUICK_SEQUENCES else pytest.mark.slow)
            for name in project.SEQUENCES]


# AK_FMU_DIR: another build's folder of the FMI 2 FMUs to test, <Model>.fmu each
# (scripts/check_sanitizers.sh passes its ASan build's); dist/ by default.
FMU_DIR = pathlib.Path(os.environ.get("AK_FMU_DIR", ROOT / "dist"))


def description_path_of(model):
    """The model's modelDescription.xml in the repository (generated from its description.py)."""
    return models.load(model).model_description


@functools.lru_cache(maxsize=None)
def value_references_of(model):
    """{name: value reference} of every variable of the model, from its modelDescription.xml, so
    that a test stays true when a variable is added (it takes the next value reference)."""
    root = ET.parse(description_path_of(model)).getroot()
    return {v.get("name"): int(v.get("valueReference")) for v in root.iter("ScalarVariable")}


def fmu_state_size(model):
    """The size of a serialized FMU state (format version 2): a 92-byte header and CRC, 8 bytes per
    value reference (N) and 16 (two input derivatives) per input (I): 92 + 8 N + 16 I."""
    root = ET.parse(description_path_of(model)).getroot()
    variables = list(root.iter("ScalarVariable"))
    inputs = [v for v in variables if v.get("causality") == "input"]
    return 92 + 8 * len(variables) + 16 * len(inputs)


def fmu_path_of(model):
    return FMU_DIR / f"{model}.fmu"


FMU_PATH = fmu_path_of("AngularKinematics")
EULER_FMU_PATH = fmu_path_of("EulerRates")

STATUS = {0: "OK", 1: "Warning", 2: "Discard", 3: "Error", 4: "Fatal", 5: "Pending"}
FIGURE = "measured figure"
FIGURES = []  # gathered from the test reports: with pytest-xdist (-n) they come from the workers


def pytest_runtest_logreport(report):
    if report.when == "teardown":  # the last report of a test carries every recorded property
        FIGURES.extend(f"{report.nodeid}: {value}" for name, value in report.user_properties
                       if name == FIGURE)


def pytest_terminal_summary(terminalreporter, exitstatus, config):
    if FIGURES:
        terminalreporter.section("measured figures")
        for line in FIGURES:
            terminalreporter.write_line(line)


@pytest.fixture
def report(request):
    """Records a measured figure, printed at the end of the run."""
    def record(line):
        request.node.user_properties.append((FIGURE, line))
    return record


@pytest.fixture(scope="session")
def root():
    return ROOT


@pytest.fixture(scope="session")
def fmu_path():
    assert FMU_PATH.is_file(), f"{FMU_PATH} is missing: build it first (bash scripts/build.sh)"
    return str(FMU_PATH)


@functools.lru_cache(maxsize=None)
def fmu_files(model):
    """(unzipped folder, fmpy's model description) of the model's FMI 2 FMU, extracted once per
    test process: every FMI 2 instance of the model is made from them."""
    path = fmu_path_of(model)
    assert path.is_file(), f"{path} is missing: build it first (bash scripts/build.sh)"
    folder = tempfile.mkdtemp(prefix=f"{model}2_")
    atexit.register(shutil.rmtree, folder, ignore_errors=True)
    return extract(str(path), unzipdir=folder), read_model_description(str(path))


@pytest.fixture(scope="session")
def model_description(fmu_path):
    return fmu_files("AngularKinematics")[1]


@pytest.fixture(scope="session")
def unzipdir(fmu_path):
    return fmu_files("AngularKinematics")[0]


def c_table_of(model):
    """The variable table a model's binary is built from, printed by its model_info tool."""
    tool = BUILD_DIR / f"model_info_{model}"
    assert tool.is_file(), f"{tool} is missing: build it first (bash scripts/build.sh)"
    return json.loads(subprocess.run([str(tool)], check=True, capture_output=True, text=True).stdout)


def abuse_program(program, model):
    """build/<program>_<Model> (cmake/abuse_tests.cmake)."""
    return BUILD_DIR / f"{program}_{model}"


@functools.lru_cache(maxsize=None)
def bad_input_rows(model):
    """The bad-input table of the C code (tests/c/fmi2_bad_input_table.c and the model's
    fmu_src/models/<Model>/tests/bad_input_rows.c), the one authority for every bad-input message, as
    its driver proved and printed it: one dict per row with state, call, status and message
    (None: nothing logged)."""
    driver = abuse_program("test_fmi2_calls", model)
    assert driver.is_file(), f"{driver} is missing: build it first (bash scripts/build.sh)"
    run = subprocess.run([str(driver), "--table"], capture_output=True, text=True)
    assert run.returncode == 0, f"{driver.name} failed:\n{run.stdout}\n{run.stderr}"
    rows = []
    for line in run.stdout.splitlines()[2:]:  # after the header and the rule
        state, call, status, message = (cell.strip() for cell in line.strip("|").split(" | "))
        rows.append(dict(line=line, state=state, call=call.strip("`"), status=status,
                         message=None if message == "(nothing logged)" else message.strip("`")))
    return rows


@pytest.fixture(scope="session")
def c_table():
    return c_table_of("AngularKinematics")


# The inputs every bad-input and state-machine test starts from: the ones the C driver
# (tests/c/fmi2_test_instance.c) initializes every instance with, value references 0 to 23.
VALID_INPUTS = [0.3, -0.7, 1.1, 0.5, -1.5, 2.0, 3.0, -0.25, 0.8, 0.9, -1.2, 0.4,
                1.7, -0.6, 0.2, -0.35, 0.15, 0.05, 0.01, -0.02, 0.03, 0.0, 0.0, -9.81]


class Model:
    """One model as built: its FMU, fmpy's reading of its model description, the FMU unzipped and
    the C variable table (names by causality in value-reference order)."""

    def __init__(self, name):
        self.name = name
        self.fmu_path = str(fmu_path_of(name))
        self.unzipdir, self.description = fmu_files(name)
        self.c_table = c_table_of(name)
        variables = self.c_table["variables"]
        self.inputs = [v["name"] for v in variables if v["causality"] == "input"]
        self.outputs = [v["name"] for v in variables if v["causality"] == "output"]
        self.parameters = [v["name"] for v in variables if v["causality"] == "parameter"]
        self.valid_inputs = dict(zip(self.inputs, VALID_INPUTS))
        # What the shared tests start an instance with: sequence 11 where the model has one.
        self.start_parameters = {"sequence": 11} if "sequence" in self.parameters else {}
        self.largest_vr = max(v["valueReference"] for v in variables)

    def __repr__(self):
        return self.name


@pytest.fixture(scope="session", params=project.MODELS)
def model(request):
    """Each model of codegen.project.MODELS in turn, for the concerns every model shares."""
    return Model(request.param)


@pytest.fixture
def new_instance():
    """The one way a test gets an instance: new_instance(model, name=..., logging_on=...,
    fmi_type="CoSimulation" or "ModelExchange", fmi_version=2 or 3) gives an Instance (FMI 2,
    below) or an fmi3_support.Instance3 of the model, freed at the end of the test. The fixtures
    make_instance, make_euler_instance, make_model_instance and attitude_support's
    make_attitude_instance are it for one model."""
    created = []

    def make(model, name="instance", logging_on=False, fmi_type="CoSimulation", fmi_version=2):
        if fmi_version == 3:
            from fmi3_support import Instance3
            instance = Instance3(model, fmi_type=fmi_type, name=name, logging_on=logging_on)
        else:
            unzipdir, description = fmu_files(model)
            instance = Instance(unzipdir, description, name=name, logging_on=logging_on,
                                fmi_type=fmi_type)
        created.append(instance)
        return instance

    yield make
    for instance in created:
        instance.free()


@pytest.fixture(params=[2, 3], ids=["fmi2", "fmi3"])
def layer(request):
    """Each FMI layer in turn (fmi_layers.Layer), for the concerns both share."""
    from fmi_layers import Layer
    return Layer(request.param)


@pytest.fixture
def make_model_instance(model, new_instance):
    """FMI 2 instances of the `model` under test (new_instance)."""
    return functools.partial(new_instance, model.name)


@pytest.fixture(scope="session")
def euler_fmu_path():
    assert EULER_FMU_PATH.is_file(), f"{EULER_FMU_PATH} is missing: build it first (bash scripts/build.sh)"
    return str(EULER_FMU_PATH)


@pytest.fixture(scope="session")
def euler_model_description(euler_fmu_path):
    return fmu_files("EulerRates")[1]


@pytest.fixture(scope="session")
def euler_unzipdir(euler_fmu_path):
    return fmu_files("EulerRates")[0]


class Instance:
    """One FMU instance, created through fmpy's FMU2Slave (co-simulation) or FMU2Model (model
    exchange) with a logger that keeps every message.

    ``call`` invokes an FMI function and returns its status without raising, so that tests can
    check the status of calls that are meant to fail.

    fmpy's native logger proxy keeps one logger: the messages of every instance reach the most
    recently created instance's ``messages``. A test that checks messages creates the instance it
    checks last."""

    def __init__(self, unzipdir, model_description, name="instance", logging_on=False,
                 fmi_type="CoSimulation"):
        self.model_description = model_description
        self.vr = {v.name: v.valueReference for v in model_description.modelVariables}
        self.messages = []  # (status name, category, message)
        self.callbacks = fmi2CallbackFunctions()
        self._logger = fmi2CallbackLoggerTYPE(self._log)
        self.callbacks.logger = self._logger
        self.callbacks.allocateMemory = fmi2CallbackAllocateMemoryTYPE(calloc)
        self.callbacks.freeMemory = fmi2CallbackFreeMemoryTYPE(free)
        addLoggerProxy(ctypes.byref(self.callbacks))
        fmu_class, interface = ((FMU2Model, model_description.modelExchange)
                                if fmi_type == "ModelExchange"
                                else (FMU2Slave, model_description.coSimulation))
        self.fmu = fmu_class(guid=model_description.guid, unzipDirectory=unzipdir,
                             modelIdentifier=interface.modelIdentifier, instanceName=name)
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

    def set_integer(self, values):
        """fmi2SetInteger by variable name; returns the status."""
        names = list(values)
        vr = (ctypes.c_uint * len(names))(*[self.vr[n] for n in names])
        array = (ctypes.c_int * len(names))(*[values[n] for n in names])
        return self.call("fmi2SetInteger", vr, len(names), array)

    def get_integer(self, names):
        return list(self.fmu.getInteger([self.vr[n] for n in names]))

    def get(self, names):
        """fmi2GetReal by variable name; returns the values as a numpy array (raises on error)."""
        return np.array(self.fmu.getReal([self.vr[n] for n in names]))

    def initialize(self, start_time=0.0, stop_time=None, inputs=None, parameters=None):
        """parameters: {name: value}, Integer ones (Enumerations) set with fmi2SetInteger."""
        self.fmu.setupExperiment(startTime=start_time, stopTime=stop_time)
        self.fmu.enterInitializationMode()
        types = {v.name: v.type for v in self.model_description.modelVariables}
        for name, value in (parameters or {}).items():
            if types[name] == "Real":
                assert self.set({name: value}) == 0
            else:
                assert self.set_integer({name: value}) == 0
        if inputs:
            assert self.set(inputs) == 0
        self.fmu.exitInitializationMode()

    def snapshot(self):
        """What a refused call must leave as it was: the serialized FMU state and the bits of
        every variable read through fmi2GetReal and fmi2GetInteger, with their statuses (an
        illegal get in the instance's state answers fmi2Error: its message is not kept)."""
        n_messages = len(self.messages)
        variables = self.model_description.modelVariables
        reals = [v.valueReference for v in variables if v.type == "Real"]
        integers = [v.valueReference for v in variables if v.type != "Real"]
        real_values = (ctypes.c_double * len(reals))()
        real_status = self.call("fmi2GetReal", (ctypes.c_uint * len(reals))(*reals), len(reals),
                                real_values)
        int_values = (ctypes.c_int * max(len(integers), 1))()
        int_status = self.call("fmi2GetInteger", (ctypes.c_uint * max(len(integers), 1))(*integers),
                               len(integers), int_values)
        from fmi_layers import Layer
        image = Layer(2).state_image(self)
        del self.messages[n_messages:]
        bits = np.array(real_values[:], dtype=float).view(np.uint64).tolist()
        return real_status, bits, int_status, list(int_values), image

    def free(self):
        if self.component is not None:
            self.fmu.freeInstance()
            self.component = None


@pytest.fixture
def make_instance(new_instance):
    """FMI 2 instances of AngularKinematics (new_instance)."""
    return functools.partial(new_instance, "AngularKinematics")


@pytest.fixture
def make_euler_instance(new_instance):
    """FMI 2 instances of EulerRates (new_instance)."""
    return functools.partial(new_instance, "EulerRates")
