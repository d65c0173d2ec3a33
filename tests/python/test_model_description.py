"""Both modelDescription.xml files (AngularKinematics at the repository root, EulerRates in
fmu_src/models/EulerRates/): valid, packaged as they are, and in agreement with the C variable table
each binary is built from and with the dependency unions found on the sympy reference."""
import math
import re
import zipfile

import pytest
from fmpy.validation import validate_fmu

from conftest import ROOT, c_table_of
from reference import KINEMATICS_INPUTS, KINEMATICS_OUTPUTS, RATES_INPUTS, RATES_OUTPUTS
from codegen import project
from codegen.project import SEQUENCES, sequence_description

DISPLAY_UNITS = {"rad": "deg", "rad/s": "deg/s", "rad/s2": "deg/s2"}
MODELS = {
    "AngularKinematics": dict(
        xml=ROOT / "modelDescription.xml",
        names=KINEMATICS_INPUTS + KINEMATICS_OUTPUTS[:21] + [f"q[{k}]" for k in (1, 2, 3, 4)]
        + KINEMATICS_OUTPUTS[21:] + ["sequence"],
        parameters={"sequence": ("Integer", "1")},
        union_table="### AngularKinematics"),
    "EulerRates": dict(
        xml=ROOT / "fmu_src" / "models" / "EulerRates" / "modelDescription.xml",
        names=RATES_INPUTS + RATES_OUTPUTS + ["singularity_distance", "sequence", "frame",
                                              "tolerance"],
        parameters={"sequence": ("Integer", "1"), "frame": ("Integer", "1"),
                    "tolerance": ("Real", "0.0001")},
        union_table="### EulerRates (union over sequences and over the frame parameter)"),
}


@pytest.fixture(scope="module")
def model(model):
    """conftest's model (every model of codegen.project.MODELS), with its pins from MODELS."""
    assert model.name in MODELS, f"pin {model.name}'s names and parameters in MODELS"
    return dict(MODELS[model.name], name=model.name, fmu=model.fmu_path,
                description=model.description, table=model.c_table)


def test_every_model_is_pinned():
    assert list(MODELS) == project.MODELS


def test_fmpy_validation_finds_no_problem(model):
    assert validate_fmu(model["fmu"]) == []


def test_fmu_archive_holds_description_binaries_documentation_sources(model, root):
    name = model["name"]
    with zipfile.ZipFile(model["fmu"]) as archive:
        names = set(archive.namelist())
        packaged = archive.read("modelDescription.xml")
        icon = archive.read("model.png")
    assert {"modelDescription.xml", "model.png", f"binaries/linux64/{name}.so",
            f"binaries/win64/{name}.dll", "documentation/index.html",
            "sources/buildDescription.xml"} <= names
    listed = (root / "build" / f"fmu_sources_{name}.txt").read_text().split()
    assert {n for n in names if n.startswith("sources/") and n.endswith(".c")} == \
        {f"sources/{c}" for c in listed}
    assert f"{name}_variables.c" in listed and "model.c" in listed
    for other in set(project.MODELS) - {name}:
        assert not any(other in n for n in names), f"{name}.fmu ships a file of {other}"
    assert icon == (root / "model.png").read_bytes()
    assert packaged == model["xml"].read_bytes(), "the packaged modelDescription.xml is not the repository's"


def test_identity_agrees_with_c_table(model):
    description, table = model["description"], model["table"]
    assert description.guid == table["guid"]
    assert description.coSimulation.modelIdentifier == table["modelIdentifier"] == model["name"]
    assert description.modelExchange.modelIdentifier == model["name"]
    assert description.fmiVersion == "2.0"
    assert description.variableNamingConvention == "structured"


def test_the_models_have_distinct_guids():
    guids = [c_table_of(name)["guid"] for name in project.MODELS]
    assert len(set(guids)) == len(guids)


def test_variables_agree_with_c_table(model):
    xml = {v.valueReference: v for v in model["description"].modelVariables}
    table = {v["valueReference"]: v for v in model["table"]["variables"]}
    assert sorted(xml) == sorted(table) == list(range(len(table)))
    for vr, row in table.items():
        variable = xml[vr]
        assert variable.name == row["name"]
        assert variable.causality == row["causality"]
        assert variable.type == ("Enumeration" if row["type"] == "Integer" else "Real")
        assert variable.variability == ("fixed" if row["causality"] == "parameter" else "continuous")
        assert variable.declaredType.name == row["declaredType"]
        assert (variable.unit or variable.declaredType.unit or "") == row["unit"]
        assert variable.description == row["description"]
        if row["causality"] == "output":
            assert variable.start is None
        else:
            assert float(variable.start) == row["start"]
        if row["causality"] == "parameter" and row["type"] == "Real":
            assert (float(variable.min), float(variable.max)) == (row["min"], row["max"])


def test_names_units_and_display_units(model):
    description = model["description"]
    assert [v.name for v in description.modelVariables] == model["names"]
    units = {u.name: [d.name for d in u.displayUnits] for u in description.unitDefinitions}
    for variable in description.modelVariables:
        unit = variable.declaredType.unit
        if variable.declaredType.name in ("Angle", "AngularVelocity", "AngularAcceleration"):
            assert variable.declaredType.displayUnit == DISPLAY_UNITS[unit]
            assert units[unit] == [DISPLAY_UNITS[unit]]
    for unit in description.unitDefinitions:
        if unit.name in DISPLAY_UNITS:
            assert unit.displayUnits[0].factor == math.degrees(1.0)
            assert unit.baseUnit.rad == 1
            assert unit.baseUnit.s == {"rad": 0, "rad/s": -1, "rad/s2": -2}[unit.name]


def test_parameters_and_enumerations(model):
    variables = {v.name: v for v in model["description"].modelVariables}
    for name, (kind, start) in model["parameters"].items():
        variable = variables[name]
        assert variable.causality == "parameter" and variable.variability == "fixed"
        assert variable.start == start
        assert variable.type == ("Enumeration" if kind == "Integer" else "Real")
    sequence = variables["sequence"].declaredType
    assert [(i.name, int(i.value), i.description) for i in sequence.items] == \
        [(name, k + 1, sequence_description(name)) for k, name in enumerate(SEQUENCES)]
    if model["name"] == "EulerRates":
        assert [(i.name, int(i.value)) for i in variables["frame"].declaredType.items] == \
            [("fixed", 1), ("body", 2)]


def test_model_structure_is_the_c_table_dependencies(model):
    description = model["description"]
    table = {v["name"]: sorted(v["dependencies"]) for v in model["table"]["variables"]
             if v["causality"] == "output"}
    for section in (description.outputs, description.initialUnknowns):
        listed = {u.variable.name: sorted(d.valueReference for d in u.dependencies) for u in section}
        assert listed == table
    assert [u.variable for u in description.outputs] == [v for v in description.modelVariables
                                                         if v.causality == "output"]


def documented_unions(heading):
    """{output: set of inputs} of a union table of docs/sequences.md (made from the sympy reference
    by tests/python/sequence_dependencies.py)."""
    text = (ROOT / "docs" / "sequences.md").read_text()
    section = text[text.index(heading):].split("\n\n")[1]
    unions = {}
    for line in section.splitlines()[2:]:
        cells = [c.strip() for c in line.strip("|").split("|")]
        unions[cells[0]] = set(re.findall(r"[a-z_]+\[\d\]", cells[1]))
    return unions


def test_model_structure_is_the_reference_union(model):
    """The union over the sequences (and frames) of the reference's dependencies: a fixed parameter
    selects the sequence, so <ModelStructure> lists what some value of it needs; q depends on the
    three angles and singularity_distance on theta[2] alone, for every sequence."""
    expected = documented_unions(model["union_table"])
    expected.update({f"q[{k}]": {"theta[1]", "theta[2]", "theta[3]"} for k in (1, 2, 3, 4)})
    expected["singularity_distance"] = {"theta[2]"}
    for unknown in model["description"].outputs:
        assert {d.name for d in unknown.dependencies} == expected[unknown.variable.name], \
            unknown.variable.name


def test_default_experiment(model):
    experiment = model["description"].defaultExperiment
    assert float(experiment.stopTime) > float(experiment.startTime)
    assert float(experiment.stepSize) > 0


def test_capability_flags(model):
    """Each flag is claimed because a test shows it works (docs/capabilities.md lists them)."""
    description = model["description"]
    full = model["name"] == "AngularKinematics"
    cs = description.coSimulation
    assert cs.canHandleVariableCommunicationStepSize is True  # test_variable_steps.py, test_euler_rates.py
    assert cs.canBeInstantiatedOnlyOncePerProcess is False  # test_fmi_calls.py (two instances)
    assert cs.canInterpolateInputs is True  # test_input_interpolation.py, test_euler_rates.py
    # AngularKinematics: test_output_derivatives.py, test_sequences_fmu.py; EulerRates: none
    assert cs.maxOutputDerivativeOrder == (1 if full else 0)
    assert cs.canRunAsynchronuously is False  # test_fmi_calls.py (fmi2CancelStep refused)
    me = description.modelExchange
    assert me is not None  # test_model_exchange.py, test_euler_rates.py
    assert me.needsCompletedIntegratorStep is False
    assert description.numberOfContinuousStates == 0
    assert description.numberOfEventIndicators == 0
    assert description.derivatives == []
    for interface in (cs, me):
        assert interface.canGetAndSetFMUstate is True  # test_fmu_state.py, test_euler_rates.py
        assert interface.canSerializeFMUstate is True
        # AngularKinematics: test_directional_derivatives.py, test_sequences_fmu.py; EulerRates: none
        assert interface.providesDirectionalDerivative is full
        assert interface.canBeInstantiatedOnlyOncePerProcess is False
        assert interface.canNotUseMemoryManagementFunctions is False


def test_log_categories(model):
    assert [c.name for c in model["description"].logCategories] == [
        "logStatusError", "logStatusWarning", "logCalls"]
