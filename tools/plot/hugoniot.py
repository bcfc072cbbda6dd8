#!/usr/bin/python3
"""Draw Hugoniostat runs on the Us(up) plane: each `mpmx md` run with ensemble = "nphug"
(run.json's hugoniot table) a point, beside a linear fit Us = c0 + s up and, optionally,
direct-MD shocks (a jet or bar run whose run.json has shock_speed_km_s: the front's lab
speed into material at rest at the piston's up) and continuum runs' shocked states (a
DDMP-MD bar or jet: the front's speed and the plateau's up, measured from the run's
records by tools/plot/shock_state.py; `--continuum RUN@T` uses the run's records to t <= T
only, before the front meets a wall or a notch).

    tools/plot/hugoniot.py RUN [RUN ...] -o FIG.png [--fit 3.94 1.49] [--direct-md DIR --up 2.5]
                           [--continuum RUN[@T] ...]
"""
import argparse
import json
import os
import sys


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("runs", nargs="+", help="nphug run folders")
    ap.add_argument("-o", "--out", required=True)
    ap.add_argument("--fit", nargs=2, type=float, default=(3.94, 1.49), metavar=("C0", "S"),
                    help="Us = C0 + S up (km/s); default copper's experimental fit")
    ap.add_argument("--direct-md", action="append", default=[], help="a direct-MD run folder (jet or bar)")
    ap.add_argument("--up", action="append", type=float, default=[], help="its piston speed (km/s), one per --direct-md")
    ap.add_argument("--continuum", action="append", default=[],
                    help="a continuum run folder (DDMP-MD bar or jet); RUN@T: its records to t <= T (ps)")
    a = ap.parse_args(argv)
    if len(a.up) != len(a.direct_md):
        print("hugoniot.py: one --up per --direct-md", file=sys.stderr)
        return 2
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    from shock_state import Bad, shock_state
    states = []
    for arg in a.continuum:
        run, _, to = arg.rpartition("@") if "@" in arg else (arg, "", "inf")
        try:
            states.append((run, shock_state(run, 0.0, float(to))))
        except (Bad, OSError, KeyError, ValueError) as e:
            print(f"hugoniot.py: {run}: {e}", file=sys.stderr)
            return 2
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    pts = []
    for run in a.runs:
        try:
            with open(os.path.join(run, "run.json")) as f:
                h = json.load(f)["hugoniot"]
        except (OSError, KeyError, ValueError) as e:
            print(f"hugoniot.py: {run}: no hugoniot table in run.json ({e})", file=sys.stderr)
            return 2
        pts.append((h["particle_velocity_km_s"], h["shock_speed_km_s"], h["pressure_GPa"], h["temperature_K"]))
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    top = max([p[0] for p in pts] + a.up + [st["particle_velocity_km_s"] for _, st in states] + [1.0]) * 1.15
    c0, s = a.fit
    ax.plot([0, top], [c0, c0 + s * top], "k--", lw=1, label=f"experiment: Us = {c0:g} + {s:g} up")
    ax.plot([p[0] for p in pts], [p[1] for p in pts], "o", color="tab:blue", label="Hugoniostat (nphug), mpmx")
    for up, us, p, t in pts:
        fit = c0 + s * up
        ax.annotate(f"{p:.0f} GPa, {t:.0f} K ({100 * (us / fit - 1):+.1f}%)", (up, us), textcoords="offset points",
                    xytext=(6, -12), fontsize=8)
    for run, up in zip(a.direct_md, a.up):
        with open(os.path.join(run, "run.json")) as f:
            front = json.load(f)["shock_speed_km_s"]
        ax.plot([up], [front + up], "s", color="tab:red", label=f"direct MD ({os.path.basename(run.rstrip('/'))})")
    for (run, st), mark in zip(states, "^vD<>"):
        up, us = st["particle_velocity_km_s"], st["shock_speed_km_s"]
        ax.plot([up], [us], mark, color="tab:green", ms=7,
                label=f"DDMP-MD plateau ({os.path.basename(run.rstrip('/'))})")
        ax.annotate(f"{st['plateau_sigma_GPa']:.0f} GPa ({100 * (us / (c0 + s * up) - 1):+.1f}%)", (up, us),
                    textcoords="offset points", xytext=(6, 6), fontsize=8, color="tab:green")
    ax.set_xlabel("particle velocity up (km/s)")
    ax.set_ylabel("shock speed Us (km/s)")
    ax.set_title("Copper Hugoniot (Mishin EAM)")
    ax.set_xlim(0, top)
    lo, hi = ax.get_ylim()
    ax.set_ylim(lo, hi + 0.06 * (hi - lo))  # room for the labels above the highest point
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, loc="upper left")
    fig.tight_layout()
    fig.savefig(a.out, dpi=130)
    for run, st in states:
        print(f"hugoniot.py: {run}: up {st['particle_velocity_km_s']:.3f} km/s, Us {st['shock_speed_km_s']:.3f} "
              f"(from the jump: {st['shock_speed_from_jump_km_s']:.3f}), plateau {st['plateau_sigma_GPa']:.1f} GPa")
    print(f"hugoniot.py: {len(pts)} Hugoniostat point(s), {len(states)} continuum state(s) -> {a.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
