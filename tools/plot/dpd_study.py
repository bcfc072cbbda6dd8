#!/usr/bin/python3
"""Figures and figures-of-merit of DPD runs (seed 004 sec. 4): the region displacement
histories (fig. 3), CNA snapshots of the last dump frame (fig. 4, when the dump has a
structure column), stress-strain curves (fig. 6) and displacement profiles (fig. 8) of
one or more `mpmx dpd` run directories (and the all-atom reference of the rod, an `mpmx md`
run of a [rod] deck, whose tracks come from the same code), overlaid, and a table of what VALIDATION.md D1-D3
compare: wave speeds (and their difference from the first run's), initial slopes and peak
stresses, and, for a concurrent run beside its all-DPD reference (a run whose deck id ends
in "reference_dpd_only"), the reflection at the interface: the largest difference of the
'interface' track's displacement from the reference's, before the wave reflected at the
far free end returns, over the reference's largest displacement there. With the runs'
undriven twins (`mpmx dpd DECK --still`: the same deck, its flyer at rest) among the
directories, each run's tracks minus its twin's are the wave alone (the two share their
random streams, so they agree to round-off until the wave arrives), and the reflection is
also measured on those: fig. `wave_response.png`.

Usage: dpd_study.py --out FIG_DIR RUN_DIR [RUN_DIR ...]
"""
import argparse
import csv
import json
import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def table(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {k: [float(r[k]) for r in rows] for k in rows[0]} if rows else {}


def interface_note(run):
    """' (interface X)' for a concurrent run, else ''."""
    face = run.get("model", {}).get("interface")
    return f" (interface {face})" if face else ""


def label(run):
    if run.get("command") == "md":
        return "all-atom MD"
    m = run.get("model", {})
    if m.get("name") == "dpd_only":
        return "DPD-only"
    if m.get("name") == "dpd_mpm_concurrent":
        return f"DPD/MPM, {m.get('grid_cell_A', 0):g} A"
    return f"DPD/MPM-grid, {m.get('grid_cell_A', 0):g} A"


def reflection(conc, ref, onset):
    """The interface's reflection: on the 'interface' track (the DPD side, next to the
    interface), the displacement gained from the incident wave's arrival there (the
    reference's onset) up to the reference's first peak, concurrent against all-DPD:
    max |du_conc - du_ref| over max |du_ref|. Gains from the arrival, because the two
    runs drift apart before it (the static continuum's pull, docs/theory.md)."""
    a, b = conc.get("tracks"), ref.get("tracks")
    if not a or not b or "interface_ux_A" not in a or "interface_ux_A" not in b or onset is None:
        return None
    t = b["time_ps"]
    n = min(len(a["time_ps"]), len(t))
    k0 = next((k for k in range(n) if t[k] >= onset), None)
    if k0 is None:
        return None
    ua, ub = a["interface_ux_A"], b["interface_ux_A"]
    du_b = [ub[k] - ub[k0] for k in range(k0, n)]
    end = first_peak_end(du_b, t[1] - t[0])  # the reference's first peak
    du_a = [ua[k0 + k] - ua[k0] for k in range(end)]
    umax = max(abs(v) for v in du_b[:end])
    if umax <= 0:
        return None
    return max(abs(x - y) for x, y in zip(du_a, du_b[:end])) / umax, t[k0], t[k0 + end - 1]


def first_peak_end(u, step, start=0):
    """One past the index where |u| reaches its first peak after `start`: it stops growing
    for 0.5 ps."""
    hold = max(1, round(0.5 / step))
    best = start
    for k in range(start, len(u)):
        if abs(u[k]) > abs(u[best]):
            best = k
        elif k - best > hold:
            return best + 1
    return len(u)


def onset_time(t, u, rise, sign):
    """The run's onset rule (app/region_tracks.cpp, RegionTracks::onset_time): the first time u has
    risen `rise` along `sign` above its lowest value so far, interpolated in the record."""
    lowest = sign * u[0] if u else 0.0
    for r in range(1, len(u)):
        a = sign * u[r - 1] - lowest
        lowest = min(lowest, sign * u[r - 1])
        b = sign * u[r] - lowest
        if b >= rise:
            return t[r - 1] + (t[r] - t[r - 1]) * (rise - a) / (b - a) if a < rise and b > a else t[r]
    return None


def onset_rule(run):
    """The deck's (rise, direction) of the onset rule, with the run's defaults."""
    a = run.get("deck", {}).get("analysis", {})
    return a.get("onset", 0.3), a.get("onset_direction", 1)


def wave_reflection(conc, ref):
    """The reflection on the wave alone: the 'interface' track's response (the run's
    displacement minus its still twin's) against the reference's, from the impact to the
    reference response's first peak after its onset: max |w_conc - w_ref| over max |w_ref|
    (the responses are zero before the wave, so the window starts at the impact)."""
    a, b = conc.get("wave"), ref.get("wave")
    if not a or not b or "interface_ux_A" not in a or "interface_ux_A" not in b:
        return None
    t = b["time_ps"]
    n = min(len(a["time_ps"]), len(t))
    wa, wb = a["interface_ux_A"][:n], b["interface_ux_A"][:n]
    arrival = onset_time(t[:n], wb, *onset_rule(ref))
    if arrival is None:
        return None
    end = first_peak_end(wb, t[1] - t[0], next(k for k in range(n) if t[k] >= arrival))
    umax = max(abs(v) for v in wb[:end])
    return max(abs(x - y) for x, y in zip(wa[:end], wb[:end])) / umax, t[end - 1]


def wave_speed_alone(run):
    """m/s between the deck's two `wave_speed` tracks from the onsets of their responses
    (the first time a response has moved `onset` Angstrom along `onset_direction`)."""
    deck, w = run.get("deck", {}), run.get("wave")
    names = deck.get("analysis", {}).get("wave_speed")
    if not w or not names or len(names) != 2:
        return None
    centre, onset = {}, {}
    for tr in deck.get("track", []):
        if tr.get("name") in names:
            centre[tr["name"]] = 0.5 * (tr["x"][0] + tr["x"][1])
            onset[tr["name"]] = onset_time(w["time_ps"], w.get(tr["name"] + "_ux_A", []), *onset_rule(run))
    if any(onset.get(n) is None or n not in centre for n in names) or onset[names[1]] == onset[names[0]]:
        return None
    return 100 * abs(centre[names[1]] - centre[names[0]]) / abs(onset[names[1]] - onset[names[0]])


def attach_waves(runs):
    """Pairs each driven run with its still twin (the same deck echo) and stores the
    difference of their tracks as run["wave"]; returns the driven runs."""
    key = lambda r: json.dumps(r.get("deck", {}), sort_keys=True)  # noqa: E731
    stills = {key(r): r for r in runs if r.get("still")}
    driven = [r for r in runs if not r.get("still")]
    for r in driven:
        twin = stills.get(key(r))
        if twin is None or not r.get("tracks") or not twin.get("tracks"):
            continue
        a, b = r["tracks"], twin["tracks"]
        n = min(len(a["time_ps"]), len(b["time_ps"]))
        r["wave"] = {"time_ps": a["time_ps"][:n]}
        for name in a:
            if name.endswith("_ux_A") and name in b:
                r["wave"][name] = [x - y for x, y in zip(a[name][:n], b[name][:n])]
    return driven


def finish(fig, ax, xlabel, ylabel, title, path, legend=8, ncol=1):
    """Labels, legend and the PNG; closes the figure."""
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title(title)
    ax.legend(fontsize=legend, ncol=ncol)
    fig.tight_layout()
    fig.savefig(path, dpi=130)
    plt.close(fig)


def last_frame(path):
    """The last frame of a LAMMPS dump: (step, {column: list of floats}), or None."""
    step, names, rows = None, [], []
    with open(path) as f:
        lines = iter(f)
        for line in lines:
            if line.startswith("ITEM: TIMESTEP"):
                step, names, rows = int(next(lines)), [], []
            elif line.startswith("ITEM: ATOMS"):
                names = line.split()[2:]
            elif names:
                rows.append(line.split())
    if not names or not rows:
        return None
    return step, {n: [float(row[k]) for row in rows] for k, n in enumerate(names)}


def cna_snapshot(run, out):
    """Fig. 4: the last dump frame's particles in a slab through the rod's middle (y within
    one coarse lattice constant of the centre), x-z, coloured by CNA structure."""
    path = os.path.join(run["dir"], "dump.lammpstrj")
    if not os.path.exists(path):
        return
    frame = last_frame(path)
    if frame is None or "structure" not in frame[1]:
        return
    step, c = frame
    a = run.get("cna", {}).get("lattice_constant_A", 7.0)
    ymid = 0.5 * (min(c["y"]) + max(c["y"]))
    keep = [k for k, y in enumerate(c["y"]) if abs(y - ymid) <= 0.5 * a]
    colours = {0: "#d0d0d0", 1: "#2ca02c", 2: "#d62728"}
    fig, ax = plt.subplots(figsize=(8, 3.2))
    for code, name in ((1, "fcc"), (2, "hcp"), (0, "other")):
        sel = [k for k in keep if int(c["structure"][k]) == code]
        ax.scatter([c["x"][k] / 10 for k in sel], [c["z"][k] / 10 for k in sel], s=9, c=colours[code],
                   label=f"{name} ({len(sel)})", edgecolors="none")
    ax.set_aspect("equal")
    t = run.get("dt_ps", 0) * (step - run.get("equilibrate_steps", 0))
    finish(fig, ax, "x (nm)", "z (nm)", f"CNA, {label(run)}, {t:g} ps into the run (seed 004 fig. 4)",
           os.path.join(out, f"fig4_cna_{run.get('case', 'run')}.png"), legend=7)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--out", required=True)
    ap.add_argument("runs", nargs="+")
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    runs = []
    for d in args.runs:
        with open(os.path.join(d, "run.json")) as f:
            r = json.load(f)
        r["dir"] = d
        if "case" not in r:  # an `mpmx md` run (the all-atom rod): its deck's name
            r["case"] = os.path.splitext(os.path.basename(r.get("deck_file", d)))[0]
        for name in ("tracks", "stress_strain", "profile"):
            p = os.path.join(d, name + ".csv")
            if os.path.exists(p):
                r[name] = table(p)
        runs.append(r)
    runs = attach_waves(runs)

    styles = ["-", "--", "-.", ":", (0, (5, 1)), (0, (1, 1))]
    def plot_tracks(key, ylabel, title, name, note):
        """Every run's '_ux_A' series of run[key] overlaid: a colour per track, a line style per run."""
        have = [r for r in runs if r.get(key)]
        if not have:
            return
        fig, ax = plt.subplots(figsize=(6.2, 4.2))
        for i, r in enumerate(have):
            t = r[key]
            for k, col in enumerate(n for n in t if n.endswith("_ux_A")):
                ax.plot(t["time_ps"], t[col], linestyle=styles[i % len(styles)], color=f"C{k}",
                        label=f"{label(r)}{note(r)}: {col[:-5]}")
        finish(fig, ax, "time after impact (ps)", ylabel, title, os.path.join(args.out, name), legend=7)

    plot_tracks("wave", "displacement minus the still twin's (Angstrom)",
                "The wave alone: each run less its undriven twin", "wave_response.png", interface_note)
    plot_tracks("tracks", "mean x displacement (Angstrom)", "Region displacement histories (seed 004 fig. 3)",
                "fig3_tracks.png", lambda r: "")
    with_ss = [r for r in runs if r.get("stress_strain")]
    if with_ss:
        fig, ax = plt.subplots(figsize=(5.6, 4.2))
        for i, r in enumerate(with_ss):
            s = r["stress_strain"]
            ax.plot(s["strain"], s["stress_GPa"], linestyle=styles[i % len(styles)], label=label(r))
        finish(fig, ax, "strain", "stress (GPa)", "Tensile test (seed 004 fig. 6)",
               os.path.join(args.out, "fig6_stress_strain.png"))
    for r in runs:
        p = r.get("profile")
        if not p:
            continue
        fig, ax = plt.subplots(figsize=(6.2, 4.0))
        times = sorted(set(p["time_ps"]))
        cmap = plt.get_cmap("viridis")
        for n, t in enumerate(times):
            xs = [x for x, tt in zip(p["x0_A"], p["time_ps"]) if tt == t]
            us = [u for u, tt in zip(p["ux_A"], p["time_ps"]) if tt == t]
            ax.plot([x / 10 for x in xs], us, color=cmap(n / max(1, len(times) - 1)), label=f"{t:g} ps")
        lo = r.get("deck", {}).get("continuum", {}).get("x")
        if lo:
            ax.axvline(lo[1] / 10, color="k", linewidth=0.8, linestyle=":")
        finish(fig, ax, "x at the run's start (nm)", "mean x displacement (Angstrom)",
               f"Displacement profiles, {label(r)} (seed 004 fig. 8)",
               os.path.join(args.out, f"fig8_profiles_{r.get('case', 'run')}.png"), legend=7, ncol=2)

    for r in runs:
        cna_snapshot(r, args.out)

    base = runs[0].get("analysis", {})
    print(f"{'run':<28} {'model':<22} {'wave m/s':>9} {'vs first':>9} {'slope GPa':>10} {'peak GPa':>9} "
          f"{'fcc start':>9} {'fcc end':>8}")
    for r in runs:
        a = r.get("analysis", {})
        w = a.get("wave_speed_m_per_s")
        w0 = base.get("wave_speed_m_per_s")
        rel = f"{100 * (w - w0) / w0:+.1f}%" if w and w0 and w > 0 and w0 > 0 else ""
        t = a.get("tensile", {})
        c = r.get("cna", {})
        print(f"{r.get('case', '?'):<28} {label(r):<22} {w if w else float('nan'):9.0f} {rel:>9} "
              f"{t.get('initial_slope_GPa', float('nan')):10.2f} {t.get('peak_stress_GPa', float('nan')):9.3f} "
              f"{c.get('interior_fcc_fraction_start', float('nan')):9.3f} "
              f"{c.get('interior_fcc_fraction_end', float('nan')):8.3f}")
    refs = [r for r in runs if str(r.get("case", "")).endswith("reference_dpd_only")]
    for r in runs:
        if r.get("model", {}).get("name") == "dpd_mpm_concurrent" and refs:
            onset = refs[0].get("analysis", {}).get("tracks", {}).get("interface", {}).get("onset_ps")
            q = reflection(r, refs[0], onset if onset and onset > 0 else None)
            if q is not None:
                print(f"interface reflection of {r.get('case')}{interface_note(r)}: {100 * q[0]:.2f}% of the "
                      f"reference's displacement gain ({q[1]:.2f}-{q[2]:.2f} ps)")
    for r in runs:
        v = wave_speed_alone(r)
        if v is not None:
            print(f"wave speed of {r.get('case')}{interface_note(r)} from the responses (still twin subtracted): "
                  f"{v:.0f} m/s")
    for r in runs:
        if r.get("model", {}).get("name") == "dpd_mpm_concurrent" and refs:
            w = wave_reflection(r, refs[0])
            if w is not None:
                print(f"interface reflection of {r.get('case')}{interface_note(r)}, the wave alone (still twins "
                      f"subtracted): {100 * w[0]:.2f}% of the reference's response (impact to {w[1]:.2f} ps)")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
