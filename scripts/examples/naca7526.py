#!/usr/bin/python3
"""NACA-7526 with boundary layers, curved to order 4: the main job from Python.

A worked example of `import homesh` (run with PYTHONPATH=build/python):

  1. geometry with gmsh.model.occ: the NACA 4-digit aerofoil of --digits as
     two cubic B-splines (upper and lower surface, sharp trailing edge) in a
     5 x 5 chords box, with the mesh sizes of geo/naca.geo (a Python port of
     that file's construction: same curves, same mesh);
  2. a linear mesh by Gmsh itself (gmsh.model.mesh.generate);
  3. homesh.layers: 15 boundary layers on the aerofoil, first 1e-3 chord thick,
     ratio 1.2, with a fan of 5 normals at the trailing edge (its domain angle
     is 326 deg, hence fan_angle = 320); skipped, with a note, if this build of
     homesh has no `layers` stage;
  4. homesh.curve(p=4, placed=0.99, local=0.99): boundary nodes on the CAD,
     interior by the elastic analogy within reach of the wall (0.994: a solve
     round the poor elements alone gives 0.988, kept by the defaults' local=0;
     the defaults' polished first guess gives 0.984 in a fifth of the time);
  5. homesh.quality: certified validity (Bezier bounds of det J) and Q4, Q17 as
     views; homesh.info; homesh.write (mesh, views, .opt sidecar);
  6. with --picture PNG: the Q4 view with the mesh, zoomed on the aerofoil, as
     the Gmsh GUI draws it (under Xvfb; scripts/examples/gui_shot.py).

Usage: naca7526.py [--digits 7526] [--order 4] [--layers 15]
                   [--msh out/examples/naca7526.msh] [--picture PNG]
"""
import argparse
import math
import os
import sys

import gmsh
import numpy as np

import homesh

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))


def surface_control_points(m, p, t, n, side):
    """Control points of one surface's clamped cubic B-spline with knots 0..n, as in
    geo/naca.geo: it interpolates the cosine-spaced samples (Abbott & von Doenhoff,
    closed trailing edge) at the knots, has the exact leading-edge derivative and a
    natural end at the trailing edge. side = +1 upper, -1 lower."""
    beta = np.arange(n + 1) * math.pi / n
    x = (1 - np.cos(beta)) / 2
    yt = 5 * t * (0.2969 * np.sqrt(x) - 0.1260 * x - 0.3516 * x**2 + 0.2843 * x**3
                  - 0.1036 * x**4)
    yc, dyc = np.zeros_like(x), np.zeros_like(x)
    if m > 0:
        front = x < p
        yc = np.where(front, m / p**2 * (2 * p * x - x**2),
                      m / (1 - p)**2 * (1 - 2 * p + 2 * p * x - x**2))
        dyc = np.where(front, 2 * m / p**2 * (p - x), 2 * m / (1 - p)**2 * (p - x))
    theta = np.arctan(dyc)
    q = np.column_stack([x - side * yt * np.sin(theta), yc + side * yt * np.cos(theta)])
    theta0 = math.atan(2 * m / p) if m > 0 else 0.0
    d_le = math.pi / n * 5 * t * 0.2969 / 2
    return interpolating_control_points(
        q, q[0] + side * d_le / 3 * np.array([-math.sin(theta0), math.cos(theta0)]))


def interpolating_control_points(q, second):
    """Control points P_0..P_{n+2} of the clamped cubic B-spline with knots 0..n that
    passes through q[0..n] at the knots, with P_1 = `second` (the leading-edge
    derivative) and a natural end at q[n]."""
    n = len(q) - 1
    P = np.zeros((n + 3, 2))
    P[0] = q[0]
    P[1] = second
    # Rows k = 1..n-1 for the unknowns P_2..P_n (a tridiagonal system).
    A = np.zeros((n - 1, n - 1))
    r = np.zeros((n - 1, 2))
    for k in range(1, n):
        i = k - 1
        if k == 1:
            A[i, i], r[i] = 7 / 12, q[1] - P[1] / 4
        else:
            A[i, i - 1], A[i, i], r[i] = 1 / 6, 2 / 3, q[k]
        if k < n - 1:
            A[i, i + 1] = 1 / 6
        else:
            r[i] = r[i] - q[n] / 6
    P[2:n + 1] = np.linalg.solve(A, r)
    P[n + 1] = (2 * q[n] + P[n]) / 3
    P[n + 2] = q[n]
    return P


def naca(digits, n_points=61):
    """The NACA 4-digit aerofoil `digits` (e.g. "7526") of unit chord in the box
    [-2, 3] x [-2.5, 2.5], built with gmsh.model.occ, with physical curves
    "aerofoil" and "farfield", surface "fluid", and geo/naca.geo's mesh sizes."""
    if len(digits) != 4 or not digits.isdigit():
        raise ValueError(f"--digits {digits}: four digits MPTT expected")
    m, p, t = int(digits[0]) / 100, int(digits[1]) / 10, int(digits[2:]) / 100
    if m > 0 and p == 0:
        raise ValueError(f"--digits {digits}: a cambered aerofoil needs its camber position P > 0")
    occ = gmsh.model.occ
    n = n_points - 1
    le, te = occ.addPoint(0, 0, 0), occ.addPoint(1, 0, 0)
    curves = []
    for side in (1, -1):
        P = surface_control_points(m, p or 0.1, t, n, side)
        inner = [occ.addPoint(x, y, 0) for x, y in P[1:-1]]
        curves.append(occ.addBSpline([le] + inner + [te]))
        occ.remove([(0, tag) for tag in inner])
    aerofoil = occ.addPlaneSurface([occ.addCurveLoop(curves)])
    box = occ.addRectangle(-2, -2.5, 0, 5, 5)
    fluid, _ = occ.cut([(2, box)], [(2, aerofoil)])
    occ.synchronize()
    wall, farfield = [], []
    for _, tag in gmsh.model.getBoundary(fluid, oriented=False):
        xmin, _, _, xmax, _, _ = gmsh.model.getBoundingBox(1, tag)
        (wall if xmin > -1 and xmax < 2 else farfield).append(tag)
    for dim, tags, name in [(1, wall, "aerofoil"), (1, farfield, "farfield"),
                            (2, [tag for _, tag in fluid], "fluid")]:
        gmsh.model.setPhysicalName(dim, gmsh.model.addPhysicalGroup(dim, tags), name)
    tip = gmsh.model.getEntitiesInBoundingBox(1 - 1e-6, -1e-6, -1e-6, 1 + 1e-6, 1e-6, 1e-6, 0)
    # Sizes of geo/naca.geo: 0.02 at the aerofoil growing to 0.4 at 1.5 chords,
    # 0.005 at the trailing edge growing to 0.02 within 0.1 chord, 40 elements
    # per 2 pi of curvature radius.
    f = gmsh.model.mesh.field
    f.add("Distance", 1)
    f.setNumbers(1, "CurvesList", wall)
    f.setNumber(1, "NumPointsPerCurve", 400)
    f.add("Threshold", 2)
    for name, value in [("InField", 1), ("SizeMin", 0.02), ("SizeMax", 0.4), ("DistMin", 0),
                        ("DistMax", 1.5)]:
        f.setNumber(2, name, value)
    f.add("Distance", 3)
    f.setNumbers(3, "PointsList", [tag for _, tag in tip])
    f.add("Threshold", 4)
    for name, value in [("InField", 3), ("SizeMin", 0.005), ("SizeMax", 0.02), ("DistMin", 0),
                        ("DistMax", 0.1), ("StopAtDistMax", 1)]:
        f.setNumber(4, name, value)
    f.add("Min", 5)
    f.setNumbers(5, "FieldsList", [2, 4])
    f.setAsBackgroundMesh(5)
    gmsh.option.setNumber("Mesh.MeshSizeFromPoints", 0)
    gmsh.option.setNumber("Mesh.MeshSizeExtendFromBoundary", 1)
    gmsh.option.setNumber("Mesh.MeshSizeFromCurvature", 40)


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
    homesh.curve(p=args.order, placed=0.99, local=0.99)  # solved within reach (naca7526.sh)
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

    def shot(name, centre, scale, size, scale_bar):
        path = gui_shot.render(msh, f"{png}.{name}.png", view="homesh: Q4 Equal volume, at nodes", edges=True, centre=centre,
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
