#!/usr/bin/python3
"""Screenshots of a homesh output in the real Gmsh GUI, off screen under Xvfb.

render(msh, png, ...) writes PNG.geo beside the picture, a Gmsh script that
shows one view of MSH (and the mesh edges if asked), then `Print`s the picture
and exits; it runs `xvfb-run -a gmsh MSH PNG.geo`. Gmsh merges MSH.opt, the
homesh sidecar (Mesh.NumSubEdges, View[i].AdaptVisualizationGrid = 1), when it
opens MSH, so the picture is what a user sees on `gmsh MSH`.

Usage: gui_shot.py MSH PNG [--view NAME] [--edges] [--centre X Y --scale S]
                           [--size W H] [--straight]
"""
import argparse
import os
import re
import shutil
import subprocess
import sys


def view_names(msh):
    """Names of the views in MSH, in the order Gmsh numbers them (first appearance)."""
    names = []
    with open(msh) as f:
        lines = iter(f)
        for line in lines:
            if re.match(r"\$(Element|ElementNode|Node)Data$", line.strip()):
                next(lines)
                name = next(lines).strip().strip('"')
                if name not in names:
                    names.append(name)
    return names


def script(view_index, edges, centre, scale, size, adapt, scale_bar, png):
    """The Gmsh commands that set up the picture and print it to `png`."""
    lines = window(size) + [
        "Geometry.Points = 0;",
        "Geometry.Curves = 0;",
        "Mesh.Points = 0;",
        "Mesh.Lines = 0;",
        f"Mesh.SurfaceEdges = {int(edges)};",
        "Mesh.ColorCarousel = 0;",
        "Mesh.Color.Triangles = {60, 60, 60};",
        "For i In {0:PostProcessing.NbViews-1}",
        "  View[i].Visible = 0;",
        "EndFor",
    ]
    if view_index is not None:
        v = f"View[{view_index}]"
        lines += [f"{v}.Visible = 1;", f"{v}.ShowScale = {int(scale_bar)};", f"{v}.Light = 0;",
                  f"{v}.ColormapNumber = 21;  // inferno: dark = low quality"]
        if adapt is not None:
            lines.append(f"{v}.AdaptVisualizationGrid = {int(adapt)};")
    if centre is not None:
        # The translation is relative to the centre of the model's bounding box.
        lines += [f"General.TranslationX = (General.MinX + General.MaxX) / 2 - ({centre[0]});",
                  f"General.TranslationY = (General.MinY + General.MaxY) / 2 - ({centre[1]});",
                  f"General.ScaleX = {scale};", f"General.ScaleY = {scale};"]
    lines += [f'Print "{png}";', "Exit;"]
    return "\n".join(lines) + "\n"


def render(msh, png, view=None, edges=False, centre=None, scale=1.0, size=(800, 600),
           adapt=None, scale_bar=True, timeout=120):
    """Print `view` (a view name, or None for none) of `msh` to `png` with the Gmsh GUI.

    centre, scale: model point at the picture's centre and zoom factor (1 = fit
    the whole model); adapt: None keeps the sidecar's AdaptVisualizationGrid,
    0 or 1 overrides it; scale_bar: draw the view's colour bar. Returns the
    path of the picture.
    """
    if shutil.which("xvfb-run") is None:
        raise RuntimeError("xvfb-run not found (Debian package xvfb)")
    names = view_names(msh)
    if view is not None and view not in names:
        raise ValueError(f"no view '{view}' in {msh}: {names}")
    index = None if view is None else names.index(view)
    png = os.path.abspath(png)
    geo = png + ".geo"
    with open(geo, "w") as f:
        f.write(script(index, edges, centre, scale, size, adapt, scale_bar, png))
    if os.path.exists(png):
        os.remove(png)
    screen = f"-screen 0 {size[0] + 64}x{size[1] + 64}x24"
    subprocess.run(["xvfb-run", "-a", "-s", screen, "gmsh", os.path.abspath(msh), geo],
                   check=True, timeout=timeout, stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL)
    if not os.path.exists(png):
        raise RuntimeError(f"Gmsh wrote no picture {png}")
    return png


def window(size):
    """Gmsh commands for a graphics window of `size` pixels on white, the model fitted."""
    return [
        "General.MenuWidth = 0;",
        f"General.GraphicsWidth = {size[0]};",
        f"General.GraphicsHeight = {size[1]};",
        "General.SmallAxes = 0;",
        "General.BackgroundGradient = 0;",
        "General.Color.Background = {255, 255, 255};",
    ]


def render_as_opened(files, png, size=(600, 600), timeout=120):
    """Print what a user sees on `gmsh FILES[0] -new FILES[1] ...` to `png`.

    Each file is read into a model of its own (Gmsh's -new: homesh files share
    element tags), its sidecar merged right after it; only the window (size,
    white background) is set, every view and mesh option is the files' own.
    Returns the path of the picture.
    """
    if shutil.which("xvfb-run") is None:
        raise RuntimeError("xvfb-run not found (Debian package xvfb)")
    png = os.path.abspath(png)
    geo = png + ".geo"
    with open(geo, "w") as f:
        f.write("\n".join(window(size) + [f'Print "{png}";', "Exit;"]) + "\n")
    if os.path.exists(png):
        os.remove(png)
    args = []
    for k, msh in enumerate(files):
        args += (["-new"] if k else []) + [os.path.abspath(msh)]
    screen = f"-screen 0 {size[0] + 64}x{size[1] + 64}x24"
    subprocess.run(["xvfb-run", "-a", "-s", screen, "gmsh", *args, geo], check=True, timeout=timeout,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    if not os.path.exists(png):
        raise RuntimeError(f"Gmsh wrote no picture {png}")
    return png


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("msh")
    parser.add_argument("png")
    parser.add_argument("--view", help="name of the view to show (default: none)")
    parser.add_argument("--edges", action="store_true", help="draw the mesh edges")
    parser.add_argument("--centre", type=float, nargs=2, metavar=("X", "Y"))
    parser.add_argument("--scale", type=float, default=1.0)
    parser.add_argument("--size", type=int, nargs=2, default=(800, 600), metavar=("W", "H"))
    parser.add_argument("--straight", action="store_true",
                        help="AdaptVisualizationGrid = 0: draw the view on straight triangles")
    a = parser.parse_args()
    render(a.msh, a.png, a.view, a.edges, a.centre, a.scale, tuple(a.size),
           0 if a.straight else None)
    print(f"wrote {a.png}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
