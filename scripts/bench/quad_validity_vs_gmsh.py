#!/usr/bin/python3
"""Study: homesh's certified minJ/maxJ of quadrilaterals against Gmsh's AnalyseMeshQuality
plugin, element by element, on perturbed quad meshes of orders 1-4 (issue 21's target:
identical validity flags).

Meshes (Gmsh 4.8, through its API): the unit square with a hole of radius 0.2, all
quadrilaterals (Mesh.RecombineAll) or a boundary layer of quadrilaterals round the hole
(BoundaryLayer field, Quads = 1) in a triangle mesh, raised to order p by setOrder. Every
node inside the surface that is not an element corner (for p = 1: every vertex inside the
surface) is moved at random by up to AMPLITUDE times the size of its thinnest element
(area / longest corner edge: the thickness of a layer element) over p, so that from small to
large amplitudes more and more elements lose validity. homesh's quality stage (Python
module, in this process) and Gmsh's plugin then run on the same model; their per-element
values are compared by element tag: invalid counts, elements flagged by one only, largest
difference. A linear mesh whose jitter turned some element's corners clockwise is refused by
homesh when it reads it (no certificate to compare): such a case is listed as refused. Times:
Gmsh's plugin alone, and homesh.validity() (reading the model into homesh, then the
certified bounds; the quality call that gives the per-element values also writes the mesh
and views back, which is not timed).

Usage: PYTHONPATH=build/python /usr/bin/python3 scripts/bench/quad_validity_vs_gmsh.py [OUTDIR]
Writes OUTDIR/quad_validity_vs_gmsh.csv and .png (default docs/bench).
"""
import csv
import os
import sys
import time

import gmsh
import numpy as np

import homesh

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
VIEW = "homesh: certified minJ/maxJ"
AMPLITUDES = [0.05, 0.15, 0.3]
SIZE = 0.03


def make_mesh(kind, p):
    """The plate with a hole meshed as `kind` ('quads' or 'layer'), order p."""
    gmsh.model.add(f"{kind}{p}")
    gmsh.model.occ.addRectangle(0, 0, 0, 1, 1, 1)
    gmsh.model.occ.addDisk(0.5, 0.5, 0, 0.2, 0.2, 2)
    out, _ = gmsh.model.occ.cut([(2, 1)], [(2, 2)])
    gmsh.model.occ.synchronize()
    gmsh.option.setNumber("Mesh.MeshSizeMax", SIZE)
    gmsh.option.setNumber("Mesh.RecombineAll", 1 if kind == "quads" else 0)
    if kind == "layer":
        curves = [abs(c[1]) for c in gmsh.model.getBoundary(out, False, False, False)]
        hole = [c for c in curves if gmsh.model.getBoundingBox(1, c)[0] > 0.1
                and gmsh.model.getBoundingBox(1, c)[3] < 0.9]
        f = gmsh.model.mesh.field.add("BoundaryLayer")
        gmsh.model.mesh.field.setNumbers(f, "CurvesList", hole)
        for name, value in [("Size", 0.002), ("Ratio", 1.2), ("Thickness", 0.02), ("Quads", 1)]:
            gmsh.model.mesh.field.setNumber(f, name, value)
        gmsh.model.mesh.field.setAsBoundaryLayer(f)
    gmsh.model.mesh.generate(2)
    if p > 1:
        gmsh.model.mesh.setOrder(p)
    return out[0][1]


def perturb(surface, p, amplitude, rng):
    """Moves the surface's non-corner nodes (p = 1: its vertices) as the docstring says."""
    tags, coord, _ = gmsh.model.mesh.getNodes()
    xy = dict(zip(tags, coord.reshape(-1, 3)[:, :2]))
    size, corner = {}, set()
    types, _, nodes = gmsh.model.mesh.getElements(2)
    for t, n in zip(types, nodes):
        _, _, _, count, _, _ = gmsh.model.mesh.getElementProperties(t)
        corners = 4 if gmsh.model.mesh.getElementProperties(t)[0].startswith("Quad") else 3
        for element in np.asarray(n).reshape(-1, count):
            c = np.array([xy[k] for k in element[:corners]])
            area = 0.5 * abs(np.dot(c[:, 0], np.roll(c[:, 1], -1)) -
                             np.dot(c[:, 1], np.roll(c[:, 0], -1)))
            longest = np.linalg.norm(c - np.roll(c, -1, axis=0), axis=1).max()
            corner.update(element[:corners])
            for k in element:
                size[k] = min(size.get(k, np.inf), area / longest)
    inside, _, _ = gmsh.model.mesh.getNodes(2, surface, False, False)
    for k in inside:
        if p > 1 and k in corner:
            continue
        x = xy[k] + amplitude * size[k] / p * rng.uniform(-1, 1, 2)
        gmsh.model.mesh.setNode(k, [x[0], x[1], 0.0], [])


def by_tag(view):
    _, tags, data, _, _ = gmsh.view.getModelData(view, 0)
    return dict(zip(tags, (d[0] for d in data)))


def compare():
    """Per-element minJ/maxJ of homesh and of Gmsh's plugin on the current model."""
    t0 = time.perf_counter()
    homesh.validity()
    t1 = time.perf_counter()
    r = homesh.quality(measures="Q4", poor=-1)
    ours = None
    for v in r["views"]:
        if gmsh.option.getString(f"View[{gmsh.view.getIndex(v)}].Name") == VIEW:
            ours = by_tag(v)
    for name, value in [("JacobianDeterminant", 1), ("IGEMeasure", 0), ("ICNMeasure", 0),
                        ("CreateView", 1), ("Recompute", 1), ("DimensionOfElements", 2)]:
        gmsh.plugin.setNumber("AnalyseMeshQuality", name, value)
    before = set(gmsh.view.getTags())
    t2 = time.perf_counter()
    gmsh.plugin.run("AnalyseMeshQuality")
    t3 = time.perf_counter()
    theirs = by_tag((set(gmsh.view.getTags()) - before).pop())
    return ours, theirs, t1 - t0, t3 - t2


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "docs", "bench")
    os.makedirs(out, exist_ok=True)
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    homesh.set_quiet(True)
    rows, pairs = [], []
    rng = np.random.default_rng(21)
    for kind in ["quads", "layer"]:
        for p in range(1, 5):
            for amplitude in AMPLITUDES:
                gmsh.clear()
                surface = make_mesh(kind, p)
                perturb(surface, p, amplitude, rng)
                quad_type = gmsh.model.mesh.getElementType("Quadrangle", p)
                try:
                    ours, theirs, t_ours, t_gmsh = compare()
                except homesh.Error as e:
                    row = dict(mesh=kind, p=p, amplitude=amplitude, refused=str(e))
                    rows.append(row)
                    print(row, flush=True)
                    continue
                quads = set(gmsh.model.mesh.getElementsByType(quad_type)[0])  # homesh's tags
                assert set(ours) >= set(theirs) and len(theirs) == len(ours) - sum(
                    len(t) for t in gmsh.model.mesh.getElements(1)[1]) - sum(
                    len(t) for t in gmsh.model.mesh.getElements(0)[1])
                q = [k for k in theirs if k in quads]
                a = np.array([ours[k] for k in q])
                b = np.array([theirs[k] for k in q])
                t = [k for k in theirs if k not in quads]
                pairs.append((a, b))
                row = dict(mesh=kind, p=p, amplitude=amplitude, refused="", quads=len(q),
                           triangles=len(t),
                           invalid_homesh=int((a <= 0).sum()), invalid_gmsh=int((b <= 0).sum()),
                           flagged_by_one=int(((a <= 0) != (b <= 0)).sum()),
                           triangles_flagged_by_one=sum(
                               (ours[k] <= 0) != (theirs[k] <= 0) for k in t),
                           max_abs_diff=float(np.abs(a - b).max()),
                           homesh_validity_s=round(t_ours, 4), gmsh_plugin_s=round(t_gmsh, 4))
                rows.append(row)
                print(row, flush=True)
    with open(os.path.join(out, "quad_validity_vs_gmsh.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(max(rows, key=len)))
        w.writeheader()
        w.writerows(rows)
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(1, 2, figsize=(10, 4.5))
    a = np.concatenate([x for x, _ in pairs])
    b = np.concatenate([y for _, y in pairs])
    ax[0].plot(b, a, ".", ms=2)
    ax[0].set_xlabel("Gmsh AnalyseMeshQuality minJ/maxJ")
    ax[0].set_ylabel("homesh certified minJ/maxJ")
    ax[0].set_title(f"{len(a)} quadrilaterals, p = 1-4")
    done = [r for r in rows if not r["refused"]]
    ax[1].semilogy(range(len(done)), [max(r["max_abs_diff"], 1e-17) for r in done], "o")
    ax[1].set_xlabel("case (mesh, p, amplitude, in CSV order)")
    ax[1].set_ylabel("largest |homesh - Gmsh|")
    ax[1].set_title(f"flagged by one only: {sum(r['flagged_by_one'] for r in done)}")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "quad_validity_vs_gmsh.png"), dpi=100)


if __name__ == "__main__":
    main()
