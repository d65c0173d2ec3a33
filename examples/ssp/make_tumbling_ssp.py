"""Builds dist/ssp/Tumbling.ssp, a self-contained SSP 1.0 system of the three built FMUs that fmpy,
libcosim and Ecos all run (tests/python/test_engines_ssp.py): components and connections only, no
connector of the system's own, which libcosim 0.0.6 and Ecos 0.7.2 refuse.

    AttitudePropagator (omega held at OMEGA by a parameter binding: a body tumbling at a constant
      rate) -> theta, theta_dot
      -> AngularKinematics -> omega_fixed
      -> EulerRates (frame = fixed, its default), with theta from the propagator
      -> theta_dot, singularity_distance

The propagator is the source: the inputs of the other two change at every step. The root system
carries OMSimulator's vendor annotation (org.openmodelica, oms:SimulationInformation), which
OMSimulator wants on a root system and SSP allows (ssc:Annotation); the other tools skip it.

    .venv/bin/python examples/ssp/make_tumbling_ssp.py [--dist DIR] [--out FILE]"""
import sys

from examples.ssp.make_ssp import NS, ROOT, command, connectors_xml, scalars, write_ssp

STEP, STOP = 2.0 ** -6, 100 * 2.0 ** -6
OMEGA = (0.4, -0.3, 0.5)  # rad/s, the propagator's input, held
OMS = "https://raw.githubusercontent.com/OpenModelica/OMSimulator/master/schema/oms.xsd"
SSV = "http://ssp-standard.org/SSP1/SystemStructureParameterValues"
# element name -> (FMU, inputs, outputs): the connectors of each component, FMU variable names.
COMPONENTS = {
    "propagator": ("AttitudePropagator", [], ["theta", "theta_dot", "omega_fixed"]),
    "kinematics": ("AngularKinematics", ["theta", "theta_dot"], ["omega_fixed"]),
    "rates": ("EulerRates", ["theta", "omega"], ["theta_dot", "singularity_distance"]),
}
CONNECTIONS = [("propagator", "theta", "kinematics", "theta"),
               ("propagator", "theta_dot", "kinematics", "theta_dot"),
               ("propagator", "theta", "rates", "theta"),
               ("kinematics", "omega_fixed", "rates", "omega")]


def binding_xml(indent):
    """The propagator's omega, held: an inline parameter set (its inputs are no connectors, so no
    master sets them)."""
    lines = [f"{indent}<ssd:ParameterBindings>", f"{indent}  <ssd:ParameterBinding>",
             f"{indent}    <ssd:ParameterValues>",
             f'{indent}      <ssv:ParameterSet version="1.0" name="omega"><ssv:Parameters>']
    for name, value in zip(scalars("omega"), OMEGA):
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
             'AttitudePropagator -> AngularKinematics -> EulerRates">',
             "    <ssd:Elements>"]
    for element, (model, inputs, outputs) in COMPONENTS.items():
        lines.append(f'      <ssd:Component name="{element}" '
                     f'type="application/x-fmu-sharedlibrary" source="resources/{model}.fmu">')
        lines += connectors_xml(inputs, outputs, "        ")
        if element == "propagator":
            lines += binding_xml("        ")
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
