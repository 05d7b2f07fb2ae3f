#!/usr/bin/python3
"""Benchmark (issue 20): homesh's layers stage on fine meshes and between close bodies, then
curved to p = 4.

Cases, each made afresh in its own Gmsh session:
  naca7526 factor F : geo/naca.geo meshed by homesh.mesh(factor=F), F = 1, 0.5, 0.25, then
                      the README's stack: 15 layers from 1e-3, ratio 1.2, normals=multi,
                      fan=5, fan_angle=320 (the trailing edge's domain angle is 326 deg);
  flap_gap02        : corpus case flap_gap02_nolayer (scripts/bench/corpus.py: main element
                      and flap, gap 0.02 of the chord, Gmsh's mesh at 0.015), then 15 layers
                      from 1e-4, ratio 1.2 (0.0072 thick), fans at the sharp trailing edges;
  slat_flap         : corpus case slat_flap_nolayer_fine (slat, main, flap, gaps 0.015 and
                      0.0225, Gmsh's mesh at 0.006), the same stack.
Then homesh.curve(p=4). Measures: triangles before and after the layers, seconds of the
layers and of the curve calls, and Gmsh's AnalyseMeshQuality on the curved mesh (invalid
triangles, worst minJ/maxJ) as referee.

Usage: PYTHONPATH=build/python /usr/bin/python3 scripts/bench/layers_fine.py [OUTDIR]
Writes OUTDIR/layers_fine.csv and OUTDIR/layers_fine.png (default docs/bench).
"""
import csv
import os
import sys
import time

import gmsh
import homesh
from gmsh_referee import referee

import corpus

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
FAN = dict(normals="multi", fan=5, fan_angle=320)
CASES = [("naca7526 factor 1", "naca", 1.0), ("naca7526 factor 0.5", "naca", 0.5),
         ("naca7526 factor 0.25", "naca", 0.25),
         ("flap_gap02", "flap_gap02_nolayer", None), ("slat_flap", "slat_flap_nolayer_fine", None)]


def triangles():
    return sum(len(gmsh.model.mesh.getElementsByType(t)[0])
               for t in gmsh.model.mesh.getElementTypes(2))


def run_case(source, factor):
    """Mesh, layer and curve one case in a fresh session; returns its measures."""
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    try:
        if source == "naca":
            gmsh.onelab.clear()
            gmsh.open(os.path.join(ROOT, "geo", "naca.geo"))
            homesh.mesh(factor=factor)
            stack = dict(walls="aerofoil", n=15, first=1e-3, ratio=1.2, **FAN)
        else:
            corpus.build(corpus.case(source))
            stack = dict(walls=corpus.WALL, n=15, first=1e-4, ratio=1.2, **FAN)
        before = triangles()
        t = time.perf_counter()
        homesh.layers(**stack)
        layer_seconds = time.perf_counter() - t
        after = triangles()
        t = time.perf_counter()
        homesh.curve(p=4)
        curve_seconds = time.perf_counter() - t
        invalid, worst, _ = referee()
    finally:
        gmsh.finalize()
    return dict(triangles_before=before, triangles_after=after, layer_seconds=layer_seconds,
                curve_seconds=curve_seconds, invalid=invalid, worst_minJ_maxJ=worst)


def main():
    outdir = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "docs", "bench")
    os.makedirs(outdir, exist_ok=True)
    homesh.set_quiet(True)
    rows = []
    for name, source, factor in CASES:
        row = run_case(source, factor)
        row = dict(case=name, **row, load=os.getloadavg()[0])
        rows.append(row)
        print(f"{name:<22} {row['triangles_before']:>6} -> {row['triangles_after']:>6} triangles, "
              f"layers {row['layer_seconds']:.2f} s, curve p=4 {row['curve_seconds']:.2f} s: "
              f"invalid {row['invalid']}, worst minJ/maxJ {row['worst_minJ_maxJ']:.4f} "
              f"(load {row['load']:.1f})", flush=True)
    with open(os.path.join(outdir, "layers_fine.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (a, b) = plt.subplots(1, 2, figsize=(12, 4.5))
    names = [r["case"] for r in rows]
    a.bar(names, [r["layer_seconds"] for r in rows], label="layers")
    a.bar(names, [r["curve_seconds"] for r in rows], bottom=[r["layer_seconds"] for r in rows],
          label="curve p = 4")
    a.set_ylabel("wall time, s")
    a.legend()
    b.bar(names, [r["worst_minJ_maxJ"] for r in rows], color="tab:green")
    for k, r in enumerate(rows):
        b.text(k, r["worst_minJ_maxJ"] + 0.01, f"{r['worst_minJ_maxJ']:.3f}\n{r['invalid']} invalid",
               ha="center", fontsize=8)
    b.set_ylim(0, 1.15)
    b.set_ylabel("worst minJ/maxJ after curve p = 4 (AnalyseMeshQuality)")
    for ax in (a, b):
        ax.tick_params(axis="x", rotation=25, labelsize=8)
    fig.suptitle("homesh layers (15) + curve p = 4: fine meshes and close bodies")
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, "layers_fine.png"), dpi=110)


if __name__ == "__main__":
    main()
