"""Derives the constants of the project's elementary functions (fmu_src/elementary/) for
fmu_src/elementary/elementary_coefficients.h: the minimax polynomials (Remez exchange in mpmath,
relative error), the parts of pi/2 for the Cody-Waite reduction, the table of atan(k/16) and the
bits of 2/pi for the Payne-Hanek reduction. A stage of python -m codegen (about 10 s: not with
--fast); tests/python/test_elementary_accuracy.py checks the committed header against it."""
import mpmath
from mpmath import mp, mpf

from codegen.models import ROOT

HEADER = ROOT / "fmu_src" / "elementary" / "elementary_coefficients.h"
PREC = 256  # bits of every mpmath computation

# The reduced arguments the kernels see (fmu_src/elementary/elementary.h): |r| <= pi/4 plus the
# rounding of the quotient n, and |u| <= 1/32 after the atan breakpoints k/16, with room to spare.
SINCOS_BOUND = mpf("0.786")
ATAN_BOUND = mpf(1) / 32 + mpf(2) ** -40
TERMS = {"sin": 7, "cos": 6, "atan": 4}


def remez(g, weight, a, b, n, iterations=12, grid=1500):
    """Coefficients c_0..c_{n-1} of the polynomial p minimizing max |weight(z) (p(z) - g(z))| on
    [a, b]; returns them with the levelled error."""
    # Chebyshev extrema without the left end: the weights vanish there (relative error at z = 0).
    nodes = [a + (b - a) * (1 - mpmath.cos(mpmath.pi * (i + 1) / (n + 1))) / 2 for i in range(n + 1)]
    zs = [a + (b - a) * (1 - mpmath.cos(mpmath.pi * (i + mpf(1) / 2) / grid)) / 2
          for i in range(grid)]
    gs = [g(z) for z in zs]
    ws = [weight(z) for z in zs]
    coefficients, level = None, None
    for _ in range(iterations):
        matrix = mpmath.matrix(n + 1, n + 1)
        rhs = mpmath.matrix(n + 1, 1)
        for i, z in enumerate(nodes):
            for j in range(n):
                matrix[i, j] = z ** j
            matrix[i, n] = (-1) ** i / weight(z)
            rhs[i] = g(z)
        solution = mpmath.lu_solve(matrix, rhs)
        coefficients = [solution[j] for j in range(n)]
        level = abs(solution[n])
        errors = [w * (mpmath.polyval(coefficients[::-1], z) - gz) for z, gz, w in zip(zs, gs, ws)]
        # One extremum per run of equal sign, then the n + 1 largest that still alternate.
        runs = []
        for z, e in zip(zs, errors):
            if runs and (e >= 0) == (runs[-1][1] >= 0):
                if abs(e) > abs(runs[-1][1]):
                    runs[-1] = (z, e)
            else:
                runs.append((z, e))
        while len(runs) > n + 1:
            drop = 0 if abs(runs[0][1]) < abs(runs[-1][1]) else len(runs) - 1
            runs.pop(drop)
        if len(runs) < n + 1:
            raise ArithmeticError(f"Remez: {len(runs)} alternations, {n + 1} needed")
        nodes = [z for z, _ in runs]
    return coefficients, level


def remez_doubles(g, weight, a, b, n):
    """remez, with coefficients rounded to doubles one at a time from the lowest degree, each time
    fitting the higher ones again to what the rounded ones leave."""
    fixed = []
    for j in range(n):
        def rest(z, j=j):
            return (g(z) - mpmath.polyval([mpf(c) for c in fixed[::-1]], z)) / z ** j if j else g(z)
        coefficients, _ = remez(rest, lambda z, j=j: weight(z) * z ** j, a, b, n - j)
        fixed.append(float(coefficients[0]))
    return fixed


def max_relative_error(function, approximation, bound, points=3000):
    worst = mpf(0)
    for i in range(1, points + 1):
        r = bound * i / points
        exact = function(r)
        worst = max(worst, abs((approximation(r) - exact) / exact))
    return worst


def polynomials():
    """The three kernels as (name, coefficients as doubles, bound on their relative error)."""
    def series_guard(f, limit):
        return lambda z: limit if z == 0 else f(z)

    zmax = SINCOS_BOUND ** 2
    sin_g = series_guard(lambda z: (mpmath.sin(mpmath.sqrt(z)) - mpmath.sqrt(z)) / z ** mpf(1.5),
                         mpf(-1) / 6)
    sin_w = lambda z: z / mpmath.sinc(mpmath.sqrt(z)) if z else mpf(0)  # noqa: E731
    cos_g = series_guard(lambda z: (mpmath.cos(mpmath.sqrt(z)) - 1 + z / 2) / z ** 2, mpf(1) / 24)
    cos_w = lambda z: z ** 2 / mpmath.cos(mpmath.sqrt(z))  # noqa: E731
    amax = ATAN_BOUND ** 2
    atan_g = series_guard(lambda z: (mpmath.atan(mpmath.sqrt(z)) - mpmath.sqrt(z)) / z ** mpf(1.5),
                          mpf(-1) / 3)
    atan_w = lambda z: z * mpmath.sqrt(z) / mpmath.atan(mpmath.sqrt(z)) if z else mpf(0)  # noqa: E731
    tiny = mpf(2) ** -30
    result = []
    for name, g, w, top, function, assemble in (
            ("sin", sin_g, sin_w, zmax, mpmath.sin, lambda r, p: r + r ** 3 * p),
            ("cos", cos_g, cos_w, zmax, mpmath.cos, lambda r, p: 1 - r * r / 2 + r ** 4 * p),
            ("atan", atan_g, atan_w, amax, mpmath.atan, lambda r, p: r + r ** 3 * p)):
        doubles = remez_doubles(g, w, top * tiny, top, TERMS[name])
        bound = SINCOS_BOUND if name != "atan" else ATAN_BOUND
        error = max_relative_error(
            function, lambda r: assemble(r, mpmath.polyval([mpf(c) for c in doubles[::-1]], r * r)),
            bound)
        result.append((name, doubles, error))
    return result


def pio2_parts():
    """pi/2 = P1 + P2 + P3 + P4 + O(2^-150): P1..P3 of 33 bits each (n P_i is exact for
    |n| < 2^20), P4 the rounded rest."""
    half_pi = mpmath.pi / 2
    parts, rest = [], half_pi
    for k in range(1, 4):
        scale = mpf(2) ** (33 * k - 1)
        part = mpmath.floor((half_pi - sum(parts, mpf(0))) * scale) / scale
        parts.append(part)
    rest = half_pi - sum(parts, mpf(0))
    parts.append(mpf(float(rest)))
    for part in parts[:3]:
        mantissa, _ = mpmath.frexp(part)
        assert (mantissa * 2 ** 33) == int(mantissa * 2 ** 33), "a part has more than 33 bits"
    return [float(p) for p in parts]


ARC_INTERVALS = 32  # atan on [0, 1] in intervals of width 1/32 (the first by the odd polynomial)
ARC_DEGREE = 10  # Taylor degree about each interval's centre: |h|^11 <= 2^-66 for |h| <= 1/64
# atan2's four quadrants: (x < 0, |y| > |x|) -> base + sign atan(min/max)
ARC_QUADRANTS = ((0, 1), ("pi/2", -1), ("pi", -1), ("pi/2", 1))


def hi26(value):
    """value rounded to 26 significant bits: its product with a Veltkamp half is exact."""
    mantissa, exponent = mpmath.frexp(value)
    return float(mpmath.ldexp(mpmath.nint(mantissa * 2 ** 26), exponent - 26))


def arc_tables():
    """Tables of the arc kernel (elementary_arc_kernel.h): for j = 1 .. ARC_INTERVALS, centre
    c_j = (2 j + 1)/64 and the Taylor coefficients of atan about it; atan(c_j) with each of the
    quadrants' bases as hi + lo; the slope 1/(1 + c_j^2) as a 26-bit part plus the rounded rest."""
    bases = {0: mpf(0), "pi/2": mpmath.pi / 2, "pi": mpmath.pi}
    rows = {"centre": [], "slope_hi": [], "slope_lo": []}
    heads = {(q, part): [] for q in range(4) for part in ("HI", "LO")}
    taylor = []
    for j in range(ARC_INTERVALS + 1):
        c = mpf(2 * j + 1) / 64 if j else mpf(0)
        coefficients = mpmath.taylor(mpmath.atan, c, ARC_DEGREE)
        rows["centre"].append(float(c))
        slope_hi = hi26(coefficients[1])
        rows["slope_hi"].append(slope_hi)
        rows["slope_lo"].append(float(coefficients[1] - slope_hi))
        for q, (base, sign) in enumerate(ARC_QUADRANTS):
            hi, lo = split(bases[base] + sign * coefficients[0])
            heads[(q, "HI")].append(hi)
            heads[(q, "LO")].append(lo)
        taylor.append([float(a) if j else 0.0 for a in coefficients[2:]])
    lines = [
        f"/* The arc kernel: atan(c_j + h) = atan(c_j) + s_j h + a_2 h^2 + ... + a_{ARC_DEGREE} "
        f"h^{ARC_DEGREE} (Taylor),",
        f" * c_j = (2 j + 1)/64 for j = 1..{ARC_INTERVALS} (the row j = 0 is unused: the odd "
        "polynomial serves [0, 1/32)).",
        " * Heads: base + sign atan(c_j) as hi + lo for the quadrants (base, sign) = (0, +), "
        "(pi/2, -), (pi, -), (pi/2, +).",
        " * Slopes s_j = 1/(1 + c_j^2) as a 26-bit part (exact products with Veltkamp halves) "
        "plus the rounded rest. */",
        "#define AK_ARC_CENTRE {" + ", ".join(v.hex() for v in rows["centre"]) + "}",
        "#define AK_ARC_SLOPE_HI {" + ", ".join(v.hex() for v in rows["slope_hi"]) + "}",
        "#define AK_ARC_SLOPE_LO {" + ", ".join(v.hex() for v in rows["slope_lo"]) + "}",
    ]
    for part in ("HI", "LO"):
        lines.append(f"#define AK_ARC_HEAD_{part} {{ \\")
        for q in range(4):
            end = ", \\" if q < 3 else " \\"
            lines.append("    {" + ", ".join(v.hex() for v in heads[(q, part)]) + "}" + end)
        lines.append("}")
    lines.append(f"#define AK_ARC_TAYLOR {{ \\")
    for j, row in enumerate(taylor):
        end = ", \\" if j < len(taylor) - 1 else " \\"
        lines.append("    {" + ", ".join(v.hex() for v in row) + "}" + end)
    lines += ["}", ""]
    return lines


def split(value):
    hi = float(value)
    return hi, float(value - mpf(hi))


def two_over_pi_words(count=48):
    """The first 32 count bits of the fraction 2/pi (2/pi < 1) as 32-bit words, most significant
    first."""
    with mp.workprec(32 * count + 64):
        value = int(mpmath.floor(2 / mpmath.pi * mpf(2) ** (32 * count)))
    return [(value >> (32 * (count - 1 - i))) & 0xFFFFFFFF for i in range(count)]


def render():
    mp.prec = PREC
    lines = [
        "/* Generated by python -m codegen (codegen/elementary_coefficients.py; mpmath, "
        f"{PREC}-bit arithmetic):",
        " * do not edit. Constants of the elementary functions in elementary.h and "
        "elementary_*.c. */",
        "#ifndef ANGULAR_KINEMATICS_ELEMENTARY_COEFFICIENTS_H",
        "#define ANGULAR_KINEMATICS_ELEMENTARY_COEFFICIENTS_H",
        "",
    ]
    p1, p2, p3, p4 = pio2_parts()
    lines += [
        "/* pi/2 = P1 + P2 + P3 + P4 + O(2^-150); P1, P2, P3 have 33 significant bits at most, so",
        " * n P_i is exact for |n| < 2^20 (Cody-Waite). */",
        f"#define AK_PIO2_1 {p1.hex()}",
        f"#define AK_PIO2_2 {p2.hex()}",
        f"#define AK_PIO2_3 {p3.hex()}",
        f"#define AK_PIO2_4 {p4.hex()}",
        "/* pi/2, pi/4, pi as hi + lo (lo the rounded rest); 3 pi/4 and 2/pi rounded. */",
    ]
    for name, value in (("PIO2", mpmath.pi / 2), ("PIO4", mpmath.pi / 4), ("PI", mpmath.pi)):
        hi, lo = split(value)
        lines += [f"#define AK_{name}_HI {hi.hex()}", f"#define AK_{name}_LO {lo.hex()}"]
    lines += [f"#define AK_THREE_PIO4 {float(3 * mpmath.pi / 4).hex()}",
              f"#define AK_TWO_OVER_PI {float(2 / mpmath.pi).hex()}", ""]
    meaning = {
        "sin": "sin r = r + r^3 (S0 + S1 z + ... ), z = r^2, |r| <= {b}",
        "cos": "cos r = 1 - z/2 + z^2 (C0 + C1 z + ...), z = r^2, |r| <= {b}",
        "atan": "atan u = u + u^3 (A0 + A1 z + ...), z = u^2, |u| <= {b}",
    }
    letters = {"sin": "S", "cos": "C", "atan": "A"}
    for name, doubles, error in polynomials():
        bound = SINCOS_BOUND if name != "atan" else ATAN_BOUND
        lines.append(f"/* Minimax (Remez, relative error) for {meaning[name].format(b=mpmath.nstr(bound, 6))};")
        lines.append(f" * relative error of the polynomial with these doubles: "
                     f"2^{float(mpmath.log(error, 2)):.1f}. */")
        for i, c in enumerate(doubles):
            lines.append(f"#define AK_{name.upper()}_{letters[name]}{i} {c.hex()}")
        lines.append("")
    lines += arc_tables()
    words = two_over_pi_words()
    lines.append(f"/* The first {32 * len(words)} bits of 2/pi = 0.101000101111..._2, 32 a word, "
                 "most significant first (Payne-Hanek). */")
    lines.append(f"#define AK_TWO_OVER_PI_WORDS {len(words)}")
    lines.append("#define AK_TWO_OVER_PI_BITS { \\")
    for i in range(0, len(words), 6):
        chunk = ", ".join(f"0x{w:08x}u" for w in words[i:i + 6])
        end = ", \\" if i + 6 < len(words) else " \\"
        lines.append(f"    {chunk}{end}")
    lines += ["}", "", "#endif", ""]
    return "\n".join(lines)


def outputs():
    with mp.workprec(PREC):  # the stages after this one keep mpmath's precision
        return {HEADER: render()}
