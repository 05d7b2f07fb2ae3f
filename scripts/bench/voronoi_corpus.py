#!/usr/bin/python3
"""Benchmark (issue 22): homesh's crystal-growth Voronoi mesher against Gmsh's 2D meshers on
the CAD models of the curving corpus (scripts/bench/corpus.py), side by side in one run.

Each model (the corpus's shapes with their wall and far-field sizes: a Gmsh Threshold field
on the distance to the walls, as corpus.py sets it) is meshed in its own forked child by:
  gmsh frontal       : generate(2) with Mesh.Algorithm 6 (Frontal-Delaunay, Gmsh's default);
  gmsh delaunay      : generate(2) with Mesh.Algorithm 5;
  voronoi            : homesh.voronoi() with its defaults (it meshes with Gmsh's default
                       first, for its sizes: that time is in its own);
  voronoi dual=grown : homesh.voronoi(dual="grown"), the crystals grown on the grid for the
                       dual (thesis Ch 2), where the default takes the exact dual of an
                       isotropic metric (the seeds' Delaunay triangulation).
Referee: Gmsh's AnalyseMeshQuality ICN (inverse condition number: for a linear triangle the
mean ratio, 1 equilateral), min and mean over the triangles, and its minJ/maxJ (invalid:
<= 0). Seconds: wall time of the meshing call alone (the CAD and the field are made first),
the least of --repeat runs, each in a fresh child (the machine's noise only ever adds time;
the meshes are deterministic, so every run gives the same quality).
voronoi's filled triangles (made by the constrained fill, not by the dual) are recorded.

Usage:
  PYTHONPATH=build/python /usr/bin/python3 scripts/bench/voronoi_corpus.py
      [--cases PATTERN] [--methods PATTERN] [--variant K=V:K=V ...] [--out out/bench/voronoi]
      [--timeout 300] [--repeat 1]
Writes OUT/voronoi_corpus.csv and OUT/voronoi_corpus.png, and prints a table per model:
triangles, ICN min / mean, seconds, and voronoi's time over frontal's.
"""
import argparse
import fnmatch
import os
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
ROOT = os.path.dirname(os.path.dirname(HERE))

import corpus  # noqa: E402
from gmsh_referee import icn  # noqa: E402

METHODS = ["gmsh frontal", "gmsh delaunay", "voronoi", "voronoi dual=grown"]
FIELDS = ["case", "method", "status", "triangles", "icn_min", "icn_mean", "invalid",
          "filled", "seconds", "error"]


def models():
    """One corpus case per CAD model and sizes (the mesher does not matter here)."""
    seen, out = set(), []
    for c in corpus.CASES:
        key = (c.shape, repr(sorted(c.args.items())), c.h_wall, c.h_far)
        if key not in seen:
            seen.add(key)
            out.append(c)
    return out


def child(conn, name, method):
    import gmsh
    row = dict(case=name, method=method, status="ok")
    try:
        gmsh.initialize()
        gmsh.option.setNumber("General.Terminal", 0)
        c = corpus.case(name)
        corpus.unmeshed(c)
        filled = ""
        if not method.startswith("gmsh"):
            import homesh  # before the clock, as gmsh is: loading a library is not meshing
            homesh.set_quiet(True)
        start = time.perf_counter()
        if method.startswith("gmsh"):
            gmsh.option.setNumber("Mesh.Algorithm", 6 if method == "gmsh frontal" else 5)
            gmsh.model.mesh.generate(2)
        else:
            r = homesh.voronoi(**corpus.method_options(method))
            filled = r["results"]["filled_triangles"]
        row["seconds"] = time.perf_counter() - start
        q_min, q_mean, triangles, invalid = icn()
        row.update(icn_min=q_min, icn_mean=q_mean, triangles=triangles, invalid=invalid,
                   filled=filled)
    except Exception as e:  # noqa: BLE001 (recorded, the run goes on)
        row.update(status="error", error=str(e).splitlines()[0][:200])
    conn.send(row)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--cases", default="*")
    parser.add_argument("--methods", default="*")
    parser.add_argument("--out", default=os.path.join(ROOT, "out", "bench", "voronoi"))
    parser.add_argument("--timeout", type=float, default=300)
    parser.add_argument("--repeat", type=int, default=1,
                        help="runs of each method on each model; the least time is kept")
    parser.add_argument("--variant", action="append", default=[],
                        help="also run voronoi with options K=V:K=V (repeatable), as the method "
                             "'voronoi K=V:K=V'")
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    cases = [c for c in models()
             if any(fnmatch.fnmatch(c.name, p) for p in args.cases.split(","))]
    methods = [m for m in METHODS if any(fnmatch.fnmatch(m, p) for p in args.methods.split(","))]
    methods += [f"voronoi {v}" for v in args.variant]
    rows = []
    for c in cases:
        for m in methods:
            r = corpus.least_time(lambda: corpus.run_method(child, c.name, m, args.timeout), args.repeat)
            rows.append(r)
            if r["status"] == "ok":
                print(f"{c.name:28s} {m:20s} {r['triangles']:6d} tri  ICN min {r['icn_min']:.4f}"
                      f" mean {r['icn_mean']:.4f}  invalid {r['invalid']}  filled "
                      f"{r['filled'] if r['filled'] != '' else '-':>3}  {r['seconds']:7.2f} s",
                      flush=True)
            else:
                print(f"{c.name:28s} {m:20s} {r['status']}: {r.get('error', '')}", flush=True)
    path = os.path.join(args.out, "voronoi_corpus.csv")
    corpus.write_rows(path, FIELDS, rows)
    summary(rows, [c.name for c in cases])
    plot(rows, [c.name for c in cases], methods, os.path.join(args.out, "voronoi_corpus.png"))
    print(f"wrote {path}")


def summary(rows, cases):
    """Per model: voronoi's time over frontal's and its ICN against frontal's."""
    by = {(r["case"], r["method"]): r for r in rows if r["status"] == "ok"}
    print(f"\n{'model':28s} {'time/frontal':>12s} {'ICN min v/f':>14s} {'ICN mean v/f':>16s}")
    for c in cases:
        f, v = by.get((c, "gmsh frontal")), by.get((c, "voronoi"))
        if f and v:
            print(f"{c:28s} {v['seconds'] / f['seconds']:12.1f} "
                  f"{v['icn_min']:6.3f}/{f['icn_min']:6.3f} {v['icn_mean']:7.4f}/{f['icn_mean']:7.4f}")


def plot(rows, cases, methods, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
    by = {(r["case"], r["method"]): r for r in rows if r["status"] == "ok"}
    fig, axes = plt.subplots(3, 1, figsize=(max(8, 0.7 * len(cases)), 11), sharex=True)
    width = 0.8 / len(methods)
    for ax, key, title in [(axes[0], "seconds", "wall time (s, log)"),
                           (axes[1], "icn_min", "worst ICN"),
                           (axes[2], "icn_mean", "mean ICN")]:
        for k, m in enumerate(methods):
            values = [float(by[(c, m)][key]) if (c, m) in by else np.nan for c in cases]
            ax.bar(np.arange(len(cases)) + (k - (len(methods) - 1) / 2) * width, values, width,
                   label=m)
        ax.set_title(title)
        ax.grid(axis="y", alpha=0.3)
    axes[0].set_yscale("log")
    axes[2].set_ylim(0.85, 1.0)
    axes[2].set_xticks(np.arange(len(cases)))
    axes[2].set_xticklabels(cases, rotation=60, ha="right", fontsize=8)
    axes[0].legend(fontsize=8)
    fig.suptitle("homesh voronoi against Gmsh's meshers on the corpus's CAD models "
                 "(referee: Gmsh's AnalyseMeshQuality)")
    fig.tight_layout()
    fig.savefig(path + ".tmp.png", dpi=100)
    os.replace(path + ".tmp.png", path)


if __name__ == "__main__":
    main()
