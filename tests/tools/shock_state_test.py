#!/usr/bin/python3
"""tools/plot/shock_state.py on synthetic 1-D runs whose shock is known: a steady front
(a tanh ramp 0.5 nm wide) at Us = 5.2 km/s into copper at rest (rho0 8.93), up = 1.3,
with a rarefaction ramp far behind it; the tool must return Us, up and the plateau's
stress within 0.5%, and refuse a run with two records."""
import json
import os
import subprocess
import sys
import tempfile

import numpy as np

TOOL = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools", "plot", "shock_state.py")
RHO0, US, UP = 8.93, 5.2, 1.3


def write_run(folder, times):
    os.makedirs(folder)
    with open(os.path.join(folder, "run.json"), "w") as f:
        json.dump({"dim": 1, "units": {"name": "nm_ps_GPa"}, "deck": {"grid": {"lower": 0, "upper": 60, "cells": 300}}}, f)
    x = np.linspace(0.1, 59.9, 600)
    with open(os.path.join(folder, "particles.csv"), "w") as f:
        f.write("time,particle,x,mass,volume,density,velocity,strain,stress\n")
        for t in times:
            front = 10.0 + US * t
            shocked = 0.5 * (1 - np.tanh((x - front) / 0.25))
            back = 0.5 * (1 + np.tanh((x - (2.0 + 0.5 * t)) / 1.0))  # a release far behind
            v = UP * shocked * back
            sigma = -RHO0 * US * v
            rho = RHO0 * US / (US - v)
            for i, xi in enumerate(x):
                f.write(f"{t},{i},{xi},1,1,{rho[i]},{v[i]},0,{sigma[i]}\n")


def main():
    with tempfile.TemporaryDirectory() as tmp:
        good = os.path.join(tmp, "good")
        write_run(good, [0.0, 1.0, 2.0, 3.0, 4.0, 5.0])
        out = subprocess.run([sys.executable, TOOL, good], capture_output=True, text=True)
        if out.returncode != 0:
            print(out.stderr)
            return 1
        s = json.loads(out.stdout)
        checks = [("shock_speed_km_s", US), ("particle_velocity_km_s", UP), ("plateau_sigma_GPa", RHO0 * US * UP),
                  ("shock_speed_from_jump_km_s", US)]
        bad = 0
        for key, want in checks:
            rel = abs(s[key] / want - 1)
            print(f"{key}: {s[key]:.5f} against {want:.5f} ({rel:.2e})")
            bad += rel > 5e-3
        short = os.path.join(tmp, "short")
        write_run(short, [0.0, 1.0])
        refused = subprocess.run([sys.executable, TOOL, short], capture_output=True, text=True)
        print("two records:", refused.returncode, refused.stderr.strip())
        bad += refused.returncode != 2 or "records" not in refused.stderr
        return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
