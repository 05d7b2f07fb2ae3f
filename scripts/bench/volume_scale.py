#!/usr/bin/python3
"""Scale of the 3D curving (issue 24): a unit ball cut out of the box [-2, 2]^3, meshed by
Gmsh's Delaunay mesher at sizes giving about 1e5, 3e5 and 1e6 tetrahedra, curved to p = 2,
beside Gmsh's setOrder on the same linear mesh.

Methods, each in its own child process (a fresh Gmsh session that builds and meshes the model
with General.NumThreads 1, so every method starts from the same linear mesh; the tetrahedron
count is checked equal):
  homesh curve     homesh.curve(p=2), then homesh.quality(measures="Q10")
  gmsh setOrder    gmsh.model.mesh.setOrder(2), then Gmsh's AnalyseMeshQuality (the referee)
  gmsh elastic     setOrder(2) + optimize("HighOrderElastic"), on the sizes up to --elastic-max
                   tetrahedra only (its solve on the whole mesh grows too fast beyond).
Times are wall seconds of the curving call and of the quality call; peak MB is the child's
resident-set high-water mark after meshing (base) and at the end (ru_maxrss), so peak - base is
what curving and quality added. Worst is the referee's minJ/maxJ (AnalyseMeshQuality) for every
method, homesh's own certified value beside it.

Usage: PYTHONPATH=build/python /usr/bin/python3 scripts/bench/volume_scale.py
           [--sizes 0.22,0.12,0.065] [--elastic-max 200000] [--out out/bench/volume_scale]
Writes OUT/volume_scale.csv and OUT/volume_scale.png and prints the table.
"""
import argparse
import csv
import multiprocessing as mp
import os
import resource
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)


def peak_mb():
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0


def build(size):
    import gmsh
    gmsh.clear()
    gmsh.model.occ.addBox(-2, -2, -2, 4, 4, 4, 1)
    gmsh.model.occ.addSphere(0, 0, 0, 1, 2)
    gmsh.model.occ.cut([(3, 1)], [(3, 2)])
    gmsh.model.occ.synchronize()
    gmsh.option.setNumber("General.NumThreads", 1)
    gmsh.option.setNumber("Mesh.Algorithm3D", 1)
    gmsh.option.setNumber("Mesh.MeshSizeMax", size)
    gmsh.model.mesh.generate(3)
    return len(gmsh.model.mesh.getElementsByType(4)[0])


def referee():
    """Gmsh's AnalyseMeshQuality over the tetrahedra: (invalid, worst)."""
    import gmsh
    for name, value in [("JacobianDeterminant", 1), ("DimensionOfElements", 3), ("CreateView", 1)]:
        gmsh.plugin.setNumber("AnalyseMeshQuality", name, value)
    gmsh.plugin.run("AnalyseMeshQuality")
    view = gmsh.view.getTags()[-1]
    _, _, data, _, _ = gmsh.view.getModelData(view, 0)
    values = [d[0] for d in data]
    return sum(v <= 0 for v in values), min(values)


def child(method, size, queue):
    import gmsh
    gmsh.initialize()
    gmsh.option.setNumber("General.Verbosity", 1)
    import homesh  # noqa: F401 (imported before the clock starts)
    row = {"method": method, "size": size}
    row["tetrahedra"] = build(size)
    row["base_mb"] = round(peak_mb(), 1)
    t0 = time.perf_counter()
    if method == "homesh curve":
        r = homesh.curve(p=2)
        row["curve_s"] = time.perf_counter() - t0
        row["homesh_worst"] = r["validity"]["worst"]
        t1 = time.perf_counter()
        homesh.quality(measures="Q10")
        row["quality_s"] = time.perf_counter() - t1
    else:
        gmsh.model.mesh.setOrder(2)
        if method == "gmsh elastic":
            gmsh.model.mesh.optimize("HighOrderElastic")
        row["curve_s"] = time.perf_counter() - t0
    t1 = time.perf_counter()
    row["invalid"], row["worst"] = referee()
    row["referee_s"] = time.perf_counter() - t1
    row["peak_mb"] = round(peak_mb(), 1)
    queue.put(row)
    gmsh.finalize()


def run(method, size):
    ctx = mp.get_context("spawn")
    queue = ctx.Queue()
    proc = ctx.Process(target=child, args=(method, size, queue))
    proc.start()
    row = queue.get()
    proc.join()
    return row


def plot(rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (a, b) = plt.subplots(1, 2, figsize=(10, 4))
    for method in sorted({r["method"] for r in rows}):
        mine = sorted((r for r in rows if r["method"] == method), key=lambda r: r["tetrahedra"])
        n = [r["tetrahedra"] for r in mine]
        a.loglog(n, [r["curve_s"] for r in mine], "o-", label=method)
        b.loglog(n, [r["peak_mb"] for r in mine], "o-", label=method)
    a.set_xlabel("tetrahedra")
    a.set_ylabel("curving wall seconds (p = 2)")
    b.set_xlabel("tetrahedra")
    b.set_ylabel("peak resident MB")
    a.legend()
    a.grid(True, which="both", alpha=0.3)
    b.grid(True, which="both", alpha=0.3)
    fig.suptitle("3D curving at scale: unit ball in a box, p = 2")
    fig.tight_layout()
    fig.savefig(path, dpi=120)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--sizes", default="0.22,0.12,0.065")
    ap.add_argument("--elastic-max", type=int, default=200000)
    ap.add_argument("--out", default="out/bench/volume_scale")
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    rows = []
    for size in [float(s) for s in args.sizes.split(",")]:
        for method in ("homesh curve", "gmsh setOrder", "gmsh elastic"):
            if method == "gmsh elastic" and rows and rows[-1]["tetrahedra"] > args.elastic_max:
                continue
            row = run(method, size)
            rows.append(row)
            print(f"{row['tetrahedra']:8d} {method:14s} curve {row['curve_s']:7.2f} s  "
                  f"quality {row.get('quality_s', float('nan')):6.2f} s  invalid {row['invalid']}  "
                  f"worst {row['worst']:.4f}  peak {row['peak_mb']:7.1f} MB "
                  f"(base {row['base_mb']:.1f})", flush=True)
    fields = ["size", "tetrahedra", "method", "curve_s", "quality_s", "referee_s", "invalid",
              "worst", "homesh_worst", "base_mb", "peak_mb"]
    with open(os.path.join(args.out, "volume_scale.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields)
        w.writeheader()
        for r in rows:
            w.writerow({k: r.get(k, "") for k in fields})
    plot(rows, os.path.join(args.out, "volume_scale.png"))


if __name__ == "__main__":
    main()
