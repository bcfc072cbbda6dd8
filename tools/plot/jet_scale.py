#!/usr/bin/python3
"""The copper jet's error against the scale (docs/jet.md, "Scale study"): eq. 7.12 of the
50 x 25 DDMP-MD rows at the scaled 10 and 20 ps and their shock front against the direct
MD's, for each scale s run, as a table and a figure.

    tools/plot/jet_scale.py --out PREFIX ROW_DIR:MD_DIR [ROW_DIR:MD_DIR ...]
    tools/plot/jet_scale.py --out PREFIX --replot PREFIX.csv

ROW_DIR is a 2-D `mpmx run` of a J3 row against reference.name = "direct_md", finished
or stopped by the physics after the scaled 10 ps (its 20 ps figure then blank, its
status and the scaled time it reached in the table);
MD_DIR the direct MD it was compared with (a run folder or a reference pack,
data/J1_direct_md_SCALE): its run.json gives the scale s. Writes PREFIX.csv (one line per
row) and PREFIX.png; --replot draws PREFIX.png from a CSV written before (the CSV is what
docs/ keeps; the runs are not).

The front at the scaled 10 ps (t = 10 s ps), before it reaches the notch, is planar: the
points' sigma_xx is reduced to a profile along x (the median of each grid column; the
direct MD's bins, the median of each bin column), the plateau is the profile's median
between a quarter and three quarters of the way to where it first rises above -50 GPa,
and the front is where the profile crosses half the plateau, interpolated between
columns. Its distance from the piston's face over t is the front's mean speed in the
piston's frame, where the shocked copper is at rest (J1's 5.21 km/s at s = 0.1), for the
row and for the direct MD. Units: nm, ps, GPa, km/s.
"""
import argparse
import csv
import json
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from check_eq712 import pvd_records, vtu_arrays  # noqa: E402  (the raw VTU reader)

FIELDS = ["scale", "per_cell", "points", "eq712_10_pct", "eq712_20_pct", "front_row_nm", "front_md_nm",
          "us_row_km_s", "us_md_km_s", "plateau_row_gpa", "plateau_md_gpa", "atom_steps", "wall_s", "end_time",
          "status", "deformation", "row"]
TEXT = ("row", "status", "deformation")
SEED = {1: 24.7, 4: 10.1, 16: 9.8}  # Table 7.1 at s = 1, the scaled 20 ps


class Bad(Exception):
    pass


def front_of(x, sxx):
    """(front x, plateau) of a profile sorted by x: see the module's text."""
    shocked = np.nonzero(sxx < -50.0)[0]
    if len(shocked) == 0:
        raise Bad("no shocked column (sigma_xx < -50 GPa)")
    start = shocked[0]
    rise = next((k for k in range(start, len(sxx)) if sxx[k] >= -50.0), None)
    if rise is None:
        raise Bad("the profile is shocked to its end: no front in it")
    band = (x >= 0.25 * x[rise]) & (x <= 0.75 * x[rise])
    if not band.any():
        raise Bad(f"no column behind the front at {x[rise]:.3g} nm to take the plateau from")
    plateau = float(np.median(sxx[band]))
    half = 0.5 * plateau
    for k in range(start, len(sxx) - 1):
        if sxx[k] < half <= sxx[k + 1]:
            return x[k] + (half - sxx[k]) / (sxx[k + 1] - sxx[k]) * (x[k + 1] - x[k]), plateau
    raise Bad("the profile does not cross half its plateau")


def row_profile(row, t):
    meta = json.load(open(os.path.join(row, "run.json")))
    grid = meta["deck"]["grid"]
    recs = pvd_records(os.path.join(row, "particles.pvd"))
    tr, f = min(recs, key=lambda r: abs(r[0] - t))
    if abs(tr - t) > 1e-6 * max(1.0, t):
        raise Bad(f"{row}: no record at t = {t:g} (the nearest {tr:g})")
    a = vtu_arrays(os.path.join(row, f))
    x, sxx = a["Points"][:, 0], a["stress"][:, 0]
    cells, lo, hi = grid["cells"][0], grid["lower"][0], grid["upper"][0]
    h = (hi - lo) / cells
    col = np.floor((x - lo) / h).astype(int)
    xs, ss = [], []
    for c in np.unique(col):
        xs.append(lo + (c + 0.5) * h)
        ss.append(np.median(sxx[col == c]))
    return meta, np.array(xs), np.array(ss)


def md_profile(md, t):
    meta = json.load(open(os.path.join(md, "run.json")))
    jet = meta["jet"]
    recs = pvd_records(os.path.join(md, "md_bins.pvd"))
    tr, f = min(recs, key=lambda r: abs(r[0] - t))
    if abs(tr - t) > 1e-6 * max(1.0, t):
        raise Bad(f"{md}: no record at t = {t:g} ps (the nearest {tr:g})")
    c = np.genfromtxt(os.path.join(md, "bins", os.path.splitext(os.path.basename(f))[0] + ".csv"),
                      delimiter=",", names=True)
    xs, ss = [], []
    for ix in np.unique(c["ix"]):
        m = (c["ix"] == ix) & (c["atoms"] > 0)
        if m.any():
            xs.append((np.mean(c["x_A"][m]) - jet["piston_face_A"]) / 10.0)
            ss.append(np.median(c["sxx_GPa"][m]))
    order = np.argsort(xs)
    xs, ss = np.array(xs)[order], np.array(ss)[order]
    keep = xs > 0  # the piston's own bins are not the sample
    return meta, xs[keep], ss[keep]


def measure(row, md):
    s = float(json.load(open(os.path.join(md, "run.json")))["jet"]["scale"])
    t10, t20 = 10 * s, 20 * s
    meta, xr, sr = row_profile(row, t10)
    _, xm, sm = md_profile(md, t10)
    fr, pr = front_of(xr, sr)
    fm, pm = front_of(xm, sm)
    errs = {round(e["time"] / s): 100 * e["error"] for e in meta["errors_by_time"]["stress_vs_direct_md"]}
    if 10 not in errs:
        raise Bad(f"{row}: run.json has no eq. 7.12 at the scaled 10 ps (t = {t10:g})")
    if 20 not in errs and meta.get("status") in ("completed", "energy_growth"):
        raise Bad(f"{row}: run.json has no eq. 7.12 at the scaled 20 ps (t = {t20:g})")
    ppc = int(np.prod(meta["deck"]["particles"]["per_cell"]))
    return {"scale": s, "per_cell": ppc, "points": meta["particles"], "eq712_10_pct": errs[10],
            "eq712_20_pct": errs.get(20, float("nan")), "front_row_nm": fr, "front_md_nm": fm, "us_row_km_s": fr / t10,
            "us_md_km_s": fm / t10, "plateau_row_gpa": pr, "plateau_md_gpa": pm,
            "atom_steps": meta["md"]["atom_steps"], "wall_s": meta["wall_seconds"], "end_time": meta["time"] / s,
            "status": meta["status"], "row": os.path.basename(row),
            "deformation": meta["deck"]["material"].get("md", {}).get("deformation", "boundary")}


def figure(rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (a, b) = plt.subplots(1, 2, figsize=(10, 4))
    seeds = set()
    for (ppc, how), colour in (((1, "boundary"), "tab:blue"), ((4, "boundary"), "tab:orange"),
                               ((16, "boundary"), "tab:green"), ((1, "affine"), "tab:purple"),
                               ((4, "affine"), "tab:red")):
        r = sorted((x for x in rows if x["per_cell"] == ppc and x["deformation"] == how), key=lambda x: x["scale"])
        if not r:
            continue
        s = [x["scale"] for x in r]
        name = f"{ppc} per cell, {how}"
        a.plot(s, [x["eq712_20_pct"] for x in r], "o-", color=colour, label=f"{name}: scaled 20 ps")
        a.plot(s, [x["eq712_10_pct"] for x in r], "s--", color=colour, mfc="none", label=f"{name}: 10 ps")
        if ppc not in seeds:
            seeds.add(ppc)
            a.plot([1.0], [SEED[ppc]], "*", color=colour, ms=12, label=f"seed (s = 1), {ppc} per cell")
        b.plot(s, [100 * (x["us_row_km_s"] / x["us_md_km_s"] - 1) for x in r], "o-", color=colour, label=name)
    ticks = [0.05, 0.1, 0.2, 0.5, 1.0]
    for ax in (a, b):
        ax.set_xscale("log")
        ax.set_xlim(0.04, 1.3)
        ax.set_xticks(ticks)
        ax.set_xticklabels([f"{t:g}" for t in ticks])
        ax.minorticks_off()
        ax.set_xlabel("scale s")
    a.set_ylabel("eq. 7.12 error (%)")
    a.set_title("50 x 25 cells against the direct MD", fontsize=10)
    a.legend(fontsize=6)
    b.axhline(0, color="k", lw=0.5)
    b.axhspan(-3, 3, color="0.9", label="within 3%")
    b.set_ylabel("front ahead of the direct MD's (%)")
    b.set_title("the shock front at the scaled 10 ps", fontsize=10)
    b.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=120)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("pairs", nargs="*", help="ROW_DIR:MD_DIR")
    ap.add_argument("--out", required=True, help="PREFIX of PREFIX.csv and PREFIX.png")
    ap.add_argument("--replot", help="draw from this CSV instead of runs")
    a = ap.parse_args(argv)
    try:
        if a.replot:
            with open(a.replot) as f:
                rows = [{k: (v if k in TEXT else float(v)) for k, v in r.items()} for r in csv.DictReader(f)]
        else:
            if not a.pairs:
                raise Bad("give ROW_DIR:MD_DIR pairs or --replot CSV")
            rows = []
            for p in a.pairs:
                if ":" not in p:
                    raise Bad(f"{p!r} is not ROW_DIR:MD_DIR")
                row, md = p.split(":", 1)
                rows.append(measure(row, md))
            with open(a.out + ".csv", "w", newline="") as f:
                w = csv.DictWriter(f, fieldnames=FIELDS)
                w.writeheader()
                for r in sorted(rows, key=lambda r: (r["deformation"], r["per_cell"], r["scale"])):
                    w.writerow({k: (f"{v:.6g}" if isinstance(v, float) else v) for k, v in r.items()})
        for r in rows:
            end = "" if r["status"] == "completed" else f" ({r['status']} at the scaled {r['end_time']:.1f} ps)"
            print(f"s = {r['scale']:g} {int(r['per_cell'])} per cell, {r['deformation']} boxes: eq. 7.12 "
                  f"{r['eq712_10_pct']:.2f}% / {r['eq712_20_pct']:.2f}%{end}, front {r['front_row_nm']:.3f} nm "
                  f"against {r['front_md_nm']:.3f} ({100 * (r['front_row_nm'] / r['front_md_nm'] - 1):+.1f}%), "
                  f"plateau {r['plateau_row_gpa']:.1f} / {r['plateau_md_gpa']:.1f} GPa")
        figure(rows, a.out + ".png")
    except (Bad, OSError, KeyError, ValueError) as e:
        print(f"jet_scale.py: {e}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
