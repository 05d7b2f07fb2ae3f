"""A homesh .vtu in ParaView itself, off screen: a pvpython script.

Opens VTU in ParaView, colours it by a field (a cell field such as minJ/maxJ,
or a point field such as Q4) over [0, 1] (or [--low, 1]), sets the display's Nonlinear
Subdivision Level (0 draws each cell straight through its corners; ParaView's
default is 1, 3 draws order-4 edges smooth) and saves the picture, white
background, parallel camera. Run it with ParaView's Python (Debian packages
paraview and python3-paraview), under `xvfb-run -a` without a display; the
`--` keeps pvpython from taking the script's options for its own:

  xvfb-run -a -s "-screen 0 1280x1024x24" pvpython -- scripts/examples/paraview_shot.py VTU PNG
      [--field NAME] [--subdivision N] [--centre X Y] [--scale S] [--size W H]
      [--edges] [--low L]

--centre and --scale (half the picture's height, in model units) fix the camera;
by default the mesh fills the picture.
"""

from paraview import simple

from shot_options import shot_parser


def render(vtu, png, field="homesh: certified minJ/maxJ", subdivision=3, centre=None, scale=None,
           size=(600, 600), edges=False, low=0.0):
    reader = simple.OpenDataFile(vtu)
    view = simple.GetActiveViewOrCreate("RenderView")
    view.ViewSize = list(size)
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = [1.0, 1.0, 1.0]
    display = simple.Show(reader, view)
    display.NonlinearSubdivisionLevel = subdivision
    if edges:
        display.SetRepresentationType("Surface With Edges")
    if field in reader.CellData.keys():
        simple.ColorBy(display, ("CELLS", field))
    elif field in reader.PointData.keys():
        simple.ColorBy(display, ("POINTS", field))
    else:
        raise SystemExit(f"{vtu}: no cell or point field '{field}'")
    simple.GetColorTransferFunction(field).RescaleTransferFunction(low, 1.0)
    simple.Render(view)  # the first render resets the camera: set it after
    x0, x1, y0, y1, _, _ = reader.GetDataInformation().GetBounds()
    cx, cy = centre if centre else ((x0 + x1) / 2, (y0 + y1) / 2)
    view.CameraParallelProjection = 1
    view.CameraFocalPoint = [cx, cy, 0.0]
    view.CameraPosition = [cx, cy, 1.0]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    view.CameraParallelScale = scale if scale else 0.5 * max(y1 - y0,
                                                             (x1 - x0) * size[1] / size[0])
    simple.Render(view)
    simple.SaveScreenshot(png, view, ImageResolution=list(size))
    return png


def main():
    parser = shot_parser(__doc__.split("\n\n")[0],
                         "Nonlinear Subdivision Level (0: straight cells)")
    parser.add_argument("--edges", action="store_true",
                        help="Surface With Edges: the cells' curved edges drawn too")
    parser.add_argument("--low", type=float, default=0.0, help="the colour scale's low end")
    a = parser.parse_args()
    render(a.vtu, a.png, a.field, a.subdivision, a.centre, a.scale, tuple(a.size), a.edges, a.low)
    print(a.png)


if __name__ == "__main__":
    main()
