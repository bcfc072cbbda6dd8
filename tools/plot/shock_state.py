#!/usr/bin/python3
"""The shocked state of a continuum run (a DDMP-MD bar or jet): the front's speed from
its positions at the run's records, the particle velocity and sigma_xx of the plateau
behind it, and the jump conditions' check, so that a run's shock can be drawn on the
Hugoniot (tools/plot/hugoniot.py --continuum RUN).

    tools/plot/shock_state.py RUN [--from T] [--to T]

The front runs along +x into material that the first record shows undisturbed at the
+x end. At each record the points (1-D: particles.csv; 2-D: particles.pvd's VTUs) are
binned along x (one bin per grid cell; each point in 1-D) and the bins' median vx and
sigma_xx taken; a first front where |vx - v_ahead| crosses half its largest value gives
the plateau (the medians over the half of the shocked length behind it, without the
eighth nearest the front, where the viscous ramp is), then the front at each record is
where sigma_xx crosses one level, half the plateaus' mean stress jump. The front speed is the
least-squares slope of its positions; Us = |V_front - v_ahead|, up the plateau's mean
|vx - v_ahead|, and the momentum jump rho0 Us up beside the plateau's -sigma_xx says how
steady the shock was. Units: the run's nm_ps_GPa (km/s, g/cm^3, GPa).
"""
import argparse
import json
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from check_eq712 import pvd_records, vtu_arrays  # noqa: E402  (the raw VTU reader)


class Bad(Exception):
    pass


def records(run):
    """[(t, x, vx, sxx, rho)] per record, in time order, and the bin width along x."""
    meta = json.load(open(os.path.join(run, "run.json")))
    if meta.get("units", {}).get("name") != "nm_ps_GPa":
        raise Bad(f"{run}: units {meta.get('units', {}).get('name')!r}; this tool reads nm_ps_GPa runs")
    grid = meta["deck"]["grid"]
    out = []
    if meta.get("dim", 1) == 1:
        data = np.genfromtxt(os.path.join(run, "particles.csv"), delimiter=",", names=True)
        for t in np.unique(data["time"]):
            r = data[data["time"] == t]
            out.append((float(t), r["x"], r["velocity"], r["stress"], r["density"]))
        return out, 0.0
    cells = grid["cells"][0]
    width = (grid["upper"][0] - grid["lower"][0]) / cells
    for t, f in pvd_records(os.path.join(run, "particles.pvd")):
        a = vtu_arrays(os.path.join(run, f))
        out.append((t, a["Points"][:, 0], a["velocity"][:, 0], a["stress"][:, 0], a["density"][:, 0]))
    return sorted(out, key=lambda r: r[0]), width


def binned(x, f, width):
    if width <= 0:
        order = np.argsort(x)
        return x[order], f[order]
    k = np.floor(x / width).astype(int)
    keys = np.unique(k)
    return (keys + 0.5) * width, np.array([np.median(f[k == i]) for i in keys])


def crossing(xb, d, level):
    """Scanning from +x, where d first reaches `level` (linear between bins)."""
    for i in range(len(xb) - 1, 0, -1):
        if d[i - 1] >= level > d[i]:
            return xb[i - 1] + (xb[i] - xb[i - 1]) * (d[i - 1] - level) / (d[i - 1] - d[i])
        if d[i] >= level:
            return xb[i]
    return None


def shock_state(run, t_from=0.0, t_to=float("inf")):
    recs, width = records(run)
    if len(recs) < 3:
        raise Bad(f"{run}: {len(recs)} records; the front's speed needs at least three")
    t0, x0, v0, s0, rho0s = recs[0]
    far = x0 >= np.quantile(x0, 0.9)
    v_ahead, s_ahead, rho0 = (float(np.median(a[far])) for a in (v0, s0, rho0s))
    fronts = []
    for t, x, vx, sxx, _ in recs:
        if t <= t0 or not (t_from <= t <= t_to):
            continue
        xb, d = binned(x, np.abs(vx - v_ahead), width)
        first = crossing(xb, d, 0.5 * d.max())
        if first is None or d.max() <= 0:
            continue
        fronts.append((t, first, x, vx, sxx))
    if len(fronts) < 2:
        raise Bad(f"{run}: a front found at {len(fronts)} records")
    # The plateau over the half of the shocked length behind each first front; then every
    # front where -sigma_xx crosses one level, half the plateaus' mean (a level that moves
    # with a growing window would tilt the fitted speed).
    origin = np.polyfit([f[0] for f in fronts], [f[1] for f in fronts], 1)[1]
    plateaus = []
    for t, first, x, vx, sxx in fronts:
        span = first - origin
        win = (x > first - 0.5 * span) & (x < first - 0.125 * span)
        if win.sum() >= 1:
            plateaus.append((t, x, sxx, float(np.median(np.abs(vx[win] - v_ahead))),
                             float(np.median(s_ahead - sxx[win]))))
    if len(plateaus) < 2:
        raise Bad(f"{run}: a plateau found at {len(plateaus)} records")
    level = 0.5 * np.mean([p[4] for p in plateaus])
    rows = []
    for t, x, sxx, up, sigma in plateaus:
        xb, d = binned(x, s_ahead - sxx, width)
        xf = crossing(xb, d, level)
        if xf is not None:
            rows.append((t, xf, up, sigma))
    if len(rows) < 2:
        raise Bad(f"{run}: the stress front found at {len(rows)} records")
    t = np.array([r[0] for r in rows])
    xf = np.array([r[1] for r in rows])
    speed, _ = np.polyfit(t, xf, 1)
    us = abs(speed - v_ahead)
    up = float(np.mean([r[2] for r in rows]))
    sigma = float(np.mean([r[3] for r in rows]))
    return {
        "run": run, "records": len(rows), "times_ps": [float(v) for v in t],
        "front_nm": [float(v) for v in xf], "front_lab_speed_km_s": float(speed),
        "velocity_ahead_km_s": v_ahead, "density_ahead_g_cm3": rho0,
        "particle_velocity_km_s": up, "shock_speed_km_s": float(us),
        "plateau_sigma_GPa": sigma, "sigma_ahead_GPa": -s_ahead, "jump_sigma_GPa": rho0 * us * up,
        "shock_speed_from_jump_km_s": sigma / (rho0 * up) if up > 0 else float("nan"),
    }


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("run")
    ap.add_argument("--from", dest="t_from", type=float, default=0.0, help="first record time used (ps)")
    ap.add_argument("--to", dest="t_to", type=float, default=float("inf"), help="last record time used (ps)")
    a = ap.parse_args(argv)
    try:
        s = shock_state(a.run, a.t_from, a.t_to)
    except (Bad, OSError, KeyError, ValueError) as e:
        print(f"shock_state.py: {e}", file=sys.stderr)
        return 2
    print(json.dumps(s, indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main())
