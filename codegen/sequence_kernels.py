"""fmu_src/core/kinematics_sequences.c: omega and alpha of each of the 24 sequences as straight-line
C, generated from the sequence's axes by running the general chain formulation of
fmu_src/core/kinematics_chain.h (chain_kinematics of tests/c/kinematics_general_kernel.c) symbolically.

Every value of that run is a structural zero (a component of a unit axis, or anything multiplied
by one), or a sign and a C expression. A product with a structural zero is a structural zero, a
product with 1 is the other factor, a sum with a structural zero is the other term, a negation
flips the sign; every other operation is written out as the general code does it, with the same
operands in the same order. Round-to-nearest is symmetric ((-a) b = -(a b), a - b = -(b - a)) and
the build does not contract (-ffp-contract=off), so each output is bit for bit the general
kernel's, except that an output which is exactly zero may have the other sign (the general code
adds zeros whose sign depends on the data). tests/c/test_sequence_kernels.c checks it."""
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


def kernel(name):
    """(C function body lines, number of operations) of the sequence `name`."""
    p = Program()
    axes = project.sequence_axes(name)
    space = name.startswith("space")
    angle = [2 - m if space else m for m in range(3)]
    axis = [axes[k] - 1 for k in angle]
    s = [(1, f"sines->sin[{k}]") for k in angle]
    c = [(1, f"sines->cos[{k}]") for k in angle]
    pd = [(1, f"theta_dot[{k}]") for k in angle]
    pdd = [(1, f"theta_ddot[{k}]") for k in angle]

    def chain(first, last, v):
        for m in range(last, first - 1, -1):
            rotate(p, axis[m], s[m], c[m], v)

    def chain_back(first, last, v):
        for m in range(first, last + 1):
            rotate_back(p, axis[m], s[m], c[m], v)

    u, v = [], []  # chain_axes
    for m in range(3):
        um = unit(axis[m])
        for l in range(m - 1, -1, -1):
            rotate(p, axis[l], s[l], c[l], um)
        vm = unit(axis[m])
        for l in range(m + 1, 3):
            rotate_back(p, axis[l], s[l], c[l], vm)
        u.append(um)
        v.append(vm)

    a1, a2, a3 = axis  # chain_cross_products
    u12 = axis_cross(a1, unit(a2))
    chain(0, 0, u12)
    w = unit(a3)
    chain(1, 1, w)
    u13 = axis_cross(a1, w)
    chain(0, 0, u13)
    u23 = axis_cross(a2, unit(a3))
    chain(0, 1, u23)
    v12 = axis_cross(a1, unit(a2))
    chain_back(1, 2, v12)
    w = unit(a1)
    chain_back(1, 1, w)
    v13 = [Program.neg(x) for x in axis_cross(a3, w)]
    chain_back(2, 2, v13)
    v23 = axis_cross(a2, unit(a3))
    chain_back(2, 2, v23)

    du = [[None] * 3, [None] * 3, [None] * 3]  # chain_axis_rates
    dv = [[None] * 3, [None] * 3, [None] * 3]
    for r in range(3):
        du[1][r] = p.mul(pd[0], u12[r])
        du[2][r] = p.add(p.mul(pd[0], u13[r]), p.mul(pd[1], u23[r]))
        dv[0][r] = p.add(p.mul(pd[1], v12[r]), p.mul(pd[2], v13[r]))
        dv[1][r] = p.mul(pd[2], v23[r])

    results = {"omega_fixed": [], "omega_body": [], "alpha_fixed": [], "alpha_body": []}
    for r in range(3):  # combine_kinematics
        results["omega_fixed"].append(p.sum(*(p.mul(pd[m], u[m][r]) for m in range(3))))
        results["omega_body"].append(p.sum(*(p.mul(pd[m], v[m][r]) for m in range(3))))
        results["alpha_fixed"].append(p.sum(*(p.mul(pdd[m], u[m][r]) for m in range(3)),
                                            p.mul(pd[1], du[1][r]), p.mul(pd[2], du[2][r])))
        results["alpha_body"].append(p.sum(*(p.mul(pdd[m], v[m][r]) for m in range(3)),
                                           p.mul(pd[0], dv[0][r]), p.mul(pd[1], dv[1][r])))
    body = list(p.lines)
    for output, values in results.items():
        for r, value in enumerate(values):
            if value is None:
                text = "0.0"
            else:
                text = "1.0" if value[1] == ONE else value[1]
                text = text if value[0] > 0 else f"-{text}"
            body.append(f"    {output}[{r}] = {text};")
    return body, len(p.lines)


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


def outputs():
    from codegen.models import ROOT
    return {ROOT / "fmu_src" / "core" / "kinematics_sequences.c": kinematics_sequences_c()}
