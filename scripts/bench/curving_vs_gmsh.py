#!/usr/bin/python3
"""Benchmark (issue 4, "Against Gmsh, same meshes, same run"): homesh's curve stage
against Gmsh's own high-order curving on exactly the same linear boundary-layer meshes.

Cases: the plate with a hole (walls "hole") and NACA-7526 (walls "aerofoil"), each with
triangle boundary layers made by homesh's layers stage, growth ratio 1.3, first cell
1e-3 (10 layers, total 0.0426) and 1e-4 (18 layers, total 0.0372: 10 layers would be only
0.0046 thick, so n grows to keep a comparable total thickness), curved to p = 2, 3, 4.

Every variant starts from the same linear mesh, re-created deterministically (open the
.geo, homesh.mesh(), homesh.layers(...)) so that the model keeps its CAD:
  homesh  : homesh.curve(p=P) with its defaults (E = 1/Ae, nu = 0.49, one load increment,
            the linear mesh's vertices held, solved within 2 wall-triangle sizes of the wall),
            the same on the whole mesh, the same with every interior node free, the plain
            analogy (E = 1, nu = 0.4, 4 increments, nodes free, whole mesh) and stiff_shear
            power 3 in 4 increments;
  gmsh    : gmsh.model.mesh.setOrder(P) (boundary nodes on the CAD) alone, then followed
            by optimize("HighOrderElastic") with Mesh.HighOrderNumLayers 6 and 20,
            optimize("HighOrderFastCurving"), and optimize("HighOrder") (Gmsh's optimiser).
Referee for all: Gmsh's AnalyseMeshQuality plugin (JacobianDeterminant=1), per-element
"minJ/maxJ" view: number of elements with minJ/maxJ <= 0 and the worst value. Seconds are
the wall time (perf_counter) of the curving calls alone: homesh.curve, or setOrder plus
optimize for Gmsh. A call that raises is reported with its message (column error); its
mesh is still refereed if it is of order P (Gmsh's optimiser raises when it misses its
target but leaves its mesh in place).

Usage: PYTHONPATH=build/python /usr/bin/python3 scripts/bench/curving_vs_gmsh.py [OUTDIR]
Writes OUTDIR/curving_vs_gmsh.csv and OUTDIR/curving_vs_gmsh.png (default out/bench).
"""
import csv
import os
import sys
import time

import gmsh
import homesh
from gmsh_referee import referee

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

GEOMETRIES = [("plate_hole", "geo/plate_hole.geo", "hole"), ("naca7526", "geo/naca.geo", "aerofoil")]
LAYERS = {1e-3: 10, 1e-4: 18}  # first cell -> number of layers (ratio 1.3)
RATIO = 1.3
ORDERS = [2, 3, 4]

HOMESH_METHODS = {
    "homesh default": dict(),  # E = 1/Ae, nu = 0.49, 1 increment, vertices fixed, reach 2
    "homesh whole mesh": dict(reach=0),
    "homesh vertices free": dict(vertices="free"),
    "homesh plain": dict(formulation="plain", nu=0.4, increments=4, reach=0, vertices="free"),
    "homesh stiff_shear^3": dict(formulation="stiff_shear", power=3, increments=4),
}
GMSH_METHODS = {
    "gmsh setOrder": (None, 6),
    "gmsh elastic L6": ("HighOrderElastic", 6),
    "gmsh elastic L20": ("HighOrderElastic", 20),
    "gmsh fastcurving": ("HighOrderFastCurving", 6),
    "gmsh optimize": ("HighOrder", 6),
}


def linear_mesh(geo, wall, first):
    """A fresh Gmsh session whose model is the .geo's CAD with homesh's linear boundary-layer
    mesh. Fresh, not gmsh.clear(): AnalyseMeshQuality keeps element data across models; and
    the ONELAB parameters are cleared, or the plate's "Mesh size/LcFarfield" would size NACA."""
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.onelab.clear()
    gmsh.open(os.path.join(ROOT, geo))
    homesh.mesh()
    homesh.layers(walls=wall, n=LAYERS[first], first=first, ratio=RATIO)


def curved_to(p):
    """Whether the model's triangles are of order p: what a curving left, even if it then raised
    (Gmsh's optimiser raises when it misses its target but keeps its mesh)."""
    return all(gmsh.model.mesh.getElementProperties(t)[2] == p
               for t in gmsh.model.mesh.getElementTypes(2))


def timed(curving):
    """(seconds, error) of curving(); error is the message of an exception ('' if none)."""
    t = time.perf_counter()
    try:
        curving()
        error = ""
    except Exception as e:  # homesh.Error (not certified valid) or a Gmsh error
        error = str(e).splitlines()[0] if str(e) else type(e).__name__
    return time.perf_counter() - t, error


def run_homesh(p, options):
    return timed(lambda: homesh.curve(p=p, **options))


def run_gmsh(p, method, layers):
    gmsh.option.setNumber("Mesh.HighOrderNumLayers", layers)

    def curving():
        gmsh.model.mesh.setOrder(p)
        if method:
            gmsh.model.mesh.optimize(method)
    return timed(curving)


def plot(rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    cases = list(dict.fromkeys((r["case"], r["first"], r["p"]) for r in rows))
    methods = list(dict.fromkeys(r["method"] for r in rows))
    by = {(r["case"], r["first"], r["p"], r["method"]): r for r in rows if r["invalid"] != ""}
    width = 0.8 / len(methods)
    fig, ax = plt.subplots(figsize=(16, 6))
    cmap = plt.get_cmap("tab10")
    for j, m in enumerate(methods):
        xs, ys, kept = [], [], []
        for i, c in enumerate(cases):
            r = by.get(c + (m,))
            if r:
                xs.append(i + (j - (len(methods) - 1) / 2) * width)
                ys.append(max(r["worst"], -0.2))
                kept.append(r)
        bars = ax.bar(xs, ys, width, label=m, color=cmap(j % 10),
                      hatch="//" if m.startswith("gmsh") else None, edgecolor="black", linewidth=0.3)
        for x, r, b in zip(xs, kept, bars):
            if r["invalid"] > 0:
                ax.text(x, min(b.get_height(), 0) - 0.01, f"{r['invalid']}", rotation=90,
                        ha="center", va="top", fontsize=6, color="red")
    ax.axhline(0, color="black", linewidth=0.8)
    ax.set_xticks(range(len(cases)))
    ax.set_xticklabels([f"{c}\nfirst {f:g}\np={p}" for c, f, p in cases], fontsize=7)
    ax.set_ylabel("worst minJ/maxJ (Gmsh AnalyseMeshQuality; clipped at -0.2)")
    ax.set_ylim(-0.35, 1.05)
    ax.set_title("Curving the same boundary-layer meshes: homesh vs Gmsh "
                 "(red numbers: invalid elements, minJ/maxJ <= 0; no bar: no mesh of order p)")
    ax.legend(fontsize=7, ncol=3, loc="upper right")
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def main():
    outdir = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "out", "bench")
    os.makedirs(outdir, exist_ok=True)
    homesh.set_quiet(True)
    rows = []
    for case, geo, wall in GEOMETRIES:
        for first in LAYERS:
            for p in ORDERS:
                variants = [(m, lambda o=o: run_homesh(p, o)) for m, o in HOMESH_METHODS.items()]
                variants += [(m, lambda n=n, k=k: run_gmsh(p, n, k))
                             for m, (n, k) in GMSH_METHODS.items()]
                for method, run in variants:
                    linear_mesh(geo, wall, first)
                    seconds, error = run()
                    invalid, worst, triangles = referee() if curved_to(p) else ("", "", "")
                    gmsh.finalize()
                    rows.append(dict(case=case, first=first, p=p, method=method, invalid=invalid,
                                     worst=worst, seconds=seconds, triangles=triangles,
                                     error=error))
                    print(*rows[-1].values(), flush=True)
    with open(os.path.join(outdir, "curving_vs_gmsh.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    print(f"\n{'case':<11} {'first':>6} {'p':>2} {'method':<24} {'invalid':>7} {'worst':>9} {'seconds':>8}")
    for r in rows:
        quality = (f"{r['invalid']:>7} {r['worst']:>9.4f}" if r["invalid"] != ""
                   else f"{'no mesh':>17}")
        print(f"{r['case']:<11} {r['first']:>6g} {r['p']:>2} {r['method']:<24} {quality} "
              f"{r['seconds']:>8.3f}  {r['error'][:60]}")
    summary(rows)
    plot(rows, os.path.join(outdir, "curving_vs_gmsh.png"))


def best(rows):
    """The row of fewest invalid elements, then highest worst minJ/maxJ (None if no mesh)."""
    rated = [r for r in rows if r["invalid"] != ""]
    return min(rated, key=lambda r: (r["invalid"], -r["worst"])) if rated else None


def summary(rows):
    """Per case: homesh's default, best homesh and best Gmsh variant, and whether the default
    beats Gmsh's best: better (valid, and a higher worst minJ/maxJ, or Gmsh has no valid
    result) and faster (less wall time than Gmsh's best valid variant; "-" if none is valid)."""
    print(f"\n{'case':<11} {'first':>6} {'p':>2} | {'homesh default':>21} | "
          f"{'best homesh':>42} | {'best gmsh':>39} | default better & faster")
    for case in dict.fromkeys((r["case"], r["first"], r["p"]) for r in rows):
        mine = [r for r in rows if (r["case"], r["first"], r["p"]) == case]
        default = next(r for r in mine if r["method"] == "homesh default")
        h = best([r for r in mine if r["method"].startswith("homesh")])
        g = best([r for r in mine if r["method"].startswith("gmsh")])
        cell = lambda r: f"{r['invalid']:>4} {r['worst']:>7.4f} {r['seconds']:>7.2f}s"
        valid = default["invalid"] == 0
        better = valid and (g["invalid"] > 0 or default["worst"] > g["worst"])
        faster = "-" if g["invalid"] > 0 else ("yes" if default["seconds"] < g["seconds"] else "NO")
        print(f"{case[0]:<11} {case[1]:>6g} {case[2]:>2} | {cell(default)} | "
              f"{h['method']:<20} {cell(h)} | {g['method']:<17} {cell(g)} | "
              f"{'yes' if better else 'NO'} & {faster}")


if __name__ == "__main__":
    main()
