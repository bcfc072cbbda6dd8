#!/usr/bin/python3
"""The lattice scan of an `mpmx md` deck with a [scan] table (M1, the seed's fig. 7.2):
energy per atom of the perfect crystal against the lattice constant, the minimum marked
with its value, and the equation of state's curvature there as a bulk modulus.

Usage: md_scan.py RUN_DIR [--out FILE.png]   (default RUN_DIR/energy_vs_lattice.png)

Reads RUN_DIR/run.json ("scan": lattice_constant (Angstrom), energy_per_atom (eV)).
Headless (Agg); python3-matplotlib and python3-numpy only. Prints the written path.
"""
import argparse
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

EV_PER_A3_GPA = 160.21766208  # 1 eV/Angstrom^3 in GPa (core/units)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("run_dir")
    ap.add_argument("--out")
    a = ap.parse_args(argv)
    path = os.path.join(a.run_dir, "run.json")
    try:
        with open(path) as f:
            run = json.load(f)
    except (OSError, ValueError) as e:
        sys.exit(f"md_scan.py: cannot read {path}: {e}")
    scan = run.get("scan")
    if not scan or len(scan.get("lattice_constant", [])) < 3:
        sys.exit(f"md_scan.py: {path} has no lattice scan (a deck with a [scan] table writes one)")
    lat = np.asarray(scan["lattice_constant"], dtype=float)
    e = np.asarray(scan["energy_per_atom"], dtype=float)
    a0, e0 = float(scan["minimum_lattice_constant"]), float(scan["minimum_energy_per_atom"])
    deck = run.get("deck", {})
    lattice = str(deck.get("lattice", {}).get("type", "fcc"))
    elements = ", ".join(deck.get("potential", {}).get("elements", []))
    potential = os.path.basename(str(deck.get("potential", {}).get("file", deck.get("potential", {}).get("style", ""))))

    fig, ax = plt.subplots(figsize=(6.4, 4.6), layout="constrained")
    ax.plot(lat, e, "-", color="C0", linewidth=1.4, label="mpmx, perfect lattice at 0 K")
    # The curvature at the minimum (a parabola through its neighbours): B = V d2E/dV2 with
    # V = a^3 / 4 per atom of fcc (a^3 / 2 for bcc).
    k = int(np.argmin(e))
    note = ""
    if 0 < k < len(lat) - 1:
        c = np.polyfit(lat[k - 1:k + 2], e[k - 1:k + 2], 2)
        per_cell = {"fcc": 4, "bcc": 2}.get(lattice)
        if per_cell:
            # E(V): dE/da = dE/dV 3a^2/n; at the minimum d2E/dV2 = d2E/da2 (n / 3a^2)^2.
            v = a0 ** 3 / per_cell
            b = v * 2 * c[0] * (per_cell / (3 * a0 ** 2)) ** 2 * EV_PER_A3_GPA
            note = f", B = {b:.1f} GPa"
    ax.plot([a0], [e0], "o", color="C3", markersize=6,
            label=f"minimum: a0 = {a0:.4f} Å, E = {e0:.4f} eV/atom{note}")
    ax.axvline(a0, color="C3", linewidth=0.6, linestyle=":")
    ax.set_xlabel("lattice constant a (Å)")
    ax.set_ylabel("energy per atom E (eV/atom)")
    ax.grid(True, linewidth=0.3, alpha=0.5)
    ax.legend(fontsize=8, loc="upper center")
    what = f"{elements} {lattice}" if elements else lattice
    ax.set_title(f"{what}: energy per atom against the lattice constant, 0 K\n"
                 f"{potential}, {len(lat)} points from {lat[0]:g} to {lat[-1]:g} Å", fontsize=10)
    out = a.out or os.path.join(a.run_dir, "energy_vs_lattice.png")
    fig.savefig(out, dpi=130)
    plt.close(fig)
    print(out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
