#!/usr/bin/python3
"""The 3D curving corpus of issue 24: linear tetrahedral meshes of the fluid round a body.

Every case is made by a script, deterministically, in the current Gmsh session: a body with
Gmsh's OpenCASCADE kernel, cut out of a box (the fluid volume round it: the one volume of the
model), physical groups "fluid" (the volume), "wall" (the body's surfaces, what curving puts
on the CAD where it matters) and "farfield" (the box's faces, or what is left of them), then a
linear tetrahedral mesh: Gmsh's Delaunay (Mesh.Algorithm3D 1) on Frontal-Delaunay surfaces
(Mesh.Algorithm 6), General.NumThreads 1, sizes from a Threshold of the Distance to the wall
surfaces only (h_wall within dist_min of the wall, growing to h_far at dist_max; no sizes
from points, curvature or the boundary), so each build gives the same mesh.

Bodies:
  sphere     radius 0.5;
  torus      radii 0.5 and 0.2 (a saddle-shaped inner wall);
  ellipsoid  a sphere of radius 0.5 scaled by (1, 0.5, 0.3) with occ.dilate (a B-spline wall);
  wing       a NACA 0012 section of chord 1 (two cubic B-splines through the section points,
             sharing the leading-edge point and the sharp trailing-edge point, as corpus.py's
             aerofoils) extruded over a span of 1.5 from the box's face z = 0 (a symmetry
             plane) to a flat tip;
  close      two spheres of radius 0.5 at a gap of 0.05 (0.1 radius);
  bracket    the filleted L-bracket with a hole of geo/3d/bracket.step (written by
             scripts/bench/make_bracket_step.py), imported with occ.importShapes.
each at two sizes, `_coarse` and `_fine` (names like sphere_coarse, wing_fine).

Library use (the benchmark does this in each method's fresh Gmsh session):

    import corpus3d
    gmsh.initialize()
    record = corpus3d.build("sphere_coarse")   # CAD + linear mesh; its counts

Command line (Debian's /usr/bin/python3, PYTHONPATH=build/python: corpus.py's aerofoil comes
with scripts/examples/naca7526.py, which imports homesh):

    corpus3d.py [--list] [--cases PATTERN] [--out DIR]

builds every case (or those matching PATTERN) and prints its record; with --out writes
DIR/NAME.msh per case.
"""
import argparse
import fnmatch
import math
import os
import sys
import time
from dataclasses import dataclass

import gmsh
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
ROOT = os.path.dirname(os.path.dirname(HERE))
BRACKET = os.path.join(ROOT, "geo", "3d", "bracket.step")

import corpus  # noqa: E402 (the aerofoil section, shared with the 2D corpus)

WALL, FARFIELD, FLUID = "wall", "farfield", "fluid"


# ---------------------------------------------------------------- bodies
# Each returns (the body's volumes as dimtags, the box round it as (x0, y0, z0, x1, y1, z1)).

def body_sphere(r=0.5):
    return [(3, gmsh.model.occ.addSphere(0, 0, 0, r))], (-2, -2, -2, 2, 2, 2)


def body_torus(R=0.5, r=0.2):
    return [(3, gmsh.model.occ.addTorus(0, 0, 0, R, r))], (-2, -2, -1.5, 2, 2, 1.5)


def body_ellipsoid(r=0.5, scale=(1.0, 0.5, 0.3)):
    occ = gmsh.model.occ
    s = [(3, occ.addSphere(0, 0, 0, r))]
    occ.dilate(s, 0, 0, 0, *scale)
    return s, (-2, -1.5, -1.5, 2, 1.5, 1.5)


def body_wing(code="0012", span=1.5):
    """The section at z = 0 extruded to z = span: its root on the box's face z = 0."""
    occ = gmsh.model.occ
    section = corpus.add_aerofoil(code, pivot=(0.0, 0.0))
    out = occ.extrude([(2, section)], 0, 0, span)
    return [d for d in out if d[0] == 3], (-1.5, -1.5, 0, 3, 1.5, 3)


def body_close(r=0.5, gap=0.05):
    occ = gmsh.model.occ
    c = r + gap / 2
    return [(3, occ.addSphere(-c, 0, 0, r)), (3, occ.addSphere(c, 0, 0, r))], \
        (-2.5, -2, -2, 2.5, 2, 2)


def body_bracket(path=BRACKET):
    if not os.path.exists(path):
        raise FileNotFoundError(f"{path}: run scripts/bench/make_bracket_step.py")
    shapes = gmsh.model.occ.importShapes(path)
    return [d for d in shapes if d[0] == 3], (-0.8, -0.8, -0.8, 2.0, 1.6, 1.8)


BODIES = dict(sphere=body_sphere, torus=body_torus, ellipsoid=body_ellipsoid, wing=body_wing,
              close=body_close, bracket=body_bracket)


# ---------------------------------------------------------------- cases

@dataclass(frozen=True)
class Case:
    name: str
    body: str
    h_wall: float          # mesh size on and near the wall
    h_far: float           # mesh size far from it
    dist_min: float = 0.0  # the wall's size holds this far out
    dist_max: float = 1.5  # the far size from this far out


def _cases():
    sizes = {   # body: (coarse (h_wall, h_far), fine (h_wall, h_far))
        "sphere": ((0.12, 0.6), (0.06, 0.4)),
        "torus": ((0.08, 0.6), (0.05, 0.4)),
        "ellipsoid": ((0.08, 0.6), (0.045, 0.4)),
        "wing": ((0.08, 0.6), (0.045, 0.45)),
        "close": ((0.1, 0.6), (0.06, 0.45)),
        "bracket": ((0.08, 0.6), (0.045, 0.4)),
    }
    return [Case(f"{body}_{level}", body, *hs)
            for body, pair in sizes.items() for level, hs in zip(("coarse", "fine"), pair)]


CASES = _cases()


def names():
    return [c.name for c in CASES]


def case(name):
    for c in CASES:
        if c.name == name:
            return c
    raise KeyError(f"no 3D corpus case '{name}'")


def select(patterns=None):
    """The cases whose names match any of the comma-separated shell patterns (a pattern
    without wildcards matches as a substring), in the order of the patterns (all, if none)."""
    if not patterns:
        return list(CASES)
    chosen = []
    for p in patterns.split(","):
        p = p if any(ch in p for ch in "*?[") else f"*{p}*"
        chosen += [c for c in CASES if fnmatch.fnmatch(c.name, p) and c not in chosen]
    return chosen


# ---------------------------------------------------------------- building

def on_box(tag, extent, tol=1e-6):
    """Whether surface `tag` lies in a face plane of the box `extent`."""
    lo = gmsh.model.getBoundingBox(2, tag)
    for k in range(3):
        flat = abs(lo[k + 3] - lo[k]) < tol
        if flat and min(abs(lo[k] - extent[k]), abs(lo[k] - extent[k + 3])) < tol:
            return True
    return False


def fluid_cad(c):
    """Case c's body cut out of its box, synchronised, with its physical groups: returns
    (volume tags, wall surface tags, farfield surface tags)."""
    occ = gmsh.model.occ
    bodies, extent = BODIES[c.body]()
    x0, y0, z0, x1, y1, z1 = extent
    fluid, _ = occ.cut([(3, occ.addBox(x0, y0, z0, x1 - x0, y1 - y0, z1 - z0))], bodies)
    occ.synchronize()
    volumes = [t for d, t in fluid if d == 3]
    if len(volumes) != 1:
        raise RuntimeError(f"case {c.name}: {len(volumes)} fluid volumes, 1 expected")
    surfaces = [abs(t) for _, t in gmsh.model.getBoundary(fluid, oriented=False)]
    farfield = [t for t in surfaces if on_box(t, extent)]
    walls = [t for t in surfaces if t not in farfield]
    for dim, tags, group in [(3, volumes, FLUID), (2, walls, WALL), (2, farfield, FARFIELD)]:
        gmsh.model.setPhysicalName(dim, gmsh.model.addPhysicalGroup(dim, tags), group)
    return volumes, walls, farfield


def mesh_options(c, walls):
    """The deterministic mesher and its size field (a Threshold of the distance to the wall)."""
    f = gmsh.model.mesh.field
    d = f.add("Distance")
    f.setNumbers(d, "SurfacesList", walls)
    f.setNumber(d, "NumPointsPerCurve", 100)
    t = f.add("Threshold")
    for name, value in [("InField", d), ("SizeMin", c.h_wall), ("SizeMax", c.h_far),
                        ("DistMin", c.dist_min), ("DistMax", c.dist_max)]:
        f.setNumber(t, name, value)
    f.setAsBackgroundMesh(t)
    for name, value in [("General.NumThreads", 1), ("Mesh.Algorithm", 6),
                        ("Mesh.Algorithm3D", 1), ("Mesh.MeshSizeFromPoints", 0),
                        ("Mesh.MeshSizeFromCurvature", 0), ("Mesh.MeshSizeExtendFromBoundary", 0),
                        ("Mesh.Optimize", 1)]:
        gmsh.option.setNumber(name, value)


def count(dim, prefix):
    """The number of linear elements of dimension `dim` whose type name starts with prefix."""
    n = 0
    for t, tags in zip(*gmsh.model.mesh.getElements(dim)[:2]):
        name, _, order = gmsh.model.mesh.getElementProperties(t)[:3]
        if name.startswith(prefix) and order == 1:
            n += len(tags)
    return n


def tetrahedra():
    """The linear tetrahedra's corner node tags (#T x 4) and the nodes' coordinates by tag
    (a dense array, rows of unused tags zero)."""
    tags, xyz, _ = gmsh.model.mesh.getNodes()
    X = np.zeros((int(tags.max()) + 1, 3))
    X[tags.astype(int)] = xyz.reshape(-1, 3)
    T = [np.asarray(nodes, dtype=int).reshape(-1, 4)
         for t, _, nodes in zip(*gmsh.model.mesh.getElements(3))
         if gmsh.model.mesh.getElementProperties(t)[0].startswith("Tetrahedron")]
    return (np.concatenate(T) if T else np.zeros((0, 4), dtype=int)), X


def worst_shape(T, X):
    """The smallest 6 sqrt(2) V / e_rms^3 over the linear tetrahedra (1: regular, 0: flat;
    e_rms the root mean square of the six edges)."""
    P = X[T]
    volume = np.abs(np.linalg.det(P[:, 1:] - P[:, :1])) / 6
    edges = [P[:, i] - P[:, j] for i in range(4) for j in range(i + 1, 4)]
    rms = np.sqrt(np.mean([np.sum(e * e, axis=1) for e in edges], axis=0))
    return float(np.min(6 * math.sqrt(2) * volume / rms**3)) if len(T) else 1.0


def wall_caps(T, walls):
    """The number of tetrahedra with two or more faces on the wall (all four corners on it: a
    cap over a fold of the wall's triangulation, or a wedge in a corner of the fluid): both
    faces are curved onto the CAD and no corner is free to give way, for every method."""
    on_wall = {tuple(sorted(tri)) for s in walls
               for nodes in gmsh.model.mesh.getElements(2, s)[2]
               for tri in np.asarray(nodes, dtype=int).reshape(-1, 3).tolist()}
    faces = [(0, 1, 2), (0, 1, 3), (0, 2, 3), (1, 2, 3)]
    return sum(1 for t in T.tolist()
               if sum(tuple(sorted(t[i] for i in f)) in on_wall for f in faces) >= 2)


def wall_triangles(walls):
    return sum(len(tags) for s in walls for tags in gmsh.model.mesh.getElements(2, s)[1])


def build(c):
    """Recreate case c (a Case or its name) in the current Gmsh session: clear it, make the
    CAD and the linear tetrahedral mesh. Returns the case's record (a dict)."""
    if isinstance(c, str):
        c = case(c)
    gmsh.clear()
    gmsh.model.add(c.name)
    _, walls, farfield = fluid_cad(c)
    mesh_options(c, walls)
    start = time.perf_counter()
    gmsh.model.mesh.generate(3)
    seconds = time.perf_counter() - start
    tets = count(3, "Tetrahedron")
    T, X = tetrahedra()
    every = sum(len(tags) for tags in gmsh.model.mesh.getElements(3)[1])
    return dict(case=c.name, body=c.body, h_wall=c.h_wall, h_far=c.h_far, tetrahedra=tets,
                other_3d=every - tets, wall_surfaces=len(walls),
                farfield_surfaces=len(farfield), wall_triangles=wall_triangles(walls),
                worst_shape=round(worst_shape(T, X), 4), wall_caps=wall_caps(T, walls),
                nodes=len(gmsh.model.mesh.getNodes()[0]), mesh_seconds=round(seconds, 3))


# ---------------------------------------------------------------- command line

def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--list", action="store_true", help="list the cases and exit")
    ap.add_argument("--cases", help="comma-separated name patterns (substring or glob)")
    ap.add_argument("--out", help="write DIR/NAME.msh per case")
    args = ap.parse_args(argv)
    cases = select(args.cases)
    if args.list:
        for c in cases:
            print(f"{c.name:<18} {c.body:<10} h_wall {c.h_wall:<6g} h_far {c.h_far:g}")
        return 0
    if args.out:
        os.makedirs(args.out, exist_ok=True)
    for c in cases:
        gmsh.initialize()
        gmsh.option.setNumber("General.Terminal", 0)
        rec = build(c)
        if args.out:
            gmsh.write(os.path.join(args.out, c.name + ".msh"))
        gmsh.finalize()
        print(" ".join(f"{k}={v}" for k, v in rec.items()), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
