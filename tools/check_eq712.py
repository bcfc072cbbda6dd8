#!/usr/bin/python3
"""Recompute a jet run's eq. 7.12 from its written files, apart from the run's own code.

    tools/check_eq712.py RUN_DIR --md MD_DIR [--digits 4]

RUN_DIR is a 2-D `mpmx run` against reference.name = "direct_md" (a DDMP-MD row of
Table 7.1 or a J4 baseline): its particles.pvd and vtk/particles_*.vtu give each point's
position and sigma_xx at the compared times, its run.json the unit system and the
figures to check (errors_by_time.stress_vs_direct_md, errors.stress_vs_direct_md).
MD_DIR is the direct-MD jet run (`mpmx md`): md_bins.pvd, bins/*.csv, run.json's jet
geometry. Eq. 7.12 (dissertation sec. 7.3; docs/jet.md):

    e = sqrt( sum (sxx_md - sxx_ms)^2 / sum sxx_md^2 )

over the material points, each against the direct-MD bin that holds it at the record
nearest the compared time (the continuum's x = 0 at the piston's face, y periodic over
the sample's period, points outside the bins or in an empty bin left out); pooled: the
sums over all compared times. Prints each time's and the pooled figure beside the run's;
exit 1 when one differs from the run's by more than 10^-DIGITS relatively, 2 on unreadable
input. Only numpy: this is the second, independent evaluation (issue 44), so it shares
no code with src/mpmx/reference/jet_history.cpp or app/mpm/references/direct_md.cpp.
"""
import argparse
import json
import math
import os
import re
import sys

import numpy as np


class Bad(Exception):
    """Input this check cannot read."""


def read_json(path):
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError) as e:
        raise Bad(f"{path}: {e}")


def pvd_records(path):
    """[(time, file)] of a ParaView collection, in file order."""
    try:
        text = open(path).read()
    except OSError as e:
        raise Bad(f"{path}: {e}")
    out = []
    for tag in re.findall(r"<DataSet\b[^>]*>", text):
        t = re.search(r'timestep="([^"]*)"', tag)
        f = re.search(r'file="([^"]*)"', tag)
        if not (t and f):
            raise Bad(f"{path}: a DataSet without timestep or file: {tag}")
        out.append((float(t.group(1)), f.group(1)))
    if not out:
        raise Bad(f"{path}: no DataSet")
    return out


def vtu_arrays(path):
    """{name: array (points x components)} of a VTU with raw appended Float64 data and
    UInt64 block headers (what io/vtk writes; each block: byte count, then the bytes)."""
    try:
        blob = open(path, "rb").read()
    except OSError as e:
        raise Bad(f"{path}: {e}")
    mark = blob.find(b"<AppendedData")
    if mark < 0:
        raise Bad(f"{path}: no <AppendedData> (not raw appended VTU)")
    head = blob[:mark].decode()
    if 'header_type="UInt64"' not in head or 'encoding="raw"' not in blob[mark:mark + 64].decode(errors="replace"):
        raise Bad(f"{path}: expected header_type UInt64 and raw encoding")
    order = "<" if 'byte_order="LittleEndian"' in head else ">"
    start = blob.index(b"_", mark) + 1
    arrays = {}
    for tag in re.findall(r"<DataArray\b[^>]*>", head):
        name = re.search(r'Name="([^"]*)"', tag).group(1)
        kind = re.search(r'type="([^"]*)"', tag).group(1)
        if kind != "Float64":
            continue
        comps = int(re.search(r'NumberOfComponents="(\d+)"', tag).group(1))
        at = start + int(re.search(r'offset="(\d+)"', tag).group(1))
        nbytes = int(np.frombuffer(blob, dtype=order + "u8", count=1, offset=at)[0])
        values = np.frombuffer(blob, dtype=order + "f8", count=nbytes // 8, offset=at + 8)
        arrays[name] = values.reshape(-1, comps)
    for need in ("Points", "stress"):
        if need not in arrays:
            raise Bad(f"{path}: no Float64 array '{need}'")
    return arrays


class Bins:
    """The direct-MD record nearest a time: sigma_xx (GPa) per bin, NaN where empty."""

    def __init__(self, md_dir):
        jet = read_json(os.path.join(md_dir, "run.json")).get("jet")
        if not jet:
            raise Bad(f"{md_dir}/run.json: no jet section (not an `mpmx md` jet run?)")
        try:
            self.face, self.x0 = float(jet["piston_face_A"]), float(jet["x0_A"])
            self.length, self.ly = float(jet["length_A"]), float(jet["ly_A"])
        except KeyError as e:
            raise Bad(f"{md_dir}/run.json: jet.{e.args[0]} missing")
        self.times, self.maps = [], []
        for t, f in pvd_records(os.path.join(md_dir, "md_bins.pvd")):
            csv = os.path.join(md_dir, "bins", os.path.splitext(os.path.basename(f))[0] + ".csv")
            self.times.append(t)
            self.maps.append(self._read(csv))
        self.times = np.array(self.times)
        self.ny, self.nx = self.maps[0].shape
        if any(m.shape != self.maps[0].shape for m in self.maps):
            raise Bad(f"{md_dir}: the records' bin grids differ")
        self.dx, self.dy = self.length / self.nx, self.ly / self.ny

    def _read(self, csv):
        try:
            with open(csv) as f:
                names = f.readline().strip().split(",")
            data = np.loadtxt(csv, delimiter=",", skiprows=1, ndmin=2)
        except (OSError, ValueError) as e:
            raise Bad(f"{csv}: {e}")
        try:
            col = {n: data[:, names.index(n)] for n in ("ix", "iy", "x_A", "y_A", "atoms", "sxx_GPa")}
        except ValueError as e:
            raise Bad(f"{csv}: header {names}: {e}")
        ix, iy = col["ix"].astype(int), col["iy"].astype(int)
        nx, ny = ix.max() + 1, iy.max() + 1
        if nx * ny != len(ix):
            raise Bad(f"{csv}: {len(ix)} bins are not a full {nx} x {ny} grid")
        # The bins' centres must be those of the geometry the lookup assumes.
        dx, dy = self.length / nx, self.ly / ny
        if (np.max(np.abs(col["x_A"] - (self.x0 + (ix + 0.5) * dx))) > 1e-2 * dx
                or np.max(np.abs(col["y_A"] - (iy + 0.5) * dy)) > 1e-2 * dy):
            raise Bad(f"{csv}: bin centres are not those of {nx} x {ny} bins over x0 = {self.x0}, "
                      f"length {self.length}, period {self.ly} A")
        m = np.full((ny, nx), np.nan)
        m[iy, ix] = np.where(col["atoms"] > 0, col["sxx_GPa"], np.nan)
        return m

    def lookup(self, t_ps, x_A, y_A):
        """sigma_xx (GPa) of the bins holding (x_A, y_A); NaN outside or empty."""
        k = int(np.argmin(np.abs(self.times - t_ps)))
        spacing = self.times[1] - self.times[0] if len(self.times) > 1 else 1.0
        if abs(self.times[k] - t_ps) > 1e-3 * spacing + 1e-9:
            raise Bad(f"the direct MD has no record at {t_ps} ps (nearest {self.times[k]} ps)")
        fx = (x_A - self.x0) / self.dx
        inside = (fx >= 0) & (fx < self.nx)
        ix = np.where(inside, np.floor(np.where(inside, fx, 0)), 0).astype(int)
        iy = np.minimum(np.floor(np.mod(y_A / self.dy, self.ny)).astype(int), self.ny - 1)
        return np.where(inside, self.maps[k][iy, ix], np.nan)


def sums(run_dir, records, t, units, bins):
    """(sum diff^2, sum md^2, points compared) of eq. 7.12 at run time t."""
    k = int(np.argmin([abs(rt - t) for rt, _ in records]))
    rt, f = records[k]
    if abs(rt - t) > 1e-9 * max(1.0, abs(t)):
        raise Bad(f"{run_dir}/particles.pvd has no record at t = {t} (nearest {rt})")
    a = vtu_arrays(os.path.join(run_dir, f))
    x, y, sxx = a["Points"][:, 0], a["Points"][:, 1], a["stress"][:, 0]
    L = units["length_A"]
    md = bins.lookup(t * units["time_ps"], bins.face + L * x, L * y) / units["stress_GPa"]
    used = np.isfinite(md)
    d = md[used] - sxx[used]
    return float(np.sum(d * d)), float(np.sum(md[used] ** 2)), int(used.sum())


def agree(mine, theirs, digits):
    """Equal to `digits` significant digits: a relative difference of at most 10^-digits
    (the two evaluations read the same doubles, so they differ by rounding, ~1e-15)."""
    return abs(mine - theirs) <= 10.0 ** -digits * abs(theirs)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("run", help="the DDMP-MD (or J4) run's output folder")
    ap.add_argument("--md", required=True, help="the direct-MD jet run's output folder")
    ap.add_argument("--digits", type=int, default=4, help="significant digits that must agree (4)")
    a = ap.parse_args()
    try:
        run = read_json(os.path.join(a.run, "run.json"))
        units = run.get("units")
        by_time = run.get("errors_by_time", {}).get("stress_vs_direct_md")
        pooled_run = run.get("errors", {}).get("stress_vs_direct_md")
        if not units or not by_time or pooled_run is None:
            raise Bad(f"{a.run}/run.json: no units, errors_by_time.stress_vs_direct_md or "
                      "errors.stress_vs_direct_md (not a 2-D direct_md run, or unfinished?)")
        records = pvd_records(os.path.join(a.run, "particles.pvd"))
        bins = Bins(a.md)
        total_d = total_r = 0.0
        ok = True
        print(f"{a.run}: eq. 7.12 recomputed (against {a.md})")
        for entry in by_time:
            t, theirs = float(entry["time"]), float(entry["error"])
            d, r, n = sums(a.run, records, t, units, bins)
            if r <= 0:
                raise Bad(f"{a.run}: no point lies in a filled bin at t = {t}")
            mine = math.sqrt(d / r)
            total_d, total_r = total_d + d, total_r + r
            good = agree(mine, theirs, a.digits)
            ok &= good
            print(f"  t = {t:<8g} {n:6d} points  {100 * mine:.8f}%  run.json {100 * theirs:.8f}%  "
                  f"rel. diff {abs(mine - theirs) / max(abs(theirs), 1e-300):.1e}  {'ok' if good else 'DIFFERS'}")
        mine = math.sqrt(total_d / total_r)
        good = agree(mine, float(pooled_run), a.digits)
        ok &= good
        print(f"  pooled {len(by_time)} time(s)      {100 * mine:.8f}%  run.json {100 * pooled_run:.8f}%  "
              f"rel. diff {abs(mine - pooled_run) / max(abs(pooled_run), 1e-300):.1e}  {'ok' if good else 'DIFFERS'}")
    except Bad as e:
        print(f"check_eq712: {e}", file=sys.stderr)
        return 2
    if not ok:
        print(f"check_eq712: {a.run}: eq. 7.12 differs from run.json beyond {a.digits} significant digits",
              file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
