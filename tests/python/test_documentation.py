"""The documentation packaged in the FMUs, docs/variables.md and README.md's table: generated from
docs/ and the modelDescription.xml files, up to date, with the variables, their units, the
capabilities and the figures, and no link that leaves the FMU."""
import posixpath
import re
import subprocess
import sys
import zipfile
from html.parser import HTMLParser

import pytest
from fmpy import read_model_description

from conftest import fmu_path_of, project

RENDER = ["scripts/render_docs.py", "--check"]


def test_readme_and_documentation_are_up_to_date(root):
    done = subprocess.run([sys.executable, *RENDER], cwd=root, capture_output=True, text=True)
    assert done.returncode == 0, done.stdout + done.stderr


class Page(HTMLParser):
    """The images, the links (href and src), the ids, the h2 headings and the text of every table
    cell of a page."""

    def __init__(self):
        super().__init__()
        self.images, self.headings, self.cells, self._open = [], [], [], None
        self.links, self.ids = [], set()

    def handle_starttag(self, tag, attributes):
        attributes = dict(attributes)
        self.links += [attributes[a] for a in ("href", "src") if a in attributes]
        if "id" in attributes:
            self.ids.add(attributes["id"])
        if tag == "img":
            self.images.append(attributes["src"])
        if tag in ("h2", "td"):
            self._open = (tag, [])

    def handle_data(self, data):
        if self._open:
            self._open[1].append(data)

    def handle_endtag(self, tag):
        if self._open and tag == self._open[0]:
            text = "".join(self._open[1]).strip()
            (self.headings if tag == "h2" else self.cells).append(text)
            self._open = None


def read_page(path):
    with zipfile.ZipFile(path) as archive:
        parser = Page()
        parser.feed(archive.read("documentation/index.html").decode())
        return parser, set(archive.namelist())


@pytest.fixture(scope="module")
def page(model):
    """The page packaged in the model's FMU."""
    return read_page(model.fmu_path)


def test_documentation_has_the_sections(page):
    parser, _ = page
    assert parser.headings == ["What it computes", "Rotation sequences and conventions",
                               "EulerRates: the inverse map", "FMI behaviour", "Capabilities",
                               "Variables of AngularKinematics", "Variables of EulerRates",
                               "Sequence items", "Capability flags"]


def test_every_link_of_the_documentation_resolves_inside_the_fmu(page):
    """Every href and src of documentation/index.html, opened from the unzipped FMU, names a file of
    the archive or an anchor of the page: nothing points outside the FMU."""
    parser, names = page
    assert parser.links, "the page has links and figures"
    for link in parser.links:
        assert "://" not in link and not link.startswith(("/", "mailto:")), link
        target, _, anchor = link.partition("#")
        if target:
            resolved = posixpath.normpath(posixpath.join("documentation", target))
            assert resolved in names, f"{link} -> {resolved} is not in the FMU"
        else:
            assert anchor in parser.ids, f"{link}: no element with that id"


@pytest.mark.parametrize("which", project.MODELS)
def test_documentation_lists_every_variable_with_its_unit(which, page):
    """Every model's variables are in the page (AngularKinematics' table first)."""
    parser, _ = page
    cells = parser.cells
    description = read_model_description(str(fmu_path_of(which)))
    start = 0 if which == "AngularKinematics" else cells.index("omega[1..3]") - 7  # its theta row
    for variable in description.modelVariables:
        vector = re.fullmatch(r"(\w+)\[\d\]", variable.name)
        matrix = re.fullmatch(r"(\w+)\[\d,\d\]", variable.name)
        label = (f"{vector.group(1)}[1..{4 if vector.group(1) == 'q' else 3}]" if vector
                 else f"{matrix.group(1)}[1..3,1..3]" if matrix else variable.name)
        row = cells.index(label, start)
        assert cells[row + 3] == (variable.declaredType.unit or "")
        assert cells[row + 4] == (variable.declaredType.displayUnit or "")
        references = cells[row + 5]
        if " .. " in references:
            first, last = map(int, references.split(" .. "))
            assert first <= variable.valueReference <= last
        else:
            assert str(variable.valueReference) in references.split(", ")


def test_documentation_states_the_capability_flags(page, model):
    model_description = model.description
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
    assert parser.images == ["tumbling_body.png", "../model.png", "models.svg"]
    assert {"documentation/tumbling_body.png", "model.png", "documentation/models.svg"} <= names


def test_icon_and_figure_are_png_images(root):
    for path, size in ((root / "model.png", (256, 256)),
                       (root / "documentation" / "tumbling_body.png", (900, 585))):
        data = path.read_bytes()
        assert data.startswith(b"\x89PNG\r\n\x1a\n"), path
        assert (int.from_bytes(data[16:20], "big"), int.from_bytes(data[20:24], "big")) == size


def test_generated_files_are_up_to_date(root):
    """Every file codegen/generate.py writes (variable tables, modelDescription.xml, sequences,
    log categories, CMake lists, build descriptions) is what it would write now."""
    from codegen import generate
    stale = [str(path.relative_to(root)) for path, text in generate.outputs().items()
             if path.read_text() != text]
    assert not stale, f"out of date: {stale}; run python3 -m codegen.generate"
