#!/usr/bin/python3
"""Benchmark (issue 6, "As the mesh generator"): the shape of the linear triangles of homesh's
voronoi stage against Gmsh's 2D meshers, on the same CAD and the same sizes.

Cases: the plate with a hole (geo/plate_hole.geo), its coarse variant of thesis Fig 4.13
(geo/plate_hole_fig413.geo), the channel with a bump (geo/channel.geo) and NACA-7526
(geo/naca.geo), each meshed afresh by the homesh CLI:
  gmsh frontal | delaunay | meshadapt : `-m mesh:algorithm=...` (frontal is Gmsh's default,
                                        Frontal-Delaunay);
  voronoi poisson  : `-m voronoi:front=0:lloyd=5` (Poisson-disc seeds, Lloyd, smoothing);
  voronoi no front : `-m voronoi:front=0` (the same with the default Lloyd iterations);
  voronoi          : `-m voronoi` (defaults: front rows, then Poisson-disc where they meet).
The voronoi stage takes its sizes from Gmsh's default mesh (metric iso), so every mesh of a
case has about the same node count.

Referee: Gmsh's AnalyseMeshQuality plugin, ICN (inverse condition number; for a linear
triangle the mean ratio, 1 equilateral, equal to homesh's Q11), min and mean over the
triangles; and its minJ/maxJ, whose count of values <= 0 must be 0. Seconds: wall time of
the homesh process (the voronoi stage runs Gmsh's default mesh first, for its sizes).

Usage: /usr/bin/python3 scripts/bench/voronoi_vs_gmsh.py [OUTDIR] [--homesh build/homesh]
Writes OUTDIR/voronoi_vs_gmsh.csv and OUTDIR/voronoi_vs_gmsh.png (default out/bench).
"""
import argparse
import csv
import os
import subprocess
import sys
import tempfile
import time

import gmsh
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gmsh_referee  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

CASES = [("plate_hole", "geo/plate_hole.geo"),
         ("plate_fig413", "geo/plate_hole_fig413.geo"),
         ("channel", "geo/channel.geo"),
         ("naca7526", "geo/naca.geo")]
METHODS = [("gmsh frontal", "mesh:algorithm=frontal"),
           ("gmsh delaunay", "mesh:algorithm=delaunay"),
           ("gmsh meshadapt", "mesh:algorithm=meshadapt"),
           ("voronoi poisson", "voronoi:front=0:lloyd=5"),
           ("voronoi no front", "voronoi:front=0"),
           ("voronoi", "voronoi")]


def icn(path):
    """(min, mean, triangles, invalid) of Gmsh's ICN and minJ/maxJ over the mesh in path."""
    gmsh.initialize()
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.open(path)
        return gmsh_referee.icn()
    finally:
        gmsh.finalize()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("outdir", nargs="?", default=os.path.join(ROOT, "out", "bench"))
    parser.add_argument("--homesh", default=os.path.join(ROOT, "build", "homesh"))
    args = parser.parse_args()
    os.makedirs(args.outdir, exist_ok=True)
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for case, geo in CASES:
            for method, stage in METHODS:
                out = os.path.join(tmp, f"{case}.msh")
                start = time.perf_counter()
                run = subprocess.run([args.homesh, os.path.join(ROOT, geo), "-q", "-m", stage, out],
                                     capture_output=True, text=True)
                seconds = time.perf_counter() - start
                if run.returncode != 0:
                    raise RuntimeError(f"{case} {method}: {run.stdout}{run.stderr}")
                q_min, q_mean, triangles, invalid = icn(out)
                rows.append(dict(case=case, method=method, triangles=triangles,
                                 icn_min=f"{q_min:.4f}", icn_mean=f"{q_mean:.4f}",
                                 invalid=invalid, seconds=f"{seconds:.2f}"))
                print(f"{case:13s} {method:17s} {triangles:5d} triangles  ICN min {q_min:.4f}"
                      f"  mean {q_mean:.4f}  invalid {invalid}  {seconds:6.2f} s", flush=True)
    path = os.path.join(args.outdir, "voronoi_vs_gmsh.csv")
    with open(path + ".tmp", "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    os.replace(path + ".tmp", path)
    plot(rows, os.path.join(args.outdir, "voronoi_vs_gmsh.png"))
    print(f"wrote {path}")


def plot(rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(12, 4.5))
    width = 0.8 / len(METHODS)
    colours = plt.cm.tab10(np.arange(len(METHODS)))
    for ax, key, title in [(axes[0], "icn_mean", "mean ICN (mean ratio)"),
                           (axes[1], "icn_min", "worst ICN")]:
        for m, (method, _) in enumerate(METHODS):
            values = [float(next(r[key] for r in rows if r["case"] == c and r["method"] == method))
                      for c, _ in CASES]
            ax.bar(np.arange(len(CASES)) + (m - (len(METHODS) - 1) / 2) * width, values, width,
                   label=method, color=colours[m])
        ax.set_xticks(np.arange(len(CASES)))
        ax.set_xticklabels([c for c, _ in CASES])
        ax.set_title(title)
        ax.set_ylim(0.85 if key == "icn_mean" else 0.4, 1.0)
        ax.grid(axis="y", alpha=0.3)
    handles, labels = axes[0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="lower center", ncol=len(METHODS), fontsize=9)
    fig.suptitle("Linear triangles: homesh voronoi against Gmsh's 2D meshers (Gmsh's "
                 "AnalyseMeshQuality as referee)")
    fig.tight_layout(rect=(0, 0.07, 1, 1))
    fig.savefig(path + ".tmp.png", dpi=110)
    os.replace(path + ".tmp.png", path)


if __name__ == "__main__":
    main()
