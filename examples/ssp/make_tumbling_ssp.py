"""Builds dist/ssp/Tumbling.ssp, a self-contained SSP 1.0 system of the four built FMUs that fmpy,
libcosim and Ecos all run (tests/python/test_ssp_engines.py): components and connections only, no
connector of the system's own, which libcosim 0.0.6 and Ecos 0.7.2 refuse.

    AttitudePropagator (omega held at OMEGA by a parameter binding: a body tumbling at a constant
      rate) -> theta, theta_dot
      -> AngularKinematics -> omega_fixed
      -> EulerRates (frame = fixed, its default), with theta from the propagator
      -> theta_dot, singularity_distance
    AttitudePropagator -> omega_body, alpha_body
      -> PointKinematics (an accelerometer at the lever arm LEVER_ARM, bound as r; in free fall:
         g = 0 and a_O = 0) -> specific_force, a_centripetal

The propagator is the source: the inputs of the other two change at every step. The root system
carries OMSimulator's vendor annotation (org.openmodelica, oms:SimulationInformation), which
OMSimulator wants on a root system and SSP allows (ssc:Annotation); the other tools skip it.

    .venv/bin/python examples/ssp/make_tumbling_ssp.py [--dist DIR] [--out FILE]"""
import sys

from examples.ssp.make_ssp import NS, ROOT, command, connectors_xml, scalars, write_ssp

STEP, STOP = 2.0 ** -6, 100 * 2.0 ** -6
OMEGA = (0.4, -0.3, 0.5)  # rad/s, the propagator's input, held
LEVER_ARM = (0.5, 0.2, -0.1)  # m, the accelerometer's position relative to the body's centre
# The inputs no connection feeds, bound by one parameter set each (its name: PARAMETER_SET).
BINDINGS = {"propagator": ("omega", OMEGA), "accelerometer": ("r", LEVER_ARM)}
PARAMETER_SET = "initial"
OMS = "https://raw.githubusercontent.com/OpenModelica/OMSimulator/master/schema/oms.xsd"
SSV = "http://ssp-standard.org/SSP1/SystemStructureParameterValues"
# element name -> (FMU, inputs, outputs): the connectors of each component, FMU variable names.
COMPONENTS = {
    "propagator": ("AttitudePropagator", [], ["theta", "theta_dot", "omega_fixed", "omega_body",
                                             "alpha_body"]),
    "kinematics": ("AngularKinematics", ["theta", "theta_dot"], ["omega_fixed"]),
    "rates": ("EulerRates", ["theta", "omega"], ["theta_dot", "singularity_distance"]),
    "accelerometer": ("PointKinematics", ["omega", "alpha"], ["specific_force", "a_centripetal"]),
}
CONNECTIONS = [("propagator", "theta", "kinematics", "theta"),
               ("propagator", "theta_dot", "kinematics", "theta_dot"),
               ("propagator", "theta", "rates", "theta"),
               ("kinematics", "omega_fixed", "rates", "omega"),
               ("propagator", "omega_body", "accelerometer", "omega"),
               ("propagator", "alpha_body", "accelerometer", "alpha")]


def binding_xml(element, indent):
    """An input of the element held by a parameter binding: an inline parameter set (its inputs
    are no connectors, so no master sets them)."""
    variable, values = BINDINGS[element]
    lines = [f"{indent}<ssd:ParameterBindings>", f"{indent}  <ssd:ParameterBinding>",
             f"{indent}    <ssd:ParameterValues>",
             f'{indent}      <ssv:ParameterSet version="1.0" name="{PARAMETER_SET}"><ssv:Parameters>']
    for name, value in zip(scalars(variable), values):
        lines.append(f'{indent}        <ssv:Parameter name="{name}"><ssv:Real value="{value!r}"/>'
                     f"</ssv:Parameter>")
    return lines + [f"{indent}      </ssv:Parameters></ssv:ParameterSet>",
                    f"{indent}    </ssd:ParameterValues>", f"{indent}  </ssd:ParameterBinding>",
                    f"{indent}</ssd:ParameterBindings>"]


def oms_annotation_xml(indent):
    return [f"{indent}<ssd:Annotations>",
            f'{indent}  <ssc:Annotation type="org.openmodelica">',
            f'{indent}    <oms:Annotations xmlns:oms="{OMS}">',
            f"{indent}      <oms:SimulationInformation>",
            f'{indent}        <oms:FixedStepMaster description="oms-ma" stepSize="{STEP!r}" '
            f'absoluteTolerance="1e-4" relativeTolerance="1e-4"/>',
            f"{indent}      </oms:SimulationInformation>",
            f"{indent}    </oms:Annotations>", f"{indent}  </ssc:Annotation>",
            f"{indent}</ssd:Annotations>"]


def ssd_xml():
    lines = ['<?xml version="1.0" encoding="UTF-8"?>',
             f'<ssd:SystemStructureDescription xmlns:ssd="{NS["ssd"]}" xmlns:ssc="{NS["ssc"]}"',
             f'    xmlns:ssv="{SSV}" version="1.0" name="Tumbling">',
             '  <ssd:System name="Tumbling" description="a body tumbling at a constant rate: '
             'AttitudePropagator -> AngularKinematics -> EulerRates, and PointKinematics: an '
             'accelerometer at a lever arm">',
             "    <ssd:Elements>"]
    for element, (model, inputs, outputs) in COMPONENTS.items():
        lines.append(f'      <ssd:Component name="{element}" '
                     f'type="application/x-fmu-sharedlibrary" source="resources/{model}.fmu">')
        lines += connectors_xml(inputs, outputs, "        ")
        if element in BINDINGS:
            lines += binding_xml(element, "        ")
        lines.append("      </ssd:Component>")
    lines += ["    </ssd:Elements>", "    <ssd:Connections>"]
    for start_element, start, end_element, end in CONNECTIONS:
        for start_scalar, end_scalar in zip(scalars(start), scalars(end)):
            lines.append(f'      <ssd:Connection startElement="{start_element}" '
                         f'startConnector="{start_scalar}" endElement="{end_element}" '
                         f'endConnector="{end_scalar}"/>')
    lines += ["    </ssd:Connections>"] + oms_annotation_xml("    ") + ["  </ssd:System>",
              f'  <ssd:DefaultExperiment startTime="0" stopTime="{STOP!r}"/>',
              "</ssd:SystemStructureDescription>", ""]
    return "\n".join(lines)


def make_tumbling_ssp(dist, out):
    return write_ssp(out, ssd_xml(), COMPONENTS, dist)


def main(argv=None):
    return command(argv, __doc__, "Tumbling.ssp", ssd_xml(), COMPONENTS)


if __name__ == "__main__":
    sys.exit(main())
