#!/usr/bin/python3
"""The table and figure of scripts/box-rates: sigma_xx, temperature and energy of a
closure's box compressed along x at each rate and scheme, read at the Hugoniot's
compression, beside the Hugoniostat's state (M8 at the jet's 2.5 km/s) and the jump
conditions' energy.

    tools/plot/box_rates.py OUT [--J 0.6686]
"""
import argparse
import os
import sys

import numpy as np

# M8's Hugoniostat at up = 2.5 km/s (docs/md.md): 172 GPa, 13.365 g/cm^3, 3,333 K, from
# copper at 8.9357 g/cm^3 (the potential's 0 K crystal).
HUGONIOT = {"sxx_GPa": -172.0, "J": 8.9357 / 13.365, "T_K": 3333.0}
RATES = ["1e11", "1e12", "1e13"]
SCHEMES = ["boundary", "affine"]


def read(run):
    d = np.genfromtxt(os.path.join(run, "thermo.csv"), delimiter=",", names=True)
    J = d["lx_A"] / d["lx_A"][0]
    e = d["pe_per_atom_eV"] + d["ke_per_atom_eV"]
    return J, d["sxx_GPa"], d["temperature_K"], e - e[0]


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("out")
    ap.add_argument("--J", type=float, default=HUGONIOT["J"], help="where the states are read (V/V0)")
    a = ap.parse_args(argv)
    # The jump's energy per atom: -sigma (V0 - V) / 2 at the Hugoniot's state, V0 the
    # 0 K crystal's volume per atom (3.614925^3 / 4 A^3), 1 GPa A^3 = 1 / 160.2177 eV.
    v0 = 3.614925066**3 / 4
    jump = 0.5 * -HUGONIOT["sxx_GPa"] * v0 * (1 - HUGONIOT["J"]) / 160.21766208
    print(f"at J = {a.J:.4f}; Hugoniot: sigma_xx {HUGONIOT['sxx_GPa']:.0f} GPa, {HUGONIOT['T_K']:.0f} K, "
          f"jump energy {jump:.3f} eV/atom")
    print(f"{'rate /s':>8} {'scheme':>9} {'sigma_xx GPa':>13} {'T K':>9} {'e - e0 eV/atom':>15}")
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(1, 2, figsize=(10, 4.2))
    colours = {"1e11": "tab:blue", "1e12": "tab:orange", "1e13": "tab:red"}
    for rate in RATES:
        for scheme in SCHEMES:
            run = os.path.join(a.out, f"{rate}_{scheme}")
            try:
                J, s, T, e = read(run)
            except (OSError, ValueError) as err:
                print(f"box_rates.py: {run}: {err}", file=sys.stderr)
                return 2
            o = np.argsort(J)
            at = [np.interp(a.J, J[o], v[o]) for v in (s, T, e)]
            print(f"{rate:>8} {scheme:>9} {at[0]:13.1f} {at[1]:9.0f} {at[2]:15.3f}")
            style = "-" if scheme == "boundary" else "--"
            ax[0].plot(J, -s, style, color=colours[rate], label=f"{rate} /s, {scheme}")
            ax[1].semilogy(J, np.maximum(T, 1.0), style, color=colours[rate], label=f"{rate} /s, {scheme}")
    for k in (0, 1):
        ax[k].axvline(a.J, color="grey", lw=0.6)
        ax[k].invert_xaxis()
        ax[k].set_xlabel("V / V0")
    ax[0].plot([HUGONIOT["J"]], [-HUGONIOT["sxx_GPa"]], "k*", ms=11, label="Hugoniostat (2.5 km/s)")
    ax[1].plot([HUGONIOT["J"]], [HUGONIOT["T_K"]], "k*", ms=11, label="Hugoniostat (2.5 km/s)")
    ax[0].set_ylabel("-sigma_xx (GPa)")
    ax[0].set_ylim(0, 400)
    ax[1].set_ylabel("temperature (K)")
    ax[0].legend(fontsize=7)
    ax[0].set_title("500-atom Cu box compressed along x")
    ax[1].set_title("its temperature")
    fig.tight_layout()
    path = os.path.join(a.out, "box_rates.png")
    fig.savefig(path, dpi=110)
    print(f"-> {path}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
