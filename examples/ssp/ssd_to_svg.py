"""Draws the connection graph of an SSP's SystemStructure.ssd as SVG: the system's inputs on the
left, its components in the order of <Elements>, its outputs on the right; the scalar connectors
theta[1], theta[2], theta[3] are drawn as one port theta[1..3].

    .venv/bin/python examples/ssp/ssd_to_svg.py dist/ssp/RoundTrip.ssp OUT.svg

python -m codegen draws docs/round_trip_ssp.svg with it (codegen/ssp_figure.py)."""
import re
import sys
import zipfile
from xml.sax.saxutils import escape

from lxml import etree

NS = {"ssd": "http://ssp-standard.org/SSP1/SystemStructureDescription"}
ROW, WIDTH, GAP, TOP = 22, 220, 110, 60


def vector_name(connector):
    return re.sub(r"\[\d+\]$", "[1..3]", connector)


def ports(element):
    """{'input': [...], 'output': [...]}: the element's connectors, grouped, in order."""
    grouped = {"input": [], "output": []}
    for connector in element.findall("ssd:Connectors/ssd:Connector", NS):
        name = vector_name(connector.get("name"))
        if name not in grouped[connector.get("kind")]:
            grouped[connector.get("kind")].append(name)
    return grouped


def svg(ssd_bytes):
    system = etree.fromstring(ssd_bytes).find("ssd:System", NS)
    columns = [("", "system inputs", ports(system)["input"], "output")]  # (element, title, ports, side)
    components = system.findall("ssd:Elements/ssd:Component", NS)
    for component in components:
        title = f'{component.get("name")}: {component.get("source").split("/")[-1]}'
        columns.append((component.get("name"), title, ports(component), "both"))
    columns.append(("", "system outputs", ports(system)["output"], "input"))

    position, boxes = {}, []  # (element, kind, port) -> (x, y)
    for c, (element, title, grouped, side) in enumerate(columns):
        x = 20 + c * (WIDTH + GAP)
        names = grouped if side != "both" else grouped["input"] + grouped["output"]
        height = ROW * (len(names) + 1) + 10
        boxes.append(f'<rect x="{x}" y="{TOP}" width="{WIDTH}" height="{height}" rx="6" '
                     f'class="{"system" if not element else "component"}"/>'
                     f'<text x="{x + WIDTH / 2}" y="{TOP + 16}" class="title">{escape(title)}</text>')
        for r, name in enumerate(names):
            y = TOP + ROW * (r + 1) + 12
            kind = side if side != "both" else ("input" if name in grouped["input"] else "output")
            anchor, px = ("start", x + 8) if kind == "input" else ("end", x + WIDTH - 8)
            boxes.append(f'<text x="{px}" y="{y + 4}" text-anchor="{anchor}">{escape(name)}</text>')
            position[(element, kind if element else ("input" if side == "output" else "output"),
                      name)] = (x if kind == "input" else x + WIDTH, y)
    lines = []
    for connection in system.findall("ssd:Connections/ssd:Connection", NS):
        start = (connection.get("startElement", ""), "output" if connection.get("startElement")
                 else "input", vector_name(connection.get("startConnector")))
        end = (connection.get("endElement", ""), "input" if connection.get("endElement")
               else "output", vector_name(connection.get("endConnector")))
        (x1, y1), (x2, y2) = position[start], position[end]
        if x2 - x1 > GAP + 1:  # past a component: over the top of the boxes
            lane = TOP - 14
            path = (f"M{x1},{y1} C{x1 + GAP / 2},{y1} {x1 + GAP / 4},{lane} {x1 + GAP / 2},{lane} "
                    f"L{x2 - GAP / 2},{lane} C{x2 - GAP / 4},{lane} {x2 - GAP / 2},{y2} {x2},{y2}")
        else:
            path = f"M{x1},{y1} C{x1 + GAP / 2},{y1} {x2 - GAP / 2},{y2} {x2},{y2}"
        if path not in lines:
            lines.append(path)
    width = 40 + len(columns) * WIDTH + (len(columns) - 1) * GAP
    height = TOP + ROW * (max(len(b) for b in [c[2] if c[3] != "both" else c[2]["input"] +
                                               c[2]["output"] for c in columns]) + 2) + 10
    style = ("<style>text{font:12px sans-serif}.title{font-weight:bold;text-anchor:middle}"
             ".system{fill:#eef3fb;stroke:#4a6fa5}.component{fill:#fdf6e3;stroke:#b58900}"
             "path{fill:none;stroke:#555;stroke-width:1.2;marker-end:url(#arrow)}</style>"
             '<defs><marker id="arrow" viewBox="0 0 10 10" refX="10" refY="5" markerWidth="6" '
             'markerHeight="6" orient="auto"><path d="M0,0L10,5L0,10z" style="fill:#555;'
             'stroke:none"/></marker></defs>')
    name = escape(system.get("name"))
    return (f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
            f'viewBox="0 0 {width} {height}"><title>{name}: connection graph</title>{style}'
            f'<text x="20" y="22" style="font-weight:bold">SSP system {name} '
            f'(generated from SystemStructure.ssd)</text>'
            + "".join(boxes) + "".join(f'<path d="{p}"/>' for p in lines) + "</svg>\n")


def main(argv):
    source, target = argv
    with zipfile.ZipFile(source) as archive:
        ssd = archive.read("SystemStructure.ssd")
    with open(target, "w") as file:
        file.write(svg(ssd))
    print(f"wrote {target}")


if __name__ == "__main__":
    main(sys.argv[1:])
