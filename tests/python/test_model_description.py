"""Every modelDescription.xml (fmu_src/models/<Model>/, and the repository root's copy of
AngularKinematics'): valid, packaged as they are, and in agreement with the C variable table
each binary is built from and with the dependency unions found on the sympy reference."""
import math
import re
import zipfile

import pytest
from fmpy import read_model_description
from fmpy.validation import validate_fmu

from conftest import ROOT, c_table_of
from codegen.reference import KINEMATICS_INPUTS, KINEMATICS_OUTPUTS, RATES_INPUTS, RATES_OUTPUTS
from codegen import project
from codegen.models import load, model_description_path
from codegen.project import SEQUENCES, sequence_description

CORE_NAMES = {path.split("/")[-1] for path in project.CORE_SOURCES}
DISPLAY_UNITS = {"rad": "deg", "rad/s": "deg/s", "rad/s2": "deg/s2"}
# The interface of every released model, written here apart from its description so that a change
# of a name, a value reference's place or a parameter is seen. A model not yet released has no pin
# and these tests skip it; its release pins it (docs/contributing.md).
MODELS = {
    "AngularKinematics": dict(
        names=KINEMATICS_INPUTS + KINEMATICS_OUTPUTS[:21] + [f"q[{k}]" for k in (1, 2, 3, 4)]
        + KINEMATICS_OUTPUTS[21:] + ["sequence"],
        parameters={"sequence": ("Integer", "1")},
        union_table="### AngularKinematics", states=0, output_derivative_order=1, directional=True),
    "EulerRates": dict(
        names=RATES_INPUTS + RATES_OUTPUTS + ["singularity_distance", "sequence", "frame",
                                              "tolerance"],
        parameters={"sequence": ("Integer", "1"), "frame": ("Integer", "1"),
                    "tolerance": ("Real", "0.0001")},
        union_table="### EulerRates (union over sequences and over the frame parameter)",
        states=0, output_derivative_order=0, directional=False),
    "AttitudePropagator": dict(
        names=[f"{name}[{k}]" for name in ("omega", "omega_dot") for k in (1, 2, 3)]
        + [f"q[{k}]" for k in (1, 2, 3, 4)] + [f"der(q[{k}])" for k in (1, 2, 3, 4)]
        + [f"R[{i},{j}]" for i in (1, 2, 3) for j in (1, 2, 3)]
        + [f"{name}[{k}]" for name in ("theta", "theta_dot", "omega_fixed", "omega_body", "alpha_fixed",
                                       "alpha_body") for k in (1, 2, 3)]
        + ["singularity_distance", "frame", "sequence"] + [f"q0[{k}]" for k in (1, 2, 3, 4)]
        + [f"{name}[{k}]" for name in ("omega_previous", "omega_dot_previous") for k in (1, 2, 3)]
        + ["h_previous"] + [f"first_step_vector[{k}]" for k in (1, 2, 3)] + ["first_step_pending"],
        parameters={"frame": ("Integer", "2"), "sequence": ("Integer", "1"), "q0[1]": ("Real", "1.0"),
                    "q0[2]": ("Real", "0.0"), "q0[3]": ("Real", "0.0"), "q0[4]": ("Real", "0.0")},
        union_table=None, states=4, output_derivative_order=0, directional=True),
}


@pytest.fixture(scope="module")
def model(model):
    """conftest's model (every model of codegen.project.MODELS), with its pins from MODELS."""
    if model.name not in MODELS:
        pytest.skip(f"{model.name} is not released yet: no pinned interface")
    return dict(MODELS[model.name], name=model.name, fmu=model.fmu_path,
                xml=model_description_path(model.name),
                description=model.description, table=model.c_table)


def test_every_pinned_model_is_built():
    """No released model left the model list, in its order."""
    assert [m for m in project.MODELS if m in MODELS] == list(MODELS)


def test_fmpy_validation_finds_no_problem(model):
    assert validate_fmu(model["fmu"]) == []


def test_fmu_archive_holds_description_binaries_documentation_sources(model, root):
    name = model["name"]
    with zipfile.ZipFile(model["fmu"]) as archive:
        names = set(archive.namelist())
        packaged = archive.read("modelDescription.xml")
        icon = archive.read("model.png")
    assert {"modelDescription.xml", "model.png", f"binaries/linux64/{name}.so",
            f"binaries/win64/{name}.dll", f"binaries/win32/{name}.dll",
            f"binaries/darwin64/{name}.dylib", "documentation/index.html",
            "sources/buildDescription.xml"} <= names
    listed = (root / "build" / f"fmu_sources_{name}.txt").read_text().split()
    assert {n for n in names if n.startswith("sources/") and n.endswith(".c")} == \
        {f"sources/{c}" for c in listed}
    assert f"{name}_variables.c" in listed and "model.c" in listed
    # the core's sources of the model's own list (its description's CORE), no other
    core = {path.split("/")[-1] for path in load(name).core_sources}
    assert {n for n in listed if n in CORE_NAMES} == core
    for other in set(project.MODELS) - {name}:
        assert not any(other in n for n in names), f"{name}.fmu ships a file of {other}"
    assert icon == (root / "model.png").read_bytes()
    assert packaged == model["xml"].read_bytes(), "the packaged modelDescription.xml is not the repository's"


def test_root_model_description_is_a_marked_copy():
    """The repository root's modelDescription.xml is project.ROOT_MODEL_DESCRIPTION's, with a
    comment after the XML declaration saying so; fmpy reads it and its XSD accepts it."""
    root = ROOT / "modelDescription.xml"
    original = model_description_path(project.ROOT_MODEL_DESCRIPTION)
    declaration, rest = original.read_text().split("\n", 1)
    copied_declaration, comment_and_rest = root.read_text().split("\n", 1)
    comment, copied_rest = comment_and_rest.split("-->\n", 1)
    assert copied_declaration == declaration == '<?xml version="1.0" encoding="UTF-8"?>'
    assert comment.startswith("<!-- A generated copy of " + original.relative_to(ROOT).as_posix())
    assert copied_rest == rest
    copy, own = (read_model_description(str(path), validate=True) for path in (root, original))
    assert copy.guid == own.guid and copy.modelName == own.modelName == project.ROOT_MODEL_DESCRIPTION
    assert [v.name for v in copy.modelVariables] == [v.name for v in own.modelVariables]


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
        elif row["causality"] == "local" and variable.start is None:
            assert variable.initial == "calculated"  # derivatives and co-simulation history
        else:
            assert float(variable.start) == row["start"]
        if row["causality"] == "parameter" and row["type"] == "Real":
            assert (float(variable.min), float(variable.max)) == (row["min"], row["max"])


def test_names_units_and_display_units(model):
    """The variables of 0.3.0 stay, in their order; a variable added since comes after them (it
    takes a new value reference above every one in use)."""
    description = model["description"]
    names = [v.name for v in description.modelVariables]
    assert names[:len(model["names"])] == model["names"]
    added = description.modelVariables[len(model["names"]):]
    assert all(v.valueReference > max(w.valueReference for w in description.modelVariables
                                      if w.name in model["names"]) for v in added)
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
    if "frame" in variables:  # every model whose inputs may be in either frame
        assert [(i.name, int(i.value)) for i in variables["frame"].declaredType.items] == \
            [("fixed", 1), ("body", 2)]


def test_model_structure_is_the_c_table_dependencies(model):
    """The inputs each output depends on are the C table's; beyond the inputs, an output depends on
    continuous states only and an initial unknown on parameters only (nothing, without states)."""
    description = model["description"]
    table = {v["name"]: sorted(v["dependencies"]) for v in model["table"]["variables"]
             if v["causality"] == "output"}
    states = {d.variable.derivative.name for d in description.derivatives}
    for section, other in ((description.outputs, states),
                           (description.initialUnknowns, set(model["parameters"]))):
        listed = {u.variable.name: sorted(d.valueReference for d in u.dependencies
                                          if d.causality == "input") for u in section}
        assert {name: listed[name] for name in table} == table
        assert set(listed) - set(table) == ({d.variable.name for d in description.derivatives}
                                            if section is description.initialUnknowns else set())
        for unknown in section:
            extra = {d.name for d in unknown.dependencies if d.causality != "input"}
            assert extra <= (other if states else set()), (unknown.variable.name, extra)
    assert [u.variable for u in description.outputs] == [v for v in description.modelVariables
                                                         if v.causality == "output"]


def documented_unions(heading):
    """{output: set of inputs} of a union table of docs/sequences.md (made from the sympy reference
    by codegen/sequence_tables.py)."""
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
    if model["union_table"] is None:
        pytest.skip(f"{model['name']}'s outputs depend on its continuous states, not on a sympy "
                    "reference union (test_attitude_derivatives.py checks its <ModelStructure>)")
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
    cs = description.coSimulation
    assert cs.canHandleVariableCommunicationStepSize is True  # test_variable_steps.py, test_euler_rates.py
    assert cs.canBeInstantiatedOnlyOncePerProcess is False  # test_fmi_calls.py (two instances)
    assert cs.canInterpolateInputs is True  # test_input_interpolation.py, test_euler_rates.py
    # AngularKinematics: test_output_derivatives.py, test_sequences_fmu.py; the others: none
    assert cs.maxOutputDerivativeOrder == model["output_derivative_order"]
    assert cs.canRunAsynchronuously is False  # test_fmi_calls.py (fmi2CancelStep refused)
    me = description.modelExchange
    assert me is not None  # test_model_exchange.py, test_euler_rates.py
    assert me.needsCompletedIntegratorStep is False
    # AttitudePropagator's states: test_attitude_fmu.py
    assert description.numberOfContinuousStates == model["states"]
    assert description.numberOfEventIndicators == 0
    assert [d.variable.name for d in description.derivatives] == [
        f"der({d.variable.derivative.name})" for d in description.derivatives]
    assert len(description.derivatives) == model["states"]
    for interface in (cs, me):
        assert interface.canGetAndSetFMUstate is True  # test_fmu_state.py, test_euler_rates.py
        assert interface.canSerializeFMUstate is True
        # AngularKinematics: test_directional_derivatives.py, test_sequences_fmu.py;
        # AttitudePropagator: test_attitude_derivatives.py; EulerRates: none
        assert interface.providesDirectionalDerivative is model["directional"]
        assert interface.canBeInstantiatedOnlyOncePerProcess is False
        assert interface.canNotUseMemoryManagementFunctions is False


def test_log_categories(model):
    assert [c.name for c in model["description"].logCategories] == [
        "logStatusError", "logStatusWarning", "logCalls"]
