#!/usr/bin/python3
"""2-D points coloured by a field, one square per point (like the dissertation's fig. 7.3).

    tools/plot/points2d.py RUN_DIR|FILE.pvd|FILE.vtu|FILE.vti --field stress --component xx \\
        [--time T] --out FILE.png

RUN_DIR means RUN_DIR/particles.pvd; with a .pvd, --time picks the record nearest T (the
last one without it). --component is x|y|z|magnitude for a vector, xx|xy|...|zz,
magnitude (Frobenius) or pressure (-trace/3) for a row-major 3x3 tensor, or a component
index. Without --field: the file's active scalars, else its first array; without
--component: magnitude for a vector, xx for a tensor. Each point is drawn as a square
marker whose sides are the point pitch along x and y (a rectangle on a rectangular
lattice; --marker-size fixes a square), in data units, so the picture is filled wherever
the material is and empty where it is not. Headless (Agg); uses
Debian's python3-vtk9, python3-numpy, python3-matplotlib. Prints the written path.
"""

import argparse
import os
import sys
import xml.etree.ElementTree as ET

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402
from mpl_toolkits.axes_grid1 import make_axes_locatable  # noqa: E402

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


def component_values(values, name, component):
    """The plotted scalar per point, and its label."""
    ncomp = values.shape[1]
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
        return np.sqrt(np.sum(values * values, axis=1)), f"|{name}|"
    if ncomp == 3 and component in AXES:
        return values[:, AXES[component]], f"{name}$_{component}$"
    if ncomp == 9 and len(component) == 2 and all(c in AXES for c in component):
        return values[:, 3 * AXES[component[0]] + AXES[component[1]]], f"{name}$_{{{component}}}$"
    if ncomp == 9 and component == "pressure":
        return -(values[:, 0] + values[:, 4] + values[:, 8]) / 3.0, f"pressure (-tr {name}/3)"
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


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("source", help="run directory, .pvd, .vtu or .vti")
    ap.add_argument("--field", help="point-data array name")
    ap.add_argument("--component", help="x|y|z|xx..zz|magnitude|pressure|index")
    ap.add_argument("--time", type=float, help="record nearest this time (a .pvd)")
    ap.add_argument("--out", help="PNG file (default: next to the data)")
    ap.add_argument("--cmap", default="jet")
    ap.add_argument("--vmin", type=float)
    ap.add_argument("--vmax", type=float)
    ap.add_argument("--scale", type=float, default=1.0, help="multiply values (unit change)")
    ap.add_argument("--unit", default="", help="colour-bar unit text, e.g. GPa")
    ap.add_argument("--marker-size", type=float, help="square side in length units "
                    "(default: the point pitch along x and y)")
    ap.add_argument("--title", help="replaces the default title (field, time)")
    args = ap.parse_args(argv)

    path, time = pick_record(args.source, args.time)
    points, fields, active = read_dataset(path)
    if not fields:
        fail(f"{path} has no point data")
    name = args.field or active or next(iter(fields))
    if name not in fields:
        fail(f"{path} has no field '{name}' (it has: {', '.join(fields)})")
    values, label = component_values(fields[name], name, args.component)
    values = values * args.scale

    xy = points[:, :2]
    h = np.array([args.marker_size] * 2 if args.marker_size else point_spacing(xy))
    # Cells in data units: filled material, as in ParaView, at any figure size or DPI.
    corners = np.array([[-0.5, -0.5], [0.5, -0.5], [0.5, 0.5], [-0.5, 0.5]]) * h
    squares = xy[:, None, :] + corners[None, :, :]
    coll = PolyCollection(squares, array=values, cmap=args.cmap, edgecolors="none",
                          antialiaseds=False)
    coll.set_clim(args.vmin if args.vmin is not None else np.nanmin(values),
                  args.vmax if args.vmax is not None else np.nanmax(values))

    lo, hi = xy.min(axis=0) - h, xy.max(axis=0) + h
    aspect = (hi[1] - lo[1]) / max(hi[0] - lo[0], 1e-300)
    fig, ax = plt.subplots(figsize=(8.0, min(max(8.0 * aspect, 2.5), 10.0) + 0.8))
    ax.add_collection(coll)
    ax.set_xlim(lo[0], hi[0])
    ax.set_ylim(lo[1], hi[1])
    ax.set_aspect("equal")
    ax.set_xlabel("x")
    ax.set_ylabel("y")
    # A colour bar as tall as the (equal-aspect) plot, whatever its shape.
    bar = fig.colorbar(coll, cax=make_axes_locatable(ax).append_axes("right", "3%", pad=0.1))
    bar.set_label(f"{label} ({args.unit})" if args.unit else label)
    if args.title:
        title = args.title
    elif time is not None:
        title = f"{label}, t = {time:g}"
    else:
        title = f"{label}, {os.path.basename(path)}"
    ax.set_title(title)

    out = args.out
    if not out:
        stem = os.path.splitext(path)[0]
        out = f"{stem}_{name}{'_' + args.component if args.component else ''}.png"
    fig.savefig(out, dpi=150, bbox_inches="tight")
    plt.close(fig)
    print(out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
