#!/usr/bin/python3
"""Benchmark (issue 22, "at equal triangle counts, 1e3 to 1e5"): the voronoi stage's wall time
over Gmsh frontal's as the mesh grows, on CAD the project ships.

Models: the plate with a hole (geo/plate_hole.geo) and NACA-7526 in its far field
(geo/naca.geo), each at Mesh.MeshSizeFactor F over a range that gives about 1e3 to 1e5
triangles (--factors overrides the models' own). For each model and F, in one forked child
per run (a fresh Gmsh):
  gmsh frontal : gmsh.open(geo), Mesh.MeshSizeFactor = F, generate(2) with Mesh.Algorithm 6;
  voronoi      : gmsh.open(geo), homesh.voronoi(factor=F) with its other defaults (it
                 meshes with Gmsh's default first, for its sizes: that time is in its own).
Seconds: wall time of the meshing call alone, the least of --repeat runs (noise only adds
time). Referee of the shape: Gmsh's AnalyseMeshQuality ICN, min and mean.

Usage:
  PYTHONPATH=build/python /usr/bin/python3 scripts/bench/voronoi_scale.py
      [--out out/bench] [--repeat 3] [--factors F,F,...]
Writes OUT/voronoi_scale.csv and OUT/voronoi_scale.png (time ratio against triangles) and
prints the table.
"""
import argparse
import os
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
ROOT = os.path.dirname(os.path.dirname(HERE))

import corpus  # noqa: E402
from gmsh_referee import icn  # noqa: E402

# Each model's factors: from about 1e3 triangles to about 1e5 (and 2e5).
MODELS = {"plate_hole": ("geo/plate_hole.geo", [0.6, 0.3, 0.1, 0.05]),
          "naca7526": ("geo/naca.geo", [1, 0.3, 0.1])}
METHODS = ["gmsh frontal", "voronoi"]
FIELDS = ["model", "factor", "method", "status", "triangles", "icn_min", "icn_mean",
          "seconds", "error"]


def child(conn, model, factor, method):
    import gmsh
    row = dict(model=model, factor=factor, method=method, status="ok")
    try:
        gmsh.initialize()
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.open(os.path.join(ROOT, MODELS[model][0]))
        if method != "gmsh frontal":
            import homesh  # before the clock, as gmsh is: loading a library is not meshing
            homesh.set_quiet(True)
        start = time.perf_counter()
        if method == "gmsh frontal":
            gmsh.option.setNumber("Mesh.MeshSizeFactor", factor)
            gmsh.option.setNumber("Mesh.Algorithm", 6)
            gmsh.model.mesh.generate(2)
        else:
            homesh.voronoi(factor=factor)
        row["seconds"] = time.perf_counter() - start
        q_min, q_mean, triangles, _ = icn()
        row.update(icn_min=q_min, icn_mean=q_mean, triangles=triangles)
    except Exception as e:  # noqa: BLE001 (recorded, the run goes on)
        row.update(status="error", error=str(e).splitlines()[0][:200])
    conn.send(row)


def run_one(model, factor, method, timeout=600):
    return corpus.in_child(child, (model, factor, method), timeout,
                           dict(model=model, factor=factor, method=method, status="timeout"))


def plot(rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    by = {(r["model"], r["factor"], r["method"]): r for r in rows if r["status"] == "ok"}
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for model in MODELS:
        pts = sorted((by[(model, f, "gmsh frontal")]["triangles"],
                      by[(model, f, "voronoi")]["seconds"] / by[(model, f, "gmsh frontal")]["seconds"])
                     for (m, f, meth) in by if m == model and meth == "voronoi"
                     and (model, f, "gmsh frontal") in by)
        ax.plot([p[0] for p in pts], [p[1] for p in pts], "o-", label=model)
    ax.axhline(3, color="k", ls="--", lw=1, label="target 3x")
    ax.set_xscale("log")
    ax.set_xlabel("triangles (Gmsh frontal)")
    ax.set_ylabel("voronoi wall time / frontal's")
    ax.set_ylim(bottom=0)
    ax.grid(alpha=0.3)
    ax.legend()
    ax.set_title("homesh voronoi against Gmsh frontal as the mesh grows")
    fig.tight_layout()
    fig.savefig(path + ".tmp.png", dpi=100)
    os.replace(path + ".tmp.png", path)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--out", default=os.path.join(ROOT, "out", "bench"))
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--factors", default="")
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    rows = []
    print(f"{'model':12s} {'factor':>7s} {'method':14s} {'triangles':>9s} {'ICN min':>8s} "
          f"{'mean':>7s} {'seconds':>8s}")
    for model, (_, factors) in MODELS.items():
        if args.factors:
            factors = [float(f) for f in args.factors.split(",")]
        for factor in factors:
            for method in METHODS:
                r = corpus.least_time(lambda: run_one(model, factor, method), args.repeat)
                rows.append(r)
                if r["status"] == "ok":
                    print(f"{model:12s} {factor:7.3g} {method:14s} {r['triangles']:9d} "
                          f"{r['icn_min']:8.4f} {r['icn_mean']:7.4f} {r['seconds']:8.3f}",
                          flush=True)
                else:
                    print(f"{model:12s} {factor:7.3g} {method:14s} {r['status']}: "
                          f"{r.get('error', '')}", flush=True)
    path = os.path.join(args.out, "voronoi_scale.csv")
    corpus.write_rows(path, FIELDS, rows)
    by = {(r["model"], r["factor"], r["method"]): r for r in rows if r["status"] == "ok"}
    print(f"\n{'model':12s} {'factor':>7s} {'triangles f/v':>15s} {'time v/f':>9s}")
    for (model, factor, method), v in by.items():
        f = by.get((model, factor, "gmsh frontal"))
        if method == "voronoi" and f:
            print(f"{model:12s} {factor:7.3g} {f['triangles']:7d}/{v['triangles']:<7d} "
                  f"{v['seconds'] / f['seconds']:9.1f}")
    plot(rows, os.path.join(args.out, "voronoi_scale.png"))
    print(f"wrote {path}")


if __name__ == "__main__":
    main()
