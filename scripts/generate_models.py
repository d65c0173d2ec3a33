"""Writes the variable tables of both models and their modelDescription.xml from one description:

    fmu_src/model_angular_kinematics_variables.c   modelDescription.xml
    fmu_src/model_euler_rates_variables.c          models/EulerRates/modelDescription.xml

    .venv/bin/python scripts/generate_models.py

The output dependencies are the unions over the 24 sequences (and, for EulerRates, the two frames)
of docs/sequences.md, found on the sympy reference; tests/test_model_description.py checks both
files against each other and against the reference, and tests/test_sequences_fmu.py checks through
the FMU that every output moves only with the inputs listed. tests/test_documentation.py checks that
the files are what this script writes.
"""
import pathlib
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "tests"))
from sequence_names import SEQUENCES, sequence_description  # noqa: E402

TYPES = {  # declared type: (unit, display unit)
    "Angle": ("rad", "deg"), "AngularVelocity": ("rad/s", "deg/s"),
    "AngularAcceleration": ("rad/s2", "deg/s2"), "Frequency": ("1/s", None)}
ORDINAL = {1: "1", 2: "2", 3: "3"}
CORE_SOURCES = ["kinematics.c", "sequences.c", "kinematics_general.c",
                "kinematics_general_jacobian.c"]
FMI_SOURCES = ["fmi2_instance.c", "fmi2_logging.c", "fmi2_state_machine.c", "fmi2_lifecycle.c",
               "fmi2_values.c", "fmi2_cosimulation.c", "fmi2_model_exchange.c",
               "fmi2_derivatives.c", "fmi2_fmu_state.c"]


def real(name, causality, declared, description, deps=(), start=0.0, unit=None):
    return dict(name=name, causality=causality, type="Real", declared=declared,
                unit=unit if unit is not None else TYPES.get(declared, ("",))[0],
                start=start, min=0.0, max=0.0, description=description, deps=list(deps))


def vector(base, causality, declared, text, deps=lambda i: ()):
    return [real(f"{base}[{i}]", causality, declared, text.format(i=i), deps(i)) for i in (1, 2, 3)]


def matrix(base, declared, text, deps):
    return [real(f"{base}[{i},{j}]", "output", declared, text.format(i=i, j=j), deps(j))
            for i in (1, 2, 3) for j in (1, 2, 3)]


def angular_kinematics():
    theta, theta_dot, all_inputs = [0, 1, 2], [3, 4, 5], list(range(9))
    v = []
    v += vector("theta", "input", "Angle", "angle {i} of the rotation sequence (parameter sequence)")
    v += vector("theta_dot", "input", "AngularVelocity", "first time derivative of theta[{i}]")
    v += vector("theta_ddot", "input", "AngularAcceleration", "second time derivative of theta[{i}]")
    v += vector("omega_fixed", "output", "AngularVelocity",
                "fixed-frame component {i} of the angular velocity of the body",
                lambda i: theta + theta_dot)
    v += vector("omega_body", "output", "AngularVelocity",
                "body-frame component {i} of the angular velocity of the body",
                lambda i: theta + theta_dot)
    v += vector("alpha_fixed", "output", "AngularAcceleration",
                "fixed-frame component {i} of the angular acceleration of the body",
                lambda i: all_inputs)
    v += vector("alpha_body", "output", "AngularAcceleration",
                "body-frame component {i} of the angular acceleration of the body",
                lambda i: all_inputs)
    v += matrix("R", "Dimensionless",
                "direction cosine matrix, row {i} column {j}: v_fixed = R v_body", lambda j: theta)
    v += [real(f"q[{k}]", "output", "Dimensionless",
               f"unit quaternion of the orientation, component {k} (scalar first: q[1] is the "
               f"scalar part, q[1] >= 0)", theta) for k in (1, 2, 3, 4)]
    others = lambda j: [k for k in theta if k != j - 1]  # noqa: E731
    v += matrix("W_fixed", "Dimensionless",
                "partial angular velocity matrix, fixed components: omega_fixed = W_fixed "
                "theta_dot, row {i} column {j}", others)
    v += matrix("W_body", "Dimensionless",
                "partial angular velocity matrix, body components: omega_body = W_body theta_dot, "
                "row {i} column {j}", others)
    v += matrix("W_fixed_dot", "Frequency", "time derivative of W_fixed[{i},{j}]",
                lambda j: others(j) + [k + 3 for k in others(j)])
    v += matrix("W_body_dot", "Frequency", "time derivative of W_body[{i},{j}]",
                lambda j: others(j) + [k + 3 for k in others(j)])
    v.append(dict(name="sequence", causality="parameter", type="Integer", declared="Sequence",
                  unit="", start=1.0, min=1.0, max=24.0,
                  description="rotation sequence of the angles theta", deps=[]))
    return v


def euler_rates():
    theta, omega, omega_dot = [0, 1, 2], [3, 4, 5], [6, 7, 8]
    v = []
    v += vector("theta", "input", "Angle", "angle {i} of the rotation sequence (parameter sequence)")
    v += vector("omega", "input", "AngularVelocity",
                "component {i} of the angular velocity of the body, in the frame of parameter frame")
    v += vector("omega_dot", "input", "AngularAcceleration",
                "time derivative of omega[{i}] (the angular acceleration in the frame of parameter "
                "frame)")
    v += vector("theta_dot", "output", "AngularVelocity", "first time derivative of theta[{i}]",
                lambda i: [0, 2] + omega if i == 2 else theta + omega)
    v += vector("theta_ddot", "output", "AngularAcceleration", "second time derivative of theta[{i}]",
                lambda i: theta + omega + omega_dot)
    v += vector("alpha_fixed", "output", "AngularAcceleration",
                "fixed-frame component {i} of the angular acceleration of the body",
                lambda i: theta + omega_dot)
    v += vector("alpha_body", "output", "AngularAcceleration",
                "body-frame component {i} of the angular acceleration of the body",
                lambda i: theta + omega_dot)
    v.append(real("singularity_distance", "output", "Dimensionless",
                  "|det W|: |cos theta[2]| (Tait-Bryan) or |sin theta[2]| (proper Euler); 0 at the "
                  "singular configuration", [1]))
    v.append(dict(name="sequence", causality="parameter", type="Integer", declared="Sequence",
                  unit="", start=1.0, min=1.0, max=24.0,
                  description="rotation sequence of the angles theta", deps=[]))
    v.append(dict(name="frame", causality="parameter", type="Integer", declared="Frame",
                  unit="", start=1.0, min=1.0, max=2.0,
                  description="frame of the components of the inputs omega and omega_dot", deps=[]))
    v.append(dict(name="tolerance", causality="parameter", type="Real", declared="Dimensionless",
                  unit="", start=1e-4, min=0.0, max=1.0,
                  description="singularity_distance below which a warning is logged (fmi2Warning)",
                  deps=[]))
    return v


MODELS = {
    "AngularKinematics": dict(
        variables=angular_kinematics(), guid="{c3391885-ba93-4824-bb36-df39703b63ee}",
        table="model_angular_kinematics_variables.c", symbol="AK_ANGULAR_KINEMATICS_VARIABLES",
        model_file="model_angular_kinematics.c", xml=ROOT / "modelDescription.xml",
        description="Angular velocity and angular acceleration of a rigid body from the angles of "
                    "any of the 24 rotation sequences and their first and second time derivatives; "
                    "rotation matrix, quaternion and partial angular velocity matrices",
        flags=dict(directional=True, interpolate=True, output_order=1)),
    "EulerRates": dict(
        variables=euler_rates(), guid="{6f0d3c8e-2b1a-4e55-9a53-2f4c1d7e8b90}",
        table="model_euler_rates_variables.c", symbol="AK_EULER_RATES_VARIABLES",
        model_file="model_euler_rates.c", xml=ROOT / "models" / "EulerRates" / "modelDescription.xml",
        description="Kinematic differential equations of any of the 24 rotation sequences: the first "
                    "and second time derivatives of the angles from the angular velocity and its "
                    "derivative (body or fixed components)",
        flags=dict(directional=False, interpolate=True, output_order=0)),
}


def sources(model):
    return CORE_SOURCES + [MODELS[model]["model_file"], MODELS[model]["table"]] + FMI_SOURCES


def c_string(text):
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'


def c_table(model):
    m = MODELS[model]
    lines = [f"/* The variable table of {model}. Generated by scripts/generate_models.py from the same",
             " * description as its modelDescription.xml: edit there, then run it. */",
             '#include "fmi2_model.h"', "",
             f"const ak_variable {m['symbol']}[{len(m['variables'])}] = {{"]
    causality = {"input": "AK_CAUSALITY_INPUT", "output": "AK_CAUSALITY_OUTPUT",
                 "parameter": "AK_CAUSALITY_PARAMETER"}
    for vr, v in enumerate(m["variables"]):
        deps = "{" + ", ".join(str(d) for d in v["deps"]) + "}" if v["deps"] else "{0}"
        lines.append(
            f"    {{{vr}, {c_string(v['name'])}, {causality[v['causality']]}, "
            f"AK_TYPE_{v['type'].upper()}, {c_string(v['declared'])}, {c_string(v['unit'])}, "
            f"{v['start']!r}, {v['min']!r}, {v['max']!r}, {c_string(v['description'])}, "
            f"{len(v['deps'])}, {deps}}},")
    lines += ["};", ""]
    return "\n".join(lines)


def xml_escape(text):
    return text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace('"', "&quot;")


def model_description(model):
    m = MODELS[model]
    f = m["flags"]
    variables = m["variables"]
    files = "\n".join(f'      <File name="{s}"/>' for s in sources(model))
    common = ('    canBeInstantiatedOnlyOncePerProcess="false"\n'
              '    canNotUseMemoryManagementFunctions="false"\n'
              '    canGetAndSetFMUstate="true"\n'
              '    canSerializeFMUstate="true"\n'
              f'    providesDirectionalDerivative="{str(f["directional"]).lower()}"')
    out = [f'''<?xml version="1.0" encoding="UTF-8"?>
<fmiModelDescription
  fmiVersion="2.0"
  modelName="{model}"
  guid="{m['guid']}"
  description="{xml_escape(m['description'])}"
  author="AngularKinematics developers"
  version="0.2.0"
  generationTool="scripts/generate_models.py, from the same description as fmu_src/{m['table']}"
  variableNamingConvention="structured"
  numberOfEventIndicators="0">

  <ModelExchange
    modelIdentifier="{model}"
    needsExecutionTool="false"
    completedIntegratorStepNotNeeded="true"
{common}>
    <SourceFiles>
{files}
    </SourceFiles>
  </ModelExchange>

  <CoSimulation
    modelIdentifier="{model}"
    needsExecutionTool="false"
    canHandleVariableCommunicationStepSize="true"
    canInterpolateInputs="{str(f['interpolate']).lower()}"
    maxOutputDerivativeOrder="{f['output_order']}"
    canRunAsynchronuously="false"
{common}>
    <SourceFiles>
{files}
    </SourceFiles>
  </CoSimulation>

  <UnitDefinitions>
    <Unit name="rad">
      <BaseUnit rad="1"/>
      <DisplayUnit name="deg" factor="57.295779513082323"/>
    </Unit>
    <Unit name="rad/s">
      <BaseUnit s="-1" rad="1"/>
      <DisplayUnit name="deg/s" factor="57.295779513082323"/>
    </Unit>
    <Unit name="rad/s2">
      <BaseUnit s="-2" rad="1"/>
      <DisplayUnit name="deg/s2" factor="57.295779513082323"/>
    </Unit>
    <Unit name="1/s">
      <BaseUnit s="-1"/>
    </Unit>
  </UnitDefinitions>

  <TypeDefinitions>
    <SimpleType name="Angle">
      <Real quantity="Angle" unit="rad" displayUnit="deg"/>
    </SimpleType>
    <SimpleType name="AngularVelocity">
      <Real quantity="AngularVelocity" unit="rad/s" displayUnit="deg/s"/>
    </SimpleType>
    <SimpleType name="AngularAcceleration">
      <Real quantity="AngularAcceleration" unit="rad/s2" displayUnit="deg/s2"/>
    </SimpleType>
    <SimpleType name="Dimensionless">
      <Real/>
    </SimpleType>
    <SimpleType name="Frequency">
      <Real quantity="Frequency" unit="1/s"/>
    </SimpleType>
    <SimpleType name="Sequence" description="rotation sequence: body-fixed (intrinsic) or space-fixed (extrinsic), axes in the order of theta[1], theta[2], theta[3]">''']
    for k, name in enumerate(SEQUENCES):
        out.append(f'        <Item name="{name}" value="{k + 1}" description="{xml_escape(sequence_description(name))}"/>')
    out[-1] = out[-1]
    out.insert(len(out) - 24, "      <Enumeration>")
    out.append("      </Enumeration>\n    </SimpleType>")
    if model == "EulerRates":
        out.append('''    <SimpleType name="Frame" description="frame of the components of omega and omega_dot">
      <Enumeration>
        <Item name="fixed" value="1" description="components along the fixed axes n1, n2, n3"/>
        <Item name="body" value="2" description="components along the body axes b1, b2, b3"/>
      </Enumeration>
    </SimpleType>''')
    out.append('''  </TypeDefinitions>

  <LogCategories>
    <Category name="logStatusError" description="Every call that returns fmi2Error, with the function, the variable and the value"/>
    <Category name="logStatusWarning" description="Calls that return fmi2Warning or fmi2Discard"/>
    <Category name="logCalls" description="Trace of every FMI call with its arguments, and of every evaluation of the model"/>
  </LogCategories>

  <DefaultExperiment startTime="0" stopTime="10" stepSize="0.01"/>

  <ModelVariables>''')
    for vr, v in enumerate(variables):
        if v["causality"] == "parameter":
            attributes = 'causality="parameter" variability="fixed"'
        elif v["causality"] == "input":
            attributes = 'causality="input" variability="continuous"'
        else:
            attributes = 'causality="output" variability="continuous"'
        if v["type"] == "Integer":
            element = f'<Enumeration declaredType="{v["declared"]}" start="{int(v["start"])}"/>'
        else:
            start = f' start="{v["start"]!r}"' if v["causality"] != "output" else ""
            bounds = (f' min="{v["min"]!r}" max="{v["max"]!r}"' if v["causality"] == "parameter"
                      else "")
            element = f'<Real declaredType="{v["declared"]}"{start}{bounds}/>'
        out.append(f"    <!-- index {vr + 1} -->")
        out.append(f'    <ScalarVariable name="{v["name"]}" valueReference="{vr}" '
                   f'description="{xml_escape(v["description"])}" {attributes}>')
        out.append(f"      {element}")
        out.append("    </ScalarVariable>")
    out.append("  </ModelVariables>\n\n  <ModelStructure>")
    for section in ("Outputs", "InitialUnknowns"):
        out.append(f"    <{section}>")
        for vr, v in enumerate(variables):
            if v["causality"] == "output":
                deps = " ".join(str(d + 1) for d in v["deps"])
                out.append(f'      <Unknown index="{vr + 1}" dependencies="{deps}"/>  <!-- {v["name"]} -->')
        out.append(f"    </{section}>")
    out.append("  </ModelStructure>\n\n</fmiModelDescription>\n")
    return "\n".join(out)


def outputs():
    """{path: text} of every generated file."""
    files = {}
    for model, m in MODELS.items():
        files[ROOT / "fmu_src" / m["table"]] = c_table(model)
        files[m["xml"]] = model_description(model)
    return files


def main():
    for path, text in outputs().items():
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
        print(f"wrote {path.relative_to(ROOT)}")


if __name__ == "__main__":
    main()
