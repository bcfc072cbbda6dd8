#!/usr/bin/python3
"""How noisy a box's stress is as a continuum step samples it: from an `mpmx md` run's
thermo.csv (write it every step: run.thermo = 1), the standard deviation of sigma_xx at
one step (`stress = "last"`) and of its means over n consecutive steps (`stress =
"average"` over a macro step of n MD steps), after a given step.

    tools/plot/stress_noise.py RUN [--after STEP] [--blocks 10 20 100]
"""
import argparse
import os
import sys

import numpy as np


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("run")
    ap.add_argument("--after", type=int, default=0, help="use the rows from this step on")
    ap.add_argument("--blocks", type=int, nargs="+", default=[10, 20, 100], help="MD steps per macro step")
    ap.add_argument("--column", default="sxx_GPa")
    a = ap.parse_args(argv)
    try:
        d = np.genfromtxt(os.path.join(a.run, "thermo.csv"), delimiter=",", names=True)
        s = d[a.column][d["step"] >= a.after]
    except (OSError, ValueError) as e:
        print(f"stress_noise.py: {a.run}: {e}", file=sys.stderr)
        return 2
    gaps = np.unique(np.diff(d["step"]))
    if len(gaps) != 1 or gaps[0] != 1:
        print(f"stress_noise.py: {a.run}: thermo.csv is not written every step (gaps {gaps[:4]}); set run.thermo = 1",
              file=sys.stderr)
        return 2
    x = s - s.mean()
    ac = np.correlate(x, x, "full")[len(x) - 1:] / (x.var() * len(x))
    print(f"{a.column}: {len(s)} steps, mean {s.mean():.4f}, one step: std {s.std():.4f} "
          f"({100 * s.std() / abs(s.mean()):.3f}% of the mean); autocorrelation first below zero at lag "
          f"{int(np.argmax(ac < 0))} steps")
    for n in a.blocks:
        m = len(s) // n * n
        b = s[:m].reshape(-1, n).mean(axis=1)
        print(f"  mean over {n} steps: std {b.std():.4f} ({b.std() / s.std():.3f} of one step's)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
