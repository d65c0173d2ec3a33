"""The dependency tables of docs/sequences.md: which inputs each output depends on, per sequence
and as the union a static <ModelStructure> lists, found on the independent sympy reference by
tests/python/sequence_dependencies.py (half a minute; needs numpy and sympy)."""
import sys

from codegen.models import ROOT

SEQUENCES_PAGE = ROOT / "docs" / "sequences.md"
FIRST_TABLE = "### AngularKinematics ("  # the tables run from here to the next "## " section


def outputs():
    sys.path.insert(0, str(ROOT / "tests" / "python"))  # the reference and its table printer
    from sequence_dependencies import tables
    text = SEQUENCES_PAGE.read_text()
    start = text.index(FIRST_TABLE)
    end = text.index("\n## ", start)
    return {SEQUENCES_PAGE: text[:start] + tables() + text[end:]}
