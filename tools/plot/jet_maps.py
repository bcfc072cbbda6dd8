#!/usr/bin/python3
"""Figures of a direct-MD jet run (`mpmx md` with a [jet] deck; dissertation figs. 7.3, 7.4).

    /usr/bin/python3 tools/plot/jet_maps.py RUN_DIR [--times 10 20] [--jet-time 30] [--quiet]

Times are those of the full-size case in ps; each is multiplied by the run's scale
(run.json jet.scale), so a run at s = 0.2 is drawn at 2, 4 and 6 ps. Reads
RUN_DIR/run.json, RUN_DIR/bins/md_bins_STEP.csv, RUN_DIR/jet_front.csv and, when there,
RUN_DIR/dump.lammpstrj; writes into RUN_DIR/figures/:

  sxx_map_t<time>.png   sigma_xx (GPa) on the bins at each of --times (fig. 7.3)
  jet_t<time>.png       the atoms in x-y at --jet-time coloured by v_x (fig. 7.4), from
                        the dump frame nearest it; the bins' density map without a dump
  front.png             the shock front's position against time, with the Hugoniot's
                        lab-frame speed Us - up (Us = 3.94 + 1.49 up km/s)

Each written path is printed unless --quiet. Only Debian's python3-matplotlib and
python3-numpy are used (Agg backend).
"""

import argparse
import csv
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from colour_scale import EMPTY, Scale  # noqa: E402


class PlotError(Exception):
    """A problem with the run directory: reported in one line, exit status 1."""


def read_columns(path):
    try:
        with open(path, newline="") as f:
            rows = list(csv.DictReader(f))
    except OSError as e:
        raise PlotError(f"{path}: {e.strerror}")
    if not rows:
        raise PlotError(f"{path}: no rows")
    return {k: np.array([float(r[k]) if r[k] not in ("", "nan") else np.nan for r in rows]) for k in rows[0]}


def record_steps(run_dir):
    names = [n for n in os.listdir(os.path.join(run_dir, "bins")) if n.startswith("md_bins_")]
    return sorted(int(n[len("md_bins_"):-len(".csv")]) for n in names)


def nearest_step(steps, dt, t):
    return min(steps, key=lambda s: abs(s * dt - t))


def grid(run_dir, step, field):
    c = read_columns(os.path.join(run_dir, "bins", f"md_bins_{step:06d}.csv"))
    nx, ny = int(c["ix"].max()) + 1, int(c["iy"].max()) + 1
    values = np.full((ny, nx), np.nan)
    values[c["iy"].astype(int), c["ix"].astype(int)] = np.where(c["atoms"] > 0, c[field], np.nan)
    x, y = np.unique(c["x_A"]), np.unique(c["y_A"])
    dx, dy = x[1] - x[0] if nx > 1 else 1.0, y[1] - y[0] if ny > 1 else 1.0
    extent = [0.1 * (x[0] - dx / 2), 0.1 * (x[-1] + dx / 2), 0.1 * (y[0] - dy / 2), 0.1 * (y[-1] + dy / 2)]
    return values, extent


def map_figure(extent):
    """A figure sized to the map's aspect (the sample is about twice as long as high, its
    jet longer still), and where its colour bar goes: beneath a wide map, beside a tall one."""
    aspect = (extent[3] - extent[2]) / max(extent[1] - extent[0], 1e-300)
    width = 7.5
    wide = aspect < 0.6
    height = width * aspect + (1.6 if wide else 1.2)
    fig, ax = plt.subplots(figsize=(width + (0 if wide else 1.2), height), layout="constrained")
    return fig, ax, "horizontal" if wide else "vertical"


def colour_bar(fig, mappable, ax, orientation, label, extend="neither"):
    bar = fig.colorbar(mappable, ax=ax, orientation=orientation, label=label, extend=extend,
                       shrink=0.6 if orientation == "horizontal" else 0.9, aspect=30)
    bar.ax.tick_params(labelsize=9)


def save(fig, path, quiet):
    fig.savefig(path, dpi=150)
    plt.close(fig)
    if not quiet:
        print(path)


def stress_map(run_dir, out, steps, dt, t, scale, quiet):
    step = nearest_step(steps, dt, t * scale)
    values, extent = grid(run_dir, step, "sxx_GPa")
    fig, ax, orientation = map_figure(extent)
    # Diverging about zero, percentile limits (colour_scale.py); empty bins grey.
    sc = Scale(values, centred=True)
    im = ax.imshow(values, origin="lower", extent=extent, cmap=sc.cmap, vmin=sc.lo, vmax=sc.hi, aspect="equal",
                   interpolation="nearest")
    ax.set_facecolor(EMPTY)
    colour_bar(fig, im, ax, orientation, "$\\sigma_{xx}$ (GPa)", sc.extend)
    ax.set_xlabel("x (nm)")
    ax.set_ylabel("y (nm)")
    fig.supxlabel(sc.caption("GPa") + "; grey: no atoms", fontsize=7, color="0.25")
    ax.set_title(f"direct MD, $\\sigma_{{xx}}$ at t = {step * dt:.3g} ps\n(full-size {t:g} ps, s = {scale:g})",
                 fontsize=11)
    save(fig, os.path.join(out, f"sxx_map_t{t:g}.png"), quiet)


def last_dump_frame_near(path, step_wanted):
    """The dump frame whose step is nearest step_wanted: (step, columns dict)."""
    best = None
    with open(path) as f:
        while True:
            line = f.readline()
            if not line:
                break
            if not line.startswith("ITEM: TIMESTEP"):
                continue
            step = int(f.readline())
            f.readline()
            n = int(f.readline())
            for _ in range(4):
                f.readline()
            header = f.readline().split()[2:]
            if best is None or abs(step - step_wanted) < abs(best[0] - step_wanted):
                rows = np.loadtxt([f.readline() for _ in range(n)], ndmin=2)
                best = (step, {h: rows[:, k] for k, h in enumerate(header)})
            else:
                for _ in range(n):
                    f.readline()
    return best


def jet_figure(run_dir, out, steps, dt, t, scale, quiet):
    dump = os.path.join(run_dir, "dump.lammpstrj")
    if os.path.exists(dump):
        step, a = last_dump_frame_near(dump, round(t * scale / dt))
        x, y = 0.1 * a["x"], 0.1 * a["y"]
        fig, ax, orientation = map_figure([x.min(), x.max(), y.min(), y.max()])
        size = min(4.0, max(0.2, 3e4 / len(a["x"])))  # dots that neither vanish nor merge
        im = ax.scatter(x, y, c=0.1 * a["vx"], s=size, cmap="coolwarm", vmin=-3, vmax=3, linewidths=0)
        ax.set_aspect("equal")
        colour_bar(fig, im, ax, orientation, "$v_x$ (km/s)")
    else:
        step = nearest_step(steps, dt, t * scale)
        values, extent = grid(run_dir, step, "density_g_cm3")
        fig, ax, orientation = map_figure(extent)
        im = ax.imshow(values, origin="lower", extent=extent, cmap="viridis", aspect="equal")
        colour_bar(fig, im, ax, orientation, "density (g/cm$^3$)")
    ax.set_xlabel("x (nm)")
    ax.set_ylabel("y (nm)")
    ax.set_title(f"direct MD, the jet at t = {step * dt:.3g} ps\n(full-size {t:g} ps, s = {scale:g})", fontsize=11)
    save(fig, os.path.join(out, f"jet_t{t:g}.png"), quiet)


def front_figure(run_dir, out, record, quiet):
    c = read_columns(os.path.join(run_dir, "jet_front.csv"))
    up = record["jet"]["velocity_km_s"]
    us = record.get("shock_speed_km_s")
    fig, ax = plt.subplots(figsize=(5.5, 3.8), layout="constrained")
    ok = np.isfinite(c["front_x_A"])
    ax.plot(c["time_ps"][ok], 0.1 * c["front_x_A"][ok], "o", color="C3", markersize=3, label="shock front (MD)")
    ax.plot(c["time_ps"], 0.1 * c["notch_tip_x_A"], "--", color="0.5", label="notch tip (unshocked block)")
    if ok.any():
        t0, x0 = c["time_ps"][ok][0], 0.1 * c["front_x_A"][ok][0]
        hug = 3.94 + 1.49 * up - up
        tt = np.array([t0, c["time_ps"].max()])
        ax.plot(tt, x0 + 0.1 * 10 * hug * (tt - t0), "k-", linewidth=1,
                label=f"Hugoniot $U_s - u_p$ = {hug:.2f} km/s")
    ax.set_xlabel("t (ps)")
    ax.set_ylabel("x (nm)")
    if us is not None:
        ax.set_title(f"lab-frame shock speed {us:.2f} km/s")
    ax.legend(fontsize=8)
    save(fig, os.path.join(out, "front.png"), quiet)


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("run_dir")
    p.add_argument("--times", nargs="+", type=float, default=[10.0, 20.0],
                   help="full-size times (ps) of the sigma_xx maps")
    p.add_argument("--jet-time", type=float, default=30.0, help="full-size time (ps) of the jet figure")
    p.add_argument("--quiet", action="store_true")
    args = p.parse_args(argv)
    try:
        with open(os.path.join(args.run_dir, "run.json")) as f:
            record = json.load(f)
        if "jet" not in record:
            raise PlotError(f"{args.run_dir}/run.json: not a jet run (no 'jet' table)")
        scale, dt = record["jet"]["scale"], record["dt_ps"]
        steps = record_steps(args.run_dir)
        out = os.path.join(args.run_dir, "figures")
        os.makedirs(out, exist_ok=True)
        for t in args.times:
            stress_map(args.run_dir, out, steps, dt, t, scale, args.quiet)
        jet_figure(args.run_dir, out, steps, dt, args.jet_time, scale, args.quiet)
        front_figure(args.run_dir, out, record, args.quiet)
    except (PlotError, OSError, KeyError, ValueError) as e:
        print(f"jet_maps: {e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
