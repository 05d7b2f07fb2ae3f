#!/usr/bin/python3
"""A homesh .vtu drawn as ParaView draws it, off screen with VTK (Debian python3-vtk9).

ParaView tessellates curved (Lagrange) cells with vtkDataSetSurfaceFilter, whose
nonlinear subdivision level is ParaView's "Nonlinear Subdivision Level"
(Properties, advanced): 0 draws each cell straight through its corners, each
level halves the straight pieces. This script runs the same filter on the
triangles of the .vtu, colours them by a field (a cell field such as "homesh: certified minJ/maxJ",
or a point field such as "homesh: Q4 Equal volume, at nodes, smallest at the point") over [0, 1] on a white background, and prints the
picture with a parallel camera. It needs a display: run it under `xvfb-run -a`
on a machine without one.

Usage: vtu_shot.py VTU PNG [--field NAME] [--subdivision N] [--centre X Y]
                           [--scale S] [--size W H]
--centre and --scale (half the picture's height, in model units) fix the camera;
by default the mesh fills the picture.
"""

import vtk

from shot_options import shot_parser


def render(vtu, png, field="homesh: certified minJ/maxJ", subdivision=3, centre=None, scale=None,
           size=(600, 600)):
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(vtu)
    reader.Update()
    grid = reader.GetOutput()
    if grid.GetNumberOfCells() == 0:
        raise SystemExit(f"{vtu}: VTK read no cells")
    # The triangles only: the boundary lines carry no quality (NaN) and would draw over them.
    # (VTK 9.1's vtkExtractCellsByType would drop the cell data.)
    ids = vtk.vtkIdList()
    for c in range(grid.GetNumberOfCells()):
        if grid.GetCellType(c) in (vtk.VTK_TRIANGLE, vtk.VTK_LAGRANGE_TRIANGLE):
            ids.InsertNextId(c)
    triangles = vtk.vtkExtractCells()
    triangles.SetInputConnection(reader.GetOutputPort())
    triangles.SetCellList(ids)
    surface = vtk.vtkDataSetSurfaceFilter()
    surface.SetInputConnection(triangles.GetOutputPort())
    surface.SetNonlinearSubdivisionLevel(subdivision)

    mapper = vtk.vtkPolyDataMapper()
    mapper.SetInputConnection(surface.GetOutputPort())
    if grid.GetCellData().GetArray(field) is not None:
        mapper.SetScalarModeToUseCellFieldData()
    elif grid.GetPointData().GetArray(field) is not None:
        mapper.SetScalarModeToUsePointFieldData()
    else:
        raise SystemExit(f"{vtu}: no cell or point field '{field}'")
    mapper.SelectColorArray(field)
    mapper.SetScalarRange(0.0, 1.0)
    mapper.ScalarVisibilityOn()
    actor = vtk.vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().LightingOff()  # flat colours: the field's, unshaded

    renderer = vtk.vtkRenderer()
    renderer.AddActor(actor)
    renderer.SetBackground(1.0, 1.0, 1.0)
    window = vtk.vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.AddRenderer(renderer)
    window.SetSize(*size)
    window.SetMultiSamples(0)
    camera = renderer.GetActiveCamera()
    camera.ParallelProjectionOn()
    x0, x1, y0, y1, _, _ = grid.GetBounds()
    cx, cy = centre if centre else ((x0 + x1) / 2, (y0 + y1) / 2)
    camera.SetFocalPoint(cx, cy, 0.0)
    camera.SetPosition(cx, cy, 1.0)
    camera.SetViewUp(0.0, 1.0, 0.0)
    renderer.ResetCameraClippingRange(x0, x1, y0, y1, -1.0, 1.0)
    camera.SetParallelScale(scale if scale else 0.5 * max(y1 - y0, (x1 - x0) * size[1] / size[0]))
    window.Render()

    shot = vtk.vtkWindowToImageFilter()
    shot.SetInput(window)
    shot.ReadFrontBufferOff()
    shot.Update()
    writer = vtk.vtkPNGWriter()
    writer.SetFileName(png)
    writer.SetInputConnection(shot.GetOutputPort())
    writer.Write()
    return png


def main():
    parser = shot_parser(__doc__.split("\n\n")[0],
                         "nonlinear subdivision level (ParaView's; 0: straight cells)")
    a = parser.parse_args()
    render(a.vtu, a.png, a.field, a.subdivision, a.centre, a.scale, tuple(a.size))
    print(a.png)


if __name__ == "__main__":
    main()
