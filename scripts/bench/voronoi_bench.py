#!/usr/bin/python3
"""Plot and summarise voronoi_bench.csv (see voronoi_bench.sh).

usage: scripts/bench/voronoi_bench.py CSV PNG

Left: CPU time against the number of seeds S, log-log, per method (CGAL
Delaunay, fast_marching, level_set), with the exponent p of time ~ S^p fitted
by least squares over the points taking 10 ms or more. Right: the share of
CGAL's triangles with their circumcentre in the square (those a partition of
the square can show) that each engine's dual reproduces; the rest are lost at
near-degenerate vertices closer than a cell to another. Prints the table and exponents.
Needs Debian's python3 with numpy and matplotlib.
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    with open(sys.argv[1]) as f:
        rows = list(csv.DictReader(f))
    methods = sorted({r["method"] for r in rows})
    grid = rows[0]["grid"]
    fig, (times, share) = plt.subplots(1, 2, figsize=(12, 5))
    print(f"grid {grid} x {grid}")
    print(f"{'method':<14}{'seeds':>8}{'seconds':>10}{'Mnodes/s':>10}{'triangles':>11}"
          f"{'of CGAL':>9}")
    for k, m in enumerate(methods):
        colour = f"C{k}"  # one colour per method in both panels
        pts = sorted((int(r["seeds"]), float(r["seconds"]), int(r["triangles"]),
                      int(r["matching"]), int(r["cgal_in_square"]))
                     for r in rows if r["method"] == m)
        s = np.array([p[0] for p in pts], dtype=float)
        t = np.array([p[1] for p in pts])
        for seeds, sec, tri, match, ref in pts:
            rate = int(grid) ** 2 / sec / 1e6 if m != "cgal" else float("nan")
            print(f"{m:<14}{seeds:>8}{sec:>10.3f}{rate:>10.2f}{tri:>11}"
                  f"{match / max(ref, 1):>9.4f}")
        fit = t >= 0.01
        label = m
        if fit.sum() >= 2:
            p = np.polyfit(np.log(s[fit]), np.log(t[fit]), 1)[0]
            label += f" (time ~ S^{p:.2f})"
            print(f"{m}: time ~ S^{p:.2f} over S = {int(s[fit].min())}..{int(s[fit].max())}")
        times.loglog(s, t, "o-", color=colour, label=label)
        if m != "cgal":
            share.semilogx(s, [p[3] / max(p[4], 1) for p in pts], "o-", color=colour, label=m)
    times.set_xlabel("seeds S")
    times.set_ylabel("CPU seconds")
    times.set_title(f"crystal growth on a {grid} x {grid} grid vs CGAL Delaunay")
    times.grid(True, which="both", alpha=0.3)
    times.legend()
    share.set_xlabel("seeds S")
    share.set_ylabel("share of CGAL's triangles in the dual")
    share.grid(True, which="both", alpha=0.3)
    share.legend()
    fig.tight_layout()
    fig.savefig(sys.argv[2], dpi=110)
    print("wrote", sys.argv[2])


if __name__ == "__main__":
    main()
