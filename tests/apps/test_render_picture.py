#!/usr/bin/python3
"""tools/render_picture.py on a model other than the README's: the camera fits the model (a
0.2 m bar, ten times the sphere picture's size, is not cropped) and the colours span the data's
range (not all one saturated colour). Skipped without xvfb-run and without a display."""
import os
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

import vtk

ABUT = os.environ["ABUT_EXE"]
SOURCE = Path(os.environ["ABUT_SOURCE_DIR"])
failures = []


def check(condition, what):
    print(("ok    " if condition else "FAIL  ") + what)
    if not condition:
        failures.append(what)


if not os.environ.get("DISPLAY") and shutil.which("xvfb-run") is None:
    print("skipped: no display and no xvfb-run")
    sys.exit(0)

with tempfile.TemporaryDirectory() as tmp:
    tmp = Path(tmp)
    out = tmp / "bar"
    r = subprocess.run([ABUT, "run", str(SOURCE / "examples/bar_impact.k"), "-q", "-o", str(out),
                        "--threads", "1"], capture_output=True, text=True, timeout=600)
    check(r.returncode == 0, "bar_impact runs")
    png = tmp / "bar.png"
    command = ["/usr/bin/python3", str(SOURCE / "tools/render_picture.py"), str(out / "results.pvd"),
               str(png), "2e-5"]
    if not os.environ.get("DISPLAY"):
        command = ["xvfb-run", "-a", *command]
    r = subprocess.run(command, capture_output=True, text=True, timeout=600)
    check(r.returncode == 0 and png.is_file(), f"render_picture writes the picture ({r.stderr.strip()[-300:]!r})")
    if png.is_file():
        reader = vtk.vtkPNGReader()
        reader.SetFileName(str(png))
        reader.Update()
        image = reader.GetOutput()
        width, height, _ = image.GetDimensions()
        scalars = image.GetPointData().GetScalars()
        # The model: pixels neither white (background) nor grey/black (edges, labels), below the
        # colour bar (the top sixth of the picture).
        columns, rows, colours = [], [], set()
        for y in range(0, int(height * 0.8)):
            for x in range(width):
                r_, g, b = (scalars.GetComponent(y * width + x, c) for c in range(3))
                if max(r_, g, b) - min(r_, g, b) < 40:
                    continue
                columns.append(x)
                rows.append(y)
                colours.add((int(r_) // 16, int(g) // 16, int(b) // 16))
        check(len(columns) > 0.02 * width * height, "the model fills a good part of the picture")
        if columns:
            margin = 3
            check(min(columns) > margin and max(columns) < width - 1 - margin and min(rows) > margin,
                  f"the model is not cropped (columns {min(columns)}..{max(columns)} of {width}, "
                  f"rows from {min(rows)})")
        check(len(colours) >= 50, f"the colours span the data's range ({len(colours)} colour classes)")

if failures:
    print(f"{len(failures)} check(s) failed")
    sys.exit(1)
print("all render_picture checks passed")
