#!/usr/bin/python3
"""Stress profiles of several 1-D runs and a direct-MD bar at the same times, one panel
per time (the layout of dissertation figs. 6.3-6.9).

  multiscale_profiles.py --md runs/H2_direct_md RUN_DIR[=LABEL] ... --out fig.png

Each RUN_DIR is an `mpmx run` directory (particles.csv, run.json); the direct-MD
directory is an `mpmx md` bar run (bar_stress.csv). The bar's bins are placed on the
continuum grid as the eq. 7.12 comparison places them: bin b of n at
lower + (b + 1/2) (upper - lower) / n. Times are those recorded by the first run."""
import argparse
import csv
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

STYLES = [dict(color="C0", lw=1.4), dict(color="C3", lw=1.2, ls="--"), dict(color="C2", lw=1.2, ls="-."),
          dict(color="C4", lw=1.0, ls=":"), dict(color="C1", lw=1.0)]


def read_run(directory):
    with open(os.path.join(directory, "run.json")) as f:
        meta = json.load(f)
    by_time = {}
    with open(os.path.join(directory, "particles.csv")) as f:
        for row in csv.DictReader(f):
            t = round(float(row["time"]), 9)
            by_time.setdefault(t, ([], []))
            by_time[t][0].append(float(row["x"]))
            by_time[t][1].append(float(row["stress"]))
    return meta, by_time


def read_bar(directory):
    path = os.path.join(directory, "bar_stress.csv")
    records = {}
    with open(path) as f:
        for row in csv.DictReader(f):
            records.setdefault(round(float(row["time_ps"]), 9), []).append(float(row["sxx_GPa"]))
    return records


def nearest(records, t):
    return min(records, key=lambda s: abs(s - t))


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("runs", nargs="+", metavar="RUN_DIR[=LABEL]")
    p.add_argument("--md", help="direct-MD bar run directory (bar_stress.csv)")
    p.add_argument("--out", required=True, help="output PNG")
    p.add_argument("--title", default=None)
    a = p.parse_args(argv)

    runs = []
    for spec in a.runs:
        d, _, label = spec.partition("=")
        meta, by_time = read_run(d)
        runs.append((label or meta["deck"]["case"]["id"], meta, by_time))
    first = runs[0][1]
    grid = first["deck"]["grid"]
    lower, upper = float(grid.get("lower", 0.0)), float(grid["upper"])
    # The deck's unit system as run.json records it (core/units), to place the bar's
    # records (ps, GPa) on the runs' axes.
    units = first.get("units")
    if a.md and not units:
        print(f"multiscale_profiles: {a.runs[0]} names no unit system (case.units), so the direct MD "
              "cannot be placed on its axes", file=sys.stderr)
        return 1
    times = sorted(t for t in runs[0][2] if t > 0)
    bar = read_bar(a.md) if a.md else None
    stress_label = "GPa" if units and units["stress_GPa"] == 1.0 else f"{(units or {}).get('name', 'deck')} units"

    n = len(times)
    cols = min(n, 2)
    rows = math.ceil(n / cols)
    # One y range over the panels: the times compare by eye.
    fig, axes = plt.subplots(rows, cols, figsize=(6.0 * cols, 3.6 * rows), squeeze=False, sharey=True)
    for k, t in enumerate(times):
        ax = axes[k // cols][k % cols]
        if bar is not None:
            rec = bar[nearest(bar, t * units["time_ps"])]
            nb = len(rec)
            xs = [lower + (b + 0.5) * (upper - lower) / nb for b in range(nb)]
            ys = [v / units["stress_GPa"] for v in rec]
            ax.plot(xs, ys, color="k", lw=0, marker="o", ms=2.5, label="direct MD", zorder=3)
        for (label, meta, by_time), style in zip(runs, STYLES):
            if t in by_time:
                ax.plot(*by_time[t], label=label, **style)
        name = units["name"] if units else ""
        ax.set_title(f"t = {t:g} ps" if name == "nm_ps_GPa" else f"t = {t:g} ({name})", fontsize=10)
        ax.set_xlabel("x (nm)" if name == "nm_ps_GPa" else f"x ({name})")
        ax.set_ylabel(f"stress $\\sigma_{{xx}}$ ({stress_label})")
        ax.grid(True, lw=0.3, alpha=0.5)
        if k == 0:
            ax.legend(fontsize=8)
    for k in range(n, rows * cols):
        axes[k // cols][k % cols].set_visible(False)
    lines = [a.title or first["deck"]["case"].get("title", "")]
    errs = [f"{label}: {100 * meta['errors']['stress_vs_direct_md']:.1f}%" for label, meta, _ in runs
            if "stress_vs_direct_md" in meta.get("errors", {})]
    if errs:
        lines.append("eq. 7.12 vs direct MD  " + ",  ".join(errs))
    fig.suptitle("\n".join(lines), fontsize=10)
    fig.tight_layout()
    os.makedirs(os.path.dirname(os.path.abspath(a.out)), exist_ok=True)
    fig.savefig(a.out, dpi=120)
    print(a.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
