"""The FMI 3.0 FMUs as files: fmpy validates them with no message; their variables are the
arrays of the model descriptions with the FMI 2 names (no element suffix), value references
(the first element's), units and display units; sequence is a fixed Enumeration parameter;
<ModelStructure> lists every output (and state derivative: AttitudePropagator's der(q), a local
with derivative= its state q) with the union of its elements' FMI 2 dependencies, and as initial
unknowns with a state replaced by the parameters its start comes from (q by q0); the FMU
holds the three platforms' binaries, sources/ that fmpy compiles (linked with the libm its
buildDescription.xml names) into a binary that needs libm and computes the same bits,
documentation/index.html without outside links and terminalsAndIcons/icon.png."""
import math
import pathlib
import re
import shutil
import xml.etree.ElementTree as ET
import zipfile

import numpy as np
import pytest
from fmpy import read_model_description, simulate_fmu
from fmpy.validation import validate_fmu

from codegen.generate import flat_fmi3_sources
from codegen.models import load
from conftest import description_path_of
from fmi3_support import MODELS, fmu3_path, unzipped
from source_build import build_from_sources, external_libraries, needed_libraries

FMI2_TYPES = {"Angle": ("rad", "deg"), "AngularVelocity": ("rad/s", "deg/s"),
              "AngularAcceleration": ("rad/s2", "deg/s2")}


@pytest.mark.parametrize("model", MODELS)
def test_fmpy_validates_with_no_message(model):
    assert validate_fmu(str(fmu3_path(model))) == []


@pytest.mark.parametrize("model", MODELS)
def test_variables_are_the_fmi2_arrays(model):
    md = read_model_description(str(fmu3_path(model)))
    assert md.fmiVersion == "3.0" and md.coSimulation and md.modelExchange
    m = load(model)
    assert md.guid == m.guid  # instantiationToken: one per model, the FMI 2 GUID
    by_name = {v.name: v for v in md.modelVariables}
    assert by_name["time"].causality == "independent"
    assert set(by_name) - {"time"} == {entry["name"] for entry in m.arrays}
    for entry in m.arrays:
        v = by_name[entry["name"]]
        first = [s for s in m.scalars if s.base == entry["name"]][0]
        assert v.valueReference == entry["vr"] == first.vr
        assert [int(d.start) for d in v.dimensions] == list(entry.get("shape", ()))
        assert v.causality == entry["causality"]
        if entry["type"] in FMI2_TYPES:
            unit, display = FMI2_TYPES[entry["type"]]
            assert v.declaredType.unit == unit and v.declaredType.displayUnit == display
            assert md.unitDefinitions
            found = {u.name: u for u in md.unitDefinitions}[unit]
            assert found.displayUnits[0].name == display
            assert found.displayUnits[0].factor == pytest.approx(180 / math.pi, rel=1e-15)
    if "sequence" in by_name:
        sequence = by_name["sequence"]
        assert (sequence.type, sequence.variability, sequence.start) == ("Enumeration", "fixed", "1")
        items = [item.name for item in sequence.declaredType.items]
        assert len(items) == 24 and items[0] == "body123" and items[-1] == "space323"


@pytest.mark.parametrize("model", MODELS)
def test_every_output_in_model_structure_with_exact_dependencies(model):
    md = read_model_description(str(fmu3_path(model)))
    m = load(model)
    owner = {s.vr: s.base for s in m.scalars}
    first_vr = {entry["name"]: entry["vr"] for entry in m.arrays}
    listed = {u.variable.name: u for u in md.outputs}
    outputs = [e["name"] for e in m.arrays if e["causality"] == "output"]
    assert sorted(listed) == sorted(outputs)
    for name in outputs:
        expected = sorted({first_vr[owner[d]] for s in m.scalars if s.base == name for d in s.depends})
        assert sorted(v.valueReference for v in listed[name].dependencies) == expected, name
        assert set(listed[name].dependenciesKind) == {"dependent"}
    derivatives = {e["name"]: e for e in m.arrays if "derivative_of" in e}
    assert sorted(u.variable.name for u in md.derivatives) == sorted(derivatives)
    for u in md.derivatives:
        state = derivatives[u.variable.name]["derivative_of"]
        assert u.variable.derivative.name == state and u.variable.causality == "local"
        expected = sorted({first_vr[owner[d]] for s in m.scalars if s.base == u.variable.name
                           for d in s.depends})
        assert sorted(v.valueReference for v in u.dependencies) == expected
    assert sorted(u.variable.name for u in md.initialUnknowns) == sorted(outputs + list(derivatives))
    by_vr = m.scalars_by_vr
    for u in md.initialUnknowns:
        expected = sorted({first_vr[owner[k]] for s in m.scalars if s.base == u.variable.name
                           for d in s.depends
                           for k in (by_vr[d].initial_depends if by_vr[d].state else [d])})
        assert sorted(v.valueReference for v in u.dependencies) == expected, u.variable.name
    if m.states:  # AttitudePropagator: q from q0 alone, der(q) from omega and q0
        initial = {u.variable.name: [v.name for v in u.dependencies] for u in md.initialUnknowns}
        assert initial["q"] == ["q0"] and initial["der(q)"] == ["omega", "q0"]


@pytest.mark.parametrize("model", MODELS)
def test_capability_flags(model):
    with zipfile.ZipFile(fmu3_path(model)) as z:
        root = ET.fromstring(z.read("modelDescription.xml"))
    jacobian = str(load(model).capabilities["provides_directional_derivative"]).lower()
    for interface in (root.find("CoSimulation"), root.find("ModelExchange")):
        assert interface.get("canGetAndSetFMUState") == "true"
        assert interface.get("canSerializeFMUState") == "true"
        assert interface.get("providesDirectionalDerivatives") == jacobian
        assert interface.get("providesAdjointDerivatives") == jacobian
        # the C table's per-element dependencies list inputs only: not declared with states
        per_element = "false" if load(model).states else "true"
        assert interface.get("providesPerElementDependencies") == per_element
    cs = root.find("CoSimulation")
    assert cs.get("canHandleVariableCommunicationStepSize") == "true"
    # what the model's FMI 2 FMU declares
    fmi2_cs = ET.parse(description_path_of(model)).getroot().find("CoSimulation")
    assert cs.get("maxOutputDerivativeOrder") == fmi2_cs.get("maxOutputDerivativeOrder")
    assert cs.get("hasEventMode") is None


@pytest.mark.external  # the other platforms' binaries come from the cross builds
@pytest.mark.parametrize("model", MODELS)
def test_fmu_contents(model):
    with zipfile.ZipFile(fmu3_path(model)) as z:
        names = set(z.namelist())
        html = z.read("documentation/index.html").decode()
        icon = z.read("terminalsAndIcons/icon.png")
    for binary in ("x86_64-linux/%s.so", "x86_64-windows/%s.dll", "aarch64-linux/%s.so",
                   "riscv64-linux/%s.so"):
        assert "binaries/" + binary % model in names
    assert "sources/buildDescription.xml" in names
    assert icon[:8] == b"\x89PNG\r\n\x1a\n"
    links = re.findall(r'(?:href|src)="([^"]*)"', html)
    assert all(not re.match(r"[a-z]+:", link) for link in links), links
    assert model in html
    assert not any(n.startswith("sources/fmi2") or n.startswith("sources/fmi3Function") for n in names)
    # the C files of its build description: the model's own core sources (its CORE), no other
    shipped = {n.split("/")[-1] for n in names if n.startswith("sources/") and n.endswith(".c")}
    assert shipped == set(flat_fmi3_sources(load(model)))


@pytest.mark.parametrize("model", MODELS)
def test_sources_compile_with_fmpy_and_compute_the_same_bits(model, tmp_path, report):
    unzipdir, _ = unzipped(model)
    copy = tmp_path / "fmu"
    shutil.copytree(unzipdir, copy)
    shutil.rmtree(copy / "binaries")
    assert external_libraries(copy) == ["m"]
    build_from_sources(copy, tmp_path)
    binary = pathlib.Path("binaries") / "x86_64-linux" / f"{model}.so"
    # what the packaged binary (linked with --no-undefined) needs: libm where that one calls it
    assert set(needed_libraries(pathlib.Path(unzipdir) / binary)) <= set(needed_libraries(copy / binary))
    inputs = [v for v in unzipped(model)[1].modelVariables if v.causality == "input"]

    def sized(values, variable):  # 3 elements, or 4 (a quaternion): the values repeated
        return np.resize(values, int(np.prod([int(d.start) for d in variable.dimensions]))).tolist()
    start = {inputs[0].name: sized([0.3, -0.4, 1.1], inputs[0]),
             inputs[1].name: sized([0.5, 0.25, -1.0], inputs[1])}
    if any(v.name == "sequence" for v in unzipped(model)[1].modelVariables):
        start["sequence"] = 7

    def simulate(fmu):
        return simulate_fmu(str(fmu), stop_time=0.1, output_interval=0.01, start_values=start)

    ours, rebuilt = simulate(fmu3_path(model)), simulate(copy)
    for name in ours.dtype.names:
        assert np.array_equal(ours[name], rebuilt[name]), name
    report(f"{model}: fmpy rebuilt the FMI 3 binary from sources/; {len(ours)} rows bit-identical")
