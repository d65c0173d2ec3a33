"""What `python -m codegen` writes is current, and what the built FMUs carry is what it says: each
FMU's documentation/index.html (FMI 2 and FMI 3) is its own model's page (its GUID, its prose, its
variables, its figures, no link that leaves the FMU), and the FMU-state sizes and header of
docs/capabilities.md are what each FMU serializes."""
import ctypes
import dataclasses
import posixpath
import re
import struct
import subprocess
import sys
import zipfile
import zlib
from html.parser import HTMLParser

import pytest
from fmpy import extract, read_model_description
from fmpy.fmi2 import FMU2Slave
from fmpy.fmi3 import FMU3Slave

from conftest import project
from fmi3_support import fmu3_path, unzipped
from codegen import __main__ as codegen_main
from codegen import generate, sequence_tables, state_layout
from codegen.documentation import sections_of
from codegen.models import ROOT, all_models, load

FMI_VERSIONS = ["2.0", "3.0"]


def test_generated_files_are_up_to_date(root):
    """Everything but the two slow tables (below and test_bad_input_table.py): C tables, XML,
    CMake lists, docs/variables.md, README's table, the FMU pages, the FMU-state layout."""
    done = subprocess.run([sys.executable, "-m", "codegen", "--check", "--fast"], cwd=root,
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stdout + done.stderr


@pytest.mark.slow  # the sympy reference: half a minute
def test_dependency_tables_are_up_to_date():
    stale = [path for path, text in sequence_tables.outputs().items() if path.read_text() != text]
    assert not stale, f"{stale} out of date: run python -m codegen"


def test_check_writes_nothing_and_names_the_stale_file(tmp_path, monkeypatch, capsys):
    current, stale = tmp_path / "current.txt", tmp_path / "stale.txt"
    current.write_text("same")
    stale.write_text("old")
    monkeypatch.setattr(codegen_main, "ROOT", tmp_path)
    monkeypatch.setattr(codegen_main, "STAGES", [
        ("one", lambda: {current: "same", stale: "new"}, False, lambda: None),
        ("slow", lambda: {stale: "from the slow stage"}, True, lambda: None),
        ("not here", lambda: {stale: "from a stage that cannot run"}, False, lambda: "no tool")])
    assert codegen_main.run(check=True, fast=True) == [stale]
    assert stale.read_text() == "old"
    printed = capsys.readouterr().out
    assert "stale: stale.txt" in printed and "not here not regenerated: no tool" in printed
    assert codegen_main.run(check=False, fast=True) == [stale]
    assert stale.read_text() == "new" and current.read_text() == "same"


def test_a_models_c_prefix_is_set_by_its_description_alone(monkeypatch):
    """Give every model another C_PREFIX: each generated C name of the model (value references,
    counts, GUID, tables) takes it, and no generated file keeps a name with the old one."""
    models = all_models()
    renamed = [dataclasses.replace(m, c_prefix=f"ZZ{k}") for k, m in enumerate(models)]
    monkeypatch.setattr(generate, "all_models", lambda: renamed)
    files = generate.outputs()
    for old, new in zip(models, renamed):
        header = files[new.folder / f"{new.name}_variables.h"]
        for name in ("GUID", "VARIABLES", "DERIVED_OUTPUTS", "N_INPUTS", "N_VALUE_REFERENCES"):
            assert f"{new.c_prefix}_{name}" in header
        for text in files.values():
            assert not re.search(rf"\b{old.c_prefix}_(VR_|VARIABLES|GUID|DERIVED|N_(INPUTS|OUTPUTS|STATES|VALUE))",
                                 text)


# --- each FMU's own page ---------------------------------------------------------------------

class Page(HTMLParser):
    """The images, the links (href and src), the ids, the h1 and h2 headings and the text of
    every table cell of a page, and its whole text."""

    def __init__(self):
        super().__init__()
        self.images, self.headings, self.cells, self.text, self._open = [], [], [], [], None
        self.links, self.ids, self.title = [], set(), None

    def handle_starttag(self, tag, attributes):
        attributes = dict(attributes)
        self.links += [attributes[a] for a in ("href", "src") if a in attributes]
        if "id" in attributes:
            self.ids.add(attributes["id"])
        if tag == "img":
            self.images.append(attributes["src"])
        if tag in ("h1", "h2", "td"):
            self._open = (tag, [])

    def handle_data(self, data):
        self.text.append(data)
        if self._open:
            self._open[1].append(data)

    def handle_endtag(self, tag):
        if self._open and tag == self._open[0]:
            text = "".join(self._open[1]).strip()
            if tag == "h1":
                self.title = text
            else:
                (self.headings if tag == "h2" else self.cells).append(text)
            self._open = None


def fmu_of(model, fmi_version):
    return fmu3_path(model) if fmi_version == "3.0" else ROOT / "dist" / f"{model}.fmu"


@pytest.fixture(scope="module", params=[(m, v) for m in project.MODELS for v in FMI_VERSIONS],
                ids=lambda p: f"{p[0]}-fmi{p[1][0]}")
def page(request):
    """(model name, FMI version, the parsed page its FMU carries, the FMU's file names, the FMU's
    GUID or instantiationToken)."""
    model, fmi_version = request.param
    path = fmu_of(model, fmi_version)
    with zipfile.ZipFile(path) as archive:
        parser = Page()
        parser.feed(archive.read("documentation/index.html").decode())
        names = set(archive.namelist())
    return model, fmi_version, parser, names, read_model_description(str(path)).guid


def test_page_names_its_own_guid_and_no_other_models(page):
    """Opened from each built FMU: the page names the FMU's own GUID (instantiationToken) and no
    GUID of another model, and is titled by its own model."""
    model, fmi_version, parser, _, guid = page
    text = "".join(parser.text)
    guids = {name: load(name).guid for name in project.MODELS}
    assert guids[model] == guid
    assert guid in text
    assert [name for name, g in guids.items() if g in text] == [model]
    assert parser.title == f"{model} (FMI {fmi_version})"


def test_page_holds_its_models_prose_and_tables(page):
    """The sections of docs/ that the model's description names (AttitudePropagator: all of
    docs/attitude_propagator.md), then its own variables, sequence items and capability flags;
    no other model's variables."""
    model, _, parser, _, _ = page
    prose = []
    for doc, sections in load(model).documentation:
        body = sections_of((ROOT / doc).read_text(), sections)
        prose += [line[3:].strip().replace("`", "") for line in body.splitlines()
                  if line.startswith("## ")]
    assert prose, f"{model}'s description names no prose"
    items = ["Sequence items"] if any(s.type == "Sequence" for s in load(model).scalars) else []
    assert parser.headings == prose + [f"Variables of {model}"] + items + ["Capability flags"]


def test_page_lists_every_variable(page):
    """FMI 2: every scalar variable with its unit, display unit and value reference; FMI 3: every
    variable (arrays) with its value reference; both as the FMU's modelDescription.xml says."""
    model, fmi_version, parser, _, _ = page
    cells = parser.cells
    description = read_model_description(str(fmu_of(model, fmi_version)))
    variables = description.modelVariables
    if fmi_version == "3.0":
        rows = {(cells[i], cells[i + 5]) for i in range(len(cells) - 5)}
        for variable in variables:
            assert (variable.name, str(variable.valueReference)) in rows, variable.name
        return
    start = table_start(cells, variables)
    for variable in variables:
        row = cells.index(label_of(variable.name, variables, cells, start), start)
        assert cells[row + 3] == (variable.declaredType.unit or "")
        assert cells[row + 4] == (variable.declaredType.displayUnit or "")
        assert refers_to(cells[row + 5], variable.valueReference), (variable.name, cells[row + 5])


def table_start(cells, variables):
    """Where the variable table begins among the page's cells: the row of its first variable
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


def test_page_states_the_capability_flags(page):
    model, fmi_version, parser, _, _ = page
    cells = parser.cells
    description = read_model_description(str(fmu_of(model, fmi_version)))
    # Columns in the order of modelDescription.xml: Model Exchange, then Co-Simulation.
    row = cells.index("canHandleVariableCommunicationStepSize")
    assert cells[row + 1:row + 3] == ["n/a", "true"]
    row = cells.index("canGetAndSetFMUstate" if fmi_version == "2.0" else "canGetAndSetFMUState")
    assert cells[row + 1:row + 3] == [str(description.modelExchange.canGetAndSetFMUstate).lower(),
                                      str(description.coSimulation.canGetAndSetFMUstate).lower()]


def test_every_link_of_the_page_resolves_inside_the_fmu(page):
    """Every href and src, opened from the unzipped FMU, names a file of the archive or an
    anchor of the page: nothing points outside the FMU."""
    _, _, parser, names, _ = page
    assert parser.links, "the page has links and figures"
    for link in parser.links:
        assert "://" not in link and not link.startswith(("/", "mailto:")), link
        target, _, anchor = link.partition("#")
        if target:
            resolved = posixpath.normpath(posixpath.join("documentation", target))
            assert resolved in names, f"{link} -> {resolved} is not in the FMU"
        else:
            assert anchor in parser.ids, f"{link}: no element with that id"


def test_page_shows_its_models_figures_and_the_icon(page):
    model, _, parser, names, _ = page
    figures = [src for src, _, _ in load(model).figures]
    assert parser.images[:-1] == figures
    assert parser.images[-1] in ("../model.png", "../terminalsAndIcons/icon.png")
    assert {f"documentation/{f}" for f in figures} <= names


def test_icon_and_figure_are_png_images(root):
    for path, size in ((root / "model.png", (256, 256)),
                       (root / "documentation" / "tumbling_body.png", (900, 585))):
        data = path.read_bytes()
        assert data.startswith(b"\x89PNG\r\n\x1a\n"), path
        assert (int.from_bytes(data[16:20], "big"), int.from_bytes(data[20:24], "big")) == size


# --- the FMU state: docs/capabilities.md against what each FMU serializes ---------------------

def serialized_state(model, fmi_version, tmp_path):
    """(fmiXSerializedFMUstateSize's answer, the serialized bytes, the GUID) of a co-simulation
    instance just out of initialization."""
    if fmi_version == "2.0":
        unzipdir = extract(str(fmu_of(model, "2.0")), unzipdir=str(tmp_path))
        description = read_model_description(unzipdir)
        fmu = FMU2Slave(guid=description.guid, unzipDirectory=unzipdir, modelIdentifier=model,
                        instanceName="state")
        fmu.instantiate()
        fmu.setupExperiment(startTime=0.0)
        fmu.enterInitializationMode()
        fmu.exitInitializationMode()
        state, size_of = fmu.getFMUstate(), fmu.fmi2SerializedFMUstateSize
        free = fmu.freeFMUstate
    else:
        unzipdir, description = unzipped(model)
        fmu = FMU3Slave(guid=description.guid, unzipDirectory=unzipdir, modelIdentifier=model,
                        instanceName="state")
        fmu.instantiate()
        fmu.enterInitializationMode()
        fmu.exitInitializationMode()
        state, size_of = fmu.getFMUState(), fmu.fmi3SerializedFMUStateSize
        free = fmu.freeFMUState
    size = ctypes.c_size_t()
    size_of(fmu.component, state, ctypes.byref(size))
    data = (fmu.serializeFMUstate if fmi_version == "2.0" else fmu.serializeFMUState)(state)
    free(state)
    fmu.terminate()
    fmu.freeInstance()
    return size.value, bytes(data), description.guid


@pytest.mark.parametrize("fmi_version", FMI_VERSIONS)
@pytest.mark.parametrize("name", project.MODELS)
def test_serialized_state_is_the_documented_layout(name, fmi_version, tmp_path):
    """The size docs/capabilities.md gives (codegen/state_layout.py) is what the FMU answers and
    writes, and its header holds the documented magic, version, size, GUID and CRC-32."""
    size, data, guid = serialized_state(name, fmi_version, tmp_path)
    model = load(name)
    expected = state_layout.size_of(model, fmi_version)
    documented = (ROOT / "docs" / "capabilities.md").read_text()
    fmi2, fmi3 = state_layout.size_of(model, "2.0"), state_layout.size_of(model, "3.0")
    assert f"| {name} | {state_layout.counts(model)[0]} | {state_layout.counts(model)[1]} | " \
           f"{fmi2} | {fmi3} |" in documented
    assert size == len(data) == expected
    form = state_layout.FORMATS[fmi_version]

    def at(prefix, fmt):
        return struct.unpack_from(fmt, data, state_layout.evaluate(
            state_layout.offset_of(fmi_version, prefix), model))[0]

    assert at("magic", "<8s") == form["magic"].encode()
    assert at("format version", "<I") == form["version"]
    assert at("total size", "<I") == expected
    assert at("GUID", "<40s").rstrip(b"\0").decode() == guid
    assert at("CRC-32", "<I") == zlib.crc32(data[:-4])
