#!/usr/bin/python3
"""Poisson on the plate with a hole, solved by DOLFINx on meshes curved by homesh.

Why curve: a finite element of degree p converges in L2 at the rate h^(p+1) only
if the mesh follows the curved wall to the same order (isoparametric elements,
Ciarlet & Raviart 1972; Lenoir 1986). On straight-sided boundary elements the
wall is off by O(h^2), and so are the Dirichlet data there: the L2 rate stalls
at 2 whatever p is. This script measures both on the same Gmsh meshes:

  -lap u = f in the plate [-1, 1]^2 minus the disk r < R (geo/plate_hole.geo),
  u = g on the boundary,   exact solution u = sin(2x) e^y, f = 3 sin(2x) e^y.

The Dirichlet data are given on the true boundary only, as a wall's data are: on
the outer edges (straight, exact in any mesh) g = u; on the hole g is a function
of the polar angle, g(theta) = u(R cos theta, R sin theta), carried to a
discrete boundary node along the ray through it. On homesh's curved mesh the
hole's nodes lie on the circle and g = u there; on the straight-sided mesh the
nodes inside an edge lie O(h^2) off the circle, which is the geometric error.

Each mesh: Gmsh meshes geo/plate_hole.geo with Mesh.MeshSizeFactor = s, then
homesh.curve(p=P) (boundary on the CAD, interior by the elastic analogy) or
homesh.order(p=P) (straight-sided), read by dolfinx.io.gmshio.model_to_mesh.
FE degree = geometry order P. DOLFINx 0.5's gmshio reads triangles of order
1, 2 and 3 only (Gmsh types 2, 9, 21; cpp.io.perm_gmsh has no 15-node triangle).

--cells quads: the same study on quadrilaterals (issue 21): Gmsh's mesh recombined
(Mesh.RecombineAll, Blossom: all quadrilaterals on this plate), then curved or
raised by homesh the same way, solved with the tensor-product Lagrange element Q_P.
DOLFINx 0.5's gmshio reads quadrilaterals of order 1 and 2 (Gmsh types 3, 10) and
one cell type per mesh, so P = 1, 2.

--cells tetrahedra: the study in 3D (issue 24): -lap u = f outside the unit ball in the
box [-1.5, 1.5]^3 (geo/ball_in_box.geo's domain, the box closer), the same u (it does not vary in z), u = g on
the box's faces and g(x) = u(x / |x|) on the sphere; Gmsh's tetrahedra of sizes SIZES,
curved by homesh (curve) or raised straight (order). DOLFINx 0.5's gmshio reads
tetrahedra of order 1 and 2 (Gmsh types 4, 11), so P = 1, 2; h = (6 sqrt 2 |Omega_h| /
tetrahedra)^(1/3), the edge of a regular tetrahedron of the mean volume.

Usage: dolfinx_poisson.py [--cells triangles|quads|tetrahedra] [--plot docs/dolfinx_convergence.png]
Prints one line per (order, mesh, factor): h, L2 error, rate.
"""
import argparse
import logging
import math
import os
import sys

import gmsh
import numpy as np
import ufl
from mpi4py import MPI

import dolfinx
import dolfinx.fem.petsc
import dolfinx.io.gmshio
import homesh

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
PLATE = os.path.join(ROOT, "geo", "plate_hole.geo")
RADIUS = 0.5  # geo/plate_hole.geo's default Plate/Radius
ORDERS = (1, 2, 3)  # the triangle orders DOLFINx 0.5's gmshio reads
QUAD_ORDERS = (1, 2)  # and its quadrilateral orders
FACTORS = (2.0, 1.0, 0.5)  # Mesh.MeshSizeFactor: LcHole = 0.1 s, LcFarfield = 0.2 s
TET_ORDERS = (1, 2)  # the tetrahedron orders DOLFINx 0.5's gmshio reads
SIZES = (0.5, 0.35, 0.25, 0.18)  # Mesh.MeshSizeMax of the ball in a box
BOX = 1.5  # the box's half-width: close to the ball, so the wall's error shows


def exact(x, y):
    """u = sin(2x) e^y for numpy arrays or UFL expressions."""
    if isinstance(x, np.ndarray):
        return np.sin(2 * x) * np.exp(y)
    return ufl.sin(2 * x) * ufl.exp(y)


def plate_mesh(order, factor, curved, quads=False):
    """Gmsh model of the plate at order `order`: curved by homesh, or straight-sided;
    all quadrilaterals if `quads`."""
    gmsh.clear()
    gmsh.option.setNumber("Mesh.MeshSizeFactor", factor)
    gmsh.open(PLATE)
    gmsh.option.setNumber("Mesh.RecombineAll", 1 if quads else 0)
    gmsh.option.setNumber("Mesh.RecombinationAlgorithm", 1)
    gmsh.model.mesh.generate(2)
    if quads:
        assert len(gmsh.model.mesh.getElementsByType(2)[0]) == 0, "recombination left triangles"
    if order > 1:
        (homesh.curve if curved else homesh.order)(p=order)


def ball_mesh(order, size, curved):
    """Gmsh model of the unit ball cut out of [-BOX, BOX]^3 at order `order`: curved by homesh,
    or straight-sided; physical groups "fluid", "box" and "ball"."""
    gmsh.clear()
    gmsh.model.occ.addBox(-BOX, -BOX, -BOX, 2 * BOX, 2 * BOX, 2 * BOX, 1)
    gmsh.model.occ.addSphere(0, 0, 0, 1, 2)
    out, _ = gmsh.model.occ.cut([(3, 1)], [(3, 2)])
    gmsh.model.occ.synchronize()
    surfaces = [abs(t) for _, t in gmsh.model.getBoundary(out, oriented=False)]
    ball = [t for t in surfaces if gmsh.model.getType(2, t) == "Sphere"]
    gmsh.model.addPhysicalGroup(3, [out[0][1]], 1)
    gmsh.model.setPhysicalName(3, 1, "fluid")
    gmsh.model.addPhysicalGroup(2, [t for t in surfaces if t not in ball], 2)
    gmsh.model.setPhysicalName(2, 2, "box")
    gmsh.model.addPhysicalGroup(2, ball, 3)
    gmsh.model.setPhysicalName(2, 3, "ball")
    gmsh.option.setNumber("General.NumThreads", 1)
    gmsh.option.setNumber("Mesh.MeshSizeMax", size)
    # Options outlive gmsh.clear: the plate's studies set these.
    gmsh.option.setNumber("Mesh.RecombineAll", 0)
    gmsh.option.setNumber("Mesh.MeshSizeFactor", 1.0)
    gmsh.model.mesh.generate(3)
    if order > 1:
        (homesh.curve if curved else homesh.order)(p=order)


def solve_ball(order, size, curved):
    """L2 error and h of the degree-`order` solution outside the ball."""
    ball_mesh(order, size, curved)
    groups = {gmsh.model.getPhysicalName(d, t): t for d, t in gmsh.model.getPhysicalGroups(2)}
    mesh, _, facets = dolfinx.io.gmshio.model_to_mesh(gmsh.model, MPI.COMM_SELF, 0, gdim=3)
    V = dolfinx.fem.FunctionSpace(mesh, ("Lagrange", order))
    box = dolfinx.fem.Function(V)
    box.interpolate(lambda p: exact(p[0], p[1]))
    wall = dolfinx.fem.Function(V)
    wall.interpolate(lambda p: exact(p[0] / np.linalg.norm(p, axis=0),
                                     p[1] / np.linalg.norm(p, axis=0)))
    bcs = [dolfinx.fem.dirichletbc(box, boundary_dofs(V, facets, groups["box"])),
           dolfinx.fem.dirichletbc(wall, boundary_dofs(V, facets, groups["ball"]))]
    x = ufl.SpatialCoordinate(mesh)
    u_exact = exact(x[0], x[1])
    u, v = ufl.TrialFunction(V), ufl.TestFunction(V)
    problem = dolfinx.fem.petsc.LinearProblem(
        ufl.inner(ufl.grad(u), ufl.grad(v)) * ufl.dx, 3 * u_exact * v * ufl.dx, bcs=bcs,
        petsc_options={"ksp_type": "preonly", "pc_type": "lu"})
    uh = problem.solve()
    quadrature = ufl.dx(metadata={"quadrature_degree": 2 * order + 4})
    error2 = dolfinx.fem.assemble_scalar(dolfinx.fem.form((uh - u_exact) ** 2 * quadrature))
    volume = dolfinx.fem.assemble_scalar(dolfinx.fem.form(1.0 * quadrature(domain=mesh)))
    cells = mesh.topology.index_map(3).size_local
    return (6 * math.sqrt(2) * volume / cells) ** (1 / 3), math.sqrt(error2)


def boundary_dofs(V, facet_tags, tag):
    fdim = V.mesh.topology.dim - 1
    return dolfinx.fem.locate_dofs_topological(V, fdim, facet_tags.find(tag))


def solve(order, factor, curved, quads=False):
    """L2 error and h of the degree-`order` solution: h = sqrt(2 |Omega_h| / triangles), or
    sqrt(|Omega_h| / quadrilaterals)."""
    plate_mesh(order, factor, curved, quads)
    groups = {gmsh.model.getPhysicalName(d, t): t for d, t in gmsh.model.getPhysicalGroups(1)}
    mesh, _, facets = dolfinx.io.gmshio.model_to_mesh(gmsh.model, MPI.COMM_SELF, 0, gdim=2)
    V = dolfinx.fem.FunctionSpace(mesh, ("Lagrange", order))

    farfield = dolfinx.fem.Function(V)
    farfield.interpolate(lambda p: exact(p[0], p[1]))
    hole = dolfinx.fem.Function(V)
    hole.interpolate(lambda p: exact(RADIUS * np.cos(np.arctan2(p[1], p[0])),
                                     RADIUS * np.sin(np.arctan2(p[1], p[0]))))
    bcs = [dolfinx.fem.dirichletbc(farfield, boundary_dofs(V, facets, groups["farfield"])),
           dolfinx.fem.dirichletbc(hole, boundary_dofs(V, facets, groups["hole"]))]

    x = ufl.SpatialCoordinate(mesh)
    u_exact = exact(x[0], x[1])
    f = 3 * u_exact  # -lap(sin 2x e^y) = (4 - 1) sin 2x e^y
    u, v = ufl.TrialFunction(V), ufl.TestFunction(V)
    problem = dolfinx.fem.petsc.LinearProblem(
        ufl.inner(ufl.grad(u), ufl.grad(v)) * ufl.dx, f * v * ufl.dx, bcs=bcs,
        petsc_options={"ksp_type": "preonly", "pc_type": "lu"})
    uh = problem.solve()

    quadrature = ufl.dx(metadata={"quadrature_degree": 2 * order + 4})
    error2 = dolfinx.fem.assemble_scalar(dolfinx.fem.form((uh - u_exact) ** 2 * quadrature))
    area = dolfinx.fem.assemble_scalar(dolfinx.fem.form(1.0 * quadrature(domain=mesh)))
    cells = mesh.topology.index_map(2).size_local
    return math.sqrt((1 if quads else 2) * area / cells), math.sqrt(error2)


def rates(hs, errors):
    """Observed orders log(e_i / e_{i+1}) / log(h_i / h_{i+1})."""
    return [math.log(errors[i] / errors[i + 1]) / math.log(hs[i] / hs[i + 1])
            for i in range(len(hs) - 1)]


def convergence(orders=ORDERS, factors=FACTORS, quads=False, tets=False):
    """{(order, "curved"|"straight"): (hs, errors, rates)}; gmsh must be initialized."""
    table = {}
    for p in orders:
        for kind in ("curved", "straight") if p > 1 else ("curved",):
            if tets:
                hs, errors = zip(*(solve_ball(p, s, kind == "curved") for s in SIZES))
            else:
                hs, errors = zip(*(solve(p, s, kind == "curved", quads) for s in factors))
            table[(p, kind)] = (hs, errors, rates(hs, errors))
    return table


def plot(table, path, quads=False, tets=False):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(5.5, 4.2), dpi=100)
    colours = {1: "tab:grey", 2: "tab:blue", 3: "tab:red"}
    for (p, kind), (hs, errors, r) in sorted(table.items()):
        label = f"p = {p}" + ("" if p == 1 else f", {kind}") + f" (rate {r[-1]:.2f})"
        ax.loglog(hs, errors, "o-" if kind == "curved" else "s--", color=colours[p], label=label)
    ax.set_xlabel("h = (6 sqrt2 |domain| / tetrahedra)^(1/3)" if tets
                  else "h = sqrt(|domain| / quadrilaterals)" if quads
                  else "h = sqrt(2 |domain| / triangles)")
    ax.set_ylabel("L2 error")
    ax.set_title(("Poisson outside a ball in a box" if tets else "Poisson on the plate with a hole")
                 + ", DOLFINx 0.5, FE degree = p" + (", quadrilaterals" if quads else ""))
    ax.title.set_fontsize(9)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--plot", help="write a PNG of error against h")
    parser.add_argument("--cells", choices=("triangles", "quads", "tetrahedra"),
                        default="triangles")
    args = parser.parse_args()
    quads, tets = args.cells == "quads", args.cells == "tetrahedra"
    logging.disable(logging.INFO)  # FFCx and cffi log every JIT compilation at INFO
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    homesh.set_quiet(True)
    table = convergence(TET_ORDERS if tets else QUAD_ORDERS if quads else ORDERS, quads=quads,
                        tets=tets)
    gmsh.finalize()
    scales = SIZES if tets else FACTORS
    print(f"{'p':>2} {'mesh':<9} {'size' if tets else 'factor':>6} {'h':>8} {'L2 error':>10} "
          f"{'rate':>6}")
    for (p, kind), (hs, errors, r) in sorted(table.items()):
        for i, (h, e) in enumerate(zip(hs, errors)):
            rate = f"{r[i - 1]:6.2f}" if i else ""
            print(f"{p:>2} {kind:<9} {scales[i]:>6g} {h:8.4f} {e:10.3e} {rate}")
    if args.plot:
        plot(table, args.plot, quads, tets)
        print(f"wrote {args.plot}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
