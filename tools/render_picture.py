#!/usr/bin/python3
"""Renders states of an abut ParaView series side by side into one PNG (the README picture).

    xvfb-run -a /usr/bin/python3 tools/render_picture.py RESULTS.pvd OUT.png [TIME ...]
        [--stress-max PA] [--view DX,DY,DZ] [--half]
        [--field NAME --range MIN,MAX --title TEXT] [--seconds]

Uses Debian's python3-vtk9; without a display run it under xvfb-run (package xvfb).
Each panel shows the exterior of the model at the state nearest to the time asked for
(default: the first and the last state), coloured by von Mises stress from 0 to --stress-max
(default 2e7 Pa), or by another field of the states (--field, a point or cell array, e.g.
temperature, over --range, labelled --title). The time label is in ms, or in s with --seconds.
Without --view the camera is the rubber-sphere picture's; with it the camera
looks along (DX, DY, DZ) and frames the first panel's model, the same framing for every panel.
--half keeps the cells with centres at y <= 0 so that folds inside a tube show in section.
"""
import argparse
import xml.etree.ElementTree as ET
from pathlib import Path

import vtk


def states(pvd):
    root = ET.parse(pvd).getroot()
    return [(float(d.get("timestep")), Path(pvd).parent / d.get("file")) for d in root.iter("DataSet")]


def panel(vtu, time, viewport, window, colour, half, seconds):
    field, value_range, title = colour
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
    surface = vtk.vtkDataSetSurfaceFilter()
    surface.SetInputConnection(source.GetOutputPort())
    mapper = vtk.vtkDataSetMapper()
    mapper.SetInputConnection(surface.GetOutputPort())
    reader.Update()
    if reader.GetOutput().GetPointData().HasArray(field):
        mapper.SetScalarModeToUsePointFieldData()
    else:
        mapper.SetScalarModeToUseCellFieldData()
    mapper.SelectColorArray(field)
    mapper.SetScalarRange(*value_range)
    lut = vtk.vtkLookupTable()
    lut.SetHueRange(0.66, 0.0)
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
    camera = renderer.GetActiveCamera()
    camera.SetFocalPoint(0.0, 0.0, 0.016)
    camera.SetPosition(0.075, -0.11, 0.06)
    camera.SetViewUp(0.0, 0.0, 1.0)
    camera.SetViewAngle(30.0)
    window.AddRenderer(renderer)
    return renderer


def main():
    parser = argparse.ArgumentParser(usage=__doc__)
    parser.add_argument("pvd")
    parser.add_argument("out")
    parser.add_argument("times", nargs="*", type=float)
    parser.add_argument("--stress-max", type=float, default=2.0e7)
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
    colour = (args.field, args.range or (0.0, args.stress_max),
              args.title or ("von Mises [Pa]" if args.field == "von_mises_stress" else args.field))
    renderers = [
        panel(vtu, time, (i / len(chosen), 0.0, (i + 1) / len(chosen), 1.0), window, colour,
              args.half, args.seconds)
        for i, (time, vtu) in enumerate(chosen)
    ]
    if args.view:
        first = renderers[0].GetActiveCamera()
        first.SetFocalPoint(0.0, 0.0, 0.0)
        first.SetPosition(*args.view)
        renderers[0].ResetCamera()
        first.Zoom(0.85)  # room for the colour bar
        for r in renderers[1:]:
            r.SetActiveCamera(first)
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
