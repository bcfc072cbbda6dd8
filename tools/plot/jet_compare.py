#!/usr/bin/python3
"""sigma_xx of direct MD and DDMP-MD side by side (dissertation fig. 7.3).

    /usr/bin/python3 tools/plot/jet_compare.py MD_RUN DDMP_RUN [--times 10 20] [--out FILE.png] [--quiet]

MD_RUN is an `mpmx md` jet run (its bins), DDMP_RUN the 2-D DDMP-MD run of the same
sample (its particles.pvd, units nm_ps_GPa). Times are full-size ps, multiplied by the MD
run's scale (run.json jet.scale). The MD bins are drawn in the continuum's frame (x from
the piston's face, nm); each DDMP-MD point is a square of its lattice pitch. One row per
time, one colour scale per row. Writes FILE.png (default DDMP_RUN/sxx_md_vs_ddmp.png).
"""

import argparse
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402

import jet_maps  # noqa: E402
from colour_scale import EMPTY, Scale  # noqa: E402
import points2d  # noqa: E402


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("md_run")
    ap.add_argument("ddmp_run")
    ap.add_argument("--times", type=float, nargs="+", default=[10.0, 20.0])
    ap.add_argument("--out")
    ap.add_argument("--quiet", action="store_true")
    a = ap.parse_args(argv)
    with open(os.path.join(a.md_run, "run.json")) as f:
        run = json.load(f)
    jet = run.get("jet")
    if not jet or "piston_face_A" not in jet:
        points2d.fail(f"{a.md_run}/run.json is not a direct-MD jet run")
    scale, face = jet["scale"], jet["piston_face_A"]
    dt_md = run["deck"]["run"]["dt"]
    steps = jet_maps.record_steps(a.md_run)
    pitch0 = np.array(points2d.point_spacing(points2d.read_dataset(points2d.list_records(a.ddmp_run)[0][1])[0][:, :2]))
    fig, axes = plt.subplots(len(a.times), 2, figsize=(11, 3.2 * len(a.times)), squeeze=False)
    for row, t_full in zip(axes, a.times):
        t = t_full * scale
        step = jet_maps.nearest_step(steps, dt_md, t)
        values, extent = jet_maps.grid(a.md_run, step, "sxx_GPa")
        extent = [extent[0] - 0.1 * face, extent[1] - 0.1 * face, extent[2], extent[3]]
        path, t_pts = points2d.pick_record(a.ddmp_run, t)
        pts, fields, _ = points2d.read_dataset(path)
        if "stress" not in fields:
            points2d.fail(f"{path} has no stress array")
        sxx, _ = points2d.component_values(fields["stress"], "stress", "xx")
        # One scale for both, diverging about zero with percentile limits (colour_scale.py).
        sc = Scale(np.concatenate([values[np.isfinite(values)], sxx]), centred=True)
        lo, hi = sc.lo, sc.hi
        im = row[0].imshow(values, origin="lower", extent=extent, cmap=sc.cmap, vmin=lo, vmax=hi, aspect="equal",
                           interpolation="nearest")
        row[0].set_title(f"direct MD, t = {step * dt_md:.3g} ps (full size {t_full:g} ps)")
        # Each point a rectangle of the initial pitch stretched by its strain, as points2d
        # draws them: the jet's stretched points leave no gaps.
        corners = np.array([[-0.5, -0.5], [0.5, -0.5], [0.5, 0.5], [-0.5, 0.5]])
        sides = pitch0[None, :] * points2d.stretches(fields, len(sxx))
        pc = PolyCollection(pts[:, None, :2] + corners[None, :, :] * sides[:, None, :], array=sxx, cmap=sc.cmap,
                            edgecolors="face", linewidths=0.3)
        pc.set_clim(lo, hi)
        row[1].add_collection(pc)
        row[1].set_xlim(extent[0], extent[1])
        row[1].set_ylim(extent[2], extent[3])
        row[1].set_aspect("equal")
        row[1].set_title(f"DDMP-MD, t = {t_pts:.3g} ps")
        row[1].annotate(sc.caption("GPa"), xy=(1.0, -0.32), xycoords="axes fraction", ha="right", va="top",
                        fontsize=7, color="0.25")
        for ax in row:
            ax.set_facecolor(EMPTY)
            ax.set_xlabel("x from the piston's face (nm)")
            ax.set_ylabel("y (nm)")
        fig.colorbar(im, ax=list(row), label="$\\sigma_{xx}$ (GPa)", shrink=0.85, extend=sc.extend)
    out = a.out or os.path.join(a.ddmp_run, "sxx_md_vs_ddmp.png")
    fig.savefig(out, dpi=150, bbox_inches="tight")
    plt.close(fig)
    if not a.quiet:
        print(out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
