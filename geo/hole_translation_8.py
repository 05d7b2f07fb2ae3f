"""Writes hole_translation_8.txt: the 8-element quadratic mesh of thesis Section 4.2.3 (a
circular hole in a square plate, hole translated diagonally) and its displacement computed by
DOLFINx, an independent finite-element code standing in for the thesis' Abaqus/CAE.

Run with Debian's python3 (python3-dolfinx): python3 geo/hole_translation_8.py
Setup (choices the thesis leaves open, see geo/README.md): plate [-1, 1]^2, hole radius 0.5
centred at the origin, hole vertices on the axes, plate corners joined to their two nearest hole
vertices (8 triangles, symmetric under the square's 8 symmetries); quadratic isoparametric
elements with the hole's mid-edge nodes on the circle; plane strain, E = 1, nu = 0.4 (the
thesis' Section 4.3 values); outer edges fixed, every hole node moved by (1, 1) (the problem is
linear: a translation (d, d) moves every node d times as far).
"""
import math
import os

import numpy as np
import ufl
from dolfinx import fem, mesh
from dolfinx.fem.petsc import LinearProblem
from mpi4py import MPI

HALF_SIDE, RADIUS, YOUNG, POISSON = 1.0, 0.5, 1.0, 0.4


def build():
    """Nodes (2 by n) and triangles (6 nodes each, Gmsh order) of the 8-element mesh."""
    nodes = [(RADIUS * math.cos(k * math.pi / 2), RADIUS * math.sin(k * math.pi / 2))
             for k in range(4)]
    nodes += [(HALF_SIDE * math.sqrt(2) * math.cos(math.pi / 4 + k * math.pi / 2),
               HALF_SIDE * math.sqrt(2) * math.sin(math.pi / 4 + k * math.pi / 2))
              for k in range(4)]
    nodes = [(round(x, 15) + 0.0, round(y, 15) + 0.0) for x, y in nodes]
    edges = {}

    def mid(a, b):
        key = (min(a, b), max(a, b))
        if key not in edges:
            if a < 4 and b < 4:  # hole arc: mid-node on the circle
                angle = math.atan2(nodes[a][1] + nodes[b][1], nodes[a][0] + nodes[b][0])
                nodes.append((RADIUS * math.cos(angle), RADIUS * math.sin(angle)))
            else:
                nodes.append(((nodes[a][0] + nodes[b][0]) / 2, (nodes[a][1] + nodes[b][1]) / 2))
            edges[key] = len(nodes) - 1
        return edges[key]

    triangles = []
    for k in range(4):
        h, h_next, c, c_prev = k, (k + 1) % 4, 4 + k, 4 + (k + 3) % 4
        for a, b, cc in ((h, c, h_next), (h, c_prev, c)):
            triangles.append([a, b, cc, mid(a, b), mid(b, cc), mid(cc, a)])
    return np.array(nodes), np.array(triangles)


def solve(x, triangles):
    """Nodal displacement (n by 2) by DOLFINx, P2 isoparametric, quadrature degree 12."""
    domain = ufl.Mesh(ufl.VectorElement("Lagrange", ufl.triangle, 2))
    dolfinx_order = [0, 1, 2, 4, 5, 3]  # edges opposite vertices 0, 1, 2
    msh = mesh.create_mesh(MPI.COMM_WORLD, triangles[:, dolfinx_order], x, domain)
    V = fem.VectorFunctionSpace(msh, ("Lagrange", 2))
    on_hole = fem.locate_dofs_geometrical(
        V, lambda p: np.isclose(np.hypot(p[0], p[1]), RADIUS))
    on_plate = fem.locate_dofs_geometrical(
        V, lambda p: np.isclose(np.maximum(abs(p[0]), abs(p[1])), HALF_SIDE))
    bcs = [fem.dirichletbc(np.array([1.0, 1.0]), on_hole, V),
           fem.dirichletbc(np.array([0.0, 0.0]), on_plate, V)]
    mu = YOUNG / (2 * (1 + POISSON))
    lmbda = YOUNG * POISSON / ((1 + POISSON) * (1 - 2 * POISSON))
    u, v = ufl.TrialFunction(V), ufl.TestFunction(V)
    eps = lambda w: ufl.sym(ufl.grad(w))
    sigma = lambda w: lmbda * ufl.tr(eps(w)) * ufl.Identity(2) + 2 * mu * eps(w)
    dx = ufl.dx(metadata={"quadrature_degree": 12})
    a = ufl.inner(sigma(u), eps(v)) * dx
    L = ufl.inner(fem.Constant(msh, (0.0, 0.0)), v) * dx
    uh = LinearProblem(a, L, bcs, petsc_options={"ksp_type": "preonly", "pc_type": "lu"}).solve()
    where = V.tabulate_dof_coordinates()[:, :2]
    values = uh.x.array.reshape(-1, 2)
    out = np.zeros((len(x), 2))
    for i, p in enumerate(x):
        j = np.argmin(np.hypot(*(where - p).T))
        assert np.hypot(*(where[j] - p)) < 1e-12
        out[i] = values[j]
    return out


def main():
    x, triangles = build()
    u = solve(x, triangles)
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "hole_translation_8.txt")
    with open(path, "w") as f:
        f.write("# Thesis Section 4.2.3: 8 quadratic triangles around a hole, hole translated by\n"
                "# (1, 1), outer edges fixed, plane strain E = 1, nu = 0.4. Written by\n"
                "# geo/hole_translation_8.py (DOLFINx %s, P2 isoparametric, quadrature degree\n"
                "# 12); see geo/README.md.\n" % __import__("dolfinx").__version__)
        f.write("nodes %d  # x y ux uy (DOLFINx displacement)\n" % len(x))
        for p, d in zip(x, u):
            f.write("%.17g %.17g %.17g %.17g\n" % (p[0], p[1], d[0], d[1]))
        f.write("triangles %d  # 6 node indices, Gmsh order\n" % len(triangles))
        for t in triangles:
            f.write(" ".join(str(i) for i in t) + "\n")


if __name__ == "__main__":
    main()
