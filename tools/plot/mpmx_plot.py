#!/usr/bin/python3
"""Figures for an mpmx run directory, styled like the seed documents' figures.

    /usr/bin/python3 tools/plot/mpmx_plot.py RUN_DIR [--quiet]
    /usr/bin/python3 tools/plot/mpmx_plot.py --compare DIR1 DIR2 ... --field pressure --out FILE.png

Single-run mode reads RUN_DIR/run.json and RUN_DIR/particles.csv (required) and
RUN_DIR/energy.csv, RUN_DIR/front.csv (optional), and writes into RUN_DIR/figures/:

  <field>_t<time>.png  one per plotted field and recorded time: the particle values
                       (markers, thin line) over the reference (solid line). The fields
                       are those with a ref_<field> column in particles.csv; without any,
                       velocity and stress (pressure for a gas).
  energy.png           total energy vs time, with ref_total when energy.csv has it.
  front.png            shock-front position vs time, when front.csv exists.

Compare mode overlays several runs of one case (the S1 scheme study): one panel per run
in a grid, each at its last recorded time with the exact solution.

Each written path is printed unless --quiet. Only Debian's python3-matplotlib and
python3-numpy are used (Agg backend).
"""

import argparse
import csv
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plot_units  # noqa: E402

FIELDS = ("velocity", "strain", "stress", "pressure", "density")
LABELS = {
    "velocity": "velocity $v$",
    "strain": "strain $\\epsilon$",
    "stress": "stress $\\sigma$",
    "pressure": "pressure $p$",
    "density": "density $\\rho$",
}
NUMERIC_STYLE = dict(color="C3", marker="o", markersize=3.0, markerfacecolor="none",
                     markeredgewidth=0.8, linewidth=0.6)
REFERENCE_STYLE = dict(color="black", linewidth=1.3)
MAX_MARKERS = 150
LEGEND_STYLE = dict(frameon=True, framealpha=0.85, edgecolor="0.8")


class PlotError(Exception):
    """A problem with the run directory: reported in one line, exit status 1."""


# ----------------------------------------------------------------------------- input

def read_csv(path):
    """Columns of a CSV file with a header row, as float arrays (blank -> nan)."""
    try:
        with open(path, newline="") as f:
            rows = list(csv.reader(f))
    except OSError as e:
        raise PlotError(f"cannot read {path}: {e.strerror}")
    if not rows or not rows[0]:
        raise PlotError(f"{path} is empty (expected a header row)")
    header = [h.strip() for h in rows[0]]
    data = [r for r in rows[1:] if r and any(c.strip() for c in r)]
    columns = {}
    for j, name in enumerate(header):
        values = []
        for i, r in enumerate(data):
            cell = r[j].strip() if j < len(r) else ""
            try:
                values.append(float(cell) if cell else math.nan)
            except ValueError:
                raise PlotError(f"{path}: row {i + 2}, column '{name}': '{cell}' is not a number")
        columns[name] = np.asarray(values, dtype=float)
    return columns


def require_columns(columns, names, path):
    missing = [n for n in names if n not in columns]
    if missing:
        raise PlotError(f"{path} lacks column(s) {', '.join(missing)}")


def has_data(columns, name):
    return name in columns and columns[name].size > 0 and np.isfinite(columns[name]).any()


def dig(table, dotted, default=None):
    node = table
    for key in dotted.split("."):
        if not isinstance(node, dict) or key not in node:
            return default
        node = node[key]
    return node


class Run:
    """One run directory: its run.json and particles.csv, loaded eagerly."""

    def __init__(self, directory):
        self.dir = directory
        if not os.path.isdir(directory):
            raise PlotError(f"{directory} is not a directory")
        missing = [n for n in ("run.json", "particles.csv")
                   if not os.path.isfile(os.path.join(directory, n))]
        if missing:
            raise PlotError(f"{directory} is not an mpmx run directory: {' and '.join(missing)} "
                            f"missing (write one with `mpmx run DECK`)")
        path = os.path.join(directory, "run.json")
        try:
            with open(path) as f:
                self.record = json.load(f)
        except (OSError, ValueError) as e:
            raise PlotError(f"cannot read {path}: {e}")
        path = os.path.join(directory, "particles.csv")
        self.particles = read_csv(path)
        require_columns(self.particles, ("time", "x"), path)
        if self.particles["time"].size == 0:
            raise PlotError(f"{path} has no rows")
        # A case compared at the nodes (deck reference.at = "nodes") is drawn from the
        # nodal fields, which are what its error norms measure.
        nodes = os.path.join(directory, "nodes.csv")
        self.at_nodes = dig(self.record, "deck.reference.at", "") == "nodes" and os.path.isfile(nodes)
        if self.at_nodes:
            self.particles = read_csv(nodes)
            require_columns(self.particles, ("time", "x"), nodes)
        self.units = plot_units.Units.of_record(self.record)

    def label(self, text, field):
        """An axis label with the run's unit of the field: 'stress $\\sigma$ (GPa)'."""
        return self.units.label(text, plot_units.QUANTITY.get(field))

    def energy_label(self, text):
        # A 1-D energy is per unit cross-section: stress x length (GPa nm = J/m^2).
        s, l = self.units.unit("stress"), self.units.unit("length")
        return f"{text} ({s} {l})" if s and l else text

    # deck values, with fallbacks so that a sparse run.json still plots
    @property
    def case_id(self):
        return str(dig(self.record, "deck.case.id", "?"))

    @property
    def case_title(self):
        return str(dig(self.record, "deck.case.title", ""))

    @property
    def seed(self):
        return str(dig(self.record, "deck.case.seed", ""))

    @property
    def scheme(self):
        return str(dig(self.record, "deck.scheme.name", "mpm"))

    @property
    def material(self):
        return str(dig(self.record, "deck.material.model", "the law"))

    @property
    def ppc(self):
        return dig(self.record, "deck.particles.per_cell", "?")

    @property
    def reference_label(self):
        """'direct MD' for a direct-MD reference (a simulation, not a formula), 'exact' for
        Riemann/shock solutions, 'analytic' for the linear-wave ones."""
        name = str(dig(self.record, "deck.reference.name", "")).lower()
        if name == "direct_md":
            return "direct MD"
        return "exact" if ("riemann" in name or "shock" in name or "tube" in name) else "analytic"

    def when(self, time):
        """'t = 0.3 ps' (the time's unit where the deck names a unit system)."""
        unit = self.units.unit("time")
        return f"t = {format_time(time)}" + (f" {unit}" if unit else "")

    def error_norms(self, field):
        l1 = dig(self.record, f"errors.{field}.l1")
        l2 = dig(self.record, f"errors.{field}.l2")
        ok = lambda v: isinstance(v, (int, float)) and not isinstance(v, bool)
        return (l1 if ok(l1) else None), (l2 if ok(l2) else None)

    def times(self):
        """Recorded times in the order they appear."""
        t = self.particles["time"]
        _, first = np.unique(t, return_index=True)
        return [float(t[i]) for i in sorted(first)]

    def snapshot(self, time):
        """Columns restricted to one recorded time, sorted by x."""
        mask = self.particles["time"] == time
        order = np.argsort(self.particles["x"][mask], kind="stable")
        return {k: v[mask][order] for k, v in self.particles.items()}

    def fields(self):
        """Fields with a reference column; without any, velocity and stress (pressure for
        a gas, i.e. deck.material.model naming a gas)."""
        with_ref = [f for f in FIELDS if has_data(self.particles, "ref_" + f) and f in self.particles]
        wanted = dig(self.record, "deck.reference.fields", None)
        if isinstance(wanted, list) and wanted:
            with_ref = [f for f in with_ref if f in wanted] or with_ref
        if with_ref:
            return with_ref
        chosen = ["velocity"] if has_data(self.particles, "velocity") else []
        model = str(dig(self.record, "deck.material.model", "")).lower()
        gas = any(w in model for w in ("gas", "fluid", "isothermal"))
        if gas and has_data(self.particles, "pressure"):
            chosen.append("pressure")
        elif has_data(self.particles, "stress"):
            chosen.append("stress")
        elif has_data(self.particles, "pressure"):
            chosen.append("pressure")
        return chosen


# ----------------------------------------------------------------------------- output

def format_time(t):
    """Compact time for titles and file names: 0.3, 125, 2.1, 1e-05."""
    s = f"{t:.6g}"
    return s.replace("e+0", "e").replace("e+", "e").replace("e-0", "e-")


def scheme_label(run):
    return f"mpmx {run.scheme}"


def plot_field(ax, run, snap, field, time, with_legend=True):
    x = snap["x"]
    ref = snap.get("ref_" + field)
    # With many particles, markers on every one would hide the reference: the thin
    # line still joins all particles, the markers go on at most ~MAX_MARKERS of them,
    # and the reference is drawn on top.
    every = max(1, int(math.ceil(x.size / MAX_MARKERS)))
    if ref is not None and np.isfinite(ref).any():
        ax.plot(x, ref, label=run.reference_label, zorder=3, **REFERENCE_STYLE)
    ax.plot(x, snap[field], label=scheme_label(run), zorder=2, markevery=every, **NUMERIC_STYLE)
    ax.set_xlabel(run.label("position $x$", "x"))
    ax.set_ylabel(run.label(LABELS.get(field, field), field))
    ax.grid(True, linewidth=0.3, alpha=0.5)
    ax.ticklabel_format(axis="y", style="sci", scilimits=(-3, 4), useOffset=False)
    if with_legend:
        ax.legend(loc="best", fontsize=8, **LEGEND_STYLE)


def title_lines(run, extra, width=70):
    """Case and detail, each wrapped to the figure's width so that no title is cut."""
    import textwrap
    head = f"{run.case_id}: {run.case_title}" if run.case_title else run.case_id
    return "\n".join(textwrap.wrap(head, width) + textwrap.wrap(extra, width))


def footnotes(fig, run):
    """The seed on the right; free-text units (no named system) on the left."""
    if run.seed:
        fig.text(0.99, 0.005, run.seed, ha="right", va="bottom", fontsize=7, color="0.5")
    if run.units.note():
        fig.text(0.01, 0.005, run.units.note(), ha="left", va="bottom", fontsize=7, color="0.5")


def save(fig, path, quiet):
    fig.savefig(path, dpi=130)
    plt.close(fig)
    if not quiet:
        print(path)


def single_run(directory, quiet):
    run = Run(directory)
    out = os.path.join(directory, "figures")
    os.makedirs(out, exist_ok=True)
    written = 0
    fields = run.fields()
    if not fields:
        print(f"mpmx_plot: {directory}/particles.csv has no velocity, stress or pressure column",
              file=sys.stderr)
    times = run.times()
    for time in times:
        snap = run.snapshot(time)
        for field in fields:
            fig, ax = plt.subplots(figsize=(6.4, 4.4))
            plot_field(ax, run, snap, field, time)
            ax.set_title(title_lines(run, f"{field}, {run.scheme}, {run.ppc} particles/cell, "
                                          f"{run.when(time)}"), fontsize=10)
            l1, l2 = run.error_norms(field)
            if time == times[-1] and (l1 is not None or l2 is not None):
                text = "  ".join(f"{n} = {v:.3g}" for n, v in (("L1", l1), ("L2", l2)) if v is not None)
                ax.text(0.99, 0.02, f"rel. error {text}", transform=ax.transAxes, ha="right",
                        va="bottom", fontsize=8, color="0.3")
            footnotes(fig, run)
            fig.tight_layout(rect=(0, 0.02, 1, 1))
            save(fig, os.path.join(out, f"{field}_t{format_time(time)}.png"), quiet)
            written += 1
    written += energy_figure(run, out, quiet)
    written += front_figure(run, out, quiet)
    return written


def energy_figure(run, out, quiet):
    path = os.path.join(run.dir, "energy.csv")
    if not os.path.isfile(path):
        print(f"mpmx_plot: {path} missing, no energy.png", file=sys.stderr)
        return 0
    e = read_csv(path)
    require_columns(e, ("time", "total"), path)
    # A law that keeps no stored-energy account (md_closure: the boxes' energy is not
    # summed) writes internal = 0 throughout: not drawn, and the total said to be kinetic.
    no_store = has_data(e, "internal") and not np.any(e["internal"][np.isfinite(e["internal"])] != 0.0)
    parts = [n for n in ("kinetic", "internal") if has_data(e, n) and not (n == "internal" and no_store)]
    if no_store:
        parts = []
    if parts:
        fig, (ax, ax2) = plt.subplots(2, 1, figsize=(6.4, 6.0), sharex=True,
                                      gridspec_kw=dict(height_ratios=[3, 2]))
    else:
        fig, ax = plt.subplots(figsize=(6.4, 4.4))
    if has_data(e, "ref_total"):
        ax.plot(e["time"], e["ref_total"], label=run.reference_label, **REFERENCE_STYLE)
    what = "kinetic" if no_store else "total"
    ax.plot(e["time"], e["total"], color="C3", linewidth=1.0, label=f"{scheme_label(run)} {what}")
    ax.set_ylabel(run.energy_label("kinetic energy" if no_store else "total energy $E$"))
    ax.set_title(title_lines(run, f"{what} energy, {run.scheme}, {run.ppc} particles/cell"
                             + (f" ({run.material} keeps no stored-energy account)" if no_store else "")),
                 fontsize=10)
    axes = [ax]
    if parts:
        styles = {"kinetic": dict(color="C0", linestyle="--"), "internal": dict(color="C2", linestyle=":")}
        for n in parts:
            ax2.plot(e["time"], e[n], linewidth=0.9, label=f"{scheme_label(run)} {n}", **styles[n])
        ax2.set_ylabel(run.energy_label("energy"))
        axes.append(ax2)
    axes[-1].set_xlabel(run.label("time $t$", "time"))
    for a in axes:
        a.grid(True, linewidth=0.3, alpha=0.5)
        a.ticklabel_format(axis="y", style="sci", scilimits=(-3, 4), useOffset=False)
        a.legend(loc="best", fontsize=8, **LEGEND_STYLE)
    footnotes(fig, run)
    fig.tight_layout(rect=(0, 0.02, 1, 1))
    save(fig, os.path.join(out, "energy.png"), quiet)
    return 1


def front_figure(run, out, quiet):
    path = os.path.join(run.dir, "front.csv")
    if not os.path.isfile(path):
        return 0
    f = read_csv(path)
    require_columns(f, ("time", "front"), path)
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    t, x = f["time"], f["front"]
    ok = np.isfinite(t) & np.isfinite(x)
    label = scheme_label(run)
    if ok.sum() >= 2 and np.ptp(t[ok]) > 0:
        speed = np.polyfit(t[ok], x[ok], 1)[0]
        v = run.units.unit("velocity")
        label += f" (fitted speed {speed:.4g}{' ' + v if v else ''})"
    if has_data(f, "ref_front"):
        ax.plot(t, f["ref_front"], label=run.reference_label, **REFERENCE_STYLE)
    ax.plot(t[ok], x[ok], label=label, **NUMERIC_STYLE)
    ax.set_xlabel(run.label("time $t$", "time"))
    ax.set_ylabel(run.label("front position $x$", "x"))
    ax.grid(True, linewidth=0.3, alpha=0.5)
    ax.legend(loc="best", fontsize=8, **LEGEND_STYLE)
    ax.set_title(title_lines(run, f"shock front, {run.scheme}, {run.ppc} particles/cell"), fontsize=10)
    footnotes(fig, run)
    fig.tight_layout(rect=(0, 0.02, 1, 1))
    save(fig, os.path.join(out, "front.png"), quiet)
    return 1


def compare(directories, field, out_path, quiet):
    runs = [Run(d) for d in directories]
    for run in runs:
        if field not in run.particles:
            raise PlotError(f"{run.dir}/particles.csv has no '{field}' column")
    n = len(runs)
    ncols = 1 if n == 1 else (2 if n <= 4 else 3)
    nrows = math.ceil(n / ncols)
    fig, axes = plt.subplots(nrows, ncols, figsize=(4.6 * ncols, 3.4 * nrows + 0.6), squeeze=False)
    # One y range over every panel (the runs' values and references), so that the
    # schemes' overshoots compare by eye.
    lo, hi = math.inf, -math.inf
    for run in runs:
        snap = run.snapshot(run.times()[-1])
        for col in (field, "ref_" + field):
            v = snap.get(col)
            if v is not None and np.isfinite(v).any():
                lo, hi = min(lo, float(np.nanmin(v))), max(hi, float(np.nanmax(v)))
    pad = 0.05 * (hi - lo) if hi > lo else 1.0
    for k, run in enumerate(runs):
        ax = axes[k // ncols][k % ncols]
        time = run.times()[-1]
        plot_field(ax, run, run.snapshot(time), field, time)
        if math.isfinite(lo):
            ax.set_ylim(lo - pad, hi + pad)
        ax.set_title(f"({chr(ord('a') + k) if k < 26 else k}) {run.scheme}, {run.ppc} particles/cell, "
                     f"{run.when(time)}", fontsize=9)
    for k in range(n, nrows * ncols):
        axes[k // ncols][k % ncols].set_visible(False)
    first = runs[0]
    # The panels may be different cases and schemes: name the field and the case ids.
    ids = sorted({r.case_id for r in runs})
    fig.suptitle(f"{', '.join(ids)}: {field}, scheme comparison", fontsize=11)
    fig.tight_layout()
    directory = os.path.dirname(os.path.abspath(out_path))
    os.makedirs(directory, exist_ok=True)
    save(fig, out_path, quiet)
    return 1


def main(argv=None):
    parser = argparse.ArgumentParser(
        prog="mpmx_plot.py",
        description="Write the figures of an mpmx run directory into RUN_DIR/figures/.")
    parser.add_argument("run_dir", nargs="?", help="run directory written by `mpmx run`")
    parser.add_argument("--compare", nargs="+", metavar="DIR",
                        help="overlay several runs at their last recorded time, one panel each")
    parser.add_argument("--field", default="pressure", help="field for --compare (default: pressure)")
    parser.add_argument("--out", help="output PNG for --compare")
    parser.add_argument("--quiet", action="store_true", help="do not print the written paths")
    args = parser.parse_args(argv)
    try:
        if args.compare:
            dirs = ([args.run_dir] if args.run_dir else []) + args.compare
            if not args.out:
                parser.error("--compare needs --out FILE.png")
            compare(dirs, args.field, args.out, args.quiet)
        elif args.run_dir:
            single_run(args.run_dir, args.quiet)
        else:
            parser.error("give a run directory, or --compare DIR ... --out FILE.png")
    except PlotError as e:
        print(f"mpmx_plot: error: {e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
