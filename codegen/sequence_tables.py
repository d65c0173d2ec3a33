"""The dependency tables of docs/sequences.md: which inputs each output depends on for every
rotation sequence, and the union over sequences (and, for EulerRates, over both frames) that a
static <ModelStructure> must list. Computed on the independent sympy reference
(codegen/reference.py, reference.dependencies; half a minute, needs numpy and sympy); the core is
checked against the same sets by test_sequences_core.py::test_dependencies_match_reference.

    .venv/bin/python -m codegen.sequence_tables   print them
    .venv/bin/python -m codegen                   writes them into docs/sequences.md
"""
import argparse

import numpy as np

from codegen import reference
from codegen.models import ROOT
from codegen.project import SEQUENCES

SEQUENCES_PAGE = ROOT / "docs" / "sequences.md"
FIRST_TABLE = "### AngularKinematics ("  # the tables run from here to the next "## " section


def short(inputs, order):
    return ", ".join(name for name in order if name in inputs) or "(none)"


def table(title, outputs, input_order, per_sequence):
    lines = [f"### {title}", "",
             "| output | depends on (union) | sequences for which the union is exact |", "|---|---|---|"]
    for output in outputs:
        sets = [deps[output] for deps in per_sequence.values()]
        union = set().union(*sets)
        exact = f"{sum(s == union for s in sets)} of {len(sets)}"
        lines.append(f"| {output} | {short(union, input_order)} | {exact} |")
    return "\n".join(lines)


def tables():
    rng = np.random.default_rng(20261121)
    states = rng.uniform(-2, 2, (2, 9))
    forward, rates = {}, {}
    for name in SEQUENCES:
        forward[name] = reference.dependencies(
            lambda x: reference.kinematics_and_derived_values(name, x), reference.KINEMATICS_INPUTS,
            reference.KINEMATICS_OUTPUTS + reference.DERIVED_OUTPUTS, states)
        for frame in ("fixed", "body"):
            rates[name, frame] = reference.dependencies(
                lambda x: reference.rates_values(name, frame, x), reference.RATES_INPUTS,
                reference.RATES_OUTPUTS, states)
    parts = [table("AngularKinematics (q[1..4]: theta[1..3] for every sequence; "
                   "singularity_distance: theta[2] alone)",
                   reference.KINEMATICS_OUTPUTS + reference.DERIVED_OUTPUTS,
                   reference.KINEMATICS_INPUTS, forward),
             table("EulerRates (union over sequences and over the frame parameter)",
                   reference.RATES_OUTPUTS, reference.RATES_INPUTS, rates)]
    for frame in ("fixed", "body"):
        parts.append(table(f"EulerRates, {frame}-frame inputs only", reference.RATES_OUTPUTS,
                           reference.RATES_INPUTS,
                           {name: rates[name, f] for name, f in rates if f == frame}))
    return "\n\n".join(parts) + "\n"


def outputs():
    text = SEQUENCES_PAGE.read_text()
    start = text.index(FIRST_TABLE)
    end = text.index("\n## ", start)
    return {SEQUENCES_PAGE: text[:start] + tables() + text[end:]}


def main():
    argparse.ArgumentParser(description=__doc__.split("\n\n")[0]).parse_args()
    print(tables(), end="")


if __name__ == "__main__":
    main()
