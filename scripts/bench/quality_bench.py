#!/usr/bin/python3
"""Benchmark: homesh's quality stage (certified minJ/maxJ bounds plus the default
measures Q4, Q17, Q11, in one pass) against Gmsh's AnalyseMeshQuality plugin (its
Jacobian bounds alone) on the same quartic meshes, in the same run.

Meshes: a unit disk (curved boundary) meshed by Gmsh with about N triangles and
raised to order 4 by Gmsh's setOrder (boundary nodes on the circle), written once
and read by both. homesh runs as a process, `-m quality` (bounds + Q4, Q17, Q11)
and `-m quality:measures=` (bounds only), on 1 and on 2 OpenMP threads (the
stage's `threads` option); its time is the one its quality stage reports for its
own pass (wall and CPU), reading the file is not counted. Gmsh (4.8, serial
plugin) runs in a fresh Python process: wall and CPU time of plugin.run alone.
Peak memory is each process's maximum RSS (reading the mesh included). Each
measurement is the best (least CPU) of 3 runs, 1 run above 2e5 triangles: the
machine may be shared, so the CPU times are the fairer comparison there. A mesh
file left in OUTDIR by an earlier run (disk_p4_N.msh) is reused, then removed.

Usage: /usr/bin/python3 scripts/bench/quality_bench.py [OUTDIR] [N ...]
Writes OUTDIR/quality_bench.csv and OUTDIR/quality_bench.png (default out/bench).
"""
import csv
import math
import os
import re
import subprocess
import sys

import gmsh

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
HOMESH = os.environ.get("HOMESH", os.path.join(ROOT, "build", "homesh"))

GMSH_RUN = """
import sys, time, gmsh
gmsh.initialize()
gmsh.option.setNumber("General.Terminal", 0)
gmsh.open(sys.argv[1])
for key, value in [("JacobianDeterminant", 1), ("IGEMeasure", 0), ("ICNMeasure", 0),
                   ("CreateView", 1)]:
    gmsh.plugin.setNumber("AnalyseMeshQuality", key, value)
wall, cpu = time.perf_counter(), time.process_time()
gmsh.plugin.run("AnalyseMeshQuality")
print(time.perf_counter() - wall, time.process_time() - cpu)
gmsh.finalize()
"""


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
    gmsh.finalize()


def run_child(args):
    """stdout and peak RSS (MB) of one child process."""
    p = subprocess.Popen(args, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    out = p.stdout.read()
    _, status, usage = os.wait4(p.pid, 0)
    p.returncode = os.waitstatus_to_exitcode(status)
    if p.returncode != 0:
        raise RuntimeError(f"{args} failed ({p.returncode})")
    return out, usage.ru_maxrss / 1024.0


def run_homesh(path, threads, measures, repeats):
    stage = f"quality:threads={threads}" + ("" if measures else ":measures=")
    best = None
    for _ in range(repeats):
        out, peak = run_child([HOMESH, path, "-m", stage])
        m = re.search(r"(\d+) triangles of order 4 "
                      r"\(bounds and measures ([\d.]+) s, ([\d.]+) s CPU", out)
        r = (float(m.group(2)), float(m.group(3)), peak,
             int(re.search(r"validity: (\d+) invalid", out).group(1)), int(m.group(1)))
        best = r if best is None or r[1] < best[1] else best
    return best


def run_gmsh(path, repeats):
    best = None
    for _ in range(repeats):
        out, peak = run_child(["/usr/bin/python3", "-c", GMSH_RUN, path])
        wall, cpu = (float(v) for v in out.split()[-2:])
        best = (wall, cpu, peak) if best is None or cpu < best[1] else best
    return best


def main():
    outdir = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "out", "bench")
    sizes = [int(float(a)) for a in sys.argv[2:]] or [10**5, 10**6]
    os.makedirs(outdir, exist_ok=True)
    rows = []
    for n in sizes:
        path = os.path.join(outdir, f"disk_p4_{n}.msh")
        if not os.path.exists(path):
            make_mesh(n, path)
        repeats = 3 if n <= 2 * 10**5 else 1
        g_wall, g_cpu, g_peak = run_gmsh(path, repeats)
        for threads in (1, 2):
            b_wall, b_cpu, _, _, _ = run_homesh(path, threads, False, repeats)
            wall, cpu, peak, invalid, count = run_homesh(path, threads, True, repeats)
            rows.append(dict(triangles=count, homesh_threads=threads, homesh_bounds_s=b_wall,
                             homesh_bounds_cpu_s=b_cpu, homesh_total_s=wall,
                             homesh_total_cpu_s=cpu, gmsh_bounds_s=g_wall,
                             gmsh_bounds_cpu_s=g_cpu, ratio_wall=wall / g_wall,
                             ratio_cpu=cpu / g_cpu, homesh_peak_mb=peak, gmsh_peak_mb=g_peak,
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
    fig, ax = plt.subplots(figsize=(6.5, 4))
    for threads, style in ((1, "o-"), (2, "s-")):
        sel = [r for r in rows if r["homesh_threads"] == threads]
        n = [r["triangles"] for r in sel]
        ax.loglog(n, [r["homesh_total_s"] for r in sel], style,
                  label=f"homesh bounds + Q4, Q17, Q11, {threads} thread(s)")
    sel = [r for r in rows if r["homesh_threads"] == 1]
    n = [r["triangles"] for r in sel]
    ax.loglog(n, [r["homesh_bounds_s"] for r in sel], "s--", label="homesh bounds only, 1 thread")
    ax.loglog(n, [r["gmsh_bounds_s"] for r in sel], "^-", label="Gmsh AnalyseMeshQuality (serial)")
    ax.set_xlabel("quartic triangles")
    ax.set_ylabel("wall seconds")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, "quality_bench.png"), dpi=100)


if __name__ == "__main__":
    main()
