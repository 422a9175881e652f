#!/usr/bin/env python3
"""Draws docs/contact-signs.svg, the picture of docs/reference.md's "Signs of contact and
friction": a slave node on a master surface, the row's normal n (out of the master, towards
the slave), the tangent t1, the slip s of the step (the slave's motion relative to the
master along t1), the forces on the slave, lambda_n n and -lambda_t t1, and their reactions
on the master. Needs matplotlib (Debian's python3-matplotlib: /usr/bin/python3).
Usage: python3 scripts/contact_signs_figure.py [OUTPUT.svg]"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.patches import FancyArrowPatch, Polygon  # noqa: E402

OUT = sys.argv[1] if len(sys.argv) > 1 else "docs/contact-signs.svg"
plt.rcParams["svg.hashsalt"] = "ffeti"  # the same file from the same script

fig, ax = plt.subplots(figsize=(7.2, 4.2))
ax.set_xlim(-3.6, 3.6)
ax.set_ylim(-2.0, 2.4)
ax.set_aspect("equal")
ax.axis("off")

# The master body below its surface y = 0, the slave body above it.
ax.add_patch(Polygon([(-3.4, 0), (3.4, 0), (3.4, -1.6), (-3.4, -1.6)], closed=True, color="#c8d3e0"))
ax.add_patch(Polygon([(-1.6, 0.02), (1.6, 0.02), (1.2, 1.6), (-1.2, 1.6)], closed=True, color="#f0dcc0"))
ax.text(-3.2, -1.35, "master", fontsize=12)
ax.text(0.5, 1.3, "slave", fontsize=12)
ax.plot([-3.4, 3.4], [0, 0], color="black", lw=1)


def arrow(start, end, colour, label, offset, dashed=False):
    ax.add_patch(FancyArrowPatch(start, end, arrowstyle="-|>", mutation_scale=16, lw=2, color=colour,
                                 linestyle="--" if dashed else "-"))
    ax.text(end[0] + offset[0], end[1] + offset[1], label, color=colour, fontsize=12)


node = (0.0, 0.02)
ax.plot(*node, "o", color="black", ms=7, zorder=5)
ax.text(0.12, -0.32, "slave node", fontsize=10)
# The row's frame.
arrow(node, (0, 1.0), "black", "n", (0.08, 0.0))
arrow(node, (1.0, 0.02), "black", "t1", (0.05, 0.06))
ax.text(-3.3, 2.05, "3D: t2 = n × t1, (t1, t2, n) right-handed", fontsize=10)
# The slip of the step along t1 (here s > 0) and the forces on the slave and the master.
arrow((1.8, 0.55), (2.9, 0.55), "#1f6f1f", "s > 0: slave moves along +t1", (-2.6, 0.15))
arrow((-0.2, 0.02), (-1.5, 0.02), "#b03030", "−λt t1 on slave", (-1.5, 0.14))
arrow((-0.05, -0.02), (-0.05, -1.0), "#2050a0", "−λn n on master", (0.08, -0.15), dashed=True)
arrow((-0.55, 0.2), (-0.55, 1.05), "#2050a0", "λn n on slave", (-1.45, 0.05))
arrow((0.4, -0.06), (1.7, -0.06), "#b03030", "+λt t1 on master", (0.05, -0.3), dashed=True)
ax.text(-3.3, -1.9, "row: n·(u_master − u_slave) ≤ gap,  λn ≥ 0;  slipping: λt = g s/|s| (same sign as s)",
        fontsize=9.5)
fig.tight_layout()
fig.savefig(OUT, metadata={"Date": None})
print("wrote", OUT)
