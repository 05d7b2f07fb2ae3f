#!/usr/bin/python3
"""Writes geo/3d/bracket.step, the filleted mechanical part of the 3D corpus (issue 24,
scripts/bench/corpus3d.py): a small L-shaped bracket made with Gmsh's OpenCASCADE kernel.

The part (units as the rest of the corpus, about 1 long):
  base    : a plate 1.2 x 0.8 x 0.2 (x, y, z from the origin);
  upright : a plate 0.2 x 0.8 x 1.0 at x = 0, its foot in the base (1.0 tall in all);
  hole    : a vertical through-hole of radius 0.15 in the base at (0.75, 0.4);
  fillets : radius 0.1 on the concave edge where the upright meets the base, 0.08 on the
            upright's four top edges, 0.1 on the base's two vertical edges at x = 1.2, 0.04 round
            the hole's top and bottom rims (toroidal patches: a doubly curved wall).

Run with Debian's python (the one that imports gmsh):
    /usr/bin/python3 scripts/bench/make_bracket_step.py [--out geo/3d/bracket.step]
The file is deterministic for a given Gmsh/OpenCASCADE version (the STEP header's time stamp
aside) and small (about 60 kB).
"""
import argparse
import os
import sys

import gmsh

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
EPS = 1e-6


def curves_in(x0, y0, z0, x1, y1, z1):
    """Tags of the model's curves inside the box (x0, y0, z0)-(x1, y1, z1), widened by EPS."""
    found = gmsh.model.getEntitiesInBoundingBox(x0 - EPS, y0 - EPS, z0 - EPS,
                                                x1 + EPS, y1 + EPS, z1 + EPS, 1)
    return [t for _, t in found]


def plain_part():
    """The base and the upright fused, the hole cut: the volume's tag."""
    occ = gmsh.model.occ
    base = occ.addBox(0, 0, 0, 1.2, 0.8, 0.2)
    upright = occ.addBox(0, 0, 0, 0.2, 0.8, 1.0)
    part, _ = occ.fuse([(3, base)], [(3, upright)])
    hole = occ.addCylinder(0.75, 0.4, -0.1, 0, 0, 0.4, 0.15)
    part, _ = occ.cut(part, [(3, hole)])
    occ.synchronize()
    return part[0][1]


def fillet(volume, edges_and_radii):
    """The volume with each group of edges (a list of curve tags) filleted with its radius,
    one group after another (each fillet makes a new volume and renumbers the curves, so the
    groups are found afresh: edges_and_radii holds functions returning the tags)."""
    occ = gmsh.model.occ
    for find, radius in edges_and_radii:
        tags = find()
        if not tags:
            raise RuntimeError(f"no edges to fillet with radius {radius}")
        out = occ.fillet([volume], tags, [radius], removeVolume=True)
        occ.synchronize()
        volume = out[0][1]
    return volume


def bracket():
    """The bracket in the current (empty) model: its volume tag."""
    volume = plain_part()
    groups = [
        # the concave edge along y where the upright's face x = 0.2 meets the base's top
        (lambda: curves_in(0.2, 0, 0.2, 0.2, 0.8, 0.2), 0.1),
        # the upright's four top edges
        (lambda: curves_in(0, 0, 1.0, 0.2, 0.8, 1.0), 0.08),
        # the base's two vertical edges at its free end
        (lambda: curves_in(1.2, 0, 0, 1.2, 0, 0.2) + curves_in(1.2, 0.8, 0, 1.2, 0.8, 0.2), 0.1),
        # the hole's rims (circles of radius 0.15 at z = 0 and z = 0.2; not its seam)
        (lambda: curves_in(0.6, 0.25, 0, 0.9, 0.55, 0) + curves_in(0.6, 0.25, 0.2, 0.9, 0.55, 0.2),
         0.04),
    ]
    return fillet(volume, groups)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default=os.path.join(ROOT, "geo", "3d", "bracket.step"))
    args = ap.parse_args(argv)
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.model.add("bracket")
    bracket()
    surfaces = len(gmsh.model.getEntities(2))
    os.makedirs(os.path.dirname(args.out), exist_ok=True)
    gmsh.write(args.out)
    gmsh.finalize()
    print(f"{args.out}: {surfaces} surfaces, {os.path.getsize(args.out)} bytes")
    return 0


if __name__ == "__main__":
    sys.exit(main())
