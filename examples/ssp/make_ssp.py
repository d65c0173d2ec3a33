"""Builds dist/ssp/RoundTrip.ssp, an SSP 1.0 system of the two built FMUs:

    body trajectory (the system's inputs theta, theta_dot, theta_ddot)
      -> AngularKinematics (kinematics) -> omega_fixed, alpha_fixed
      -> EulerRates (rates, frame = fixed, its default), with theta from the trajectory
      -> the system's outputs: the recovered theta_dot, theta_ddot and singularity_distance.

The trajectory's true theta_dot and theta_ddot are the system's inputs of those names: fmpy's
master (0.3.32) records every connector, inputs too, but cannot connect a system input straight to
a system output (fmpy.ssp.ssd.get_connections fails on such a connection), so there is no copy.

The archive holds SystemStructure.ssd and resources/<Model>.fmu; its entries carry a fixed date so
that the same FMUs give the same bytes.

    .venv/bin/python examples/ssp/make_ssp.py [--dist DIR] [--out FILE]"""
import argparse
import pathlib
import sys
import zipfile

ROOT = pathlib.Path(__file__).resolve().parents[2]
NS = {"ssd": "http://ssp-standard.org/SSP1/SystemStructureDescription",
      "ssc": "http://ssp-standard.org/SSP1/SystemStructureCommon"}
VECTOR = [1, 2, 3]
# element name -> (FMU, inputs, outputs): the connectors of each component, FMU variable names.
COMPONENTS = {
    "kinematics": ("AngularKinematics", ["theta", "theta_dot", "theta_ddot"],
                   ["omega_fixed", "alpha_fixed"]),
    "rates": ("EulerRates", ["theta", "omega", "omega_dot"],
              ["theta_dot", "theta_ddot", "singularity_distance"]),
}
SYSTEM_INPUTS = ["theta", "theta_dot", "theta_ddot"]
SYSTEM_OUTPUTS = ["theta_dot_recovered", "theta_ddot_recovered", "singularity_distance"]
# (start element or "" for the system, start vector, end element or "", end vector)
CONNECTIONS = [
    ("", "theta", "kinematics", "theta"), ("", "theta_dot", "kinematics", "theta_dot"),
    ("", "theta_ddot", "kinematics", "theta_ddot"), ("", "theta", "rates", "theta"),
    ("kinematics", "omega_fixed", "rates", "omega"),
    ("kinematics", "alpha_fixed", "rates", "omega_dot"),
    ("rates", "theta_dot", "", "theta_dot_recovered"),
    ("rates", "theta_ddot", "", "theta_ddot_recovered"),
    ("rates", "singularity_distance", "", "singularity_distance"),
]
SCALARS = {"singularity_distance"}


def scalars(name):
    return [name] if name in SCALARS else [f"{name}[{i}]" for i in VECTOR]


def connectors_xml(inputs, outputs, indent):
    lines = [f"{indent}<ssd:Connectors>"]
    for kind, names in (("input", inputs), ("output", outputs)):
        for name in names:
            for scalar in scalars(name):
                lines.append(f'{indent}  <ssd:Connector name="{scalar}" kind="{kind}"><ssc:Real/>'
                             f"</ssd:Connector>")
    return lines + [f"{indent}</ssd:Connectors>"]


def ssd_xml():
    lines = ['<?xml version="1.0" encoding="UTF-8"?>',
             f'<ssd:SystemStructureDescription xmlns:ssd="{NS["ssd"]}" xmlns:ssc="{NS["ssc"]}"',
             '    version="1.0" name="RoundTrip">',
             '  <ssd:System name="RoundTrip" description="AngularKinematics then EulerRates: the '
             'round trip theta_dot, theta_ddot -> omega, alpha -> theta_dot, theta_ddot">']
    lines += connectors_xml(SYSTEM_INPUTS, SYSTEM_OUTPUTS, "    ")
    lines.append("    <ssd:Elements>")
    for element, (model, inputs, outputs) in COMPONENTS.items():
        lines.append(f'      <ssd:Component name="{element}" '
                     f'type="application/x-fmu-sharedlibrary" source="resources/{model}.fmu">')
        lines += connectors_xml(inputs, outputs, "        ")
        lines.append("      </ssd:Component>")
    lines += ["    </ssd:Elements>", "    <ssd:Connections>"]
    for start_element, start, end_element, end in CONNECTIONS:
        for start_scalar, end_scalar in zip(scalars(start), scalars(end)):
            start_attribute = f'startElement="{start_element}" ' if start_element else ""
            end_attribute = f'endElement="{end_element}" ' if end_element else ""
            lines.append(f'      <ssd:Connection {start_attribute}startConnector="{start_scalar}" '
                         f'{end_attribute}endConnector="{end_scalar}"/>')
    lines += ["    </ssd:Connections>", "  </ssd:System>",
              '  <ssd:DefaultExperiment startTime="0" stopTime="4"/>',
              "</ssd:SystemStructureDescription>", ""]
    return "\n".join(lines)


def write_entry(archive, name, data):
    info = zipfile.ZipInfo(name, date_time=(1980, 1, 1, 0, 0, 0))  # no build date inside
    info.compress_type = zipfile.ZIP_DEFLATED
    info.external_attr = 0o644 << 16
    archive.writestr(info, data)


def write_ssp(out, ssd, components, dist):
    """The archive: the .ssd and the FMU of every model of components (element -> (model, ...))."""
    out.parent.mkdir(parents=True, exist_ok=True)
    with zipfile.ZipFile(out, "w") as archive:
        write_entry(archive, "SystemStructure.ssd", ssd.encode())
        for model in sorted({model for model, _, _ in components.values()}):
            write_entry(archive, f"resources/{model}.fmu", (dist / f"{model}.fmu").read_bytes())
    return out


def make_ssp(dist, out):
    return write_ssp(out, ssd_xml(), COMPONENTS, dist)


def command(argv, doc, name, ssd, components):
    """The command line of a make_*.py here: [--dist DIR] [--out FILE], default dist/ssp/<name>."""
    parser = argparse.ArgumentParser(description=doc.splitlines()[0])
    parser.add_argument("--dist", default=str(ROOT / "dist"), help="folder of the built FMUs")
    parser.add_argument("--out", default=str(ROOT / "dist" / "ssp" / name))
    args = parser.parse_args(argv)
    dist = pathlib.Path(args.dist)
    missing = [m for m, _, _ in components.values() if not (dist / f"{m}.fmu").is_file()]
    if missing:
        print(f"missing in {dist}: {', '.join(missing)} (build first: bash scripts/build.sh)")
        return 2
    print(f"wrote {write_ssp(pathlib.Path(args.out), ssd, components, dist)}")
    return 0


def main(argv=None):
    return command(argv, __doc__, "RoundTrip.ssp", ssd_xml(), COMPONENTS)


if __name__ == "__main__":
    sys.exit(main())
