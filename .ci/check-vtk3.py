#!/usr/bin/env python3
"""Checks a platefall 3-D VTK series (`--span … --vtk DIR`) with VTK's own XML reader.

Usage: check-vtk3.py DIR

For every snapshot listed in DIR/run.pvd:
- the .vts opens in vtkXMLStructuredGridReader with the same dimensions as the first, and its
  field data TimeValue is the collection's time;
- the points, taken back to body axes through the field data position and rotation (quaternion
  x, y, z, w), are one tensor-product grid x_i, y_j, z_k, the same at every snapshot (to 1e-9);
- the cell data velocity, vorticity, Q, pressure and solid are there; the solid cells (the
  plate) are the same at every snapshot and more than none; Q and vorticity are NaN exactly there;
- the velocity in the plate's cells is a rigid motion a + w x r (least squares over its cells;
  residual below 1e-9 of the largest speed there).
Prints one line per failure and exits 1 if there is any.
"""
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy


def rotation(q):
    x, y, z, w = q
    return np.array([
        [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
        [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
        [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)],
    ])


def main(directory):
    failures = []
    entries = [(float(d.get("timestep")), d.get("file"))
               for d in ET.parse(Path(directory) / "run.pvd").getroot().iter("DataSet")]
    if not entries:
        failures.append("run.pvd lists no snapshot")
    first = None
    for t, name in entries:
        reader = vtk.vtkXMLStructuredGridReader()
        reader.SetFileName(str(Path(directory) / name))
        reader.Update()
        grid = reader.GetOutput()
        e = grid.GetExtent()
        dims = (e[1] - e[0] + 1, e[3] - e[2] + 1, e[5] - e[4] + 1)
        field = grid.GetFieldData()
        value = lambda n: vtk_to_numpy(field.GetArray(n))
        if abs(value("TimeValue")[0] - t) > 1e-12:
            failures.append(f"{name}: TimeValue {value('TimeValue')[0]} is not the collection's {t}")
        r, x0 = rotation(value("rotation").reshape(4)), value("position").reshape(3)
        body = (vtk_to_numpy(grid.GetPoints().GetData()) - x0) @ r
        body = body.reshape(dims[2], dims[1], dims[0], 3)
        axes = [body[0, 0, :, 0], body[0, :, 0, 1], body[:, 0, 0, 2]]
        tensor = np.stack(np.meshgrid(axes[2], axes[1], axes[0], indexing="ij")[::-1], axis=-1)
        if np.abs(body - tensor).max() > 1e-9:
            failures.append(f"{name}: the points are not a tensor-product grid in body axes")
        cells = grid.GetCellData()
        arrays = {n: cells.GetArray(n) for n in ("velocity", "vorticity", "Q", "pressure", "solid")}
        missing = [n for n, a in arrays.items() if a is None]
        if missing:
            failures.append(f"{name}: no cell data {missing}")
            continue
        solid = vtk_to_numpy(arrays["solid"]).astype(bool)
        q = vtk_to_numpy(arrays["Q"])
        if not solid.any() or not np.array_equal(np.isnan(q), solid):
            failures.append(f"{name}: Q is not NaN exactly in the {solid.sum()} plate cells")
        if first is None:
            first = (dims, axes, solid)
        elif dims != first[0] or not np.array_equal(solid, first[2]) or any(
                np.abs(a - b).max() > 1e-9 for a, b in zip(axes, first[1])):
            failures.append(f"{name}: not the first snapshot's grid and plate")
        centres = vtk.vtkCellCenters()
        centres.SetInputData(grid)
        centres.Update()
        c = vtk_to_numpy(centres.GetOutput().GetPoints().GetData())[solid]
        v = vtk_to_numpy(arrays["velocity"])[solid]
        rel = c - c.mean(axis=0)
        # v = a + w x r, linear in (a, w): the x, y and z rows of every cell.
        one, zero = np.ones(len(c)), np.zeros(len(c))
        rx, ry, rz = rel.T
        a = np.vstack([
            np.column_stack([one, zero, zero, zero, rz, -ry]),
            np.column_stack([zero, one, zero, -rz, zero, rx]),
            np.column_stack([zero, zero, one, ry, -rx, zero]),
        ])
        b = np.concatenate([v[:, 0], v[:, 1], v[:, 2]])
        sol = np.linalg.lstsq(a, b, rcond=None)[0]
        residual = np.abs(a @ sol - b).max()
        if residual > 1e-9 * max(1.0, np.abs(v).max()):
            failures.append(f"{name}: the plate's velocity is not rigid (residual {residual:.2e})")
    for f in failures:
        print(f)
    print(f"{len(entries)} snapshots checked, {len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
