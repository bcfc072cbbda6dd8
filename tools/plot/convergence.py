#!/usr/bin/python3
"""A convergence study's figure: each compared field's L2 error against the cell size,
log-log, with the fitted order (run.json of `mpmx run` on a deck with convergence.levels).

Usage: convergence.py RUN_DIR   (writes RUN_DIR/convergence.png)
"""
import json
import math
import os
import sys
import textwrap

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plot_units  # noqa: E402


def main(run_dir):
    with open(f"{run_dir}/run.json") as f:
        run = json.load(f)
    levels = run["convergence"]["levels"]
    orders = run["convergence"].get("order", {})
    dx = [lv["dx"] for lv in levels]
    fig, ax = plt.subplots(figsize=(6.0, 4.6))
    anchor = None
    for field in levels[-1]["errors"]:
        e = [lv["errors"].get(field, {}).get("l2") for lv in levels]
        pts = [(h, v) for h, v in zip(dx, e) if v is not None and v > 0]
        if not pts:
            continue
        order = orders.get(field)
        finite = isinstance(order, (int, float)) and math.isfinite(order)
        label = f"{field} (order {order:.2f})" if finite else field
        ax.loglog([p[0] for p in pts], [p[1] for p in pts], "o-", label=label)
        anchor = anchor or pts[-1]
    if anchor:  # slope 2 through the finest point, for the eye
        h0, e0 = anchor
        ax.loglog([h0, dx[0]], [e0, e0 * (dx[0] / h0) ** 2], ":", color="gray", label="slope 2")
    units = plot_units.Units.of_record(run)
    ax.set_xlabel(units.label("cell size dx", "length"))
    ax.set_ylabel("L2 error (relative)")
    case = run.get("deck", {}).get("case", {})
    head = plot_units.shown(f"{case.get('id', '')}: {case.get('title', 'convergence')}".strip(": "))
    # Wrapped to the axes' width: a long case title is otherwise cut at the figure's edge.
    ax.set_title("\n".join(textwrap.wrap(f"{head}, grid convergence", 60)), fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=9)
    if units.note():
        fig.text(0.01, 0.005, units.note(), ha="left", va="bottom", fontsize=7, color="0.5")
    fig.tight_layout(rect=(0, 0.02, 1, 1))
    fig.savefig(f"{run_dir}/convergence.png", dpi=120)


if __name__ == "__main__":
    main(sys.argv[1])
