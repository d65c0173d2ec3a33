"""The project's elementary functions (fmu_src/elementary/) against mpmath, on a bounded seeded
sample of every argument kind of tools/elementary/accuracy.py (random doubles, [-10, 10], near
multiples of pi/2 with the known hard cases, tiny, huge, subnormal; atan2 pairs with extreme
ratios): at most 1 ulp everywhere. The long run (10^7 arguments per function) is documented in
docs/elementary.md. Also: the committed coefficient header is what python -m codegen writes."""
import pytest

from codegen import elementary_coefficients
from tools.elementary import accuracy

ARGUMENTS_PER_FUNCTION = 3000
SEED = 20261125


@pytest.fixture(scope="module")
def table():
    assert accuracy.LIBRARY.is_file(), (f"{accuracy.LIBRARY} is missing: build it first "
                                        "(bash scripts/build.sh)")
    return accuracy.run(ARGUMENTS_PER_FUNCTION, SEED)


@pytest.mark.parametrize("name", ["sin", "cos", "atan", "atan2", "asin", "acos"])
def test_at_most_one_ulp(table, name, report):
    rows = {kind: stats for (function, kind), stats in table.items() if function == name}
    assert rows, f"no argument kind checked {name}"
    count, worst, argument, correct = accuracy.summary(table)[name]
    report(f"{name}: {count} arguments of {len(rows)} kinds, worst {worst:.3f} ulp (at {argument}), "
           f"{100 * correct / count:.2f} % correctly rounded")
    for kind, (n, kind_worst, kind_argument, _) in rows.items():
        assert n > 0
        assert kind_worst <= 1.0, f"{name}, {kind}: {kind_worst:.3f} ulp at {kind_argument}"


def test_error_measure_sees_one_ulp():
    """The measure itself: the double after the correctly rounded value is about 1 ulp off."""
    from mpmath.libmp import from_float, mpf_atan
    exact = mpf_atan(from_float(0.5), accuracy.PRECISION)
    rounded = float(accuracy.mpmath_value(exact))
    assert accuracy.ulp_error(rounded, exact) < 0.5
    import math
    assert 0.5 < accuracy.ulp_error(math.nextafter(rounded, 2.0), exact) < 1.5


def test_coefficients_are_current():
    """fmu_src/elementary/elementary_coefficients.h is what python -m codegen writes
    (codegen/elementary_coefficients.py, derived with mpmath)."""
    for path, text in elementary_coefficients.outputs().items():
        assert path.read_text() == text, f"{path} is out of date: run .venv/bin/python -m codegen"
