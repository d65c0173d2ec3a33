"""Draws model.png, the FMU's icon (FMI 2.0 allows one at the archive's root): the fixed frame N in
grey and the body frame B, rotated by a 1-2-3 sequence, in colour, with the angular velocity omega.

Usage: .venv/bin/python scripts/make_icon.py [OUTPUT]   (default: model.png at the repository root)"""
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (the backend is chosen first)
import numpy as np  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parent.parent
SIZE_PIXELS = 256


def rotation(axis, angle):
    c, s = np.cos(angle), np.sin(angle)
    i, j = [(1, 2), (2, 0), (0, 1)][axis]
    R = np.eye(3)
    R[i, i], R[i, j], R[j, i], R[j, j] = c, -s, s, c
    return R


def project(v):
    """An oblique view of 3-D points onto the icon's plane."""
    view = np.array([[-0.55, 1.0, 0.0], [-0.40, -0.25, 1.0]])
    return view @ v


def draw(output):
    R = rotation(0, 0.5) @ rotation(1, 0.4) @ rotation(2, 0.7)
    figure = plt.figure(figsize=(1, 1), dpi=SIZE_PIXELS)
    axes = figure.add_axes([0, 0, 1, 1])
    axes.set_xlim(-1.2, 1.2)
    axes.set_ylim(-0.8, 1.4)
    axes.set_axis_off()
    origin = np.zeros(2)
    for k in range(3):
        tip = project(np.eye(3)[:, k])
        axes.annotate("", tip, origin, arrowprops=dict(arrowstyle="-|>", color="0.6", lw=1.4,
                                                       mutation_scale=8))
    for k, colour in enumerate(("#d62728", "#2ca02c", "#1f77b4")):
        tip = project(R[:, k] * 1.05)
        axes.annotate("", tip, origin, arrowprops=dict(arrowstyle="-|>", color=colour, lw=2.4,
                                                       mutation_scale=10))
    # omega: a circular arrow about the body's third axis.
    b1, b2, b3 = R[:, 0], R[:, 1], R[:, 2]
    phi = np.linspace(0.3, 2 * np.pi - 0.6, 60)
    ring = project(0.9 * b3[:, None] + 0.32 * (np.outer(b1, np.cos(phi)) + np.outer(b2, np.sin(phi))))
    axes.plot(ring[0], ring[1], color="#ff7f0e", lw=1.8)
    axes.annotate("", ring[:, -1], ring[:, -4], arrowprops=dict(arrowstyle="-|>", color="#ff7f0e",
                                                                lw=1.8, mutation_scale=9))
    figure.savefig(output, transparent=True, metadata={"Software": None})
    plt.close(figure)


if __name__ == "__main__":
    draw(sys.argv[1] if len(sys.argv) > 1 else ROOT / "model.png")
