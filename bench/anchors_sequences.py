"""Writes bench/anchors_sequences.c: omega and alpha of each of the 24 rotation sequences in closed
form, derived by sympy from elementary rotation matrices (nothing of the FMU's code), the anchors
"the same formula for each sequence" (docs/performance.md). Run once and committed:
the file is an anchor and is frozen on purpose (its output depends on sympy's version; rerunning
it is only needed to change the anchors, which then are new anchors).

    .venv/bin/python bench/anchors_sequences.py > bench/anchors_sequences.c

For body-fixed I-J-K, R = R_I(theta1) R_J(theta2) R_K(theta3) and
    omega_fixed = e_I theta1' + R_I e_J theta2' + R_I R_J e_K theta3',
    omega_body  = R_K^T R_J^T e_I theta1' + R_K^T e_J theta2' + e_K theta3';
for space-fixed I-J-K, R = R_K(theta3) R_J(theta2) R_I(theta1) and
    omega_fixed = R_K R_J e_I theta1' + R_K e_J theta2' + e_K theta3',
    omega_body  = e_I theta1' + R_I^T e_J theta2' + R_I^T R_J^T e_K theta3'.
alpha in either set of components is the time derivative of those components (omega x omega = 0),
by the chain rule. sin and cos are glibc's, as in the hand-written 1-2-3 formula."""
import sympy as sp

TAIT_BRYAN = ("123", "132", "213", "231", "312", "321")
PROPER_EULER = ("121", "131", "212", "232", "313", "323")
SEQUENCES = [kind + order for kind in ("body", "space") for order in TAIT_BRYAN + PROPER_EULER]

th = sp.symbols("theta1:4")
td = sp.symbols("td1:4")
tdd = sp.symbols("tdd1:4")
s = sp.symbols("s1:4")
c = sp.symbols("c1:4")


def rotation(axis, x):
    cx, sx = sp.cos(x), sp.sin(x)
    return {1: sp.Matrix([[1, 0, 0], [0, cx, -sx], [0, sx, cx]]),
            2: sp.Matrix([[cx, 0, sx], [0, 1, 0], [-sx, 0, cx]]),
            3: sp.Matrix([[cx, -sx, 0], [sx, cx, 0], [0, 0, 1]])}[axis]


def unit(axis):
    e = sp.zeros(3, 1)
    e[axis - 1] = 1
    return e


def omegas(name):
    i, j, k = (int(a) for a in name[-3:])
    Ri, Rj, Rk = rotation(i, th[0]), rotation(j, th[1]), rotation(k, th[2])
    if name.startswith("body"):
        fixed = unit(i) * td[0] + Ri * unit(j) * td[1] + Ri * Rj * unit(k) * td[2]
        body = Rk.T * Rj.T * unit(i) * td[0] + Rk.T * unit(j) * td[1] + unit(k) * td[2]
    else:
        fixed = Rk * Rj * unit(i) * td[0] + Rk * unit(j) * td[1] + unit(k) * td[2]
        body = unit(i) * td[0] + Ri.T * unit(j) * td[1] + Ri.T * Rj.T * unit(k) * td[2]
    return fixed, body


def rate(expression):
    return sum(sp.diff(expression, th[n]) * td[n] + sp.diff(expression, td[n]) * tdd[n]
               for n in range(3))


def kernel(name):
    fixed, body = omegas(name)
    outputs = list(fixed) + list(body) + [rate(e) for e in fixed] + [rate(e) for e in body]
    trig = {sp.sin(th[n]): s[n] for n in range(3)}
    trig.update({sp.cos(th[n]): c[n] for n in range(3)})
    outputs = [sp.expand(e.subs(trig)) for e in outputs]
    temporaries, results = sp.cse(outputs, symbols=sp.numbered_symbols("x"))
    lines = [f"void ak_anchor_{name}(const double theta[3], const double theta_dot[3],",
             " " * (16 + len(name)) + "const double theta_ddot[3], double y[12]) {"]
    for n in range(3):
        lines.append(f"    const double s{n + 1} = sin(theta[{n}]), c{n + 1} = cos(theta[{n}]);")
    for n in range(3):
        lines.append(f"    const double td{n + 1} = theta_dot[{n}], tdd{n + 1} = theta_ddot[{n}];")
    for symbol, value in temporaries:
        lines.append(f"    const double {symbol} = {sp.ccode(value)};")
    for n, value in enumerate(results):
        lines.append(f"    y[{n}] = {sp.ccode(value)};")
    lines.append("}")
    return lines


def main():
    print("/* The anchors for every sequence: omega_fixed, omega_body, alpha_fixed,"
          " alpha_body")
    print(" * (y[0..11]) in closed form, generated ONCE by bench/anchors_sequences.py (sympy, from")
    print(" * elementary rotation matrices; nothing of the FMU's code) and frozen on purpose: an")
    print(" * anchor must not move with the code it judges. Do not edit; do not regenerate but to")
    print(" * make new anchors (docs/performance.md). */")
    print('#include "anchors_sequences.h"')
    print()
    print("#include <math.h>")
    print()
    for name in SEQUENCES:
        print()
        print("\n".join(kernel(name)))
    print()
    print("ak_anchor_kernel *const AK_ANCHORS[24] = {")
    for name in SEQUENCES:
        print(f"    ak_anchor_{name},")
    print("};")


if __name__ == "__main__":
    main()
