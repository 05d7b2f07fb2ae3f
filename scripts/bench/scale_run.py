#!/usr/bin/python3
"""Scale run (issue 8): a linear mesh of about 10^6 triangles through the pipeline on this
machine, with the wall time and peak memory of every stage.

Pipeline, in one process on the Gmsh model of geo/plate_hole.geo (hole radius 0.5 in the
square [-1, 1]^2):
  mesh     homesh.mesh(factor=F)  - Gmsh's frontal mesher, all sizes scaled by F
  layers   homesh.layers(walls="hole", n=5, first=1e-3, ratio=1.3)
  curve    homesh.curve(p=3)      - the default elastic analogy (E = 1/Ae, nu = 0.49, one
                                    increment, solved within reach 2 of the wall, cholmod)
  quality  homesh.quality()       - certified validity and the Q4, Q17, Q11 views
  write    homesh.write(OUTDIR/scale_run.msh)
Each stage is timed with perf_counter (wall) and process_time (CPU); "peak RSS" is the
process' resident-set high-water mark (getrusage ru_maxrss) after the stage, so it is the
peak of all stages so far - the stage that raises it is the one that needs it. The API
certifies the validity of the mesh after every stage (api::run), inside the stage's time.

Usage: PYTHONPATH=build/python /usr/bin/python3 scripts/bench/scale_run.py [--factor F] [OUTDIR]
The default F = 0.017 gives about 10^6 triangles. Writes OUTDIR/scale_run.csv and
OUTDIR/scale_run.png (default out/bench) and prints the table.
"""
import argparse
import csv
import os
import resource
import time

import gmsh
import homesh

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def peak_rss_mib():
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0  # Linux: KiB


def plot(rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    names = [r["stage"] for r in rows]
    fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4))
    a.bar(names, [r["wall_s"] for r in rows], color="tab:blue")
    a.set_ylabel("wall time (s)")
    a.set_title(f"{rows[-1]['triangles']:,} triangles, p = {rows[-1]['order']}")
    for x, r in enumerate(rows):
        a.text(x, r["wall_s"], f"{r['wall_s']:.1f}", ha="center", va="bottom", fontsize=8)
    b.plot(names, [r["peak_rss_mib"] / 1024 for r in rows], "o-", color="tab:red")
    b.set_ylabel("peak RSS so far (GiB)")
    b.set_ylim(bottom=0)
    b.set_title("process high-water mark after each stage")
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("outdir", nargs="?", default=os.path.join(ROOT, "out", "bench"))
    parser.add_argument("--factor", type=float, default=0.017, help="mesh size factor")
    parser.add_argument("--order", type=int, default=3)
    args = parser.parse_args()
    os.makedirs(args.outdir, exist_ok=True)
    msh = os.path.join(args.outdir, "scale_run.msh")

    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.onelab.clear()
    gmsh.open(os.path.join(ROOT, "geo", "plate_hole.geo"))
    homesh.set_quiet(True)
    stages = [
        ("mesh", lambda: homesh.mesh(factor=args.factor)),
        ("layers", lambda: homesh.layers(walls="hole", n=5, first=1e-3, ratio=1.3)),
        ("curve", lambda: homesh.curve(p=args.order)),
        ("quality", lambda: homesh.quality()),
        ("write", lambda: homesh.write(msh)),
    ]
    rows = []
    for name, run in stages:
        wall, cpu = time.perf_counter(), time.process_time()
        result = run()
        wall, cpu = time.perf_counter() - wall, time.process_time() - cpu
        validity = (result or {}).get("validity") or homesh.validity()
        rows.append(dict(stage=name, wall_s=round(wall, 2), cpu_s=round(cpu, 2),
                         peak_rss_mib=round(peak_rss_mib()), order=(result or {}).get("order", ""),
                         nodes=(result or {}).get("nodes", ""),
                         triangles=validity["triangles"], invalid=validity["invalid"],
                         worst=round(validity["worst"], 4)))
        if not rows[-1]["order"] and len(rows) > 1:
            rows[-1]["order"], rows[-1]["nodes"] = rows[-2]["order"], rows[-2]["nodes"]
        print(*rows[-1].values(), flush=True)
    gmsh.finalize()
    with open(os.path.join(args.outdir, "scale_run.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    print(f"\n{'stage':<8} {'wall s':>8} {'cpu s':>8} {'peak RSS MiB':>12} {'order':>5} "
          f"{'nodes':>9} {'triangles':>9} {'invalid':>7} {'worst':>7}")
    for r in rows:
        print(f"{r['stage']:<8} {r['wall_s']:>8.2f} {r['cpu_s']:>8.2f} {r['peak_rss_mib']:>12} "
              f"{r['order']:>5} {r['nodes']:>9} {r['triangles']:>9} {r['invalid']:>7} "
              f"{r['worst']:>7.4f}")
    plot(rows, os.path.join(args.outdir, "scale_run.png"))


if __name__ == "__main__":
    main()
