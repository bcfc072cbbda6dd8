#!/usr/bin/python3
"""Gauge histories and the x-t diagram of sigma_xx of an mpmx continuum run.

    /usr/bin/python3 tools/plot/gauges.py RUN_DIR [--quiet]

Reads RUN_DIR/gauge_<name>.csv (the deck's [[gauge]] tables) and RUN_DIR/xt_sigma_xx.csv
(1-D and quasi-1-D runs) and writes into RUN_DIR/figures/:

  gauges.png         one row per gauge: a point gauge's x-velocity and sigma_xx against
                     time, a free-surface gauge's velocity (what a VISAR records).
  xt_sigma_xx.png    sigma_xx over x (the grid's cells, by the points' current places)
                     and t: fronts, reflections and releases are its lines. A diverging
                     map centred on zero (compression blue), its limits the 1st and 99th
                     percentiles, the clipped extremes said in the colour bar's label;
                     grey where a cell holds no material.

Each written path is printed unless --quiet. Only Debian's python3-matplotlib and
python3-numpy are used (Agg backend).
"""

import argparse
import glob
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.colors import TwoSlopeNorm  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_units import Units  # noqa: E402


def read_table(path):
    with open(path) as f:
        header = f.readline().strip().split(",")
    data = np.genfromtxt(path, delimiter=",", skip_header=1, ndmin=2)
    return header, data


def label(units, text, quantity):
    u = units.unit(quantity)
    return f"{text} ({u})" if u else text


def plot_gauges(run_dir, units, out_dir):
    paths = sorted(glob.glob(os.path.join(run_dir, "gauge_*.csv")))
    if not paths:
        return None
    fig, axes = plt.subplots(len(paths), 2, figsize=(10, 2.8 * len(paths)), squeeze=False)
    for row, path in zip(axes, paths):
        name = os.path.basename(path)[len("gauge_"):-len(".csv")]
        header, data = read_table(path)
        col = {c: k for k, c in enumerate(header)}
        t = data[:, col["time"]]
        row[0].plot(t, data[:, col["vx"]], color="C0", lw=1.2)
        row[0].set_ylabel(label(units, "x-velocity", "velocity"))
        if "sigma_xx" in col:
            row[0].set_title(f"gauge {name}: velocity")
            row[1].plot(t, data[:, col["sigma_xx"]], color="C3", lw=1.2)
            row[1].set_ylabel(label(units, "$\\sigma_{xx}$", "stress"))
            row[1].set_title(f"gauge {name}: $\\sigma_{{xx}}$ (tension positive)")
        else:
            row[0].set_title(f"gauge {name}: free-surface velocity ({int(data[0, col['points']])} points)")
            row[1].plot(t, data[:, col["x"]], color="C2", lw=1.2)
            row[1].set_ylabel(label(units, "mean x of the face", "length"))
            row[1].set_title(f"gauge {name}: the face's place")
        for ax in row:
            ax.set_xlabel(label(units, "t", "time"))
            ax.grid(alpha=0.3)
    fig.tight_layout()
    out = os.path.join(out_dir, "gauges.png")
    fig.savefig(out, dpi=130)
    plt.close(fig)
    return out


def plot_xt(run_dir, units, out_dir):
    path = os.path.join(run_dir, "xt_sigma_xx.csv")
    if not os.path.isfile(path):
        return None
    header, data = read_table(path)
    x = np.array([float(h) for h in header[1:]])
    t = data[:, 0]
    s = data[:, 1:]
    finite = s[np.isfinite(s)]
    if finite.size == 0 or len(t) < 2:
        return None
    lo, hi = np.percentile(finite, [1, 99])
    lo, hi = min(lo, -1e-12), max(hi, 1e-12)  # zero inside the range: the map's centre
    clipped = (finite < lo).sum() + (finite > hi).sum()
    fig, ax = plt.subplots(figsize=(8, 5))
    ax.set_facecolor("0.8")  # cells without material, apart from zero stress (white)
    mesh = ax.pcolormesh(x, t, np.ma.masked_invalid(s), cmap="RdBu_r", norm=TwoSlopeNorm(0.0, lo, hi),
                         shading="nearest")
    bar = fig.colorbar(mesh, ax=ax)
    bar.set_label(label(units, "$\\sigma_{xx}$", "stress")
                  + f"\n(1st-99th percentile: {clipped} of {finite.size} values clipped)")
    ax.set_xlabel(label(units, "x", "length"))
    ax.set_ylabel(label(units, "t", "time"))
    ax.set_title("$\\sigma_{xx}(x, t)$: mean over each cell's points (grey: no material)")
    fig.tight_layout()
    out = os.path.join(out_dir, "xt_sigma_xx.png")
    fig.savefig(out, dpi=130)
    plt.close(fig)
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("run_dir")
    ap.add_argument("--quiet", action="store_true")
    a = ap.parse_args()
    units = Units.of_source(a.run_dir)
    out_dir = os.path.join(a.run_dir, "figures")
    os.makedirs(out_dir, exist_ok=True)
    for out in (plot_gauges(a.run_dir, units, out_dir), plot_xt(a.run_dir, units, out_dir)):
        if out and not a.quiet:
            print(out)


if __name__ == "__main__":
    main()
