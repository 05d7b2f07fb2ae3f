#!/usr/bin/python3
"""Benchmark: homesh's quality stage (certified minJ/maxJ bounds plus the default
measures Q4, Q17, Q11) against Gmsh's AnalyseMeshQuality plugin (its Jacobian
bounds alone) on the same quartic meshes, in the same run.

Meshes: a unit disk (curved boundary) meshed by Gmsh with about N triangles and
raised to order 4 by Gmsh's setOrder (boundary nodes on the circle). homesh's
times are the ones its quality stage reports for its own work (reading the file
is Gmsh's in both cases and is not counted); Gmsh's is the wall time of the
plugin run. Peak memory is the homesh process's maximum RSS.

Usage: /usr/bin/python3 scripts/bench/quality_bench.py [OUTDIR] [N ...]
Writes OUTDIR/quality_bench.csv and OUTDIR/quality_bench.png (default out/bench).
"""
import csv
import math
import os
import re
import resource
import subprocess
import sys
import time

import gmsh

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
HOMESH = os.environ.get("HOMESH", os.path.join(ROOT, "build", "homesh"))


def make_mesh(n, path):
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.model.occ.addDisk(0, 0, 0, 1, 1)
    gmsh.model.occ.synchronize()
    h = math.sqrt(math.pi / (0.433 * n))
    gmsh.option.setNumber("Mesh.MeshSizeMin", h)
    gmsh.option.setNumber("Mesh.MeshSizeMax", h)
    gmsh.model.mesh.generate(2)
    gmsh.model.mesh.setOrder(4)
    gmsh.option.setNumber("Mesh.Binary", 1)
    gmsh.write(path)
    count = sum(len(t) for t in gmsh.model.mesh.getElements(2)[1])
    gmsh.finalize()
    return count


def run_homesh(path):
    before = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss
    out = subprocess.run([HOMESH, path, "-m", "quality"], capture_output=True, text=True, check=True)
    peak_kb = max(before, resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)
    m = re.search(r"bounds ([\d.]+) s, measures ([\d.]+) s", out.stdout)
    invalid = int(re.search(r"validity: (\d+) invalid", out.stdout).group(1))
    return float(m.group(1)), float(m.group(2)), peak_kb / 1024.0, invalid


def run_gmsh(path):
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.open(path)
    gmsh.plugin.setNumber("AnalyseMeshQuality", "JacobianDeterminant", 1)
    gmsh.plugin.setNumber("AnalyseMeshQuality", "IGEMeasure", 0)
    gmsh.plugin.setNumber("AnalyseMeshQuality", "ICNMeasure", 0)
    gmsh.plugin.setNumber("AnalyseMeshQuality", "CreateView", 1)
    t = time.perf_counter()
    gmsh.plugin.run("AnalyseMeshQuality")
    elapsed = time.perf_counter() - t
    gmsh.finalize()
    return elapsed


def main():
    outdir = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "out", "bench")
    sizes = [int(float(a)) for a in sys.argv[2:]] or [10**4, 10**5, 10**6]
    os.makedirs(outdir, exist_ok=True)
    rows = []
    for n in sizes:
        path = os.path.join(outdir, f"disk_p4_{n}.msh")
        count = make_mesh(n, path)
        bounds, measures, peak_mb, invalid = run_homesh(path)
        g = run_gmsh(path)
        rows.append(dict(triangles=count, homesh_bounds_s=bounds, homesh_measures_s=measures,
                         homesh_total_s=bounds + measures, gmsh_bounds_s=g,
                         ratio_total_vs_gmsh=(bounds + measures) / g, homesh_peak_mb=peak_mb,
                         invalid=invalid))
        print(rows[-1], flush=True)
        os.remove(path)
    with open(os.path.join(outdir, "quality_bench.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    n = [r["triangles"] for r in rows]
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.loglog(n, [r["homesh_total_s"] for r in rows], "o-", label="homesh: bounds + Q4, Q17, Q11")
    ax.loglog(n, [r["homesh_bounds_s"] for r in rows], "s--", label="homesh: certified bounds")
    ax.loglog(n, [r["gmsh_bounds_s"] for r in rows], "^-", label="Gmsh AnalyseMeshQuality")
    ax.set_xlabel("quartic triangles")
    ax.set_ylabel("seconds")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, "quality_bench.png"), dpi=100)


if __name__ == "__main__":
    main()
