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
    variables = [f"Variables of {name}" for name in project.MODELS]
    start = parser.headings.index(variables[0])
    assert parser.headings[:start] == ["What it computes", "Rotation sequences and conventions",
                                       "EulerRates: the inverse map", "FMI behaviour", "Capabilities"]
    assert parser.headings[start:] == variables + ["Sequence items", "Capability flags"]


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


def table_start(cells, variables):
    """Where a model's variable table begins among the page's cells: the row of its first variable
    followed by the row of the next one not in that row (name and value reference both)."""
    first = variables[0]
    label = label_of(first.name, variables, cells, 0)
    second = next(v for v in variables if label_of(v.name, variables, cells, 0) != label)
    second_label = label_of(second.name, variables, cells, 0)
    return next(i for i in range(len(cells) - 12)
                if cells[i] == label and refers_to(cells[i + 5], first.valueReference)
                and cells[i + 7] == second_label and refers_to(cells[i + 12], second.valueReference))


def refers_to(references, vr):
    """Whether the value-reference column ("3, 4, 5" or "14 .. 22") holds vr."""
    if " .. " in references:
        first, last = map(int, references.split(" .. "))
        return first <= vr <= last
    return str(vr) in references.split(", ")


def label_of(name, variables, cells, start):
    """The name column of a variable's row: name[1..n] or name[1..3,1..3] for a group of array
    elements, else the name (an element whose row is its own)."""
    vector = re.fullmatch(r"(\w+)\[\d\]", name)
    matrix = re.fullmatch(r"(\w+)\[\d,\d\]", name)
    if vector:
        n = sum(bool(re.fullmatch(re.escape(vector.group(1)) + r"\[\d\]", v.name)) for v in variables)
        label = f"{vector.group(1)}[1..{n}]"
    else:
        label = f"{matrix.group(1)}[1..3,1..3]" if matrix else name
    return label if label in cells[start:] else name


@pytest.mark.parametrize("which", project.MODELS)
def test_documentation_lists_every_variable_with_its_unit(which, page):
    """Every model's variables are in the page, each in its model's table."""
    parser, _ = page
    cells = parser.cells
    description = read_model_description(str(fmu_path_of(which)))
    start = table_start(cells, description.modelVariables)
    for variable in description.modelVariables:
        row = cells.index(label_of(variable.name, description.modelVariables, cells, start), start)
        assert cells[row + 3] == (variable.declaredType.unit or "")
        assert cells[row + 4] == (variable.declaredType.displayUnit or "")
        assert refers_to(cells[row + 5], variable.valueReference), (variable.name, cells[row + 5])


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
