"""fmu_src/core/kinematics_sequences.c: omega and alpha of each of the 24 sequences as straight-line
C, generated from the sequence's axes by running the general chain formulation of
fmu_src/core/kinematics_chain.h (chain_kinematics of tests/c/kinematics_general_kernel.c) symbolically;
fmu_src/core/kinematics_rates_sequences.c: the inverse map of each sequence and frame the same way
(ak_chain_euler_rates_of_sines of that file, between its checks, which stay hand-written in
fmu_src/core/kinematics_euler_rates.c). Only the operations the outputs need are written.

Every value of that run is a structural zero (a component of a unit axis, or anything multiplied
by one), or a sign and a C expression. A product with a structural zero is a structural zero, a
product with 1 is the other factor, a sum with a structural zero is the other term, a negation
flips the sign; every other operation is written out as the general code does it, with the same
operands in the same order. Round-to-nearest is symmetric ((-a) b = -(a b), a - b = -(b - a)) and
the build does not contract (-ffp-contract=off), so each output is bit for bit the general
kernel's, except that an output which is exactly zero may have the other sign (the general code
adds zeros whose sign depends on the data). The one division, by det (rows of W^-1), is written as
the general code does it: (-x) / d = -(x / d). A structural zero times an infinite or NaN value
is dropped where the general code gets NaN; the inverse map's overflow check sees such a value in
another output either way, so the statuses agree. tests/c/test_sequence_kernels.c checks it all."""
import re

from codegen import project
from codegen.generate import HEADER_NOTE

ONE = "1"
NEXT = (1, 2, 0)
AFTER_NEXT = (2, 0, 1)


class Program:
    """The straight-line code of one kernel: each distinct operation once, named t0, t1, .."""

    def __init__(self):
        self.lines = []
        self.names = {}

    def emit(self, expression):
        if expression not in self.names:
            self.names[expression] = f"t{len(self.names)}"
            self.lines.append(f"    const double {self.names[expression]} = {expression};")
        return self.names[expression]

    # Values: None (a structural zero) or (sign, name), name ONE for the constant 1.
    def mul(self, a, b):
        if a is None or b is None:
            return None
        if a[1] == ONE:
            return (a[0] * b[0], b[1])
        if b[1] == ONE:
            return (a[0] * b[0], a[1])
        first, second = sorted((a[1], b[1]))  # a b = b a exactly: one name for both
        return (a[0] * b[0], self.emit(f"{first} * {second}"))

    def add(self, a, b):
        if a is None:
            return b
        if b is None:
            return a
        x = "1.0" if a[1] == ONE else a[1]
        y = "1.0" if b[1] == ONE else b[1]
        if a[0] == b[0]:
            first, second = sorted((x, y))
            return (a[0], self.emit(f"{first} + {second}"))
        if a[0] > 0:
            return (1, self.emit(f"{x} - {y}"))
        return (1, self.emit(f"{y} - {x}"))

    def div(self, a, divisor):
        """a / divisor, divisor a name: (-x) / d = -(x / d) exactly."""
        if a is None:
            return None
        return (a[0], self.emit(f"{'1.0' if a[1] == ONE else a[1]} / {divisor}"))

    @staticmethod
    def neg(a):
        return None if a is None else (-a[0], a[1])

    def sub(self, a, b):
        return self.add(a, self.neg(b))

    def sum(self, *terms):
        """Left to right, as C adds a + b + c."""
        total = terms[0]
        for term in terms[1:]:
            total = self.add(total, term)
        return total


def unit(axis):
    v = [None, None, None]
    v[axis] = (1, ONE)
    return v


def rotate(p, axis, s, c, v):
    """v := R_axis(x) v, as rotate() of kinematics_chain.h."""
    i, j = NEXT[axis], AFTER_NEXT[axis]
    vi, vj = v[i], v[j]
    v[i] = p.sub(p.mul(c, vi), p.mul(s, vj))
    v[j] = p.add(p.mul(s, vi), p.mul(c, vj))


def rotate_back(p, axis, s, c, v):
    rotate(p, axis, p.neg(s), c, v)


def axis_cross(axis, x):
    i, j = NEXT[axis], AFTER_NEXT[axis]
    out = [None, None, None]
    out[i] = Program.neg(x[j])
    out[j] = x[i]
    return out


class Chain:
    """The chain of the sequence `name` run symbolically: its axes u, v (chain_axes) and their
    cross products (chain_cross_products), values of the program p."""

    def __init__(self, p, name):
        self.p = p
        axes = project.sequence_axes(name)
        self.angle = [2 - m if name.startswith("space") else m for m in range(3)]
        self.axis = [axes[k] - 1 for k in self.angle]
        self.s = [(1, f"sines->sin[{k}]") for k in self.angle]
        self.c = [(1, f"sines->cos[{k}]") for k in self.angle]
        axis, s, c = self.axis, self.s, self.c
        self.u, self.v = [], []  # chain_axes
        for m in range(3):
            um = unit(axis[m])
            for l in range(m - 1, -1, -1):
                rotate(p, axis[l], s[l], c[l], um)
            vm = unit(axis[m])
            for l in range(m + 1, 3):
                rotate_back(p, axis[l], s[l], c[l], vm)
            self.u.append(um)
            self.v.append(vm)

        a1, a2, a3 = axis  # chain_cross_products
        self.u12 = axis_cross(a1, unit(a2))
        self.chain(0, 0, self.u12)
        w = unit(a3)
        self.chain(1, 1, w)
        self.u13 = axis_cross(a1, w)
        self.chain(0, 0, self.u13)
        self.u23 = axis_cross(a2, unit(a3))
        self.chain(0, 1, self.u23)
        self.v12 = axis_cross(a1, unit(a2))
        self.chain_back(1, 2, self.v12)
        w = unit(a1)
        self.chain_back(1, 1, w)
        self.v13 = [Program.neg(x) for x in axis_cross(a3, w)]
        self.chain_back(2, 2, self.v13)
        self.v23 = axis_cross(a2, unit(a3))
        self.chain_back(2, 2, self.v23)

    def chain(self, first, last, v):
        for m in range(last, first - 1, -1):
            rotate(self.p, self.axis[m], self.s[m], self.c[m], v)

    def chain_back(self, first, last, v):
        for m in range(first, last + 1):
            rotate_back(self.p, self.axis[m], self.s[m], self.c[m], v)

    def axis_rates(self, pd):
        """du, dv of axis_rates_of: du[0] and dv[2] are zero."""
        p = self.p
        du = [[None] * 3, [None] * 3, [None] * 3]
        dv = [[None] * 3, [None] * 3, [None] * 3]
        for r in range(3):
            du[1][r] = p.mul(pd[0], self.u12[r])
            du[2][r] = p.add(p.mul(pd[0], self.u13[r]), p.mul(pd[1], self.u23[r]))
            dv[0][r] = p.add(p.mul(pd[1], self.v12[r]), p.mul(pd[2], self.v13[r]))
            dv[1][r] = p.mul(pd[2], self.v23[r])
        return du, dv

    def rotation_matrix(self):
        """R of chain_rotation_matrix."""
        R = [[None] * 3 for _ in range(3)]
        for col in range(3):
            e = unit(col)
            self.chain(0, 2, e)
            for r in range(3):
                R[r][col] = e[r]
        return R


def text_of(value):
    if value is None:
        return "0.0"
    text = "1.0" if value[1] == ONE else value[1]
    return text if value[0] > 0 else f"-{text}"


def finish(p, results):
    """The body lines: the operations the results need, in the order they were formed, then the
    stores; and the number of those operations."""
    needed = set()
    for values in results.values():
        for value in values:
            if value is not None:
                needed.add(value[1])
    lines = []
    for line in reversed(p.lines):
        name, expression = line.split(" = ", 1)
        name = name.split()[-1]
        if name in needed:
            lines.append(line)
            needed.update(re.findall(r"\bt\d+\b", expression))
    lines.reverse()
    for output, values in results.items():
        for r, value in enumerate(values):
            lines.append(f"    {output}[{r}] = {text_of(value)};")
    return lines, len(lines) - sum(len(v) for v in results.values())


def kernel(name):
    """(C function body lines, number of operations) of the sequence `name`."""
    p = Program()
    ch = Chain(p, name)
    u, v = ch.u, ch.v
    pd = [(1, f"theta_dot[{k}]") for k in ch.angle]
    pdd = [(1, f"theta_ddot[{k}]") for k in ch.angle]
    du, dv = ch.axis_rates(pd)

    results = {"omega_fixed": [], "omega_body": [], "alpha_fixed": [], "alpha_body": []}
    for r in range(3):  # combine_kinematics
        results["omega_fixed"].append(p.sum(*(p.mul(pd[m], u[m][r]) for m in range(3))))
        results["omega_body"].append(p.sum(*(p.mul(pd[m], v[m][r]) for m in range(3))))
        results["alpha_fixed"].append(p.sum(*(p.mul(pdd[m], u[m][r]) for m in range(3)),
                                            p.mul(pd[1], du[1][r]), p.mul(pd[2], du[2][r])))
        results["alpha_body"].append(p.sum(*(p.mul(pdd[m], v[m][r]) for m in range(3)),
                                           p.mul(pd[0], dv[0][r]), p.mul(pd[1], dv[1][r])))
    return finish(p, results)


def rates_kernel(name, body):
    """(C function body lines, number of operations) of the inverse map of the sequence `name`
    with omega in body (or fixed) components: ak_chain_euler_rates of
    tests/c/kinematics_general_kernel.c between its singularity and overflow checks, which stay
    hand-written in fmu_src/core/kinematics_euler_rates.c."""
    p = Program()
    ch = Chain(p, name)
    x12, x23 = (ch.v12, ch.v23) if body else (ch.u12, ch.u23)
    middle = ch.v[1] if body else ch.u[1]
    rows = [[p.div(x23[r], "det") for r in range(3)], list(middle),
            [p.div(x12[r], "det") for r in range(3)]]
    omega = [(1, f"omega[{r}]") for r in range(3)]
    omega_dot = [(1, f"omega_dot[{r}]") for r in range(3)]

    def dot(a, b):
        return p.sum(*(p.mul(a[r], b[r]) for r in range(3)))

    pd = [dot(rows[m], omega) for m in range(3)]
    du, dv = ch.axis_rates(pd)
    rate = dv if body else du
    rhs = [p.sub(omega_dot[r], p.sum(*(p.mul(pd[m], rate[m][r]) for m in range(3))))
           for r in range(3)]
    pdd = [dot(rows[m], rhs) for m in range(3)]
    R = ch.rotation_matrix()
    other = [dot(R[r] if body else [R[0][r], R[1][r], R[2][r]], omega_dot) for r in range(3)]
    results = {"theta_dot": [None] * 3, "theta_ddot": [None] * 3, "other": other}
    for m in range(3):
        results["theta_dot"][ch.angle[m]] = pd[m]
        results["theta_ddot"][ch.angle[m]] = pdd[m]
    return finish(p, results)


def kinematics_sequences_c():
    lines = ["/* Omega and alpha of each rotation sequence as straight-line code: the general chain",
             " * formulation (kinematics_general.h, sections 2 and 3) with its structurally zero terms",
             " * left out, so bit for bit the general kernel's outputs (but the sign of an exact zero;",
             " * codegen/sequence_kernels.py says why). tests/c/test_sequence_kernels.c compares them.",
             f" * {HEADER_NOTE.format(source='codegen/sequence_kernels.py')} */",
             '#include "kinematics_sequences.h"', ""]
    table = []
    for name in project.SEQUENCES:
        body, operations = kernel(name)
        function = f"{name}_kinematics"
        table.append(function)
        lines += [f"/* {name}: {operations} operations. */",
                  f"static void {function}(const ak_sines *sines, const double theta_dot[3],",
                  " " * (13 + len(function))
                  + "const double theta_ddot[3], double omega_fixed[3],",
                  " " * (13 + len(function))
                  + "double omega_body[3], double alpha_fixed[3], double alpha_body[3]) {"]
        lines += body + ["}", ""]
    lines.append("ak_sequence_kinematics *const AK_SEQUENCE_KINEMATICS[AK_SEQUENCE_COUNT] = {")
    lines += [f"    {function}," for function in table]
    lines += ["};", ""]
    return "\n".join(lines)


def kinematics_rates_sequences_c():
    lines = ["/* The inverse map of each rotation sequence and frame as straight-line code: the general",
             " * chain formulation (kinematics_general.h, section 6) between its checks, with its",
             " * structurally zero terms left out, so bit for bit the general code's results (but the",
             " * sign of an exact zero; codegen/sequence_kernels.py says why). The checks and the",
             " * statuses are kinematics_euler_rates.c's; tests/c/test_sequence_kernels.c compares.",
             f" * {HEADER_NOTE.format(source='codegen/sequence_kernels.py')} */",
             '#include "kinematics_sequences.h"', ""]
    table = []
    for name in project.SEQUENCES:
        pair = []
        for frame in ("fixed", "body"):
            body, operations = rates_kernel(name, frame == "body")
            function = f"{name}_rates_{frame}"
            pair.append(function)
            indent = " " * (13 + len(function))
            lines += [f"/* {name}, omega in {frame} components: {operations} operations. */",
                      f"static void {function}(const ak_sines *sines, double det, const double omega[3],",
                      f"{indent}const double omega_dot[3], double theta_dot[3],",
                      f"{indent}double theta_ddot[3], double other[3]) {{"]
            lines += body + ["}", ""]
        table.append(pair)
    lines.append("ak_sequence_rates *const AK_SEQUENCE_RATES[2][2][3][3][2] = {")
    for name, (fixed, body) in zip(project.SEQUENCES, table):
        lines.append(f"    {project.sequence_table_index(name)} = {{{fixed}, {body}}},")
    lines += ["};", ""]
    return "\n".join(lines)


def outputs():
    from codegen.models import ROOT
    core = ROOT / "fmu_src" / "core"
    return {core / "kinematics_sequences.c": kinematics_sequences_c(),
            core / "kinematics_rates_sequences.c": kinematics_rates_sequences_c()}
