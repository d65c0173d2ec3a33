"""modelDescription.xml: valid, and in agreement with the C variable table it is built with."""
import math
import zipfile

import reference
from fmpy.validation import validate_fmu

DISPLAY_UNITS = {"rad": "deg", "rad/s": "deg/s", "rad/s2": "deg/s2"}


def test_fmpy_validation_finds_no_problem(fmu_path):
    assert validate_fmu(fmu_path) == []


def test_fmu_archive_holds_description_binary_and_documentation(fmu_path, root):
    with zipfile.ZipFile(fmu_path) as archive:
        names = set(archive.namelist())
        packaged = archive.read("modelDescription.xml")
    assert {"modelDescription.xml", "model.png", "binaries/linux64/AngularKinematics.so",
            "binaries/win64/AngularKinematics.dll", "documentation/index.html",
            "sources/buildDescription.xml"} <= names
    assert {n for n in names if n.startswith("sources/") and n.endswith(".c")} == \
        {f"sources/{p.name}" for p in (root / "fmu_src").glob("*.c")}
    with zipfile.ZipFile(fmu_path) as archive:
        assert archive.read("model.png") == (root / "model.png").read_bytes()
    assert packaged == (root / "modelDescription.xml").read_bytes(), \
        "the packaged modelDescription.xml is not the repository's"


def test_identity_agrees_with_c_table(model_description, c_table):
    assert model_description.guid == c_table["guid"]
    assert model_description.coSimulation.modelIdentifier == c_table["modelIdentifier"]
    assert model_description.fmiVersion == "2.0"
    assert model_description.variableNamingConvention == "structured"


def test_variables_agree_with_c_table(model_description, c_table):
    xml = {v.valueReference: v for v in model_description.modelVariables}
    table = {v["valueReference"]: v for v in c_table["variables"]}
    assert sorted(xml) == sorted(table)
    for vr, row in table.items():
        variable = xml[vr]
        assert variable.name == row["name"]
        assert variable.causality == row["causality"]
        assert variable.type == "Real"
        assert variable.variability == "continuous"
        assert variable.declaredType.name == row["declaredType"]
        assert variable.unit == row["unit"] or variable.declaredType.unit == row["unit"]
        assert variable.description == row["description"]
        if row["causality"] == "input":
            assert float(variable.start) == row["start"]
        else:
            assert variable.start is None


def test_interface_names_units_and_display_units(model_description):
    names = [v.name for v in model_description.modelVariables]
    assert names == reference.INPUT_NAMES + reference.OUTPUT_NAMES
    units = {u.name: [d.name for d in u.displayUnits] for u in model_description.unitDefinitions}
    for variable in model_description.modelVariables:
        unit = variable.declaredType.unit
        assert unit in DISPLAY_UNITS
        assert variable.declaredType.displayUnit == DISPLAY_UNITS[unit]
        assert units[unit] == [DISPLAY_UNITS[unit]]
    for unit in model_description.unitDefinitions:
        assert unit.displayUnits[0].factor == math.degrees(1.0)
        assert unit.baseUnit.rad == 1
        assert unit.baseUnit.s == {"rad": 0, "rad/s": -1, "rad/s2": -2}[unit.name]


def test_model_structure_is_the_c_table_dependencies(model_description, c_table):
    variables = model_description.modelVariables
    table = {v["name"]: sorted(v["dependencies"]) for v in c_table["variables"]
             if v["causality"] == "output"}
    for section in (model_description.outputs, model_description.initialUnknowns):
        listed = {u.variable.name: sorted(d.valueReference for d in u.dependencies) for u in section}
        assert listed == table
    assert [u.variable for u in model_description.outputs] == [v for v in variables
                                                             if v.causality == "output"]


def test_model_structure_is_exactly_the_reference_dependencies(model_description):
    """No false dependency (a false algebraic loop for importers) and none missing."""
    expected = reference.output_dependencies()
    for unknown in model_description.outputs:
        assert {d.name for d in unknown.dependencies} == expected[unknown.variable.name]


def test_default_experiment(model_description):
    experiment = model_description.defaultExperiment
    assert experiment is not None
    assert float(experiment.stopTime) > float(experiment.startTime)
    assert float(experiment.stepSize) > 0


def test_capability_flags(model_description):
    """Each flag is claimed because a test shows it works (docs/capabilities.md lists them)."""
    cs = model_description.coSimulation
    assert cs.canHandleVariableCommunicationStepSize is True  # test_variable_steps.py
    assert cs.canBeInstantiatedOnlyOncePerProcess is False  # test_fmi_calls.py (two instances)
    assert cs.canInterpolateInputs is True  # test_input_interpolation.py
    assert cs.maxOutputDerivativeOrder == 1  # test_output_derivatives.py
    assert cs.canRunAsynchronuously is False  # test_fmi_calls.py (fmi2CancelStep refused)
    me = model_description.modelExchange
    assert me is not None  # test_model_exchange.py
    assert me.modelIdentifier == cs.modelIdentifier
    assert me.needsCompletedIntegratorStep is False
    assert model_description.numberOfContinuousStates == 0
    assert model_description.numberOfEventIndicators == 0
    assert model_description.derivatives == []
    for interface in (cs, me):
        assert interface.canGetAndSetFMUstate is True  # test_fmu_state.py
        assert interface.canSerializeFMUstate is True  # test_fmu_state.py
        assert interface.providesDirectionalDerivative is True  # test_directional_derivatives.py
        assert interface.canBeInstantiatedOnlyOncePerProcess is False
        assert interface.canNotUseMemoryManagementFunctions is False


def test_log_categories(model_description):
    assert [c.name for c in model_description.logCategories] == [
        "logStatusError", "logStatusWarning", "logCalls"]
