"""`python -m codegen`: writes every generated file of the project; `--check` writes nothing,
names the stale files and exits 1 if there are any (CMake at configure time and
tests/python/test_documentation.py run it with --fast; that test checks the dependency tables
apart, as a slow test, tests/python/test_ssp.py the SSP figure,
tests/python/test_elementary_accuracy.py the coefficients,
tests/python/test_bad_input_table.py the bad-input tables and tests/python/test_engines.py the
engine table).
`python -m codegen new-model NAME --like MODEL` adds a model as a copy of another
(codegen/new_model.py), then writes the generated files.

    C, XML, CMake (codegen/generate.py)    variable tables, sequences, log categories, the
                                           modelDescription.xml and buildDescription.xml files
                                           (FMI 2 and FMI 3) and their copy at the root,
                                           cmake/generated.cmake, docs/fmi3_variables.md
    docs (codegen/docs.py)                 docs/variables.md, README.md's table of the FMUs,
                                           documentation/models.svg, dist/README.md
    pages (codegen/documentation.py)       each FMU's documentation/index.html, FMI 2 and FMI 3
    state layout (codegen/state_layout.py) docs/capabilities.md's FMU state layout and sizes
    dependency tables (codegen/sequence_tables.py)   docs/sequences.md, from the sympy reference
                                           (codegen/reference.py; half a minute; not with --fast)
    SSP figure (codegen/ssp_figure.py)     docs/round_trip_ssp.svg, RoundTrip.ssp's connection
                                           graph (lxml: not with --fast)
    elementary coefficients (codegen/elementary_coefficients.py)
                                           fmu_src/elementary/elementary_coefficients.h, derived
                                           with mpmath (about 10 s; not with --fast)
    bad-input tables (codegen/bad_input.py) docs/bad_input.md, from the C drivers in build/
                                           (only when they are built; not with --fast)
    engine table (codegen/engine_table.py) docs/cosimulation.md's table: the FMUs of dist/ in
                                           libcosim and Ecos against fmpy (only when the FMUs are
                                           built and the engines installed; not with --fast)

The stages run in this order, each reading what the ones before wrote."""
import argparse
import importlib
import sys

from codegen import docs, documentation, generate, new_model, state_layout
from codegen.models import ROOT, all_models


def deferred(module, function):
    """codegen.<module>.<function>, imported when the stage runs: the fast stages need the
    standard library only, the slow ones numpy, sympy, mpmath, fmpy or the engines."""
    return lambda: getattr(importlib.import_module(f"codegen.{module}"), function)()


# (name, {path: text} of its files, slow: skipped by --fast, why it cannot run here or None)
STAGES = [
    ("C, XML, CMake", generate.outputs, False, lambda: None),
    ("docs", docs.outputs, False, lambda: None),
    ("pages", lambda: documentation.outputs(all_models()), False, lambda: None),
    ("state layout", lambda: state_layout.outputs(all_models()), False, lambda: None),
    ("dependency tables", deferred("sequence_tables", "outputs"), True, lambda: None),
    ("SSP figure", deferred("ssp_figure", "outputs"), True, lambda: None),
    ("elementary coefficients", deferred("elementary_coefficients", "outputs"), True, lambda: None),
    ("bad-input tables", deferred("bad_input", "outputs"), True,
     deferred("bad_input", "why_not_here")),
    ("engine table", deferred("engine_table", "outputs"), True,
     deferred("engine_table", "why_not_here")),
]


def is_stale(path, text):
    return not path.is_file() or path.read_text() != text


def run(check, fast, only=None):
    """Every stage (fast: the fast ones; only: the named ones); the stale files."""
    stale = []
    for name, files, slow, why_not in STAGES:
        if (fast and slow) or (only and name not in only):
            continue
        reason = why_not()
        if reason:
            print(f"{name} not regenerated: {reason}")
            continue
        for path, text in files().items():
            if not is_stale(path, text):
                continue
            stale.append(path)
            if check:
                print(f"stale: {path.relative_to(ROOT)}")
            else:
                path.parent.mkdir(parents=True, exist_ok=True)
                path.write_text(text)
                print(f"wrote {path.relative_to(ROOT)}")
    if check and stale:
        print("run: python -m codegen")
    return stale


def new_model_command(argv):
    """python -m codegen new-model NAME --like MODEL (codegen/new_model.py), then every fast
    stage regenerated."""
    parser = argparse.ArgumentParser(prog="python -m codegen new-model",
                                     description=" ".join(new_model.__doc__.split("\n\n")[0].split()))
    parser.add_argument("name", metavar="NAME", help="the new model's name (its model identifier)")
    parser.add_argument("--like", metavar="MODEL", required=True,
                        help="the model whose folder is copied")
    args = parser.parse_args(argv)
    new_model.new_model(args.name, args.like)
    run(check=False, fast=True)


def main():
    if sys.argv[1:2] == ["new-model"]:
        new_model_command(sys.argv[2:])
        return
    summary, details = __doc__.split("\n\n", 1)
    parser = argparse.ArgumentParser(prog="python -m codegen", description=" ".join(summary.split()),
                                     epilog=details,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--check", action="store_true",
                        help="write nothing; name the stale files, exit 1 if there are any")
    parser.add_argument("--fast", action="store_true",
                        help="skip the stages that need more than the standard library, are slow or "
                             "need the build: the dependency tables, the SSP figure, the elementary "
                             "coefficients, the bad-input and engine tables (for CMake's configure "
                             "check)")
    parser.add_argument("--stage", action="append", choices=[name for name, *_ in STAGES],
                        help="only this stage (repeatable), e.g. --stage 'bad-input tables'")
    parser.add_argument("--figures", action="store_true",
                        help="first redraw model.png and documentation/tumbling_body.png "
                             "(needs dist/AngularKinematics.fmu)")
    args = parser.parse_args()
    if args.figures and not args.check:
        docs.redraw_figures()
    stale = run(args.check, args.fast, args.stage)
    sys.exit(1 if args.check and stale else 0)


if __name__ == "__main__":
    main()
