"""The documentation packaged in the FMU and README.md: generated from the same sources and up to
date, with the variables, their units, the capabilities and the figures."""
import re
import subprocess
import sys
import zipfile
from html.parser import HTMLParser

import pytest

RENDER = ["scripts/render_docs.py", "--check"]


def test_readme_and_documentation_are_up_to_date(root):
    done = subprocess.run([sys.executable, *RENDER], cwd=root, capture_output=True, text=True)
    assert done.returncode == 0, done.stdout + done.stderr


class Page(HTMLParser):
    """The images, the h2 headings and the text of every table cell of a page."""

    def __init__(self):
        super().__init__()
        self.images, self.headings, self.cells, self._open = [], [], [], None

    def handle_starttag(self, tag, attributes):
        if tag == "img":
            self.images.append(dict(attributes)["src"])
        elif tag in ("h2", "td"):
            self._open = (tag, [])

    def handle_data(self, data):
        if self._open:
            self._open[1].append(data)

    def handle_endtag(self, tag):
        if self._open and tag == self._open[0]:
            text = "".join(self._open[1]).strip()
            (self.headings if tag == "h2" else self.cells).append(text)
            self._open = None


@pytest.fixture(scope="module")
def page(fmu_path):
    with zipfile.ZipFile(fmu_path) as archive:
        parser = Page()
        parser.feed(archive.read("documentation/index.html").decode())
        return parser, set(archive.namelist())


def test_documentation_has_the_sections(page):
    parser, _ = page
    assert parser.headings == ["What it computes", "Variables", "FMI behaviour", "Capabilities"]


def test_documentation_lists_every_variable_with_its_unit(page, model_description):
    parser, _ = page
    cells = parser.cells
    for variable in model_description.modelVariables:
        base, index = re.fullmatch(r"(\w+)\[(\d)\]", variable.name).groups()
        row = cells.index(f"{base}[1..3]")
        assert cells[row + 3] == variable.declaredType.unit
        assert cells[row + 4] == variable.declaredType.displayUnit
        assert str(variable.valueReference) in cells[row + 5].split(", ")


def test_documentation_states_the_capability_flags(page, model_description):
    parser, _ = page
    cells = parser.cells
    # Columns in the order of modelDescription.xml: Model Exchange, then Co-Simulation.
    row = cells.index("canHandleVariableCommunicationStepSize")
    assert cells[row + 1:row + 3] == ["n/a", "true"]
    row = cells.index("canGetAndSetFMUstate")
    assert cells[row + 1:row + 3] == [str(model_description.modelExchange.canGetAndSetFMUstate).lower(),
                                      str(model_description.coSimulation.canGetAndSetFMUstate).lower()]


def test_documentation_figures_are_in_the_fmu(page):
    parser, names = page
    assert parser.images == ["tumbling_body.png", "../model.png"]
    assert {"documentation/tumbling_body.png", "model.png"} <= names


def test_icon_and_figure_are_png_images(root):
    for path, size in ((root / "model.png", (256, 256)),
                       (root / "documentation" / "tumbling_body.png", (900, 585))):
        data = path.read_bytes()
        assert data.startswith(b"\x89PNG\r\n\x1a\n"), path
        assert (int.from_bytes(data[16:20], "big"), int.from_bytes(data[20:24], "big")) == size
