#!/usr/bin/python3
"""NACA-7526 with boundary layers, curved to order 4: the main job from Python.

A worked example of `import homesh` (run with PYTHONPATH=build/python):

  1. geometry: geo/naca.geo opened by Gmsh, its ONELAB parameters (NACA/M,
     NACA/P, NACA/T) set first from --digits, as geo/README.md explains;
  2. a linear mesh by Gmsh itself (gmsh.model.mesh.generate);
  3. homesh.layers: 15 boundary layers on the aerofoil, first 1e-3 chord thick,
     ratio 1.2, with a fan of 5 normals at the trailing edge (its domain angle
     is 326 deg, hence fan_angle = 320); skipped, with a note, if this build of
     homesh has no `layers` stage;
  4. homesh.curve(p=4): boundary nodes on the CAD, interior by the elastic
     analogy in certified-valid increments;
  5. homesh.quality: certified validity (Bezier bounds of det J) and Q4, Q17 as
     views; homesh.info; homesh.write (mesh, views, .opt sidecar);
  6. with --picture PNG: the Q4 view with the mesh, zoomed on the aerofoil, as
     the Gmsh GUI draws it (under Xvfb; scripts/examples/gui_shot.py).

Usage: naca7526.py [--digits 7526] [--order 4] [--layers 15]
                   [--msh out/examples/naca7526.msh] [--picture PNG]
"""
import argparse
import os
import sys

import gmsh

import homesh

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))


def naca(digits):
    """Open geo/naca.geo as the NACA 4-digit aerofoil `digits` (e.g. "7526")."""
    if len(digits) != 4 or not digits.isdigit():
        raise ValueError(f"--digits {digits}: four digits MPTT expected")
    gmsh.onelab.setNumber("NACA/M", [int(digits[0])])
    gmsh.onelab.setNumber("NACA/P", [int(digits[1])])
    gmsh.onelab.setNumber("NACA/T", [int(digits[2:])])
    gmsh.open(os.path.join(ROOT, "geo", "naca.geo"))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--digits", default="7526", help="NACA 4-digit code")
    parser.add_argument("--order", type=int, default=4)
    parser.add_argument("--layers", type=int, default=15, help="boundary layers (0: none)")
    parser.add_argument("--msh", default=os.path.join(ROOT, "out", "examples", "naca7526.msh"))
    parser.add_argument("--picture", help="PNG of the Q4 view drawn by the Gmsh GUI")
    args = parser.parse_args()
    os.makedirs(os.path.dirname(os.path.abspath(args.msh)), exist_ok=True)

    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    naca(args.digits)
    gmsh.model.mesh.generate(2)

    if args.layers > 0:
        if "layers" in [s["name"] for s in homesh.stages()]:
            homesh.layers(walls="aerofoil", n=args.layers, first=1e-3, ratio=1.2,
                          normals="multi", fan=5, fan_angle=320)
        else:
            print("note: this homesh has no 'layers' stage: no boundary layers", flush=True)
    homesh.curve(p=args.order)
    homesh.quality(measures="Q4,Q17")
    homesh.info()
    homesh.write(args.msh)
    print(f"wrote {args.msh}", flush=True)
    gmsh.finalize()

    if args.picture:
        picture(args.msh, args.picture)
        print(f"wrote {args.picture}", flush=True)
    return 0


def picture(msh, png):
    """The aerofoil (900 x 450 pixels) above its leading and trailing edges, zoomed 40 and 25
    times: the Q4 view and the mesh as the Gmsh GUI draws them, in one PNG."""
    sys.path.insert(0, HERE)
    import gui_shot
    import matplotlib.image
    import numpy as np

    def shot(name, centre, scale, size, scale_bar):
        path = gui_shot.render(msh, f"{png}.{name}.png", view="Q4", edges=True, centre=centre,
                               scale=scale, size=size, scale_bar=scale_bar)
        image = matplotlib.image.imread(path)[:, :, :3]
        os.remove(path)
        os.remove(path + ".geo")
        return image

    whole = shot("aerofoil", (0.5, 0.04), 4.5, (900, 450), True)
    le = shot("leading_edge", (0.03, 0.03), 40, (448, 400), False)
    te = shot("trailing_edge", (1.02, 0.0), 25, (448, 400), False)
    white = np.ones((400, 4, 3), dtype=whole.dtype)
    matplotlib.image.imsave(png, np.vstack([whole, np.ones((4, 900, 3), whole.dtype),
                                            np.hstack([le, white, te])]))


if __name__ == "__main__":
    sys.exit(main())
