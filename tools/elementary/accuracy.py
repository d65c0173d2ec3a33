"""Accuracy of the project's elementary functions (fmu_src/elementary/) against mpmath.

Evaluates the C functions through the test library build/testlib (CMake target
elementary_testlib: the same sources and flags as the FMUs) on arguments of several kinds and
compares each result with mpmath's value at 128 bits or more (mpmath widens the precision itself
for the reduction of huge arguments). Prints a table: function, kind, arguments, worst error in
ulp of the exact value, the argument of the worst, and the share correctly rounded.

    python tools/elementary/accuracy.py --count 20000            (arguments per function)
    python tools/elementary/accuracy.py --count 10000000 --processes 2     (docs/elementary.md)
"""
import argparse
import ctypes
import math
import multiprocessing
import pathlib
import sys
import time

import numpy as np
from mpmath.libmp import (from_float, mpf_acos, mpf_asin, mpf_atan, mpf_atan2, mpf_cos_sin,
                          mpf_sub)

ROOT = pathlib.Path(__file__).resolve().parents[2]
LIBRARY = ROOT / "build" / "testlib" / {"win32": "elementary_testlib.dll",
                                        "darwin": "libelementary_testlib.dylib"}.get(
                                            sys.platform, "libelementary_testlib.so")
PRECISION = 128
CHUNK = 20000  # arguments per unit of work
# Known hard cases of the reduction: doubles extremely close to multiples of pi/2.
HARD_CASES = [float.fromhex(h) for h in (
    "0x1.6ac5b262ca1ffp+849", "0x1.921fb54442d18p+0", "0x1.921fb54442d18p+1",
    "0x1.921fb54442d18p+2", "0x1.2d97c7f3321d2p+1", "0x1.5fdbbe9bba775p+61",
    "0x1.c463abeccb2bbp+2", "0x1.b1d8b5d6e5a9ap+1023", "0x1.fffffffffffffp+1023",
    "0x1.0p+20", "0x1.fffffffffffffp+19", "0x1.921fb54442d19p-1", "0x1.921fb54442d18p-1")]

# function -> kinds; each kind draws `n` arguments (numpy Generator) as one array, or two for atan2.
def _random_doubles(rng, n):
    bits = rng.integers(0, 2 ** 64, size=n, dtype=np.uint64)
    x = bits.view(np.float64)
    return np.where(np.isfinite(x), x, 1.0)


def _log_uniform(rng, n, low_exponent, high_exponent):
    mantissa = rng.uniform(1.0, 2.0, n)
    exponent = rng.integers(low_exponent, high_exponent, n)
    signs = rng.choice([-1.0, 1.0], n)
    return signs * np.ldexp(mantissa, exponent)


def _subnormal(rng, n):
    bits = rng.integers(1, 2 ** 52, size=n, dtype=np.uint64)
    return rng.choice([-1.0, 1.0], n) * bits.view(np.float64)


def _near_pio2_multiples(rng, n):
    """The doubles nearest k pi/2 and their neighbours, k up to 2^62 (mpmath computes k pi/2)."""
    from mpmath import mp, mpf, pi
    out = np.empty(n)
    with mp.workprec(200):
        for i in range(n):
            k = int(rng.integers(1, 2 ** int(rng.integers(1, 63))))
            x = float(k * pi / 2)
            out[i] = np.nextafter(x, np.inf) if i % 3 == 1 else (
                np.nextafter(x, -np.inf) if i % 3 == 2 else x)
            if i < len(HARD_CASES):
                out[i] = HARD_CASES[i]
    return out * rng.choice([-1.0, 1.0], n)


def _near_one(rng, n):
    return rng.choice([-1.0, 1.0], n) * (1.0 - np.ldexp(rng.uniform(1.0, 2.0, n),
                                                       -rng.integers(1, 53, n)))


def _ratio_pairs(rng, n, spread):
    x = _log_uniform(rng, n, -1000, 1000)
    with np.errstate(over="ignore", under="ignore"):
        y = np.ldexp(rng.uniform(1.0, 2.0, n), rng.integers(-spread, spread, n)) * x
    y = np.where(np.isfinite(y) & (y != 0), y, 1.0) * rng.choice([-1.0, 1.0], n)
    return y, x


KINDS = {
    "sincos": {
        "random double": _random_doubles,
        "[-10, 10]": lambda rng, n: rng.uniform(-10, 10, n),
        "near k pi/2": _near_pio2_multiples,
        "tiny": lambda rng, n: _log_uniform(rng, n, -80, -20),
        "huge": lambda rng, n: _log_uniform(rng, n, 20, 1024),
        "subnormal": _subnormal,
    },
    "atan": {
        "random double": _random_doubles,
        "[-10, 10]": lambda rng, n: rng.uniform(-10, 10, n),
        "tiny": lambda rng, n: _log_uniform(rng, n, -80, -20),
        "huge": lambda rng, n: _log_uniform(rng, n, 20, 1024),
        "subnormal": _subnormal,
    },
    "atan2": {
        "random pairs": lambda rng, n: (_random_doubles(rng, n), _random_doubles(rng, n)),
        "[-10, 10]^2": lambda rng, n: (rng.uniform(-10, 10, n), rng.uniform(-10, 10, n)),
        "ratio 2^+-70": lambda rng, n: _ratio_pairs(rng, n, 70),
        "ratio 2^+-1100": lambda rng, n: _ratio_pairs(rng, n, 1100),
        "subnormal pairs": lambda rng, n: (_subnormal(rng, n), _subnormal(rng, n)),
    },
    "asin": {
        "[-1, 1]": lambda rng, n: rng.uniform(-1, 1, n),
        "near +-1": _near_one,
        "tiny": lambda rng, n: _log_uniform(rng, n, -80, -20),
        "subnormal": _subnormal,
    },
}
KINDS["acos"] = KINDS["asin"]
CODES = {"sincos": 0, "atan": 1, "atan2": 2, "asin": 3, "acos": 4}


def _evaluate(function, x, y, library):
    lib = ctypes.CDLL(str(library))
    lib.ake_evaluate.argtypes = [ctypes.c_int] + [ctypes.c_void_p] * 4 + [ctypes.c_size_t]
    x = np.ascontiguousarray(x, dtype=np.float64)
    y = np.ascontiguousarray(x if y is None else y, dtype=np.float64)
    out, out2 = np.zeros_like(x), np.zeros_like(x)
    status = lib.ake_evaluate(CODES[function], x.ctypes.data, y.ctypes.data, out.ctypes.data,
                              out2.ctypes.data, len(x))
    assert status == 0
    return out, out2


def mpmath_value(exact):
    """An mpf tuple as an mpmath number."""
    from mpmath import mpf
    return mpf(exact)


def ulp_error(got, exact):
    """|got - exact| in ulp of the exact value (an mpf tuple), subnormal ulp below 2^-1022."""
    _, _, exp, bc = exact
    ulp_exponent = max(exp + bc - 53, -1074)
    sign, man, dexp, _ = mpf_sub(from_float(got), exact, PRECISION + 64)
    return math.ldexp(float(man), dexp - ulp_exponent) if man else 0.0


def _check_chunk(task):
    """Statistics of one chunk: (function, name, kind, count, worst, worst argument, correct)."""
    function, kind, n, seed, library = task
    rng = np.random.default_rng(seed)
    drawn = KINDS[function][kind](rng, n)
    x, y = drawn if isinstance(drawn, tuple) else (drawn, None)
    out, out2 = _evaluate(function, x, y, library)
    rows = {}
    def account(name, got, exact, argument):
        count, worst, worst_argument, correct = rows.get(name, (0, -1.0, None, 0))
        error = ulp_error(got, exact)
        if error > worst:
            worst, worst_argument = error, argument
        rows[name] = (count + 1, worst, worst_argument, correct + (error < 0.5))
    for i in range(n):
        xi = float(x[i])
        if function == "sincos":
            cos_exact, sin_exact = mpf_cos_sin(from_float(xi), PRECISION)
            account("sin", float(out[i]), sin_exact, xi.hex())
            account("cos", float(out2[i]), cos_exact, xi.hex())
        elif function == "atan":
            account("atan", float(out[i]), mpf_atan(from_float(xi), PRECISION), xi.hex())
        elif function == "atan2":
            yi = float(y[i])
            account("atan2", float(out[i]), mpf_atan2(from_float(xi), from_float(yi), PRECISION),
                    f"{xi.hex()}, {yi.hex()}")
        else:
            exact = (mpf_asin if function == "asin" else mpf_acos)(from_float(xi), PRECISION)
            account(function, float(out[i]), exact, xi.hex())
    return [(function, name, kind) + stats for name, stats in rows.items()]


def tasks(count, seed, functions, library=LIBRARY):
    """Chunks of work: count arguments per function, shared equally among its kinds; in an order
    that interleaves the functions and kinds, so that a partial run covers them all."""
    work = []
    for f_index, function in enumerate(functions):
        kinds = list(KINDS[function])
        for k_index, kind in enumerate(kinds):
            share = count // len(kinds) + (k_index < count % len(kinds))
            for c_index, start in enumerate(range(0, share, CHUNK)):
                work.append((c_index, function, kind, min(CHUNK, share - start),
                             [seed, f_index, k_index, c_index], str(library)))
    work.sort(key=lambda task: task[0])
    return [task[1:] for task in work]


def run(count, seed=2026, processes=1, functions=tuple(KINDS), library=LIBRARY, progress=None):
    """{(name, kind): (count, worst ulp, worst argument, correctly rounded)}, name sin, cos, ...
    With progress (a path), the table so far is written there after every 20 chunks."""
    work = tasks(count, seed, functions, library)
    table = {}
    started = time.time()
    def merge(chunk):
        for _, name, kind, n, worst, argument, correct in chunk:
            total, top, top_argument, right = table.get((name, kind), (0, -1.0, None, 0))
            if worst > top:
                top, top_argument = worst, argument
            table[(name, kind)] = (total + n, top, top_argument, right + correct)
    def report(done):
        if progress and (done % 20 == 0 or done == len(work)):
            pathlib.Path(progress).write_text(
                f"{done} of {len(work)} chunks, {time.time() - started:.0f} s\n\n"
                + format_table(table) + "\n")
    if processes > 1:
        with multiprocessing.Pool(processes) as pool:
            for done, chunk in enumerate(pool.imap_unordered(_check_chunk, work), 1):
                merge(chunk)
                report(done)
    else:
        for done, task in enumerate(work, 1):
            merge(_check_chunk(task))
            report(done)
    return table


def summary(table):
    """{name: (count, worst, worst argument, correct)} over all kinds."""
    result = {}
    for (name, _), (n, worst, argument, correct) in table.items():
        total, top, top_argument, right = result.get(name, (0, -1.0, None, 0))
        if worst > top:
            top, top_argument = worst, argument
        result[name] = (total + n, top, top_argument, right + correct)
    return result


def format_table(table):
    lines = ["| function | kind | arguments | worst ulp | worst at | correctly rounded |",
             "|---|---|---:|---:|---|---:|"]
    for (name, kind), (n, worst, argument, correct) in table.items():
        lines.append(f"| {name} | {kind} | {n} | {worst:.4f} | {argument} | "
                     f"{100 * correct / n:.4f} % |")
    for name, (n, worst, argument, correct) in summary(table).items():
        lines.append(f"| **{name}** | all | {n} | {worst:.4f} | {argument} | "
                     f"{100 * correct / n:.4f} % |")
    return "\n".join(lines)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--count", type=int, default=20000, help="arguments per function")
    parser.add_argument("--seed", type=int, default=2026)
    parser.add_argument("--processes", type=int, default=1, help="at most 2 on a shared machine")
    parser.add_argument("--functions", nargs="+", choices=list(KINDS), default=list(KINDS))
    parser.add_argument("--library", default=str(LIBRARY),
                        help="the test library to load (default: the build's)")
    parser.add_argument("--progress", help="file to write the table so far to, now and then")
    args = parser.parse_args(argv)
    started = time.time()
    table = run(args.count, args.seed, args.processes, args.functions, args.library,
                args.progress)
    print(format_table(table))
    print(f"\n{args.count} arguments per function, seed {args.seed}, {args.processes} process(es), "
          f"{time.time() - started:.0f} s")
    return 0 if all(worst <= 1.0 for _, worst, _, _ in summary(table).values()) else 1


if __name__ == "__main__":
    sys.exit(main())
