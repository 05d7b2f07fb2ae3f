#!/usr/bin/python3
"""Plate with a hole, built with the Gmsh API and curved to order 4 by homesh.

A worked example of `import homesh` (run with PYTHONPATH=build/python):

  1. CAD with gmsh.model.occ: the square [-1, 1]^2 minus the disk of radius 0.5,
     physical groups "hole", "farfield" and "plate" (as geo/plate_hole.geo);
  2. a linear mesh by Gmsh itself (gmsh.model.mesh.generate);
  3. homesh.order(p=4): order 4, straight-sided; homesh.curve(p=4): order 4 with
     the boundary nodes on the CAD and the interior by the elastic analogy;
  4. after each, the domain's area integrated by Gmsh (Jacobian determinants at
     Gauss points): the straight-sided mesh misses the circular segments,
     O(h^2); the curved one matches 4 - pi/4 to interpolation accuracy;
  5. homesh.quality (certified validity and Q4, Q17 views), homesh.info and
     homesh.write (mesh, views and the .opt sidecar for curved display).

Usage: plate_hole.py [--order P] [--size H] [--msh out/examples/plate_hole.msh]
Then `gmsh out/examples/plate_hole.msh` shows the curved mesh and its views.
"""
import argparse
import math
import os
import sys

import gmsh
import numpy as np

import homesh

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
HALF_SIDE, RADIUS = 1.0, 0.5


def plate(size):
    """CAD of the plate with a hole and its physical groups; mesh size `size` on the hole."""
    occ = gmsh.model.occ
    square = occ.addRectangle(-HALF_SIDE, -HALF_SIDE, 0, 2 * HALF_SIDE, 2 * HALF_SIDE)
    disk = occ.addDisk(0, 0, 0, RADIUS, RADIUS)
    (surface,), _ = occ.cut([(2, square)], [(2, disk)])
    occ.synchronize()
    curves = [c for _, c in gmsh.model.getBoundary([surface], oriented=False)]
    hole = [c for c in curves if gmsh.model.getType(1, c) != "Line"]  # OCC says "Ellipse"
    farfield = [c for c in curves if c not in hole]
    for dim, tags, name in ((1, hole, "hole"), (1, farfield, "farfield"),
                            (2, [surface[1]], "plate")):
        gmsh.model.setPhysicalName(dim, gmsh.model.addPhysicalGroup(dim, tags), name)
    for point in gmsh.model.getEntities(0):
        on_hole = np.hypot(*gmsh.model.getValue(*point, [])[:2]) < RADIUS + 1e-9
        gmsh.model.mesh.setSize([point], size if on_hole else 2 * size)


def area():
    """Area of the current mesh: sum over triangles of det J w at Gmsh's Gauss points."""
    total = 0.0
    for element_type in gmsh.model.mesh.getElementTypes(2):
        order = gmsh.model.mesh.getElementProperties(element_type)[2]
        points, weights = gmsh.model.mesh.getIntegrationPoints(element_type, f"Gauss{2 * order}")
        _, determinants, _ = gmsh.model.mesh.getJacobians(element_type, points)
        total += np.sum(determinants.reshape(-1, len(weights)) @ weights)
    return total


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--order", type=int, default=4)
    parser.add_argument("--size", type=float, default=0.1, help="mesh size on the hole")
    parser.add_argument("--msh", default=os.path.join(ROOT, "out", "examples", "plate_hole.msh"))
    args = parser.parse_args()
    os.makedirs(os.path.dirname(os.path.abspath(args.msh)), exist_ok=True)

    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.model.add("plate_hole")
    plate(args.size)
    gmsh.model.mesh.generate(2)

    exact = (2 * HALF_SIDE) ** 2 - math.pi * RADIUS**2
    homesh.order(p=args.order)
    straight = area() - exact
    homesh.curve(p=args.order, formulation="heat_q17")
    curved = area() - exact
    print(f"area: exact {exact:.9f}, straight-sided error {straight:.2e}, "
          f"curved error {curved:.2e}", flush=True)

    homesh.quality(measures="Q4,Q17")
    homesh.info()
    homesh.write(args.msh)
    print(f"wrote {args.msh}", flush=True)
    gmsh.finalize()
    return 0


if __name__ == "__main__":
    sys.exit(main())
