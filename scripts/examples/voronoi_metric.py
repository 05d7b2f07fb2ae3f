#!/usr/bin/python3
"""Voronoi mesh of a domain with a user metric (thesis chapter 2).

A channel [0, 2] x [0, 1] with a circular obstacle, built with gmsh.model.occ;
the user's metric is a Gmsh tensor view (the format of Gmsh's anisotropic
background meshes: |v|_M = sqrt(v^T M v), eigenvalues 1 / h^2) that asks for
elements of length H_ALONG along an oblique "shock" line and H_ACROSS across
it, relaxing to isotropic H_FAR away from it. homesh places seeds in that
metric and meshes the domain with their Delaunay triangulation in it, the dual
of their Voronoi cells in the metric (dual=grown: of crystals grown under it,
the thesis' way), checks it and writes it with its quality views.

The metric is honoured where it is asked for: the script prints the median
length of the mesh's edges measured in the metric (1 is the target) near the
line and away from it, and the mean direction of the short edges.

Usage: /usr/bin/python3 scripts/examples/voronoi_metric.py [--msh OUT.msh]
(PYTHONPATH=build/python). Writes out/examples/voronoi_metric.msh by default.
"""
import argparse
import math
import os

import gmsh
import numpy as np

import homesh

H_ALONG, H_ACROSS, H_FAR, WIDTH = 0.12, 0.04, 0.12, 0.3
# The shock: the line through (0.3, 0) with direction (cos A, sin A).
ANGLE = math.radians(60)
ORIGIN = np.array([0.3, 0.0])
TANGENT = np.array([math.cos(ANGLE), math.sin(ANGLE)])
NORMAL = np.array([-TANGENT[1], TANGENT[0]])


def metric(x, y):
    """The user's metric at (x, y): 2 by 2 SPD."""
    d = abs(np.dot(np.array([x, y]) - ORIGIN, NORMAL))
    across = H_ACROSS + (H_FAR - H_ACROSS) * min(d / WIDTH, 1.0)
    R = np.column_stack([TANGENT, NORMAL])
    return R @ np.diag([1 / H_ALONG**2, 1 / across**2]) @ R.T


def add_metric_view(n=60):
    """A tensor view ("TT": tensors on triangles) on an n by n grid over the box."""
    xs, ys = np.linspace(-0.05, 2.05, n + 1), np.linspace(-0.05, 1.05, n + 1)
    data, count = [], 0
    for i in range(n):
        for j in range(n):
            a, b = (xs[i], ys[j]), (xs[i + 1], ys[j])
            c, d = (xs[i + 1], ys[j + 1]), (xs[i], ys[j + 1])
            for tri in ((a, b, c), (a, c, d)):
                values = []
                for x, y in tri:
                    M = metric(x, y)
                    values += [M[0, 0], M[0, 1], 0, M[1, 0], M[1, 1], 0, 0, 0, 1]
                data += [p[0] for p in tri] + [p[1] for p in tri] + [0, 0, 0] + values
                count += 1
    tag = gmsh.view.add("user metric")
    gmsh.view.addListData(tag, "TT", count, data)
    return tag


def metric_edge_lengths(near):
    """Lengths of the mesh's edges in the metric, split by distance to the line."""
    node_tags, coords, _ = gmsh.model.mesh.getNodes()
    xy = dict(zip(node_tags, np.reshape(coords, (-1, 3))[:, :2]))
    _, _, elem_nodes = gmsh.model.mesh.getElements(2)
    tri = np.reshape(elem_nodes[0], (-1, 3))
    edges = {tuple(sorted((t[k], t[(k + 1) % 3]))) for t in tri for k in range(3)}
    inside, outside, short_dirs = [], [], []
    for a, b in edges:
        pa, pb = xy[a], xy[b]
        mid, v = (pa + pb) / 2, pb - pa
        length = math.sqrt(v @ metric(*mid) @ v)
        if abs(np.dot(mid - ORIGIN, NORMAL)) < near:
            inside.append(length)
            if np.linalg.norm(v) < 0.5 * H_ALONG:
                short_dirs.append(abs(np.dot(v / np.linalg.norm(v), NORMAL)))
        else:
            outside.append(length)
    return np.median(inside), np.median(outside), np.mean(short_dirs), len(tri)


def main():
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--msh", default=os.path.join(root, "out", "examples", "voronoi_metric.msh"))
    args = ap.parse_args()
    os.makedirs(os.path.dirname(os.path.abspath(args.msh)), exist_ok=True)

    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    box = gmsh.model.occ.addRectangle(0, 0, 0, 2, 1)
    hole = gmsh.model.occ.addDisk(1.4, 0.5, 0, 0.15, 0.15)
    gmsh.model.occ.cut([(2, box)], [(2, hole)])
    gmsh.model.occ.synchronize()
    fluid = gmsh.model.addPhysicalGroup(2, [s for _, s in gmsh.model.getEntities(2)])
    gmsh.model.setPhysicalName(2, fluid, "fluid")

    view = add_metric_view()
    result = homesh.voronoi(metric=f"view{view}")
    quality = homesh.quality(measures="Q11")
    along_line, elsewhere, across, triangles = metric_edge_lengths(near=H_ACROSS)
    print(f"voronoi mesh: {triangles} triangles, {result['nodes']} nodes")
    print(f"median metric edge length: {along_line:.3f} at the line, {elsewhere:.3f} away from it")
    print(f"short edges at the line: mean |cos| to the line's normal {across:.3f}")
    print(quality["validity"]["line"])
    gmsh.view.remove(view)
    homesh.write(args.msh)
    print(f"wrote {args.msh}")
    gmsh.finalize()


if __name__ == "__main__":
    main()
