#!/usr/bin/env python3
"""Checks a platefall VTK series (--vtk DIR) with VTK's own XML readers against the run's CSV.

Usage: check-vtk.py DIR RUN.csv [--far-field TOL]

For every snapshot listed in DIR/run.pvd:
- the .vts opens in vtkXMLStructuredGridReader, the .vtp in vtkXMLPolyDataReader; the time
  (field data TimeValue) is the collection's and a CSV row's (matched by step);
- the grid points, taken back to body coordinates through the pose logged in the CSV (X, Y,
  theta), are one tensor-product grid x_i by y_j, the same at every snapshot (to 1e-9);
- the velocity on the outer boundary, 15 chords out, is that of the fluid at rest at infinity:
  zero to TOL (default 0.1 of the velocity scale) at every node and to TOL/4 in the root mean square
  (what remains is the wake a long tumbling run has carried out there: the default free fall
  reaches 0.057 at t = 20, 0.018 rms at t = 15);
- the velocity at the points on the plate (on_plate = 1) is the plate's rigid-body velocity
  from the CSV (Xdot, Ydot, thetadot) to 1e-9;
- the outline lies on the body: its centroid is the plate's centre and its extent, in body
  coordinates, that of the points on the plate within one cell of the plate's grid.
Prints one line per failure and exits 1 if there is any.
"""
import csv
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy

TOL = 1e-9


def read(reader_class, path):
    reader = reader_class()
    reader.SetFileName(str(path))
    reader.Update()
    data = reader.GetOutput()
    if data is None or data.GetNumberOfPoints() == 0:
        raise SystemExit(f"{path}: {reader_class.__name__} read no points")
    return data


def csv_rows(path):
    with open(path) as f:
        lines = [l for l in f if not l.startswith("#")]
    return {int(r["step"]): {k: float(v) for k, v in r.items()} for r in csv.DictReader(lines)}


def to_body(points, pose):
    x0, y0, th = pose
    c, s = np.cos(th), np.sin(th)
    dx, dy = points[:, 0] - x0, points[:, 1] - y0
    return np.stack([c * dx + s * dy, -s * dx + c * dy], axis=1)


def polygon_centroid(p):
    x, y = p[:, 0], p[:, 1]
    xn, yn = np.roll(x, -1), np.roll(y, -1)
    cross = x * yn - xn * y
    area = cross.sum() / 2
    return np.array([((x + xn) * cross).sum(), ((y + yn) * cross).sum()]) / (6 * area)


class Checker:
    def __init__(self, far_tol):
        self.failures = []
        self.far_tol = far_tol
        self.body_grid = None
        self.far_max = 0.0

    def expect(self, ok, what):
        if not ok:
            self.failures.append(what)

    def snapshot(self, name, t, flow_path, plate_path, rows):
        grid = read(vtk.vtkXMLStructuredGridReader, flow_path)
        dims = [0, 0, 0]
        grid.GetDimensions(dims)
        nx, ny = dims[0], dims[1]
        fd = grid.GetFieldData()
        step = int(vtk_to_numpy(fd.GetArray("step"))[0])
        self.expect(vtk_to_numpy(fd.GetArray("TimeValue"))[0] == t, f"{name}: TimeValue is not the collection's {t}")
        row = rows.get(step)
        if row is None:
            self.expect(False, f"{name}: step {step} is not in the CSV")
            return
        self.expect(row["time"] == t, f"{name}: CSV time {row['time']} at step {step}, collection {t}")
        pose = (row["X"], row["Y"], row["theta"])
        pts = vtk_to_numpy(grid.GetPoints().GetData())
        body = to_body(pts, pose).reshape(ny, nx, 2)
        xs, ys = body[0, :, 0], body[:, 0, 1]
        tensor = np.abs(body[:, :, 0] - xs[None, :]).max() + np.abs(body[:, :, 1] - ys[:, None]).max()
        self.expect(tensor < TOL, f"{name}: the points at the CSV pose are not a body-fixed grid ({tensor:.2e})")
        if self.body_grid is None:
            self.body_grid = (xs, ys)
        else:
            moved = max(np.abs(xs - self.body_grid[0]).max(), np.abs(ys - self.body_grid[1]).max())
            self.expect(moved < TOL, f"{name}: the body-fixed grid differs from the first snapshot's ({moved:.2e})")
        pd = grid.GetPointData()
        vel = vtk_to_numpy(pd.GetArray("velocity")).reshape(ny, nx, 3)
        ring = np.concatenate([vel[0], vel[-1], vel[:, 0], vel[:, -1]])
        speed = np.hypot(ring[:, 0], ring[:, 1])
        far, rms = speed.max(), np.sqrt((speed**2).mean())
        self.far_max = max(self.far_max, far)
        self.expect(far < self.far_tol, f"{name}: far-field speed {far:.3g} (>= {self.far_tol})")
        self.expect(rms < self.far_tol / 4, f"{name}: far-field rms speed {rms:.3g} (>= {self.far_tol / 4})")
        on = vtk_to_numpy(pd.GetArray("on_plate")).reshape(ny, nx) == 1
        self.expect(on.any(), f"{name}: no point on the plate")
        p = pts.reshape(ny, nx, 3)[on]
        rigid_x = row["Xdot"] - row["thetadot"] * (p[:, 1] - pose[1])
        rigid_y = row["Ydot"] + row["thetadot"] * (p[:, 0] - pose[0])
        slip = max(np.abs(vel[on][:, 0] - rigid_x).max(), np.abs(vel[on][:, 1] - rigid_y).max())
        self.expect(slip < TOL, f"{name}: velocity on the plate differs from the rigid motion by {slip:.2e}")
        self.outline(name, plate_path, pose, body[on], xs, ys)

    def outline(self, name, path, pose, on_plate, xs, ys):
        poly = read(vtk.vtkXMLPolyDataReader, path)
        self.expect(poly.GetNumberOfPolys() == 1, f"{path.name}: not one polygon")
        body = to_body(vtk_to_numpy(poly.GetPoints().GetData()), pose)
        off = np.abs(polygon_centroid(body)).max()
        self.expect(off < TOL, f"{path.name}: outline centroid {off:.2e} from the plate's centre")
        h = max(np.diff(xs).min(), np.diff(ys).min()) * 1.0001 + TOL
        gap = max(np.abs(body.min(axis=0) - on_plate.min(axis=0)).max(),
                  np.abs(body.max(axis=0) - on_plate.max(axis=0)).max())
        self.expect(gap <= h, f"{path.name}: outline extent {gap:.3g} from the plate's points (cell {h:.3g})")


def main(argv):
    if len(argv) < 3:
        raise SystemExit(__doc__)
    vtk_dir, rows = Path(argv[1]), csv_rows(argv[2])
    far_tol = float(argv[argv.index("--far-field") + 1]) if "--far-field" in argv else 0.1
    sets = ET.parse(vtk_dir / "run.pvd").getroot().iter("DataSet")
    entries = {}
    for d in sets:
        entries.setdefault(float(d.get("timestep")), {})[d.get("part")] = vtk_dir / d.get("file")
    checker = Checker(far_tol)
    for t, parts in entries.items():
        checker.snapshot(parts["0"].name, t, parts["0"], parts["1"], rows)
    count = len(list(vtk_dir.glob("*.vts")))
    checker.expect(count == len(entries), f"{count} .vts files, {len(entries)} in run.pvd")
    for f in checker.failures:
        print(f"check-vtk: {f}")
    print(f"check-vtk: {vtk_dir}: {len(entries)} snapshots, largest far-field speed "
          f"{checker.far_max:.3g}, {len(checker.failures)} failures")
    return 1 if checker.failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
