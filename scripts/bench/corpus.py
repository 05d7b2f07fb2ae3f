#!/usr/bin/python3
"""The curving corpus of issue 16: linear 2D triangle meshes homesh did not design for.

Every case is made by a script, deterministically, in the current Gmsh session: its CAD with
`gmsh.model.occ` (so curving can put the high-order nodes on it), then a linear triangle mesh
by one of four meshers:

  gmsh_bl  : Gmsh's BoundaryLayer field on the wall curves (Size = first cell, Ratio, the
             Thickness of n layers, Quads = 0, a fan of Mesh.BoundaryLayerFanElements at every
             sharp wall point, e.g. a trailing edge, via FanPointsList), generate(2);
  layers   : Gmsh's mesh, then homesh's `layers` stage (normals=multi with fans at sharp
             points when there are any);
  none     : Gmsh's mesh alone (no layers);
  voronoi  : homesh's `voronoi` stage (crystal-growth Voronoi regions, sizes from the same
             Gmsh size field).

The quad family (issue 21; listed only with `--family quads` or `all`, so the runs of the
triangle corpus above are unchanged) is meshed by three more:

  gmsh_bl_quads : as gmsh_bl with Quads = 1: quadrilaterals in the layers, triangles outside
                  and in the fans at sharp wall points (a mixed mesh);
  gmsh_quads    : Gmsh's Frontal-Delaunay (Mesh.Algorithm 6) with Mesh.RecombineAll = 1
                  (Blossom, Mesh.RecombinationAlgorithm 1): all quadrilaterals, with a Quads = 1
                  BoundaryLayer field where the case has layers. (Gmsh 4.8.4's Frontal-Delaunay
                  for quads, Algorithm 8, crashes on these domains with their size field, and
                  RecombineAll with the layers' trailing-edge fans throws: the all-quad cases
                  are smooth bodies.)
  gmsh_transfinite : a structured O-grid round a circle (transfinite, recombined), graded
                  from the first cell at the wall: the all-quad case whose linear quads are
                  good (recombined ones have a worst minJ/maxJ of about 0.2 already).

Shapes: NACA 4- and 5-digit aerofoils (thin, thick, cambered, at incidence; closed sharp
trailing edges, each surface a cubic B-spline with the exact leading-edge tangent), a main
element with a flap and with slat + flap (small gaps, small nose radii), circles and ellipses
alone and in arrays, smooth random star-shaped bodies (fixed seeds), an L-shaped domain with a
rounded re-entrant corner and a hole, a plate with holes. Wall sizes coarse and fine; first
cells 1e-3 .. 1e-5 of the chord. Every case has the physical curve group "wall" (what is
curved and what layers grow from), "farfield" where it has one, and the surface "fluid".

The layers family (issue 20; `--family layers`) is every gmsh_bl case again with homesh's
layers instead of Gmsh's field (mesher `layers`, `_hl_` in the name for `_bl_`): the same
geometry, sizes and stack, so the two layer meshers meet case by case.

The record of a case (`build` returns it): triangles, other 2D elements (must be 0; the quad
family's records count the linear quadrangles apart, `quads`, and only the rest as other), wall
edges, the requested and the measured first-cell height (over the wall nodes, the shortest
mesh edge to a node off the wall), and the largest turning angle of consecutive linear wall
edges, both over all wall nodes (`turn_all_deg`) and over the nodes where the CAD wall is
smooth (`turn_deg`: CAD corners such as a trailing edge, which curving keeps sharp, left out).
The issue's target worst minJ/maxJ is 0.9 where `turn_deg` < 30 degrees, 0.8 elsewhere.

Library use (the benchmark does this before each method, in a fresh Gmsh session):

    import corpus
    gmsh.initialize()
    record = corpus.build(corpus.case("naca0012_bl_1e-4"))

Command line (Debian's /usr/bin/python3, PYTHONPATH=build/python for homesh):

    corpus.py [--list] [--cases PATTERN] [--family default|quads|layers|all] [--out DIR]

writes DIR/NAME.msh (the linear mesh; see `write`) and DIR/NAME.brep
(its CAD) per case, and DIR/corpus.csv (the records); default DIR out/bench/corpus/meshes.
"""
import argparse
import csv
import fnmatch
import math
import multiprocessing as mp
import os
import sys
import time
from dataclasses import dataclass, field, replace

import gmsh
import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts", "examples"))
from naca7526 import interpolating_control_points  # noqa: E402 (the example's spline, shared)

WALL = "wall"


# ---------------------------------------------------------------- aerofoil sections

def method_options(method):
    """The homesh stage options of a benchmark method "NAME K=V:K=V" ({} for a bare "NAME"; the
    values stay text, which the stage parses as the CLI does): the --variant methods of
    curving_corpus.py and voronoi_corpus.py."""
    words = method.split(" ", 1)
    if len(words) == 1:
        return {}
    return dict(kv.split("=", 1) for kv in words[1].split(":"))


def in_child(target, args, timeout, timed_out):
    """target(conn, *args) in a forked child (a fresh Gmsh session each run): the row it sends
    on conn, or `timed_out` if none comes within `timeout` seconds (the child is killed)."""
    ctx = mp.get_context("fork")
    here, there = ctx.Pipe(duplex=False)
    proc = ctx.Process(target=target, args=(there, *args))
    proc.start()
    if here.poll(timeout):
        row = here.recv()
        proc.join()
        return row
    proc.kill()
    proc.join()
    return timed_out


def run_method(target, name, method, timeout):
    """target(conn, name, method) in a fresh child (in_child): the row it sends, or the row
    of a timeout (the benchmarks' methods on one corpus case each)."""
    return in_child(target, (name, method), timeout,
                    dict(case=name, method=method, status="timeout"))


def least_time(run, repeat, under=float("inf"), first=None):
    """run() `repeat` times in all (each a row with "status" and "seconds"; `first`, if given,
    the first run's row): the first row, with the seconds (and stage_seconds, where rows have
    them) of the fastest ok run if the first was ok (noise only adds time; the results are the
    same). The repeats stop once the first row is not ok or took `under` seconds or more."""
    row = run() if first is None else first
    for _ in range(repeat - 1):
        if row["status"] != "ok" or not row["seconds"] < under:
            break
        again = run()
        if again["status"] == "ok" and again["seconds"] < row["seconds"]:
            row["seconds"] = again["seconds"]
            if "stage_seconds" in again:
                row["stage_seconds"] = again["stage_seconds"]
    return row


def write_rows(path, fields, rows):
    """rows (dicts) as a CSV with the columns `fields`, written to a temporary file and renamed
    (a stopped run never leaves half a file)."""
    with open(path + ".tmp", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields)
        w.writeheader()
        w.writerows(rows)
    os.replace(path + ".tmp", path)


def naca_section(code):
    """(t, camber) of a NACA 4-digit (MPTT) or 5-digit (LPQTT, non-reflexed Q = 0) section:
    t the thickness over chord, camber(x) -> (yc, dyc/dx) on x in [0, 1]."""
    if len(code) == 4:
        m, p, t = int(code[0]) / 100, int(code[1]) / 10, int(code[2:]) / 100

        def camber(x):
            if m == 0:
                return np.zeros_like(x), np.zeros_like(x)
            front = x < p
            yc = np.where(front, m / p**2 * (2 * p * x - x**2),
                          m / (1 - p)**2 * (1 - 2 * p + 2 * p * x - x**2))
            dyc = np.where(front, 2 * m / p**2 * (p - x), 2 * m / (1 - p)**2 * (p - x))
            return yc, dyc
        return t, camber
    if len(code) == 5 and code[2] == "0":
        # Abbott & von Doenhoff's table of the 5-digit mean lines (design cl 0.3, L = 2):
        # position digit P -> (r, k1); k1 scales linearly with the design lift L.
        table = {1: (0.0580, 361.4), 2: (0.1260, 51.64), 3: (0.2025, 15.957),
                 4: (0.2900, 6.643), 5: (0.3910, 3.230)}
        r, k1 = table[int(code[1])]
        k1 *= int(code[0]) / 2
        t = int(code[3:]) / 100

        def camber(x):
            front = x < r
            yc = np.where(front, k1 / 6 * (x**3 - 3 * r * x**2 + r**2 * (3 - r) * x),
                          k1 * r**3 / 6 * (1 - x))
            dyc = np.where(front, k1 / 6 * (3 * x**2 - 6 * r * x + r**2 * (3 - r)),
                           -k1 * r**3 / 6 * np.ones_like(x))
            return yc, dyc
        return t, camber
    raise ValueError(f"NACA {code}: 4 digits MPTT or 5 digits LP0TT expected")


def surface_control_points(code, n, side):
    """Control points of one surface's clamped cubic B-spline with knots 0..n (the
    construction of scripts/examples/naca7526.py, for any mean line): it interpolates the
    cosine-spaced samples (closed trailing edge) at the knots, has the exact leading-edge
    derivative and a natural end at the trailing edge. side = +1 upper, -1 lower."""
    t, camber = naca_section(code)
    beta = np.arange(n + 1) * math.pi / n
    x = (1 - np.cos(beta)) / 2
    yt = 5 * t * (0.2969 * np.sqrt(x) - 0.1260 * x - 0.3516 * x**2 + 0.2843 * x**3
                  - 0.1036 * x**4)
    yc, dyc = camber(x)
    theta = np.arctan(dyc)
    q = np.column_stack([x - side * yt * np.sin(theta), yc + side * yt * np.cos(theta)])
    theta0 = float(theta[0])
    d_le = math.pi / n * 5 * t * 0.2969 / 2
    P = interpolating_control_points(
        q, q[0] + side * d_le / 3 * np.array([-math.sin(theta0), math.cos(theta0)]))
    return P, q


def placed(points, chord=1.0, pitch=0.0, at=(0.0, 0.0), pivot=(0.0, 0.0)):
    """points of a unit-chord section scaled by chord, turned nose-up by pitch degrees about
    the unit section's pivot, then moved so that the pivot lies at `at`."""
    a = -math.radians(pitch)
    R = np.array([[math.cos(a), -math.sin(a)], [math.sin(a), math.cos(a)]])
    return (np.asarray(points) - pivot) @ R.T * chord + at


def add_aerofoil(code, chord=1.0, pitch=0.0, at=(0.0, 0.0), pivot=(0.25, 0.0), n=60):
    """An aerofoil surface (occ), two B-splines meeting at the leading edge and at the sharp
    trailing edge; returns its surface tag."""
    occ = gmsh.model.occ
    ends, curves = None, []
    for side in (1, -1):
        P, _ = surface_control_points(code, n, side)
        P = placed(P, chord, pitch, at, pivot)
        if ends is None:
            ends = [occ.addPoint(*P[0], 0), occ.addPoint(*P[-1], 0)]
        inner = [occ.addPoint(x, y, 0) for x, y in P[1:-1]]
        curves.append(occ.addBSpline([ends[0]] + inner + [ends[1]]))
        occ.remove([(0, tag) for tag in inner])
    return occ.addPlaneSurface([occ.addCurveLoop(curves)])


def outline(code, chord=1.0, pitch=0.0, at=(0.0, 0.0), pivot=(0.25, 0.0), n=200):
    """Sampled closed outline of a placed aerofoil (for gaps between elements)."""
    up = surface_control_points(code, n, 1)[1]
    lo = surface_control_points(code, n, -1)[1]
    return placed(np.vstack([up, lo[::-1]]), chord, pitch, at, pivot)


def gap(a, b):
    return float(np.min(np.linalg.norm(a[:, None, :] - b[None, :, :], axis=2)))


def solve_offset(fixed, make, target, lo, hi):
    """The offset s in [lo, hi] at which gap(fixed, make(s)) = target, by bisection (the gap
    grows with s)."""
    for _ in range(60):
        s = (lo + hi) / 2
        lo, hi = (s, hi) if gap(fixed, make(s)) < target else (lo, s)
    return (lo + hi) / 2


# ---------------------------------------------------------------- shapes

def box(x0, y0, x1, y1):
    return gmsh.model.occ.addRectangle(x0, y0, 0, x1 - x0, y1 - y0)


def shape_aerofoil(code, aoa=0.0):
    return [add_aerofoil(code, pitch=aoa)], (-2, -2, 3, 2)


def shape_multi(flap_gap=0.02, slat=False, aoa=4.0):
    """Main NACA 2412 (chord 1) with a NACA 0009 flap (chord 0.3, deflected 25 degrees, its
    nose under the main trailing edge at flap_gap), and with slat a NACA 0012 slat (chord
    0.16, 30 degrees nose down) ahead of the main leading edge at 1.5 flap_gap."""
    main = dict(code="2412", chord=1.0, pitch=0.0, at=(0.0, 0.0), pivot=(0.0, 0.0))
    elements = [main]
    fixed = outline(**main)
    flap = lambda s: dict(code="0009", chord=0.3, pitch=25.0, at=(0.9, -0.02 - s),
                          pivot=(0.0, 0.0))
    s = solve_offset(fixed, lambda s: outline(**flap(s)), flap_gap, -0.05, 0.3)
    elements.append(flap(s))
    if slat:
        sl = lambda s: dict(code="0012", chord=0.16, pitch=-30.0, at=(0.03 - s, 0.02 - s / 2),
                            pivot=(1.0, 0.0))
        s = solve_offset(fixed, lambda s: outline(**sl(s)), 1.5 * flap_gap, -0.05, 0.4)
        elements.append(sl(s))
    bodies = [add_aerofoil(**e) for e in elements]
    gmsh.model.occ.rotate([(2, b) for b in bodies], 0.25, 0, 0, 0, 0, 1, -math.radians(aoa))
    return bodies, (-2, -2, 3, 2)


def shape_ellipses(centres, a, b=None, turn=0.0, domain=(-2, -2, 3, 2)):
    occ = gmsh.model.occ
    bodies = []
    for cx, cy in centres:
        d = occ.addDisk(cx, cy, 0, a, b or a)
        if turn:
            occ.rotate([(2, d)], cx, cy, 0, 0, 0, 1, math.radians(turn))
        bodies.append(d)
    return bodies, domain


def shape_star(seed, modes=6, amplitude=0.25, n=96):
    """A smooth star-shaped body: r(phi) = 0.5 (1 + sum_k a_k cos(k phi + c_k)), k = 2..modes,
    random a_k ~ amplitude / k (fixed seed), as a periodic spline through n points."""
    rng = np.random.default_rng(seed)
    k = np.arange(2, modes + 1)
    a = amplitude * rng.uniform(0.3, 1.0, len(k)) / k * rng.choice([-1, 1], len(k))
    c = rng.uniform(0, 2 * math.pi, len(k))
    occ = gmsh.model.occ
    phi = np.arange(n) * 2 * math.pi / n
    r = 0.5 * (1 + (a[None, :] * np.cos(k[None, :] * phi[:, None] + c[None, :])).sum(axis=1))
    pts = [occ.addPoint(0.5 + ri * math.cos(f), ri * math.sin(f), 0) for ri, f in zip(r, phi)]
    curve = occ.addSpline(pts + [pts[0]])
    occ.remove([(0, t) for t in pts[1:]])
    return [occ.addPlaneSurface([occ.addCurveLoop([curve])])], (-1.5, -2, 3, 2)


def shape_lshape(fillet=0.05, hole=0.2):
    """An L-shaped domain [0,2]x[0,1] u [0,1]x[0,2] whose re-entrant corner (1,1) is rounded
    by an arc of radius `fillet`, with a circular hole of radius `hole` at (0.5, 0.5). The
    walls: the arc, the two straight edges that meet it, and the hole."""
    occ = gmsh.model.occ
    r = fillet
    p = [occ.addPoint(x, y, 0) for x, y in
         [(0, 0), (2, 0), (2, 1), (1 + r, 1), (1, 1 + r), (1, 2), (0, 2)]]
    centre = occ.addPoint(1 + r, 1 + r, 0)
    lines = [occ.addLine(p[0], p[1]), occ.addLine(p[1], p[2]), occ.addLine(p[2], p[3]),
             occ.addCircleArc(p[3], centre, p[4]), occ.addLine(p[4], p[5]),
             occ.addLine(p[5], p[6]), occ.addLine(p[6], p[0])]
    occ.remove([(0, centre)])
    outer = occ.addCurveLoop(lines)
    disk = occ.addCircle(0.5, 0.5, 0, hole)
    surface = occ.addPlaneSurface([outer, occ.addCurveLoop([disk])])
    return surface, lines[2:5] + [disk]


def shape_plate_holes():
    """A 3 x 2 plate with a circle, a slanted 3:1 ellipse and a small circle cut out."""
    occ = gmsh.model.occ
    holes = [occ.addDisk(0.8, 1.0, 0, 0.3, 0.3), occ.addDisk(1.9, 0.7, 0, 0.36, 0.12),
             occ.addDisk(2.2, 1.45, 0, 0.08, 0.08)]
    occ.rotate([(2, holes[1])], 1.9, 0.7, 0, 0, 0, 1, math.radians(30))
    return holes, (0, 0, 3, 2)


def shape_ogrid(r=0.5, R=3.0):
    """An annulus r < |x - (0.5, 0)| < R cut by four radial lines at 45, 135, 225 and 315
    degrees into four four-sided patches (an O-grid for a transfinite mesh). Returns (surface
    tags, wall curves: the inner arcs, farfield curves: the outer arcs)."""
    occ = gmsh.model.occ
    centre = occ.addPoint(0.5, 0, 0)
    angles = [math.radians(45 + 90 * i) for i in range(4)]
    inner = [occ.addPoint(0.5 + r * math.cos(a), r * math.sin(a), 0) for a in angles]
    outer = [occ.addPoint(0.5 + R * math.cos(a), R * math.sin(a), 0) for a in angles]
    walls = [occ.addCircleArc(inner[i], centre, inner[(i + 1) % 4]) for i in range(4)]
    farfield = [occ.addCircleArc(outer[i], centre, outer[(i + 1) % 4]) for i in range(4)]
    radial = [occ.addLine(inner[i], outer[i]) for i in range(4)]   # from the wall outwards
    occ.remove([(0, centre)])
    # Each loop starts along its radial line outwards: counterclockwise, normal +z.
    surfaces = [occ.addPlaneSurface([occ.addCurveLoop(
        [radial[i], farfield[i], radial[(i + 1) % 4], walls[i]])]) for i in range(4)]
    return surfaces, walls, farfield


SHAPES = dict(aerofoil=shape_aerofoil, multi=shape_multi, ellipses=shape_ellipses,
              star=shape_star, lshape=shape_lshape, plate_holes=shape_plate_holes,
              ogrid=shape_ogrid)


# ---------------------------------------------------------------- cases

@dataclass
class Case:
    name: str
    shape: str
    args: dict
    mesher: str            # gmsh_bl | layers | none | voronoi | gmsh_bl_quads | gmsh_quads
    #                        | gmsh_transfinite
    h_wall: float          # mesh size at the wall
    h_far: float = 0.3     # mesh size far from it
    first: float = 0.0     # first-cell height (0: no layers)
    n: int = 0             # number of layers
    ratio: float = 1.2
    fan: int = 5           # fan elements at sharp points (gmsh_bl) / normals per fan (layers)
    tags: list = field(default_factory=list)

    @property
    def quads(self):
        """Whether the case is of the quad family (its mesh may hold quadrangles)."""
        return self.mesher in QUAD_MESHERS

    @property
    def thickness(self):
        return self.first * (self.ratio ** self.n - 1) / (self.ratio - 1) if self.n else 0.0


def layers_for(first, ratio, total):
    """The number of layers of a geometric stack from `first` reaching about `total`."""
    return max(3, int(round(math.log(1 + total * (ratio - 1) / first) / math.log(ratio))))


def _cases():
    C = []

    def add(name, shape, args, mesher, h_wall, first=0.0, ratio=1.2, total=None, **kw):
        n = layers_for(first, ratio, total if total else h_wall) if first else 0
        C.append(Case(name, shape, args, mesher, h_wall, first=first, n=n, ratio=ratio, **kw))

    A = "aerofoil"
    # Single aerofoils: Gmsh's BoundaryLayer field.
    add("naca0012_bl_1e-3_coarse", A, dict(code="0012"), "gmsh_bl", 0.04, 1e-3, 1.2)
    add("naca0012_bl_1e-4", A, dict(code="0012"), "gmsh_bl", 0.02, 1e-4, 1.2)
    add("naca0012_bl_1e-5_fine", A, dict(code="0012"), "gmsh_bl", 0.01, 1e-5, 1.3)
    add("naca0006_bl_1e-4", A, dict(code="0006"), "gmsh_bl", 0.02, 1e-4, 1.15)
    add("naca0024_bl_1e-3", A, dict(code="0024"), "gmsh_bl", 0.03, 1e-3, 1.3)
    add("naca4412_a8_bl_1e-4", A, dict(code="4412", aoa=8), "gmsh_bl", 0.02, 1e-4, 1.2)
    add("naca2412_a-4_bl_1e-5", A, dict(code="2412", aoa=-4), "gmsh_bl", 0.02, 1e-5, 1.3)
    add("naca6409_bl_1e-4", A, dict(code="6409"), "gmsh_bl", 0.015, 1e-4, 1.2)
    add("naca9415_a5_bl_1e-3", A, dict(code="9415", aoa=5), "gmsh_bl", 0.03, 1e-3, 1.15)
    add("naca23012_bl_1e-4", A, dict(code="23012"), "gmsh_bl", 0.02, 1e-4, 1.2)
    add("naca23015_a12_bl_1e-5", A, dict(code="23015", aoa=12), "gmsh_bl", 0.015, 1e-5, 1.25)
    add("naca24021_bl_1e-3_coarse", A, dict(code="24021"), "gmsh_bl", 0.05, 1e-3, 1.2)
    # Single aerofoils: homesh's layers, no layers, voronoi.
    add("naca0012_layers_1e-3", A, dict(code="0012"), "layers", 0.02, 1e-3, 1.2)
    add("naca4412_a8_layers_1e-4", A, dict(code="4412", aoa=8), "layers", 0.02, 1e-4, 1.25)
    add("naca23012_layers_1e-4_coarse", A, dict(code="23012"), "layers", 0.04, 1e-4, 1.3)
    add("naca0012_nolayer_coarse", A, dict(code="0012"), "none", 0.05)
    add("naca4412_a8_nolayer_fine", A, dict(code="4412", aoa=8), "none", 0.01)
    add("naca0012_voronoi", A, dict(code="0012"), "voronoi", 0.02)
    add("naca23015_voronoi_coarse", A, dict(code="23015"), "voronoi", 0.04)
    # Multi-element.
    M = "multi"
    add("flap_gap02_bl_1e-4", M, dict(flap_gap=0.02), "gmsh_bl", 0.015, 1e-4, 1.2, total=0.005)
    add("flap_gap01_bl_1e-5", M, dict(flap_gap=0.01), "gmsh_bl", 0.01, 1e-5, 1.3, total=0.003)
    add("slat_flap_bl_1e-4", M, dict(flap_gap=0.015, slat=True), "gmsh_bl", 0.01, 1e-4, 1.2,
        total=0.004)
    add("flap_gap02_layers_1e-4", M, dict(flap_gap=0.02), "layers", 0.015, 1e-4, 1.2,
        total=0.005)
    add("flap_gap02_nolayer", M, dict(flap_gap=0.02), "none", 0.015)
    add("slat_flap_nolayer_fine", M, dict(flap_gap=0.015, slat=True), "none", 0.006)
    add("slat_flap_voronoi", M, dict(flap_gap=0.015, slat=True), "voronoi", 0.01)
    # Circles and ellipses.
    E = "ellipses"
    one = dict(centres=[(0.5, 0)], a=0.5)
    row = dict(centres=[(x, y) for x in (0, 0.55, 1.1) for y in (-0.3, 0.3)], a=0.2,
               domain=(-1.5, -1.5, 2.5, 1.5))
    add("circle_bl_1e-3_coarse", E, one, "gmsh_bl", 0.1, 1e-3, 1.3)
    add("circle_bl_1e-5_fine", E, one, "gmsh_bl", 0.015, 1e-5, 1.25)
    add("ellipse4_a10_bl_1e-4", E, dict(centres=[(0.5, 0)], a=0.5, b=0.125, turn=-10),
        "gmsh_bl", 0.02, 1e-4, 1.2)
    add("ellipse10_bl_1e-4", E, dict(centres=[(0.5, 0)], a=0.5, b=0.05), "gmsh_bl", 0.015,
        1e-4, 1.2)
    add("circles6_bl_1e-3", E, row, "gmsh_bl", 0.03, 1e-3, 1.2, total=0.02)
    add("circles6_layers_1e-3", E, row, "layers", 0.03, 1e-3, 1.2, total=0.02)
    add("ellipse4_a10_layers_1e-4", E, dict(centres=[(0.5, 0)], a=0.5, b=0.125, turn=-10),
        "layers", 0.02, 1e-4, 1.25)
    add("circle_nolayer_coarse", E, one, "none", 0.3)
    add("circles6_nolayer", E, row, "none", 0.04)
    add("circle_voronoi", E, one, "voronoi", 0.05)
    add("ellipses_voronoi", E, dict(centres=[(0, 0), (1.2, 0.2)], a=0.4, b=0.15, turn=20),
        "voronoi", 0.03)
    # Smooth random star-shaped bodies.
    S = "star"
    add("star1_bl_1e-3", S, dict(seed=1), "gmsh_bl", 0.03, 1e-3, 1.2)
    add("star2_bl_1e-4_fine", S, dict(seed=2, amplitude=0.35), "gmsh_bl", 0.01, 1e-4, 1.2)
    add("star3_layers_1e-3", S, dict(seed=3), "layers", 0.03, 1e-3, 1.2)
    add("star4_nolayer_coarse", S, dict(seed=4, amplitude=0.35), "none", 0.08)
    add("star5_voronoi", S, dict(seed=5), "voronoi", 0.03)
    # Re-entrant corner, holes.
    add("lshape_r05_bl_1e-3", "lshape", dict(fillet=0.05), "gmsh_bl", 0.03, 1e-3, 1.2,
        total=0.01)
    add("lshape_r02_layers_1e-4", "lshape", dict(fillet=0.02), "layers", 0.03, 1e-4, 1.3,
        total=0.01)
    add("lshape_r02_nolayer", "lshape", dict(fillet=0.02), "none", 0.05)
    add("lshape_r05_voronoi", "lshape", dict(fillet=0.05), "voronoi", 0.04)
    add("plate_holes_bl_1e-4", "plate_holes", {}, "gmsh_bl", 0.02, 1e-4, 1.2)
    add("plate_holes_layers_1e-3", "plate_holes", {}, "layers", 0.03, 1e-3, 1.2)
    add("plate_holes_nolayer_coarse", "plate_holes", {}, "none", 0.1)
    return C


QUAD_MESHERS = ("gmsh_bl_quads", "gmsh_quads", "gmsh_transfinite")


def _quad_cases():
    """The quad family (issue 21): Gmsh's quad boundary layers on a subset of the shapes
    above (mixed meshes), and a few all-quad meshes."""
    C = []

    def add(name, shape, args, mesher, h_wall, first=0.0, ratio=1.2, total=None, **kw):
        n = layers_for(first, ratio, total if total else h_wall) if first else 0
        C.append(Case(name, shape, args, mesher, h_wall, first=first, n=n, ratio=ratio, **kw))

    A, E, Q = "aerofoil", "ellipses", "gmsh_bl_quads"
    row = dict(centres=[(x, y) for x in (0, 0.55, 1.1) for y in (-0.3, 0.3)], a=0.2,
               domain=(-1.5, -1.5, 2.5, 1.5))
    # Mixed: quads in the layers, triangles outside and in the trailing-edge fans.
    add("naca0012_blq_1e-3_coarse", A, dict(code="0012"), Q, 0.04, 1e-3, 1.2)
    add("naca0012_blq_1e-4_fine", A, dict(code="0012"), Q, 0.01, 1e-4, 1.2)
    add("naca4412_a8_blq_1e-4", A, dict(code="4412", aoa=8), Q, 0.02, 1e-4, 1.2)
    add("naca23012_blq_1e-5", A, dict(code="23012"), Q, 0.015, 1e-5, 1.3)
    add("flap_gap02_blq_1e-4", "multi", dict(flap_gap=0.02), Q, 0.015, 1e-4, 1.2,
        total=0.005)
    add("circle_blq_1e-3_coarse", E, dict(centres=[(0.5, 0)], a=0.5), Q, 0.1, 1e-3, 1.3)
    add("ellipse4_a10_blq_1e-4", E, dict(centres=[(0.5, 0)], a=0.5, b=0.125, turn=-10), Q,
        0.02, 1e-4, 1.2)
    add("circles6_blq_1e-3", E, row, Q, 0.03, 1e-3, 1.2, total=0.02)
    add("star1_blq_1e-3", "star", dict(seed=1), Q, 0.03, 1e-3, 1.2)
    add("star2_blq_1e-4_fine", "star", dict(seed=2, amplitude=0.35), Q, 0.01, 1e-4, 1.2)
    add("plate_holes_blq_1e-4", "plate_holes", {}, Q, 0.02, 1e-4, 1.2)
    # All quadrilaterals.
    add("plate_holes_quads", "plate_holes", {}, "gmsh_quads", 0.05)
    add("circle_blq_1e-3_allquads", E, dict(centres=[(0.5, 0)], a=0.5), "gmsh_quads", 0.05,
        1e-3, 1.2)
    add("star1_blq_1e-3_allquads", "star", dict(seed=1), "gmsh_quads", 0.03, 1e-3, 1.2)
    add("circle_ogrid_1e-3", "ogrid", {}, "gmsh_transfinite", 0.05, 1e-3, 1.15, total=2.5)
    return C


def _layer_twins(cases):
    """The layers family (issue 20): every gmsh_bl case of the triangle corpus again, its
    layers made by homesh instead (mesher `layers`, the same CAD, sizes, first cell, ratio,
    count and fans), named with `_hl_` for `_bl_`: Gmsh's BoundaryLayer field and homesh's
    layers stage on the same geometries and stacks."""
    return [replace(c, name=c.name.replace("_bl_", "_hl_"), mesher="layers")
            for c in cases if c.mesher == "gmsh_bl"]


CASES = _cases()
QUAD_CASES = _quad_cases()
LAYER_CASES = _layer_twins(CASES)
FAMILIES = dict(default=CASES, quads=QUAD_CASES, layers=LAYER_CASES,
                all=CASES + QUAD_CASES + LAYER_CASES)


def twin(c):
    """The gmsh_bl case a layers-family case was made from (by name), or None."""
    name = c.name.replace("_hl_", "_bl_")
    return next((b for b in CASES if b.name == name and b.mesher == "gmsh_bl"), None)


def case(name):
    for c in CASES + QUAD_CASES + LAYER_CASES:
        if c.name == name:
            return c
    raise KeyError(f"no corpus case '{name}'")


def select(patterns=None, family="default"):
    """The cases of `family` (default: the triangle corpus; quads: the quad family; all)
    whose names match any of the comma-separated shell patterns (substrings match too), in
    the order of the patterns (all the family's cases, in corpus order, if none)."""
    cases = FAMILIES[family]
    if not patterns:
        return list(cases)
    pats = [p if any(ch in p for ch in "*?[") else f"*{p}*" for p in patterns.split(",")]
    chosen = []
    for p in pats:
        chosen += [c for c in cases if fnmatch.fnmatch(c.name, p) and c not in chosen]
    return chosen


# ---------------------------------------------------------------- building

def _cad(c):
    """The case's CAD; returns (surface tags, wall curve tags, farfield curve tags)."""
    occ = gmsh.model.occ
    made = SHAPES[c.shape](**c.args)
    if c.shape == "lshape":
        surface, walls = made
        occ.synchronize()
        boundary = [t for _, t in gmsh.model.getBoundary([(2, surface)], oriented=False)]
        return [surface], walls, [t for t in boundary if t not in walls]
    if c.shape == "ogrid":
        occ.synchronize()
        return made
    bodies, domain = made
    fluid, _ = occ.cut([(2, box(*domain))], [(2, b) for b in bodies])
    occ.synchronize()
    x0, y0, x1, y1 = domain
    walls, farfield = [], []
    for _, t in gmsh.model.getBoundary(fluid, oriented=False):
        bx0, by0, _, bx1, by1, _ = gmsh.model.getBoundingBox(1, abs(t))
        on_box = (min(abs(bx0 - x0), abs(bx1 - x1)) < 1e-6 and abs(bx1 - bx0) < 1e-6) or \
                 (min(abs(by0 - y0), abs(by1 - y1)) < 1e-6 and abs(by1 - by0) < 1e-6)
        (farfield if on_box else walls).append(abs(t))
    return [t for _, t in fluid], walls, farfield


def sharp_points(walls, limit=60.0):
    """Wall CAD points where two wall curves meet at a wedge narrower than `limit` degrees
    (a sharp trailing edge): the points that get a fan."""
    ends = {}
    for c in walls:
        lo, hi = gmsh.model.getParametrizationBounds(1, c)
        b = gmsh.model.getBoundary([(1, c)], oriented=True, combined=False)
        if len(b) != 2:
            continue
        for (_, p), u, sign in [(b[0], lo[0], 1.0), (b[1], hi[0], -1.0)]:
            d = np.array(gmsh.model.getDerivative(1, c, [u])[:2]) * sign
            ends.setdefault(abs(p), []).append(d / np.linalg.norm(d))
    sharp = []
    for p, ds in ends.items():
        if len(ds) == 2:
            angle = math.degrees(math.acos(np.clip(np.dot(ds[0], ds[1]), -1, 1)))
            if angle < limit:
                sharp.append(p)
    return sorted(sharp)


def smooth_points(walls, limit=1.0):
    """Wall CAD points where two wall curves meet with tangents within `limit` degrees (or a
    closed curve meets itself): the wall is smooth there."""
    ends = {}
    for c in walls:
        lo, hi = gmsh.model.getParametrizationBounds(1, c)
        b = gmsh.model.getBoundary([(1, c)], oriented=True, combined=False)
        if len(b) == 0:
            continue
        if len(b) == 1 or abs(b[0][1]) == abs(b[-1][1]):   # closed curve (circle, star)
            ends.setdefault(abs(b[0][1]), [])
        for (_, p), u, sign in [(b[0], lo[0], 1.0), (b[-1], hi[0], -1.0)]:
            d = np.array(gmsh.model.getDerivative(1, c, [u])[:2]) * sign
            ends.setdefault(abs(p), []).append(d / np.linalg.norm(d))
    smooth = set()
    for p, ds in ends.items():
        if len(ds) == 2 and math.degrees(math.acos(np.clip(-np.dot(ds[0], ds[1]), -1, 1))) < limit:
            smooth.add(p)
    return smooth


def _sizes(c, walls):
    f = gmsh.model.mesh.field
    d = f.add("Distance")
    f.setNumbers(d, "CurvesList", walls)
    f.setNumber(d, "NumPointsPerCurve", 400)
    t = f.add("Threshold")
    for name, value in [("InField", d), ("SizeMin", c.h_wall), ("SizeMax", c.h_far),
                        ("DistMin", max(c.thickness, 0.5 * c.h_wall)), ("DistMax", 1.2)]:
        f.setNumber(t, name, value)
    f.setAsBackgroundMesh(t)
    for name, value in [("Mesh.MeshSizeFromPoints", 0), ("Mesh.MeshSizeFromCurvature", 0),
                        ("Mesh.MeshSizeExtendFromBoundary", 0), ("Mesh.Algorithm", 6)]:
        gmsh.option.setNumber(name, value)


def unmeshed(c):
    """Case c's CAD as a new model of the current Gmsh session, its walls, far field and
    surfaces in the physical groups WALL, "farfield" and "fluid", its size field set, no mesh
    (what the meshers are compared on). Returns (surfaces, walls, farfield)."""
    gmsh.model.add(c.name)
    surfaces, walls, farfield = _cad(c)
    for dim, tags, group in [(1, walls, WALL), (1, farfield, "farfield"), (2, surfaces, "fluid")]:
        if tags:
            gmsh.model.setPhysicalName(dim, gmsh.model.addPhysicalGroup(dim, tags), group)
    _sizes(c, walls)
    return surfaces, walls, farfield


def _gmsh_bl(c, walls, quads=False):
    """Gmsh's BoundaryLayer field on the walls (Quads = 1 with quads), then generate(2)."""
    f = gmsh.model.mesh.field
    b = f.add("BoundaryLayer")
    f.setNumbers(b, "CurvesList", walls)
    f.setNumber(b, "Size", c.first)
    f.setNumber(b, "Ratio", c.ratio)
    # Gmsh adds layers while their total stays below Thickness: a hair above the n-th.
    f.setNumber(b, "Thickness", c.thickness * (1 + 1e-6))
    f.setNumber(b, "Quads", 1 if quads else 0)
    fans = sharp_points(walls)
    if fans:
        f.setNumbers(b, "FanPointsList", fans)
        gmsh.option.setNumber("Mesh.BoundaryLayerFanElements", c.fan - 1)
    f.setAsBoundaryLayer(b)
    gmsh.model.mesh.generate(2)


def _transfinite(c, surfaces, walls, farfield):
    """A structured quad mesh of an O-grid (shape_ogrid): nodes about h_wall apart along the
    wall arcs (as many on the outer arcs), c.n cells on every radial line in a geometric
    progression of c.ratio from the wall; transfinite surfaces, recombined."""
    m = gmsh.model.mesh
    arc = gmsh.model.occ.getMass(1, walls[0])
    n_arc = max(2, int(round(arc / c.h_wall)) + 1)
    for t in walls + farfield:
        m.setTransfiniteCurve(t, n_arc)
    for _, t in gmsh.model.getBoundary([(2, s) for s in surfaces], combined=False,
                                       oriented=False):
        if abs(t) not in walls + farfield:
            m.setTransfiniteCurve(abs(t), c.n + 1, "Progression", c.ratio)
    for s in surfaces:
        m.setTransfiniteSurface(s)
        m.setRecombine(2, s)
    m.generate(2)


def build(c, quiet=True):
    """Recreate case c (a Case or its name) in the current Gmsh session: clear the model, make
    the CAD and the linear mesh. Returns the case's record (a dict, see `record`)."""
    if isinstance(c, str):
        c = case(c)
    gmsh.clear()
    surfaces, walls, farfield = unmeshed(c)
    start, layers_seconds = time.perf_counter(), None
    if c.mesher == "gmsh_bl":
        _gmsh_bl(c, walls)
    elif c.mesher == "gmsh_bl_quads":
        _gmsh_bl(c, walls, quads=True)
    elif c.mesher == "gmsh_transfinite":
        _transfinite(c, surfaces, walls, farfield)
    elif c.mesher == "gmsh_quads":
        gmsh.option.setNumber("Mesh.Algorithm", 6)
        gmsh.option.setNumber("Mesh.RecombinationAlgorithm", 1)
        gmsh.option.setNumber("Mesh.RecombineAll", 1)
        if c.n:
            _gmsh_bl(c, walls, quads=True)
        else:
            gmsh.model.mesh.generate(2)
    elif c.mesher in ("layers", "none"):
        gmsh.model.mesh.generate(2)
        if c.mesher == "layers":
            import homesh
            homesh.set_quiet(quiet)
            opts = dict(walls=WALL, n=c.n, first=c.first, ratio=c.ratio)
            if sharp_points(walls):
                opts.update(normals="multi", fan=c.fan, fan_angle=320)
            t = time.perf_counter()
            homesh.layers(**opts)
            layers_seconds = time.perf_counter() - t
    elif c.mesher == "voronoi":
        import homesh
        homesh.set_quiet(quiet)
        homesh.voronoi()
    else:
        raise ValueError(f"case {c.name}: unknown mesher {c.mesher}")
    seconds = time.perf_counter() - start
    rec = record(c, walls)
    rec.update(mesh_seconds=seconds, layers_seconds=layers_seconds)
    return rec


def load(c, msh):
    """Recreate case c's CAD in the current Gmsh session and merge its linear mesh from `msh`
    (a file `write` made): the same model as `build`, without meshing again. Returns the
    case's record."""
    if isinstance(c, str):
        c = case(c)
    gmsh.clear()
    gmsh.model.add(c.name)
    _, walls, _ = _cad(c)
    gmsh.merge(msh)
    names = {gmsh.model.getPhysicalName(d, t) for d, t in gmsh.model.getPhysicalGroups(1)}
    if WALL not in names:
        raise RuntimeError(f"{msh}: no physical curve '{WALL}'")
    return record(c, walls)


def write(c, path):
    """Build case c and write its linear mesh to path (.msh) and its CAD beside it (.brep).
    Returns the record. Gmsh's meshes are saved with their nodes' parametric coordinates
    (merged back by `load`, the same model to 1e-11); homesh's layers and voronoi meshes
    without: homesh gives the nodes it makes on boundary curves none (an L-shape's layers
    ending on the far-field lines), and a file saved with some merges broken (setOrder left
    every triangle invalid); without any, `load` gives what `build` does (checked: setOrder
    identical, homesh's curve within 1e-5)."""
    rec = build(c)
    gmsh.option.setNumber("Mesh.SaveParametric",
                          1 if c.mesher in ("gmsh_bl", "none") + QUAD_MESHERS else 0)
    gmsh.write(path)
    gmsh.write(os.path.splitext(path)[0] + ".brep")
    return rec


# ---------------------------------------------------------------- records

def _coords():
    tags, xyz, _ = gmsh.model.mesh.getNodes()
    return dict(zip(tags.astype(int).tolist(), xyz.reshape(-1, 3)[:, :2]))


def wall_edges(walls):
    """The linear wall edges (node tag pairs) of the wall curves."""
    edges = []
    for c in walls:
        for t, nodes in zip(*gmsh.model.mesh.getElements(1, c)[::2]):
            k = gmsh.model.mesh.getElementProperties(t)[3]
            n = np.asarray(nodes, dtype=int).reshape(-1, k)
            edges += [(int(a), int(b)) for a, b in n[:, :2]]
    return edges


def radius_ratios(corners):
    """Eq 4.17 per triangle (corners #T x 3 x 2): Q = 8 (s-a)(s-b)(s-c) / (a b c), s the half
    perimeter; 1 equilateral, 0 degenerate."""
    a = np.linalg.norm(corners[:, 1] - corners[:, 2], axis=1)
    b = np.linalg.norm(corners[:, 2] - corners[:, 0], axis=1)
    c = np.linalg.norm(corners[:, 0] - corners[:, 1], axis=1)
    s = (a + b + c) / 2
    return 8 * (s - a) * (s - b) * (s - c) / (a * b * c)


def record(c, walls):
    """Counts, the wall's turning angles and the first-cell height of the current model."""
    x = _coords()
    triangles, quads, others = 0, 0, 0
    cells = []   # the linear elements' corner node tags, one array per element type
    for t, tags, nodes in zip(*gmsh.model.mesh.getElements(2)):
        name, _, order, k, _, _ = gmsh.model.mesh.getElementProperties(t)
        if name.startswith("Triangle") and order == 1:
            triangles += len(tags)
            cells.append(np.asarray(nodes, dtype=int).reshape(-1, 3))
        elif c.quads and name.startswith("Quadrilateral") and order == 1:
            quads += len(tags)
            cells.append(np.asarray(nodes, dtype=int).reshape(-1, 4))
        else:
            others += len(tags)
    edges = wall_edges(walls)
    # Turning angle at each wall node shared by two wall edges.
    incident = {}
    for a, b in edges:
        incident.setdefault(a, []).append(b)
        incident.setdefault(b, []).append(a)
    smooth = smooth_points(walls)
    corner_nodes = set()
    for _, p in gmsh.model.getEntities(0):
        nodes = gmsh.model.mesh.getNodes(0, p)[0]
        if len(nodes) and p not in smooth:
            corner_nodes.add(int(nodes[0]))
    turn_all, turn_smooth = 0.0, 0.0
    for v, nb in incident.items():
        if len(nb) != 2:
            continue
        u, w = x[v] - x[nb[0]], x[nb[1]] - x[v]
        a = math.degrees(math.acos(np.clip(np.dot(u, w) / np.linalg.norm(u) / np.linalg.norm(w),
                                           -1, 1)))
        turn_all = max(turn_all, a)
        if v not in corner_nodes:
            turn_smooth = max(turn_smooth, a)
    # First-cell height: over the wall nodes, the shortest mesh edge to a node off the wall.
    on_wall = set(incident)
    heights = {}
    for T in cells:
        k = T.shape[1]
        for i, j in [(i, (i + 1) % k) for i in range(k)]:
            for a, b in zip(T[:, i].tolist(), T[:, j].tolist()):
                for v, o in ((a, b), (b, a)):
                    if v in on_wall and o not in on_wall:
                        h = float(np.linalg.norm(x[v] - x[o]))
                        if h < heights.get(v, math.inf):
                            heights[v] = h
    h = np.array(list(heights.values())) if heights else np.array([math.nan])
    # Worst radius ratio (thesis Eq 4.17) of the linear triangles.
    tri = [T for T in cells if T.shape[1] == 3]
    rr = math.nan
    if tri:
        rr = float(radius_ratios(np.concatenate(
            [np.array([x[v] for v in T.ravel()]).reshape(-1, 3, 2) for T in tri])).min())
    rec = dict(case=c.name, shape=c.shape, mesher=c.mesher, h_wall=c.h_wall, first=c.first,
               layers=c.n, ratio=c.ratio if c.n else "", triangles=triangles, other_2d=others,
               wall_edges=len(edges), first_min=float(h.min()), first_median=float(np.median(h)),
               turn_deg=round(turn_smooth, 2), turn_all_deg=round(turn_all, 2),
               target=0.9 if turn_smooth < 30 else 0.8, worst_radius_ratio=rr)
    if c.quads:   # the quad family: its quads counted beside the triangles
        rec = {k: v for key, value in rec.items()
               for k, v in ([(key, value), ("quads", quads)] if key == "triangles"
                            else [(key, value)])}
    return rec


# ---------------------------------------------------------------- command line

def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--list", action="store_true", help="list the cases and exit")
    ap.add_argument("--cases", help="comma-separated name patterns (substring or glob)")
    ap.add_argument("--family", choices=sorted(FAMILIES), default="default",
                    help="default: the triangle corpus; quads: the quad family (issue 21); "
                         "layers: the gmsh_bl cases with homesh's layers (issue 20); all")
    ap.add_argument("--out", default=os.path.join(ROOT, "out", "bench", "corpus", "meshes"))
    args = ap.parse_args(argv)
    cases = select(args.cases, args.family)
    if args.list:
        for c in cases:
            print(f"{c.name:<30} {c.shape:<11} {c.mesher:<8} h_wall {c.h_wall:<6g} "
                  f"first {c.first:<6g} n {c.n:<3} ratio {c.ratio:g}")
        return 0
    os.makedirs(args.out, exist_ok=True)
    rows = []
    for c in cases:
        gmsh.initialize()
        gmsh.option.setNumber("General.Terminal", 0)
        rec = write(c, os.path.join(args.out, c.name + ".msh"))
        gmsh.finalize()
        rows.append(rec)
        print(" ".join(f"{k}={v:.4g}" if isinstance(v, float) else f"{k}={v}"
                       for k, v in rec.items()), flush=True)
    with open(os.path.join(args.out, "corpus.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(dict.fromkeys(k for r in rows for k in r)),
                           restval="")
        w.writeheader()
        w.writerows(rows)
    print(f"{len(rows)} cases -> {args.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
