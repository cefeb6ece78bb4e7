# Run by pvpython (ParaView's Python): opens a run folder's snapshots.xmf and analysis/fields.xmf as
# a ParaView user would (OpenDataFile, the default representation) and checks what ParaView reads
# against the HDF5 files read with h5py: points, cells, arrays and time steps.
# Usage: pvpython paraview_opens_outputs.py RUN_DIR [--clumps]
# With --clumps (a run of rigid clumps, make_tiny_clump_run.sh) every snapshot must also carry each
# member sphere's `body`, which ParaView must read as a point array (colour by it to see the grains),
# and the fields' nodes are the bodies.
# Reading needs no rendering, so this runs without a display. Rendering does: Debian's ParaView is
# built for X (GLX) only, so Render() without an X server crashes in XSync even with
# --force-offscreen-rendering; this script never renders.
import os
import sys

import h5py
import numpy as np
from paraview import servermanager
from paraview.simple import CreateView, OpenDataFile, Show
from vtkmodules.util.numpy_support import vtk_to_numpy

VTK_VERTEX, VTK_POLY_VERTEX, VTK_TRIANGLE = 1, 2, 5
failures = []


def check(ok, what):
    if not ok:
        failures.append(what)
        print("FAILED:", what)


def point_array(data, name):
    array = data.GetPointData().GetArray(name)
    check(array is not None, f"point array {name} present")
    return None if array is None else vtk_to_numpy(array)


def cell_array(data, name):
    array = data.GetCellData().GetArray(name)
    check(array is not None, f"cell array {name} present")
    return None if array is None else vtk_to_numpy(array)


def same(a, b, what):
    check(a is not None and np.array_equal(np.asarray(a).reshape(np.shape(b)), b), what)


def read_at(reader, time):
    reader.UpdatePipeline(time)
    return servermanager.Fetch(reader)


def check_default_view(reader, what):
    # ParaView's default representation of an unstructured grid is Surface, which draws cells only:
    # a grid of points without cells shows nothing.
    view = CreateView("RenderView")
    shown = Show(reader, view)
    check(shown.Representation == "Surface", f"{what}: default representation Surface (got {shown.Representation})")
    info = reader.GetDataInformation()
    check(info.GetNumberOfCells() > 0, f"{what}: the default view has cells to show")


def check_snapshots(run, clumps):
    xmf = os.path.join(run, "snapshots.xmf")
    reader = OpenDataFile(xmf)
    check(reader is not None, "snapshots.xmf opens")
    with h5py.File(os.path.join(run, "snapshots.h5"), "r") as f:
        groups = [g for _, g in f["snapshots"].items() if len(g["id"]) > 0]
        times = [float(g.attrs["time"]) for g in groups]
        check(len(groups) >= 4, f"snapshots.h5 holds the run's snapshots ({len(groups)})")
        check(list(reader.TimestepValues) == times,
              f"every snapshot is a time step: {list(reader.TimestepValues)} against {times}")
        check_default_view(reader, "snapshots.xmf")
        for g, time in zip(groups, times):
            data = read_at(reader, time)
            n = len(g["id"])
            where = f"snapshots.xmf at t = {time} ({g.name})"
            check(data.GetNumberOfPoints() == n, f"{where}: {data.GetNumberOfPoints()} points, {n} particles")
            check(data.GetNumberOfCells() == n, f"{where}: {data.GetNumberOfCells()} cells, {n} particles")
            types = {data.GetCellType(c) for c in range(data.GetNumberOfCells())}
            check(types <= {VTK_VERTEX, VTK_POLY_VERTEX}, f"{where}: vertex cells (types {types})")
            sizes = {data.GetCell(c).GetNumberOfPoints() for c in range(0, data.GetNumberOfCells(), 97)}
            check(sizes == {1}, f"{where}: one particle per cell")
            same(vtk_to_numpy(data.GetPoints().GetData()), g["position"][:], f"{where}: points at the positions")
            for name in ("id", "radius", "velocity", "angular_velocity"):
                same(point_array(data, name), g[name][:], f"{where}: {name}")
            check(("body" in g) == clumps, f"{where}: a member's body {'present' if clumps else 'absent'}")
            if clumps and "body" in g:
                body = g["body"][:]
                same(point_array(data, "body"), body, f"{where}: body")
                ids = set(g["bodies/id"][:].tolist())
                check(set(body.tolist()) == ids, f"{where}: every member's body is one of bodies/id and each has members")
                check(len(ids) < n, f"{where}: {len(ids)} bodies of {n} member spheres")


def check_fields(run):
    xmf = os.path.join(run, "analysis", "fields.xmf")
    reader = OpenDataFile(xmf)
    check(reader is not None, "fields.xmf opens")
    check_default_view(reader, "fields.xmf")
    data = read_at(reader, 0.0)
    with h5py.File(os.path.join(run, "analysis", "fields.h5"), "r") as f:
        nodes, triangles = f["nodes"], f["triangles"]
        n, m = len(nodes["id"]), len(triangles["connectivity"])
        check(data.GetNumberOfPoints() == n, f"fields.xmf: {data.GetNumberOfPoints()} points, {n} nodes")
        check(data.GetNumberOfCells() == m, f"fields.xmf: {data.GetNumberOfCells()} cells, {m} triangles")
        types = {data.GetCellType(c) for c in range(data.GetNumberOfCells())}
        check(types == {VTK_TRIANGLE}, f"fields.xmf: triangle cells (types {types})")
        connectivity = np.array([[data.GetCell(c).GetPointId(k) for k in range(3)] for c in range(m)])
        same(connectivity, triangles["connectivity"][:], "fields.xmf: the triangles' nodes")
        same(vtk_to_numpy(data.GetPoints().GetData()), nodes["position"][:], "fields.xmf: points at the nodes")
        for name in ("id", "radius", "displacement", "vertical_displacement"):
            same(point_array(data, name), nodes[name][:], f"fields.xmf: node {name}")
        for name in ("gamma_max", "gamma_max_smoothed", "volumetric_strain", "exx", "ezz", "gamma_xz"):
            same(cell_array(data, name), triangles[name][:], f"fields.xmf: strain {name}")


run = os.path.abspath(sys.argv[1])
clumps = sys.argv[2:] == ["--clumps"]
check(sys.argv[2:] in ([], ["--clumps"]), f"arguments: RUN_DIR [--clumps], got {sys.argv[1:]}")
check_snapshots(run, clumps)
check_fields(run)
if failures:
    print(f"{len(failures)} checks failed")
    sys.exit(1)
print("ParaView reads snapshots.xmf and fields.xmf as the HDF5 files hold them")
