#!/usr/bin/python3
"""The copper-jet study's table and figures (dissertation Table 7.1, figs. 7.3, 7.4).

    /usr/bin/python3 tools/plot/jet_study.py STUDY_DIR --md MD_RUN --scale S ROW...

STUDY_DIR holds one run folder per ROW (scripts/jet-study runs them, in the order of the
table: 1, 4 and 16 points per cell on the coarse grid, 4 per cell on the medium (the J2
row) and the fine grid, then the mie_gruneisen and cubic_elastic baselines on the
medium grid); MD_RUN is the direct MD they are compared with. Reads each row's run.json
and writes into STUDY_DIR:

  table71.csv   row,cells,per_cell,points,error_percent,seed_percent,atom_steps,
                atom_steps_unshared,wall_seconds,peak_memory_bytes: eq. 7.12 at the
                scaled 20 ps against the seed's (dissertation Table 7.1)
  table71.png   the errors beside the seed's: against points per cell (coarse grid) and
                against cells (4 per cell), the baselines as lines
  fig7_3.png    sigma_xx of the direct MD and the J2 row side by side at the scaled 10
                and 20 ps (tools/plot/jet_compare.py)
  fig7_4.png    the same at the scaled 30 ps: the jet
  summary.md    the table, the sharing's figures (atom-steps against one box per point,
                the audit) and the study's wall time and peak memory

Only Debian's python3-matplotlib and python3-numpy are used (Agg backend).
"""

import argparse
import csv
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import jet_compare  # noqa: E402

# Table 7.1 (dissertation sec. 7.3): eq. 7.12 at t = 20 ps, percent.
SEED = [24.7, 10.1, 9.8, 6.0, 5.6, None, None]
SCALES = {"tiny": 0.05, "s0p05": 0.05, "s0p1": 0.1, "s0p2": 0.2, "s0p5": 0.5, "full": 1.0}


def fail(msg):
    print(f"jet_study.py: {msg}", file=sys.stderr)
    sys.exit(1)


def error_at(run, t):
    """Eq. 7.12 (percent) of the compared time nearest t, and that time."""
    series = run.get("errors_by_time", {}).get("stress_vs_direct_md", [])
    if not series:
        return None, None
    best = min(series, key=lambda e: abs(e["time"] - t))
    if abs(best["time"] - t) > 1e-6 * max(1.0, t):
        return None, None
    return 100.0 * best["error"], best["time"]


def not_run(name):
    """A row the study has not finished (--partial): its numbers blank."""
    keys = ["error_percent", "atom_steps", "atom_steps_unshared", "wall_seconds", "peak_memory_bytes",
            "audit_rel_rms", "audit_max_gpa", "boxes_max", "points"]
    return {"row": name, "cells": "", "per_cell": None, "status": "not run", **{k: None for k in keys}}


def row_figures(study, name, t20, partial=False):
    path = os.path.join(study, name, "run.json")
    if not os.path.exists(path):
        if partial:
            return not_run(name)
        fail(f"no {path}: run scripts/jet-study first")
    with open(path) as f:
        run = json.load(f)
    if partial and run.get("status") not in ("completed", "energy_growth"):
        return not_run(name)
    deck = run["deck"]
    cells = deck["grid"]["cells"]
    per = deck["particles"]["per_cell"]
    per = per if isinstance(per, list) else [per, per]
    err, _ = error_at(run, t20)
    md = run.get("md", {})
    return {
        "row": name,
        "cells": f"{cells[0]}x{cells[1]}",
        "per_cell": per[0] * per[1],
        "points": run["particles"],
        "error_percent": err,
        "atom_steps": md.get("atom_steps", 0),
        "atom_steps_unshared": md.get("atom_steps_unshared", 0),
        "wall_seconds": run["wall_seconds"],
        "peak_memory_bytes": run.get("peak_memory_bytes", 0),
        "status": run.get("status"),
        "audit_rel_rms": md.get("share", {}).get("audit_rel_rms"),
        "audit_max_gpa": md.get("share", {}).get("audit_max_gpa"),
        "boxes_max": md.get("boxes", {}).get("max"),
    }


def fmt(v, spec):
    return "" if v is None else format(v, spec)


def write_csv(study, rows):
    keys = ["row", "cells", "per_cell", "points", "error_percent", "seed_percent", "atom_steps",
            "atom_steps_unshared", "wall_seconds", "peak_memory_bytes"]
    path = os.path.join(study, "table71.csv")
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(keys)
        for r in rows:
            w.writerow([fmt(r[k], ".4g") if isinstance(r[k], float) else ("" if r[k] is None else r[k]) for k in keys])
    return path


def table_figure(study, rows, scale):
    fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4.2))
    coarse, fourpc = rows[0:3], [rows[1], rows[3], rows[4]]
    per_cell = [1, 4, 16]  # the table's, whether or not a row has run
    nan = float("nan")
    a.plot(per_cell, [nan if r["error_percent"] is None else r["error_percent"] for r in coarse], "o-",
           label=f"mpmx, s = {scale:g}")
    a.plot(per_cell, [r["seed_percent"] for r in coarse], "s--", label="dissertation (s = 1)")
    a.set_xscale("log", base=2)
    a.set_xlabel(f"points per cell ({coarse[0]['cells'] or 'coarse'} cells)")
    a.set_ylabel("eq. 7.12 error at the scaled 20 ps (%)")
    a.set_title("(a) points per cell")
    labels = [r["cells"] or r["row"].split("_")[3] for r in fourpc]
    b.plot(range(3), [nan if r["error_percent"] is None else r["error_percent"] for r in fourpc], "o-",
           label=f"mpmx DDMP-MD, s = {scale:g}")
    b.plot(range(3), [r["seed_percent"] for r in fourpc], "s--", label="dissertation DDMP-MD (s = 1)")
    for r, style, law in zip(rows[5:], (":", "-."), ("mie_gruneisen", "cubic_elastic")):
        if r["error_percent"] is not None:
            b.axhline(r["error_percent"], ls=style, color="gray", label=f"{law}, {r['cells']} x 4")
    b.set_xticks(range(3), labels)
    b.set_xlabel("cells (4 points per cell)")
    b.set_title("(b) grid")
    for ax in (a, b):
        ax.set_ylim(bottom=0)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    path = os.path.join(study, "table71.png")
    fig.tight_layout()
    fig.savefig(path, dpi=150)
    plt.close(fig)
    return path


def summary(study, rows, scale, md_run):
    with open(os.path.join(md_run, "run.json")) as f:
        md = json.load(f)
    lines = [f"# Copper-jet study at s = {scale:g}", "",
             f"Direct MD: {md['atoms']} atoms, {md['wall_seconds'] / 60:.1f} min ({md_run}).", "",
             "| row | cells | per cell | points | eq. 7.12 at the scaled 20 ps | seed (s = 1) | atom-steps | "
             "one box per point | saving | boxes (most) | audit rms | audit max (GPa) | wall | peak memory |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    wall, peak = md["wall_seconds"], 0
    for r in rows:
        if r["status"] == "not run":
            lines.append(f"| {r['row']} | not run yet |" + " |" * 12)
            continue
        save = r["atom_steps_unshared"] / r["atom_steps"] if r["atom_steps"] else None
        lines.append(f"| {r['row']} | {r['cells']} | {r['per_cell']} | {r['points']} | {fmt(r['error_percent'], '.2f')}% | "
                     f"{fmt(r['seed_percent'], '.1f')}{'%' if r['seed_percent'] else ''} | {fmt(r['atom_steps'] or None, '.3g')} | "
                     f"{fmt(r['atom_steps_unshared'] or None, '.3g')} | {fmt(save, '.2f')}{'x' if save else ''} | "
                     f"{'' if r['boxes_max'] is None else r['boxes_max']} | "
                     f"{fmt(None if r['audit_rel_rms'] is None else 100 * r['audit_rel_rms'], '.3f')}"
                     f"{'%' if r['audit_rel_rms'] is not None else ''} | {fmt(r['audit_max_gpa'], '.3g')} | "
                     f"{r['wall_seconds'] / 60:.1f} min | {r['peak_memory_bytes'] / 2**20:.0f} MiB |")
        wall += r["wall_seconds"]
        peak = max(peak, r["peak_memory_bytes"])
    lines += ["", f"The whole study: {wall / 3600:.2f} hours of wall time (the runs' own), "
              f"peak memory {peak / 2**30:.2f} GiB (the largest run's).", ""]
    path = os.path.join(study, "summary.md")
    with open(path, "w") as f:
        f.write("\n".join(lines))
    return path


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("study")
    ap.add_argument("rows", nargs="+")
    ap.add_argument("--md", required=True, help="the direct-MD run")
    ap.add_argument("--scale", required=True, choices=sorted(SCALES))
    ap.add_argument("--quiet", action="store_true")
    ap.add_argument("--partial", action="store_true",
                    help="rows without a finished run stay blank (an interrupted study)")
    a = ap.parse_args(argv)
    if len(a.rows) != len(SEED):
        fail(f"{len(a.rows)} rows: the table has {len(SEED)}")
    s = SCALES[a.scale]
    rows = [row_figures(a.study, name, 20 * s, a.partial) for name in a.rows]
    for r, seed in zip(rows, SEED):
        r["seed_percent"] = seed
    written = [write_csv(a.study, rows), table_figure(a.study, rows, s), summary(a.study, rows, s, a.md)]
    j2 = os.path.join(a.study, a.rows[3])
    for name, times in (("fig7_3.png", ["10", "20"]), ("fig7_4.png", ["30"])):
        if rows[3]["status"] == "not run":
            break  # the figures are the J2 row's
        out = os.path.join(a.study, name)
        jet_compare.main([a.md, j2, "--times", *times, "--out", out, "--quiet"])
        written.append(out)
    if not a.quiet:
        print("\n".join(written))
    return 0


if __name__ == "__main__":
    sys.exit(main())
