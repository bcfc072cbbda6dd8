#!/usr/bin/python3
"""Reads VTK XML files with VTK's own readers and prints what VTK sees, as JSON.

    /usr/bin/python3 tests/io/vtk_readback.py FILE.vtu FILE.vti FILE.pvd ...

For vtk_test.cpp: an independent reader proves mpmx's files are valid, not merely
consistent with mpmx's own idea of the format. Output: a JSON list, one object per file,
in order. Floats are printed by repr, so they read back bit-exactly. Exit 77 when VTK
is not installed (the test skips), 1 when VTK reported any error or warning.
"""

import json
import os
import sys
import xml.etree.ElementTree as ET

try:
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkCommonCore import vtkOutputWindow, vtkStringOutputWindow
    from vtkmodules.vtkIOXML import vtkXMLImageDataReader, vtkXMLUnstructuredGridReader
except ImportError as e:
    print(f"vtk_readback: VTK is not installed (python3-vtk9): {e}", file=sys.stderr)
    sys.exit(77)

# VTK reports problems to an output window instead of raising: capture them all, so a
# file VTK merely complains about fails the test.
LOG = vtkStringOutputWindow()
vtkOutputWindow.SetInstance(LOG)


def check_log(path):
    text = LOG.GetOutput()
    if text.strip():
        print(f"vtk_readback: VTK complained reading {path}:\n{text}", file=sys.stderr)
        sys.exit(1)


def read(path, reader_class):
    if not os.path.isfile(path):
        print(f"vtk_readback: no file {path}", file=sys.stderr)
        sys.exit(1)
    reader = reader_class()
    reader.SetFileName(path)
    reader.Update()
    check_log(path)
    if reader.GetErrorCode() != 0:
        print(f"vtk_readback: reader error {reader.GetErrorCode()} on {path}", file=sys.stderr)
        sys.exit(1)
    return reader.GetOutput()


def point_data(data):
    pd = data.GetPointData()

    def active(a):
        return a.GetName() if a is not None else None

    arrays = []
    for i in range(pd.GetNumberOfArrays()):
        a = pd.GetArray(i)
        arrays.append({
            "name": a.GetName(),
            "components": a.GetNumberOfComponents(),
            "type": a.GetDataTypeAsString(),
            "values": [float(v) for v in vtk_to_numpy(a).ravel()],
        })
    return {
        "attributes": {
            "scalars": active(pd.GetScalars()),
            "vectors": active(pd.GetVectors()),
            "tensors": active(pd.GetTensors()),
        },
        "arrays": arrays,
    }


def read_vtu(path):
    grid = read(path, vtkXMLUnstructuredGridReader)
    n = grid.GetNumberOfPoints()
    types = sorted({grid.GetCellType(i) for i in range(grid.GetNumberOfCells())})
    # Each cell must be the vertex of its own point.
    for i in range(grid.GetNumberOfCells()):
        ids = grid.GetCell(i).GetPointIds()
        if ids.GetNumberOfIds() != 1 or ids.GetId(0) != i:
            print(f"vtk_readback: {path}: cell {i} is not vertex {i}", file=sys.stderr)
            sys.exit(1)
    points = vtk_to_numpy(grid.GetPoints().GetData()) if n > 0 else []
    out = {
        "kind": "vtu",
        "path": path,
        "number_of_points": n,
        "number_of_cells": grid.GetNumberOfCells(),
        "cell_types": types,
        "points_type": grid.GetPoints().GetData().GetDataTypeAsString() if n > 0 else None,
        "points": [float(v) for v in (points.ravel() if n > 0 else [])],
    }
    out.update(point_data(grid))
    return out


def read_vti(path):
    image = read(path, vtkXMLImageDataReader)
    out = {
        "kind": "vti",
        "path": path,
        "number_of_points": image.GetNumberOfPoints(),
        "dimensions": list(image.GetDimensions()),
        "origin": [float(v) for v in image.GetOrigin()],
        "spacing": [float(v) for v in image.GetSpacing()],
    }
    out.update(point_data(image))
    return out


def read_pvd(path):
    # vtkPVDReader is ParaView's, not VTK's: parse the collection and open each file.
    root = ET.parse(path).getroot()
    if root.tag != "VTKFile" or root.get("type") != "Collection":
        print(f"vtk_readback: {path} is not a VTK Collection", file=sys.stderr)
        sys.exit(1)
    folder = os.path.dirname(path)
    entries = []
    for ds in root.iter("DataSet"):
        file = ds.get("file")
        entry = read_any(os.path.join(folder, file))
        entries.append({
            "time": float(ds.get("timestep")),
            "file": file,
            "kind": entry["kind"],
            "number_of_points": entry["number_of_points"],
        })
    return {"kind": "pvd", "path": path, "entries": entries}


def read_any(path):
    ext = os.path.splitext(path)[1]
    readers = {".vtu": read_vtu, ".vti": read_vti, ".pvd": read_pvd}
    if ext not in readers:
        print(f"vtk_readback: unknown extension {path}", file=sys.stderr)
        sys.exit(1)
    return readers[ext](path)


def main(paths):
    if not paths:
        print(__doc__, file=sys.stderr)
        return 2
    json.dump([read_any(p) for p in paths], sys.stdout)
    sys.stdout.write("\n")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
