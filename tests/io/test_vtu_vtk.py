#!/usr/bin/env python3
"""Reads abut's VTU/PVD output back with VTK's own XML reader.

The files come from the GoogleTests VtuWriter.WritesTwoHexSeriesForParaView and
VtuWriter.WritesHexesThenShellsForParaView, which this script runs itself (in a temporary
directory) so that it does not depend on the order of the tests.
That test writes two unit hexahedra side by side along x, at t = 0 and, sheared by x += 0.25 z,
at t = 0.001, with point fields velocity = (1 + x, 2 y, -3 z) and
temperature = 300 + 10 x + y + 0.5 z, and cell fields part = (1, 2) and center = the mean of
each cell's points. Those formulas are evaluated here on the points VTK read. The second test
writes shells.vtu: the two unit hexahedra, then a unit quad shell on the top face of the first
and a triangle (area 1/2) on the top face of the second, with a cell field thickness.

VTK's vtkPVDReader belongs to ParaView, not to VTK, so the .pvd is parsed with xml.etree.
Exit code 0 on success, 1 on failure.
"""
import os
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

from vtkmodules.vtkCommonCore import vtkOutputWindow, vtkStringOutputWindow
from vtkmodules.vtkCommonDataModel import VTK_HEXAHEDRON, VTK_QUAD, VTK_TRIANGLE
from vtkmodules.vtkFiltersVerdict import vtkCellSizeFilter
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader

GTEST = "VtuWriter.WritesTwoHexSeriesForParaView:VtuWriter.WritesHexesThenShellsForParaView"
TOL = 1e-12


class Failure(Exception):
    pass


def check(condition, message):
    if not condition:
        raise Failure(message)


def close(a, b):
    return len(a) == len(b) and all(abs(x - y) <= TOL * max(1.0, abs(y)) for x, y in zip(a, b))


def produce_files(workdir):
    build_dir = os.environ.get("ABUT_BUILD_DIR")
    check(build_dir, "ABUT_BUILD_DIR is not set (ctest sets it to the build root)")
    exe = os.path.join(build_dir, "tests", "test_io")
    check(os.path.isfile(exe), f"test binary {exe} not found; build target test_io first")
    out_dir = os.path.join(workdir, "out")
    env = dict(os.environ, ABUT_TEST_OUTPUT_DIR=out_dir)
    run = subprocess.run([exe, f"--gtest_filter={GTEST}"], cwd=workdir, env=env,
                         capture_output=True, text=True, timeout=120)
    check(run.returncode == 0, f"{GTEST} failed:\n{run.stdout}\n{run.stderr}")
    check("[  PASSED  ] 2 tests" in run.stdout, f"{GTEST} did not run:\n{run.stdout}")
    return out_dir


def read_pvd(path):
    root = ET.parse(path).getroot()
    check(root.tag == "VTKFile" and root.get("type") == "Collection", "pvd is not a Collection")
    return [(float(d.get("timestep")), d.get("file")) for d in root.iter("DataSet")]


def read_vtu(path, log):
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    errors = log.GetOutput()
    check(not errors.strip(), f"VTK reported while reading {path}:\n{errors}")
    return reader.GetOutput()


def check_state(grid, name, shear):
    check(grid.GetNumberOfPoints() == 12, f"{name}: {grid.GetNumberOfPoints()} points, expected 12")
    check(grid.GetNumberOfCells() == 2, f"{name}: {grid.GetNumberOfCells()} cells, expected 2")
    for c in range(2):
        check(grid.GetCellType(c) == VTK_HEXAHEDRON,
              f"{name}: cell {c} has VTK type {grid.GetCellType(c)}, expected {VTK_HEXAHEDRON}")
    bounds = grid.GetBounds()
    check(close(bounds, (0, 2 + shear, 0, 1, 0, 1)), f"{name}: bounds {bounds}")

    # A wrong node order gives VTK a negative or distorted volume; shear keeps it 1.
    sizes = vtkCellSizeFilter()
    sizes.SetInputData(grid)
    sizes.Update()
    volume = sizes.GetOutput().GetCellData().GetArray("Volume")
    volumes = [volume.GetValue(c) for c in range(2)]
    check(close(volumes, [1.0, 1.0]), f"{name}: cell volumes {volumes}, expected 1 and 1")

    points = [grid.GetPoint(i) for i in range(12)]
    pd, cd = grid.GetPointData(), grid.GetCellData()
    names = sorted(pd.GetArrayName(i) for i in range(pd.GetNumberOfArrays()))
    check(names == ["temperature", "velocity"], f"{name}: point fields {names}")
    names = sorted(cd.GetArrayName(i) for i in range(cd.GetNumberOfArrays()))
    check(names == ["center", "part"], f"{name}: cell fields {names}")

    velocity, temperature = pd.GetArray("velocity"), pd.GetArray("temperature")
    check(velocity.GetNumberOfComponents() == 3, f"{name}: velocity is not a 3-vector")
    check(temperature.GetNumberOfComponents() == 1, f"{name}: temperature is not a scalar")
    for i, (x, y, z) in enumerate(points):
        got = velocity.GetTuple(i)
        check(close(got, (1 + x, 2 * y, -3 * z)), f"{name}: velocity at point {i} is {got}")
        got = temperature.GetValue(i)
        check(close([got], [300 + 10 * x + y + 0.5 * z]), f"{name}: temperature at {i} is {got}")

    part, center = cd.GetArray("part"), cd.GetArray("center")
    check([part.GetValue(c) for c in range(2)] == [1.0, 2.0], f"{name}: part ids")
    for c in range(2):
        ids = grid.GetCell(c).GetPointIds()
        cell_points = [points[ids.GetId(a)] for a in range(ids.GetNumberOfIds())]
        mean = [sum(p[k] for p in cell_points) / 8 for k in range(3)]
        check(close(center.GetTuple(c), mean), f"{name}: center of cell {c}")


def check_shells(grid):
    check(grid.GetNumberOfCells() == 4, f"shells.vtu: {grid.GetNumberOfCells()} cells, expected 4")
    types = [grid.GetCellType(c) for c in range(4)]
    check(types == [VTK_HEXAHEDRON, VTK_HEXAHEDRON, VTK_QUAD, VTK_TRIANGLE],
          f"shells.vtu: cell types {types}")
    sizes = vtkCellSizeFilter()
    sizes.SetInputData(grid)
    sizes.Update()
    out = sizes.GetOutput().GetCellData()
    areas = [out.GetArray("Area").GetValue(c) for c in (2, 3)]
    check(close(areas, [1.0, 0.5]), f"shells.vtu: shell areas {areas}, expected 1 and 0.5")
    thickness = grid.GetCellData().GetArray("thickness")
    values = [thickness.GetValue(c) for c in range(4)]
    check(close(values, [0.0, 0.0, 0.01, 0.02]), f"shells.vtu: thickness {values}")


def main():
    log = vtkStringOutputWindow()
    vtkOutputWindow.SetInstance(log)
    with tempfile.TemporaryDirectory(prefix="abut_vtu_") as workdir:
        out_dir = produce_files(workdir)
        series = read_pvd(os.path.join(out_dir, "results.pvd"))
        check(series == [(0.0, "state_0000.vtu"), (0.001, "state_0001.vtu")],
              f"pvd lists {series}")
        for (time, file), shear in zip(series, (0.0, 0.25)):
            check_state(read_vtu(os.path.join(out_dir, file), log), file, shear)
        check_shells(read_vtu(os.path.join(out_dir, "shells.vtu"), log))
    print("PASS: VTK reads the 2-state series: 12 points, 2 hexahedra of volume 1, "
          "fields velocity, temperature, part, center; and hexahedra, a quad and a triangle")


if __name__ == "__main__":
    try:
        main()
    except Failure as failure:
        print(f"FAIL: {failure}")
        sys.exit(1)
