"""Reads the model descriptions (fmu_src/models/<Model>/description.py) and expands them into
scalar variables: what the generator writes from and what the Python tests read."""
import importlib.util
import pathlib
import re
from dataclasses import dataclass, field
from itertools import product

from codegen import project

ROOT = pathlib.Path(__file__).resolve().parent.parent
MODELS_DIR = ROOT / "fmu_src" / "models"


@dataclass
class Scalar:
    """One FMI 2 ScalarVariable: an element of an array of the description, or a scalar."""
    name: str
    base: str              # the description's variable name: "R" for "R[2,3]"
    indices: tuple         # 1-based indices within the array; () for a scalar
    vr: int
    causality: str         # input, output, parameter, local
    type: str              # declared type: Angle, ..., Sequence, Frame
    fmi_type: str          # Real or Integer (Enumerations are Integers in the C table)
    group: str             # outputs: main, lazy, or derived (computed_by)
    start: float
    min: float
    max: float
    description: str
    out_of_range: str = ""  # parameters: why a value outside [min, max] is refused
    depends: list = field(default_factory=list)  # value references of inputs and states
    state: bool = False    # a continuous state (model exchange)
    derivative_of: int = None  # the value reference of the state this is der() of
    initial_depends: list = field(default_factory=list)  # states: parameters their start is from
    computed_by: tuple = None  # derived outputs: (core function, argument names...)


@dataclass
class Model:
    name: str
    c_prefix: str          # of the generated C names (description.py's C_PREFIX, nowhere else)
    guid: str
    description: str
    sources: list          # relative to fmu_src/
    headers: list
    core_sources: list     # the core's sources it calls (description.py's CORE), fmu_src/-relative
    core_headers: list     # the core's headers those and the model's sources include
    core_tests: list       # the unit tests of its core files (description.py's CORE_TESTS), root-relative
    cross_check_outputs: list  # the outputs of its cross-check results (CROSS_CHECK_OUTPUTS), FMI 2 names
    capabilities: dict
    enumerations: dict
    arrays: list           # the description's entries, as written
    scalars: list          # expanded, in value-reference order

    documentation: list    # [(docs page, its sections or None for all)]: the FMU's prose
    figures: list          # [(file of documentation/, alt text, caption)]

    @property
    def folder(self):
        return MODELS_DIR / self.name

    @property
    def model_description(self):
        """The FMI 2.0 modelDescription.xml, in the model's folder like every other file of it."""
        return model_description_path(self.name)

    def scalar(self, name):
        return next(s for s in self.scalars if s.name == name)

    def by_causality(self, causality):
        return [s for s in self.scalars if s.causality == causality]

    @property
    def states(self):
        return [s for s in self.scalars if s.state]

    @property
    def derivatives(self):
        """der(x) of each state, in the order of the states."""
        by_state = {s.derivative_of: s for s in self.scalars if s.derivative_of is not None}
        return [by_state[s.vr] for s in self.states]

    def input_dependencies(self, scalar):
        """The inputs among a scalar's dependencies (the C table lists only those)."""
        return [vr for vr in scalar.depends if self.scalars_by_vr[vr].causality == "input"]

    def arguments_of(self, scalar):
        """The scalars a derived output (`computed_by`) is computed from."""
        return _arguments_of(scalar, self.scalars)

    @property
    def scalars_by_vr(self):
        return {s.vr: s for s in self.scalars}


def _load_module(path):
    spec = importlib.util.spec_from_file_location(f"description_{path.parent.name}", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def _element_name(base, indices):
    """theta[2], R[1,3]; a derivative "der(q)" names its elements der(q[2]) (FMI 2.0, 2.2.9)."""
    if base.startswith("der(") and indices:
        return f"der({_element_name(base[4:-1], indices)})"
    return f"{base}[{','.join(str(i) for i in indices)}]" if indices else base


def _included_core_headers(sources):
    """The headers of fmu_src/core/ and fmu_src/elementary/ that the sources include, directly or
    through other headers, in the order of project.CORE_HEADERS."""
    fmu_src = ROOT / "fmu_src"
    folders = [fmu_src / f for f in ("core", "elementary", "models", "runtime", "common")]
    found, todo = set(), [fmu_src / s for s in sources]
    while todo:
        path = todo.pop()
        for name in re.findall(r'^#include "([^"]+)"', path.read_text(), re.MULTILINE):
            header = next((f / name for f in [path.parent] + folders if (f / name).is_file()),
                          # a generated core header that this run writes first
                          next((fmu_src / h for h in project.CORE_HEADERS
                                if h.split("/")[-1] == name), None))
            if header is not None and header not in found:
                found.add(header)
                if header.is_file():
                    todo.append(header)
    included = {h.relative_to(fmu_src).as_posix() for h in found}
    core = {h for h in included if h.split("/")[0] in ("core", "elementary")}
    assert core <= set(project.CORE_HEADERS), f"not in project.CORE_HEADERS: {core - set(project.CORE_HEADERS)}"
    return [h for h in project.CORE_HEADERS if h in core]


def load(name):
    d = _load_module(MODELS_DIR / name / "description.py")
    enumerations = dict(project.ENUMERATIONS)
    enumerations.update(getattr(d, "ENUMERATIONS", {}))
    scalars = []
    for entry in d.VARIABLES:
        shape = tuple(entry.get("shape", ()))
        index_sets = list(product(*(range(1, n + 1) for n in shape))) if shape else [()]
        for offset, indices in enumerate(index_sets):
            declared = entry["type"]
            if declared in enumerations:
                items = [item for item, _ in enumerations[declared]["items"]]
                fmi_type = "Integer"
                start = float(items.index(entry["start"]) + 1)
                low, high = 1.0, float(len(items))
                listed = [f"{k} {item}" for k, item in enumerate(items, 1)]
                listed = ", ".join(listed) if len(items) <= 2 else f"{listed[0]} .. {listed[-1]}"
                out_of_range = f"is not an item of the Enumeration {declared} ({listed})"
            else:
                fmi_type = "Real"
                start = entry.get("start", 0.0)
                start = float(start(*indices) if callable(start) else start)
                low, high = float(entry.get("min", 0.0)), float(entry.get("max", 0.0))
                note = entry.get("range_note")
                out_of_range = f"is outside [{low:g}, {high:g}]" + (f", {note}" if note else "")
            keys = dict(zip("ij", indices))
            scalars.append(Scalar(
                name=_element_name(entry["name"], indices), base=entry["name"], indices=indices,
                vr=entry["vr"] + offset, causality=entry["causality"], type=declared,
                fmi_type=fmi_type, group=_group(entry), start=start, min=low,
                max=high, description=entry["description"].format(**keys),
                out_of_range=out_of_range if entry["causality"] == "parameter" else "",
                depends=entry.get("depends", []), state=entry.get("state", False),
                initial_depends=entry.get("initial_depends", []),
                computed_by=tuple(entry["computed_by"]) if "computed_by" in entry else None))
            if "derivative_of" in entry:
                scalars[-1].derivative_of = _element_name(entry["derivative_of"], indices)
    by_name = {s.name: s for s in scalars}
    for s in scalars:
        if s.derivative_of is not None:
            s.derivative_of = by_name[s.derivative_of].vr

    # Dependencies: whole inputs ("theta") or, per element, a function of the indices.
    def resolve(names):
        vrs = []
        for name in names:
            if name in by_name:
                vrs.append(by_name[name].vr)
            else:
                vrs += [t.vr for t in scalars if t.base == name]
        return sorted(set(vrs))  # an element named twice (e.g. by two terms) is one dependency

    for s in sorted(scalars, key=lambda s: s.vr):
        if s.computed_by and "depends" not in _entry(d, s.base):
            # A derived output depends on what its arguments depend on (their vrs are lower).
            s.depends = sorted({vr for t in _arguments_of(s, scalars) for vr in t.depends})
            continue
        wanted = s.depends(*s.indices) if callable(s.depends) else s.depends
        s.depends = resolve(wanted)
        assert all(t.causality == "input" or t.state for t in scalars if t.vr in s.depends), \
            f"{s.name}: depends on a variable that is neither an input nor a state"
        s.initial_depends = resolve(s.initial_depends)
    scalars.sort(key=lambda s: s.vr)
    _check(name, scalars)
    folder = f"models/{name}"
    sources = ([f"{folder}/{source}" for source in d.SOURCES] +
               [f"{folder}/{name}_variables.c", f"{folder}/{name}_derived.c"])
    assert set(d.CORE) <= set(project.CORE_SOURCES), f"{name}: CORE names a file not in the core"
    core_sources = [s for s in project.CORE_SOURCES if s in d.CORE]
    return Model(
        name=d.NAME, c_prefix=d.C_PREFIX, guid=d.GUID, description=d.DESCRIPTION,
        documentation=d.DOCUMENTATION, figures=getattr(d, "FIGURES", []),
        sources=sources, headers=[f"{folder}/{name}_variables.h"], core_sources=core_sources,
        core_headers=_included_core_headers(core_sources + sources),
        core_tests=getattr(d, "CORE_TESTS", []),
        cross_check_outputs=d.CROSS_CHECK_OUTPUTS,
        capabilities=d.CAPABILITIES, enumerations=enumerations, arrays=d.VARIABLES,
        scalars=scalars)


def _group(entry):
    """An output computed from outputs is of the derived group: computed only when read."""
    if "computed_by" in entry:
        assert "group" not in entry, f"{entry['name']}: computed_by outputs are of their own group"
        return "derived"
    return entry.get("group", "main")


def _arguments_of(scalar, scalars):
    return [t for t in scalars if t.base in scalar.computed_by[1:]]


def _entry(description, base):
    return next(e for e in description.VARIABLES if e["name"] == base)


def _check_derived(name, scalars):
    """A derived output (`computed_by`) is computed from outputs of its own model that come
    before it in value-reference order."""
    for s in scalars:
        if not s.computed_by:
            continue
        assert s.causality == "output", f"{name}: {s.name} is computed_by a core function: an output"
        for argument in s.computed_by[1:]:
            assert any(t.base == argument for t in scalars), (
                f"{name}: {s.name}: no variable {argument} to compute it from")
        for t in _arguments_of(s, scalars):
            assert t.causality == "output" and t.vr < s.vr, (
                f"{name}: {s.name} is computed from {t.name}: an output with a lower value "
                "reference")


def _check(name, scalars):
    """The rules the FMI layers rely on (models/model.h)."""
    _check_derived(name, scalars)
    vrs = [s.vr for s in scalars]
    assert len(set(vrs)) == len(vrs), f"{name}: a value reference is used twice"
    inputs = sorted(s.vr for s in scalars if s.causality == "input")
    assert inputs == list(range(len(inputs))), (
        f"{name}: the inputs must hold the value references 0 .. n_inputs - 1 (models/model.h)")
    for s in scalars:
        assert re.fullmatch(r"[A-Za-z_][A-Za-z0-9_]*(\[[0-9,]+\])?|der\([A-Za-z_][A-Za-z0-9_]*"
                            r"(\[[0-9,]+\])?\)", s.name), s.name
    states = [s for s in scalars if s.state]
    derivatives = [s for s in scalars if s.derivative_of is not None]
    assert sorted(d.derivative_of for d in derivatives) == sorted(s.vr for s in states), (
        f"{name}: every state needs exactly one derivative and every derivative a state")
    assert all(s.causality in ("output", "local") for s in states + derivatives), (
        f"{name}: states and derivatives are outputs or locals")


def model_description_path(name):
    """fmu_src/models/<name>/modelDescription.xml: the FMI 2.0 model description of every model
    (the repository root's modelDescription.xml is a generated copy of one, see project.py)."""
    return MODELS_DIR / name / "modelDescription.xml"


def all_models():
    return [load(name) for name in project.MODELS]
