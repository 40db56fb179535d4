#!/usr/bin/env python3
"""Reads a platefall VTK series (--vtk DIR) with VTK's own readers and plots its last snapshot.

    python read_vtk.py DIR [--out DIR] [--window 3]

For every snapshot of DIR/run.pvd prints its time, the plate's pose and the range of the
vorticity and the pressure; writes vtk_vorticity.png: the vorticity of the last snapshot in the
inertial frame (the body-fixed grid as it lies at that moment) within --window chords of the
plate, with the plate's outline from its .vtp.
"""
import argparse
import xml.etree.ElementTree as ET
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import vtk  # noqa: E402
from vtk.util.numpy_support import vtk_to_numpy  # noqa: E402


def series(directory):
    """(time, flow .vts, plate .vtp) of each snapshot in the collection."""
    parts = {}
    for d in ET.parse(directory / "run.pvd").getroot().iter("DataSet"):
        parts.setdefault(float(d.get("timestep")), {})[d.get("part")] = directory / d.get("file")
    return [(t, p["0"], p["1"]) for t, p in sorted(parts.items())]


def read_flow(path):
    reader = vtk.vtkXMLStructuredGridReader()
    reader.SetFileName(str(path))
    reader.Update()
    grid = reader.GetOutput()
    dims = [0, 0, 0]
    grid.GetDimensions(dims)
    nx, ny = dims[0], dims[1]
    pts = vtk_to_numpy(grid.GetPoints().GetData()).reshape(ny, nx, 3)
    arrays = {name: vtk_to_numpy(grid.GetPointData().GetArray(name)) for name in
              ["velocity", "vorticity", "stream_function"]}
    arrays["pressure"] = vtk_to_numpy(grid.GetCellData().GetArray("pressure"))
    pose = vtk_to_numpy(grid.GetFieldData().GetArray("pose"))[0]
    return pts, {k: v.reshape(ny, nx, -1).squeeze() if k != "pressure" else v.reshape(ny - 1, nx - 1)
                 for k, v in arrays.items()}, pose


def read_outline(path):
    reader = vtk.vtkXMLPolyDataReader()
    reader.SetFileName(str(path))
    reader.Update()
    return vtk_to_numpy(reader.GetOutput().GetPoints().GetData())


def plot_last(flow, plate, window, out):
    pts, arrays, pose = read_flow(flow)
    outline = read_outline(plate)
    fig, ax = plt.subplots(figsize=(7, 6))
    mesh = ax.pcolormesh(pts[:, :, 0], pts[:, :, 1], arrays["vorticity"], cmap="RdBu_r",
                         vmin=-10, vmax=10, shading="gouraud")
    ax.fill(outline[:, 0], outline[:, 1], color="k")
    ax.set_xlim(pose[0] - window, pose[0] + window)
    ax.set_ylim(pose[1] - window, pose[1] + window)
    ax.set_aspect("equal")
    ax.set_xlabel("X / c")
    ax.set_ylabel("Y / c")
    fig.colorbar(mesh, ax=ax, label="vorticity ω c/U")
    ax.set_title(f"{flow.name}: θ = {pose[2]:.3f} rad")
    fig.tight_layout()
    fig.savefig(out / "vtk_vorticity.png", dpi=120)
    plt.close(fig)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("dir", type=Path, help="the --vtk directory")
    ap.add_argument("--out", type=Path, default=Path("."), help="directory of the figure")
    ap.add_argument("--window", type=float, default=3.0, help="half-width of the figure in chords")
    args = ap.parse_args()
    args.out.mkdir(parents=True, exist_ok=True)
    snapshots = series(args.dir)
    if not snapshots:
        raise SystemExit(f"{args.dir}/run.pvd lists no snapshots")
    for t, flow, _ in snapshots:
        _, a, pose = read_flow(flow)
        print(f"t = {t:8.4f}  X = {pose[0]:8.4f}  Y = {pose[1]:8.4f}  θ = {pose[2]:7.4f}  "
              f"ω in [{a['vorticity'].min():7.2f}, {a['vorticity'].max():7.2f}]  "
              f"p in [{a['pressure'].min():6.3f}, {a['pressure'].max():6.3f}]")
    plot_last(snapshots[-1][1], snapshots[-1][2], args.window, args.out)
    print(f"read_vtk: {len(snapshots)} snapshots; {args.out / 'vtk_vorticity.png'}")


if __name__ == "__main__":
    main()
