#!/usr/bin/python3
"""Renders states of an abut ParaView series side by side into one PNG (the README picture).

    xvfb-run -a /usr/bin/python3 tools/render_picture.py RESULTS.pvd OUT.png [TIME ...]
        [--stress-max PA] [--view DX,DY,DZ] [--half]
        [--field NAME --range MIN,MAX --title TEXT] [--seconds]

Uses Debian's python3-vtk9; without a display run it under xvfb-run (package xvfb).
Each panel shows the exterior of the model at the state nearest to the time asked for
(default: the first and the last state), coloured by von Mises stress, or by another field of
the states (--field, a point or cell array, e.g. temperature; a vector by its magnitude),
labelled --title. The colour range is the field's range over the panels shown (from 0 for von
Mises stress) unless --range MIN,MAX or --stress-max MAX (from 0 to MAX) gives it (the README
picture: --stress-max 2e7). The time label is in ms, or in s with --seconds.
The camera looks along (DX, DY, DZ) (default 0.075,-0.11,0.044, the README picture's direction)
and frames the models of all panels, the same framing for every panel.
--half keeps the cells with centres at y <= 0 so that folds inside a tube show in section.
"""
import argparse
import xml.etree.ElementTree as ET
from pathlib import Path

import vtk


def states(pvd):
    root = ET.parse(pvd).getroot()
    return [(float(d.get("timestep")), Path(pvd).parent / d.get("file")) for d in root.iter("DataSet")]


# The README picture's viewing direction, from the focal point towards the camera.
DEFAULT_VIEW = (0.075, -0.11, 0.044)


def read(vtu, half):
    """The state's cells (with --half those at y <= 0), read."""
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(str(vtu))
    source = reader
    if half:
        plane = vtk.vtkPlane()
        plane.SetOrigin(0.0, 0.0, 0.0)
        plane.SetNormal(0.0, 1.0, 0.0)
        cut = vtk.vtkExtractGeometry()
        cut.SetInputConnection(reader.GetOutputPort())
        cut.SetImplicitFunction(plane)
        cut.ExtractInsideOn()
        cut.ExtractBoundaryCellsOff()
        source = cut
    source.Update()
    return source


def field_range(sources, field):
    """The smallest and largest value of `field` (a vector's magnitude) over the states."""
    low, high = float("inf"), float("-inf")
    for source in sources:
        grid = source.GetOutput()
        array = grid.GetPointData().GetArray(field) or grid.GetCellData().GetArray(field)
        if array is None or array.GetNumberOfTuples() == 0:
            continue
        a, b = array.GetRange(-1 if array.GetNumberOfComponents() > 1 else 0)
        low, high = min(low, a), max(high, b)
    if low > high:
        raise SystemExit(f"render_picture: no state has the field '{field}'")
    if high <= low:  # a uniform field: a range around it, so that it takes a colour
        high = low + (abs(low) if low != 0.0 else 1.0)
    return low, high


def panel(source, time, viewport, window, colour, seconds):
    field, value_range, title = colour
    surface = vtk.vtkDataSetSurfaceFilter()
    surface.SetInputConnection(source.GetOutputPort())
    mapper = vtk.vtkDataSetMapper()
    mapper.SetInputConnection(surface.GetOutputPort())
    if source.GetOutput().GetPointData().HasArray(field):
        mapper.SetScalarModeToUsePointFieldData()
    else:
        mapper.SetScalarModeToUseCellFieldData()
    mapper.SelectColorArray(field)
    mapper.SetScalarRange(*value_range)
    lut = vtk.vtkLookupTable()
    lut.SetHueRange(0.66, 0.0)
    lut.SetVectorModeToMagnitude()
    lut.Build()
    mapper.SetLookupTable(lut)
    actor = vtk.vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().EdgeVisibilityOn()
    actor.GetProperty().SetEdgeColor(0.15, 0.15, 0.15)
    actor.GetProperty().SetLineWidth(0.5)
    renderer = vtk.vtkRenderer()
    renderer.SetViewport(*viewport)
    renderer.SetBackground(1.0, 1.0, 1.0)
    renderer.AddActor(actor)
    label = vtk.vtkTextActor()
    label.SetInput(f"t = {time:.3g} s" if seconds else f"t = {time * 1e3:.2f} ms")
    label.GetTextProperty().SetColor(0.0, 0.0, 0.0)
    label.GetTextProperty().SetFontSize(22)
    label.SetPosition(12, 12)
    renderer.AddActor2D(label)
    if viewport[0] == 0.0:
        bar = vtk.vtkScalarBarActor()
        bar.SetLookupTable(lut)
        bar.SetTitle(title)
        bar.SetNumberOfLabels(3)
        bar.SetOrientationToHorizontal()
        bar.SetPosition(0.05, 0.84)
        bar.SetWidth(0.8)
        bar.SetHeight(0.12)
        for prop in (bar.GetTitleTextProperty(), bar.GetLabelTextProperty()):
            prop.SetColor(0.0, 0.0, 0.0)
            prop.SetFontSize(14)
            prop.ItalicOff()
            prop.ShadowOff()
        renderer.AddActor2D(bar)
    window.AddRenderer(renderer)
    return renderer


def main():
    parser = argparse.ArgumentParser(usage=__doc__)
    parser.add_argument("pvd")
    parser.add_argument("out")
    parser.add_argument("times", nargs="*", type=float)
    parser.add_argument("--stress-max", type=float)
    parser.add_argument("--view", type=lambda v: [float(c) for c in v.split(",")])
    parser.add_argument("--half", action="store_true")
    parser.add_argument("--field", default="von_mises_stress")
    parser.add_argument("--range", type=lambda v: [float(c) for c in v.split(",")])
    parser.add_argument("--title")
    parser.add_argument("--seconds", action="store_true")
    args = parser.parse_args()
    series = states(args.pvd)
    wanted = args.times or [series[0][0], series[-1][0]]
    chosen = [min(series, key=lambda s: abs(s[0] - t)) for t in wanted]
    window = vtk.vtkRenderWindow()
    window.SetOffScreenRendering(1)
    width = 520
    window.SetSize(width * len(chosen), 520)
    sources = [read(vtu, args.half) for _, vtu in chosen]
    if args.range:
        value_range = args.range
    elif args.stress_max:
        value_range = (0.0, args.stress_max)
    else:
        value_range = field_range(sources, args.field)
        if args.field == "von_mises_stress":
            value_range = (0.0, value_range[1])
    colour = (args.field, value_range,
              args.title or ("von Mises [Pa]" if args.field == "von_mises_stress" else args.field))
    renderers = [
        panel(source, time, (i / len(chosen), 0.0, (i + 1) / len(chosen), 1.0), window, colour,
              args.seconds)
        for i, ((time, _), source) in enumerate(zip(chosen, sources))
    ]
    # One camera for all panels, framing the union of their models' bounds.
    bounds = [float("inf"), float("-inf")] * 3
    for source in sources:
        b = source.GetOutput().GetBounds()
        for k in range(3):
            bounds[2 * k] = min(bounds[2 * k], b[2 * k])
            bounds[2 * k + 1] = max(bounds[2 * k + 1], b[2 * k + 1])
    camera = renderers[0].GetActiveCamera()
    camera.SetFocalPoint(0.0, 0.0, 0.0)
    view = args.view or DEFAULT_VIEW
    camera.SetPosition(*view)
    # z up, unless the camera looks along z
    camera.SetViewUp(*((0.0, 1.0, 0.0) if abs(view[2]) > 0.99 * sum(c * c for c in view) ** 0.5
                       else (0.0, 0.0, 1.0)))
    camera.SetViewAngle(30.0)
    renderers[0].ResetCamera(bounds)
    camera.Zoom(0.85)  # room for the colour bar
    for r in renderers[1:]:
        r.SetActiveCamera(camera)
    window.Render()
    image = vtk.vtkWindowToImageFilter()
    image.SetInput(window)
    image.Update()
    writer = vtk.vtkPNGWriter()
    writer.SetFileName(args.out)
    writer.SetInputConnection(image.GetOutputPort())
    writer.Write()
    print(f"wrote {args.out}: states at " + ", ".join(f"{t:.3g}" for t, _ in chosen))


if __name__ == "__main__":
    main()
