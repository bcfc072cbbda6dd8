#!/usr/bin/python3
"""2-D points coloured by a field, one square per point (like the dissertation's fig. 7.3).

    tools/plot/points2d.py RUN_DIR|FILE.pvd|FILE.vtu|FILE.vti --field stress --component xx \\
        [--time T | --times T1 T2 ... | --frames N] --out FILE.png

RUN_DIR means RUN_DIR/particles.pvd; with a .pvd, --time picks the record nearest T (the
last one without it), --times one panel per time, --frames N up to N panels: the first
record, the one where the field spans most (a collision at its height), the last, and
records evenly between; one colour scale and one frame of axes for all panels.
--component is x|y|z|magnitude for a vector, xx|xy|...|zz,
magnitude (Frobenius) or pressure (-trace/3) for a row-major 3x3 tensor, or a component
index. Without --field: the file's active scalars, else its first array; without
--component: magnitude for a vector, xx for a tensor. Each point is drawn as a rectangle:
the initial point pitch along x and y, stretched by the point's own strain where it has
been stretched (--marker-size fixes a square), in data units, so the picture is filled
wherever the material is (no white seams where it has thinned) and empty (grey) where it
is not.

Colours: a field that takes both signs (a stress) in a diverging map (RdBu_r) centred on
zero with symmetric limits, one of one sign (density, temperature) in viridis; the limits
are the 1st and 99th percentiles of the values shown (--vmin, --vmax override), and the
figure says how many points lie beyond them and their extremes. A body much longer than
high (a quasi-1-D run: a plate impact) gets the field's profile along x beside its maps
(the mean over y per column of points, one line per frame).

Units come from the run's run.json (units.name, from the deck's case.units: nm_ps_GPa,
mm_us_GPa, metal, SI) onto the axes and the colour bar; a deck with free-text units has
them printed under the figure. --unit and --length-unit override. A body much longer
than wide (a planar impact, a jet) is drawn with y stretched, and says by how much, so
that its thickness stays visible; its panels stack and the colour bar lies beneath.
Headless (Agg); uses Debian's python3-vtk9, python3-numpy, python3-matplotlib. Prints
the written path.
"""

import argparse
import os
import sys
import xml.etree.ElementTree as ET

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.ticker  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plot_units  # noqa: E402
from colour_scale import DIVERGING, EMPTY, SEQUENTIAL, Scale  # noqa: E402

try:
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkIOXML import vtkXMLImageDataReader, vtkXMLUnstructuredGridReader
except ImportError:
    sys.exit("points2d.py: needs VTK for Python (apt-get install python3-vtk9)")

AXES = {"x": 0, "y": 1, "z": 2}


def fail(msg):
    sys.exit(f"points2d.py: {msg}")


def pick_record(source, time):
    """(dataset file, time or None) for a run directory, a .pvd, or a single file."""
    if os.path.isdir(source):
        source = os.path.join(source, "particles.pvd")
    if not os.path.exists(source):
        fail(f"no such file {source}")
    if not source.endswith(".pvd"):
        return source, None
    try:
        root = ET.parse(source).getroot()
    except ET.ParseError as e:
        fail(f"{source}: {e}")
    records = [(float(d.get("timestep")), d.get("file")) for d in root.iter("DataSet")]
    if not records:
        fail(f"{source} lists no records yet")
    if time is None:
        t, file = max(records, key=lambda r: r[0])
    else:
        t, file = min(records, key=lambda r: abs(r[0] - time))
    return os.path.join(os.path.dirname(source), file), t


def list_records(source):
    """[(time, dataset file)] of a run directory or .pvd, in time order."""
    if os.path.isdir(source):
        source = os.path.join(source, "particles.pvd")
    if not source.endswith(".pvd"):
        fail(f"{source}: a time series needs a run directory or a .pvd")
    if not os.path.exists(source):
        fail(f"no such file {source}")
    try:
        root = ET.parse(source).getroot()
    except ET.ParseError as e:
        fail(f"{source}: {e}")
    records = sorted((float(d.get("timestep")), os.path.join(os.path.dirname(source), d.get("file")))
                     for d in root.iter("DataSet"))
    if not records:
        fail(f"{source} lists no records yet")
    return records


def frame_indices(spans, n):
    """Up to n record indices in time order: the last, the one whose field spans most
    (a single last frame after a collision shows only its ringing), the first, and the
    rest spread evenly in between."""
    count = len(spans)
    if count <= n:
        return list(range(count))
    peak = int(np.nanargmax(spans)) if np.isfinite(spans).any() else 0
    chosen = []
    for j in [count - 1, peak, 0] + [int(round(k)) for k in np.linspace(0, count - 1, n)]:
        if j not in chosen:
            chosen.append(j)
    for j in range(count):  # even picks that coincided: any record not shown yet
        if len(chosen) >= n:
            break
        if j not in chosen:
            chosen.append(j)
    return sorted(chosen[:n])


def read_dataset(path):
    """(points n x 3, {name: values n x components}, active scalars name or None)."""
    if path.endswith(".vtu"):
        reader = vtkXMLUnstructuredGridReader()
    elif path.endswith(".vti"):
        reader = vtkXMLImageDataReader()
    else:
        fail(f"{path}: expected a .vtu or .vti file")
    if not os.path.exists(path):
        fail(f"no such file {path}")
    reader.SetFileName(path)
    reader.Update()
    data = reader.GetOutput()
    n = data.GetNumberOfPoints()
    if n == 0:
        fail(f"{path} has no points")
    if path.endswith(".vti"):
        # Image nodes are implicit: x fastest, as the writer orders them.
        nx, ny, nz = data.GetDimensions()
        o, h = data.GetOrigin(), data.GetSpacing()
        k, j, i = np.meshgrid(np.arange(nz), np.arange(ny), np.arange(nx), indexing="ij")
        points = np.column_stack([o[0] + h[0] * i.ravel(), o[1] + h[1] * j.ravel(),
                                  o[2] + h[2] * k.ravel()])
    else:
        points = vtk_to_numpy(data.GetPoints().GetData()).reshape(n, 3)
    pd = data.GetPointData()
    fields = {}
    for a in range(pd.GetNumberOfArrays()):
        arr = pd.GetArray(a)
        fields[arr.GetName()] = vtk_to_numpy(arr).reshape(n, arr.GetNumberOfComponents())
    active = pd.GetScalars().GetName() if pd.GetScalars() is not None else None
    return points, fields, active


SYMBOLS = {"stress": "\\sigma", "strain": "\\varepsilon", "velocity": "v", "velocity_gradient": "L",
           "displacement": "u"}


def component_values(values, name, component):
    """The plotted scalar per point, and its label (sigma_xx for stress xx)."""
    ncomp = values.shape[1]
    sym = SYMBOLS.get(name)
    if component is None:
        component = {1: None, 3: "magnitude", 9: "xx"}.get(ncomp)
    if component is None:
        if ncomp != 1:
            fail(f"{name} has {ncomp} components: give --component")
        return values[:, 0], name
    if component.isdigit():
        c = int(component)
        if c >= ncomp:
            fail(f"{name} has {ncomp} components, no component {c}")
        return values[:, c], f"{name}[{c}]"
    if component == "magnitude":
        return np.sqrt(np.sum(values * values, axis=1)), f"$|{sym}|$" if sym else f"|{name}|"
    if ncomp == 3 and component in AXES:
        return values[:, AXES[component]], f"${sym}_{component}$" if sym else f"{name}$_{component}$"
    if ncomp == 9 and len(component) == 2 and all(c in AXES for c in component):
        label = f"${sym}_{{{component}}}$" if sym else f"{name}$_{{{component}}}$"
        return values[:, 3 * AXES[component[0]] + AXES[component[1]]], label
    if ncomp == 9 and component == "pressure":
        return -(values[:, 0] + values[:, 4] + values[:, 8]) / 3.0, \
            f"pressure (-tr ${sym}$/3)" if sym else f"pressure (-tr {name}/3)"
    fail(f"component '{component}' does not apply to {name} ({ncomp} components)")


def point_spacing(xy):
    """(hx, hy): the lattice pitch along x and y, from a sample of up to 400 points.

    For each sampled point, its nearest neighbour lying more along x than y gives |dx|,
    the nearest lying more along y gives |dy|; the medians are the pitch. A square
    lattice gives its spacing twice, a rectangular one both spacings, a hexagonal one the
    spacing and the row distance, so cells tile the material without gaps.
    """
    n = len(xy)
    rng = np.random.default_rng(0)
    sample = xy[rng.choice(n, size=min(n, 400), replace=False)]
    best = np.full((2, len(sample)), np.inf)  # squared distance of the nearest per cone
    pitch = np.full((2, len(sample)), np.nan)  # its |dx| (x cone) or |dy| (y cone)
    rows = np.arange(len(sample))
    for start in range(0, n, 5000):
        d = xy[None, start:start + 5000, :] - sample[:, None, :]
        ad = np.abs(d)
        d2 = (d * d).sum(axis=2)
        along_x = ad[:, :, 0] >= ad[:, :, 1]
        for cone, mask in enumerate((along_x, ~along_x)):
            masked = np.where(mask & (d2 > 0), d2, np.inf)  # not the point itself
            j = masked.argmin(axis=1)
            closer = masked[rows, j] < best[cone]
            best[cone, closer] = masked[rows, j][closer]
            pitch[cone, closer] = ad[rows, j, cone][closer]
    h = [float(np.nanmedian(p)) if np.isfinite(p).any() else np.nan for p in pitch]
    # One row or one column of points: use the other axis' pitch (or 1 for one point).
    if np.isnan(h[0]) and np.isnan(h[1]):
        return 1.0, 1.0
    return (h[0] if not np.isnan(h[0]) else h[1]), (h[1] if not np.isnan(h[1]) else h[0])


# Shapes of the drawing: a body flatter than MIN_ASPECT is stretched along y up to it
# (N6's strip is 70:1, a line at any width); one flatter than STACK_ASPECT stacks its
# panels in a column under one horizontal colour bar, otherwise they stand in a row.
MIN_ASPECT = 0.12
STACK_ASPECT = 0.6
# A point's rectangle grows with its stretch up to this factor (a spalled layer's points
# stay points, not bands).
MAX_STRETCH = 3.0
# Every rectangle a little larger than the pitch: points a scheme has jostled (CPDI at a
# shock) leave no pinholes between them.
COVER = 1.1


def stretches(fields, n, volume0=None):
    """(n x 2) stretch of each point along x and y, at least 1: 1 + eps_aa of its strain
    tensor (an integrated rate: the stretch to first order), else (a gas keeps no strain)
    sqrt(V / V0) of its volume against the first record's."""
    s = np.ones((n, 2))
    strain = fields.get("strain")
    volume = fields.get("volume")
    if strain is not None and strain.shape[1] == 9 and np.any(strain[:, [0, 4]] != 0):
        s[:, 0] = 1.0 + strain[:, 0]
        s[:, 1] = 1.0 + strain[:, 4]
    elif volume is not None and volume0 is not None and len(volume0) == n:
        s[:, :] = np.sqrt(volume[:, 0] / volume0)[:, None]
    return COVER * np.clip(np.nan_to_num(s, nan=1.0), 1.0, MAX_STRETCH)


def column_profile(xy, values, hx):
    """(x, mean over y) of the points binned into columns hx wide along x."""
    ok = np.isfinite(values)
    xy, values = xy[ok], values[ok]
    if len(values) == 0:
        return np.array([]), np.array([])
    lo = xy[:, 0].min()
    k = np.floor((xy[:, 0] - lo) / hx).astype(int)
    count = np.bincount(k)
    used = count > 0
    centre = np.bincount(k, weights=xy[:, 0])[used] / count[used]
    return centre, np.bincount(k, weights=values)[used] / count[used]


def layout(width, height, panels):
    """(rows, columns, panel width and height in inches, y stretch, colour bar orientation)."""
    aspect = height / max(width, 1e-300)
    # A whole factor, so that the label's "stretched 6x" is exact.
    stretch = float(np.ceil(MIN_ASPECT / aspect)) if aspect < MIN_ASPECT else 1.0
    shown = aspect * stretch
    if shown < STACK_ASPECT:
        w = min(9.0, max(6.0, 3.0 / shown))  # a stacked panel about 1-3 inches high
        return panels, 1, w, max(w * shown, 0.9), stretch, "horizontal"
    cols = min(panels, 4)
    rows = -(-panels // cols)
    w = {1: 6.0, 2: 4.6}.get(cols, 3.4)
    h = min(w * shown, 8.0)
    return rows, cols, h / shown, h, stretch, "vertical"


def title_text(base, width_in):
    """The title wrapped to the figure's width (about 0.11 inch a character at 11 pt)."""
    import textwrap
    return "\n".join(textwrap.wrap(base, max(30, int(width_in / 0.11))))


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("source", help="run directory, .pvd, .vtu or .vti")
    ap.add_argument("--field", help="point-data array name")
    ap.add_argument("--component", help="x|y|z|xx..zz|magnitude|pressure|index")
    ap.add_argument("--time", type=float, help="record nearest this time (a .pvd)")
    ap.add_argument("--times", type=float, nargs="+", help="one panel per record nearest each time")
    ap.add_argument("--frames", type=int, help="up to N panels chosen over the run (first, peak, last)")
    ap.add_argument("--out", help="PNG file (default: next to the data)")
    ap.add_argument("--cmap", help=f"colour map (default: {DIVERGING} centred on zero for a field of both signs, "
                    f"{SEQUENTIAL} otherwise)")
    ap.add_argument("--vmin", type=float)
    ap.add_argument("--vmax", type=float)
    ap.add_argument("--scale", type=float, default=1.0, help="multiply values (unit change)")
    ap.add_argument("--unit", help="colour-bar unit text, e.g. GPa (default: the run's units)")
    ap.add_argument("--length-unit", help="axis unit text, e.g. nm (default: the run's units)")
    ap.add_argument("--marker-size", type=float, help="square side in length units "
                    "(default: the point pitch along x and y)")
    ap.add_argument("--title", help="replaces the default title (case, field)")
    ap.add_argument("--no-profile", action="store_true", help="no profile along x beneath a quasi-1-D run's maps")
    args = ap.parse_args(argv)
    if sum(a is not None for a in (args.time, args.times, args.frames)) > 1:
        fail("give one of --time, --times, --frames")
    if args.frames is not None and args.frames < 1:
        fail("--frames needs at least 1")

    # The frames: (dataset, time or None), each with its points and values.
    if args.times or args.frames:
        records = list_records(args.source)
        if args.times:
            picks = sorted({min(range(len(records)), key=lambda k: abs(records[k][0] - t)) for t in args.times})
            records = [records[k] for k in picks]
    else:
        path, time = pick_record(args.source, args.time)
        records = [(time, path)]
    # The first record's volumes, for the stretch of laws that keep no strain.
    series = list_records(args.source) if (args.source.endswith(".pvd") or os.path.isdir(args.source)) else []
    start = read_dataset(series[0][1]) if series else None
    volume0 = start[1]["volume"][:, 0] if start and "volume" in start[1] else None
    frames = []
    for time, path in records:
        points, fields, active = read_dataset(path)
        if not fields:
            fail(f"{path} has no point data")
        name = args.field or active or next(iter(fields))
        if name not in fields:
            fail(f"{path} has no field '{name}' (it has: {', '.join(fields)})")
        values, label = component_values(fields[name], name, args.component)
        frames.append((time, path, points[:, :2], values * args.scale, stretches(fields, len(values), volume0)))
    if args.frames:
        spans = np.array([np.nanmax(v) - np.nanmin(v) if np.isfinite(v).any() else np.nan
                          for _, _, _, v, _ in frames])
        frames = [frames[k] for k in frame_indices(spans, args.frames)]

    units = plot_units.Units.of_source(args.source)
    vunit = args.unit if args.unit is not None else (units.of_field(name) if args.scale == 1.0 else "")
    lunit = args.length_unit if args.length_unit is not None else units.unit("length")
    tunit = units.unit("time")

    every = np.concatenate([v for _, _, _, v, _ in frames])
    every = every[np.isfinite(every)]
    if every.size == 0:
        fail(f"{name} has no finite value in the records drawn")
    # colour_scale.py: diverging about zero for a signed field, percentile limits (a few
    # points at a contact, N3's disks: -600 against some -50 elsewhere, would leave the
    # rest one colour); the bar's arrows and the caption say what lies beyond.
    # A tensor or vector component is centred on zero whatever its sign (a magnitude is not).
    centred = name in SYMBOLS and args.component not in ("magnitude",) and \
        not (args.component is None and frames and fields[name].shape[1] == 3)
    scale = Scale(every, args.vmin, args.vmax, args.cmap, centred)
    lo_v, hi_v, cmap, extend = scale.lo, scale.hi, scale.cmap, scale.extend
    # The lattice pitch of the first record of the series (undeformed), each point's
    # rectangle stretched with it; a single file's own.
    if args.marker_size:
        pitch0 = np.array([args.marker_size] * 2)
    else:
        first = start[0][:, :2] if start else frames[0][2]
        pitch0 = np.array(point_spacing(first))
    pitch = [pitch0[None, :] * (st if not args.marker_size else 1.0) for _, _, _, _, st in frames]
    h = pitch0 * 1.0
    lo = np.min([xy.min(axis=0) for _, _, xy, _, _ in frames], axis=0) - 0.6 * h  # half a square and a little
    hi = np.max([xy.max(axis=0) for _, _, xy, _, _ in frames], axis=0) + 0.6 * h
    rows, cols, pw, ph, stretch, orient = layout(hi[0] - lo[0], hi[1] - lo[1], len(frames))
    # A quasi-1-D run (drawn stretched): its profile along x beside the maps.
    profile = stretch > 1.0 and orient == "horizontal" and not args.no_profile

    bar_in = 0.9 if orient == "horizontal" else 0.0
    # Room for the labels, the title and the bar around the panels; equal-aspect panels
    # leave any excess as blank margin, so it is kept small.
    fig_w = cols * (pw + 0.15) + (1.0 if orient == "vertical" else 0.0) + 0.8
    fig_h = rows * (ph + (0.35 if len(frames) > 1 else 0.0)) + bar_in + 1.3
    if profile:
        prof_h = 2.6
        fig = plt.figure(figsize=(fig_w, fig_h + prof_h), layout="constrained")
        sub = fig.subfigures(2, 1, height_ratios=[fig_h, prof_h])
        axes = sub[0].subplots(rows, cols, squeeze=False, sharex=True, sharey=True)
        pax = sub[1].subplots()
    else:
        fig, axes = plt.subplots(rows, cols, figsize=(fig_w, fig_h), squeeze=False, layout="constrained",
                                 sharex=True, sharey=True)
    # Cells in data units: filled material, as in ParaView, at any figure size or DPI.
    corners = np.array([[-0.5, -0.5], [0.5, -0.5], [0.5, 0.5], [-0.5, 0.5]])
    coll = None
    for k, ax in enumerate(axes.flat):
        if k >= len(frames):
            ax.set_visible(False)
            continue
        time, path, xy, values, _ = frames[k]
        # Each point's rectangle; the edges in the face's colour close the seams that
        # rasterising abutting rectangles leaves.
        coll = PolyCollection(xy[:, None, :] + corners[None, :, :] * pitch[k][:, None, :], array=values, cmap=cmap,
                              edgecolors="face", linewidths=0.3, antialiaseds=False)
        coll.set_clim(lo_v, hi_v)
        ax.add_collection(coll)
        ax.set_xlim(lo[0], hi[0])
        ax.set_ylim(lo[1], hi[1])
        ax.set_aspect(stretch)  # 1: equal; a y unit drawn `stretch` times an x unit
        ax.set_facecolor(EMPTY)
        ax.yaxis.set_major_locator(matplotlib.ticker.MaxNLocator(nbins=4 if ph > 1.5 else 2))
        if len(frames) > 1 and time is not None:
            ax.set_title(f"t = {time:g}" + (f" {tunit}" if tunit else ""), fontsize=10)
        if k // cols == rows - 1 or orient == "horizontal" and k == len(frames) - 1:
            ax.set_xlabel(f"x ({lunit})" if lunit else "x")
        if k % cols == 0:
            ylabel = f"y ({lunit})" if lunit else "y"
            ax.set_ylabel(ylabel + (f"\n(stretched {stretch:.0f}x)" if stretch > 1.0 else ""))
        ax.tick_params(labelsize=9)
    used = [ax for ax in axes.flat if ax.get_visible()]
    # A bar about 0.35 inch thick, whatever the figure's size (the default is 15% of it).
    bar = (sub[0] if profile else fig).colorbar(coll, ax=used, orientation=orient, extend=extend, pad=0.02,
                       fraction=0.35 / (fig_w if orient == "vertical" else fig_h), shrink=0.9 if orient == "vertical" else 0.6,
                       aspect=30 if orient == "horizontal" else 25)
    bar.set_label(f"{label} ({vunit})" if vunit else label)
    bar.ax.tick_params(labelsize=9)
    if profile:
        for k, (time, _, xy, values, _) in enumerate(frames):
            px, pv = column_profile(xy, values, pitch0[0])
            when = f"t = {time:g}" + (f" {tunit}" if tunit else "") if time is not None else os.path.basename(frames[k][1])
            pax.plot(px, pv, linewidth=1.0, label=when)
        pax.set_xlim(lo[0], hi[0])
        pax.set_xlabel(f"x ({lunit})" if lunit else "x")
        pax.set_ylabel((f"{label} ({vunit})" if vunit else label) + "\nmean over y")
        if scale.signed:
            pax.axhline(0.0, color="0.6", linewidth=0.5)
        pax.grid(True, linewidth=0.3, alpha=0.5)
        pax.legend(fontsize=8, loc="best")
        pax.tick_params(labelsize=9)

    if args.title:
        title = title_text(args.title, fig_w)
    else:
        case = ""
        run_json = plot_units.find_run_json(args.source)
        if run_json:
            import json
            try:
                with open(run_json) as f:
                    c = json.load(f).get("deck", {}).get("case", {})
                case = plot_units.shown(f"{c.get('id', '')}: {c.get('title', '')}".strip(": "))
            except (OSError, ValueError):
                pass
        time = frames[0][0]
        when = ("" if len(frames) > 1 else f", t = {time:g}" + (f" {tunit}" if tunit else "")
                if time is not None else f", {os.path.basename(frames[0][1])}")
        title = title_text(case, fig_w) + "\n" if case else ""
        title += f"{label}{when}"
    fig.suptitle(title, fontsize=11)
    # What the colour limits leave out, said where the reader looks for the scale.
    caption = scale.caption(vunit) + "; grey: no material"
    note = units.note() if not (args.unit or args.length_unit) else ""
    # Under the figure, where the layout keeps room for it.
    (sub[1] if profile else fig).supxlabel(caption + (f"\n{note}" if note else ""), fontsize=7, color="0.25")

    out = args.out
    if not out:
        stem = os.path.splitext(frames[-1][1])[0]
        out = f"{stem}_{name}{'_' + args.component if args.component else ''}.png"
    fig.savefig(out, dpi=150)
    plt.close(fig)
    print(out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
