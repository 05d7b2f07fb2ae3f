#!/usr/bin/python3
"""Benchmark (issue 5, "Against Gmsh's BoundaryLayer field"): homesh's layers stage against
Gmsh's BoundaryLayer field on the same geometry and layer parameters, then curved to p = 2, 3, 4.

Cases: the plate with a hole (geo/plate_hole.geo, walls "hole") and NACA-7526 (geo/naca.geo,
walls "aerofoil", a fan at the trailing-edge point), both with first layer 1e-3, ratio 1.3
and 10 layers (total thickness 0.0426).

Linear layer meshes, each made afresh in its own Gmsh session from the .geo:
  homesh : homesh.mesh() then homesh.layers(walls, n, first, ratio); on NACA normals=multi,
           fan=5, fan_angle=320 (the trailing edge's domain angle is 326 deg);
  gmsh   : a BoundaryLayer field (CurvesList = the wall curves, Size = first, Ratio = ratio,
           Thickness = the total of the n layers, Quads = 0; on NACA FanPointsList = the
           trailing-edge point with Mesh.BoundaryLayerFanElements = 4, the 4 sectors between
           homesh's 5 normals), setAsBoundaryLayer, then generate(2); the .geo's own size
           field stays the background field, as it is for homesh.mesh().
Curvings, each on its own fresh copy of a linear mesh: Gmsh's setOrder(P) (boundary nodes on
the CAD, nothing else moved) and homesh.curve(p=P) (elastic analogy, certified valid), on
both linear meshes, so that the layer mesh and the curving can be judged apart.

Measures: triangles; worst radius ratio Q = 8 (s-a)(s-b)(s-c) / (a b c) (thesis Eq 4.17,
s the half perimeter; 1 equilateral, 0 degenerate) over the linear triangles, and on NACA
over the fan, the triangles with a corner at the trailing-edge point; after curving,
Gmsh's AnalyseMeshQuality plugin (JacobianDeterminant=1) as referee: the number of
triangles with minJ/maxJ <= 0 and the worst minJ/maxJ. Seconds: wall time of the layer
insertion (homesh.mesh + homesh.layers, or generate with the field) and of the curving call.

Timing (issue 20, `--timing`): the README's NACA-7526 stack (15 layers from 1e-3, ratio 1.2,
a fan of 5 normals at the trailing edge) on meshes of about 1e4 and 1e5 triangles (the .geo's
sizes times Mesh.MeshSizeFactor, TIMING_FACTORS; add 1e6 with --timing-1e6). Wall time of
homesh's layers stage alone (homesh.layers, after homesh.mesh, timed apart) against Gmsh's
generate(2) with the BoundaryLayer field above (same factor, same stack; it builds its layers
while it meshes, so its whole meshing is what the stage is set against), each the best of
TIMING_REPEATS fresh runs in one process (one at 1e6), the two alternating; the ratio is
homesh / Gmsh.

Usage: PYTHONPATH=build/python /usr/bin/python3 scripts/bench/layers_vs_gmsh.py [OUTDIR]
       PYTHONPATH=build/python /usr/bin/python3 scripts/bench/layers_vs_gmsh.py --timing [OUTDIR]
Writes OUTDIR/layers_vs_gmsh.csv and OUTDIR/layers_vs_gmsh.png (default out/bench), with
--timing OUTDIR/layers_timing.csv and OUTDIR/layers_timing.png.
"""
import csv
import os
import sys
import time

import gmsh
import homesh
from corpus import radius_ratios
from gmsh_referee import referee
import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

# name, .geo, wall group, whether the wall has a trailing-edge fan
GEOMETRIES = [("plate_hole", "geo/plate_hole.geo", "hole", False),
              ("naca7526", "geo/naca.geo", "aerofoil", True)]
FIRST, RATIO, LAYERS = 1e-3, 1.3, 10
FAN_NORMALS, FAN_ANGLE = 5, 320
ORDERS = [2, 3, 4]
QUALITY_VIEW = "radius ratio (Eq 4.17)"


def total_thickness():
    return FIRST * (RATIO ** LAYERS - 1) / (RATIO - 1)


def open_geo(geo):
    """A fresh Gmsh session with the .geo's CAD. Fresh, not gmsh.clear(): AnalyseMeshQuality
    keeps element data across models; ONELAB is cleared so one .geo's sizes do not leak."""
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.onelab.clear()
    gmsh.open(os.path.join(ROOT, geo))


def wall_curves(wall):
    for dim, tag in gmsh.model.getPhysicalGroups(1):
        if gmsh.model.getPhysicalName(dim, tag) == wall:
            return [int(c) for c in gmsh.model.getEntitiesForPhysicalGroup(dim, tag)]
    raise RuntimeError(f"no physical curve '{wall}'")


def trailing_edge(curves):
    """The end point of the wall curves with the largest x (NACA's trailing edge)."""
    points = {t for c in curves for _, t in gmsh.model.getBoundary([(1, c)], oriented=False)}
    return max(points, key=lambda p: gmsh.model.getValue(0, p, [])[0])


def homesh_layers(wall, fan):
    options = dict(walls=wall, n=LAYERS, first=FIRST, ratio=RATIO)
    if fan:
        options.update(normals="multi", fan=FAN_NORMALS, fan_angle=FAN_ANGLE)
    homesh.mesh()
    return homesh.layers(**options)


def gmsh_layers(wall, fan):
    curves = wall_curves(wall)
    f = gmsh.model.mesh.field.add("BoundaryLayer")
    gmsh.model.mesh.field.setNumbers(f, "CurvesList", curves)
    gmsh.model.mesh.field.setNumber(f, "Size", FIRST)
    gmsh.model.mesh.field.setNumber(f, "Ratio", RATIO)
    # Gmsh adds layers while their total stays below Thickness: a hair above the n-th.
    gmsh.model.mesh.field.setNumber(f, "Thickness", total_thickness() * (1 + 1e-6))
    gmsh.model.mesh.field.setNumber(f, "Quads", 0)
    if fan:
        gmsh.model.mesh.field.setNumbers(f, "FanPointsList", [trailing_edge(curves)])
        gmsh.option.setNumber("Mesh.BoundaryLayerFanElements", FAN_NORMALS - 1)
    gmsh.model.mesh.field.setAsBoundaryLayer(f)
    gmsh.model.mesh.generate(2)


def linear(geo, wall, fan, mesher):
    """Open the .geo and insert the layers with `mesher`; returns its wall-clock seconds."""
    open_geo(geo)
    t = time.perf_counter()
    if mesher == "homesh":
        homesh_layers(wall, fan)
    else:
        gmsh_layers(wall, fan)
    return time.perf_counter() - t


def triangle_corners():
    """Corner coordinates of the model's triangles, #T x 3 x 2, and their element tags."""
    tags, coords, _ = gmsh.model.mesh.getNodes()
    index = np.zeros(int(tags.max()) + 1, dtype=int)
    index[tags.astype(int)] = np.arange(len(tags))
    x = coords.reshape(-1, 3)[:, :2]
    corners, elements = [], []
    for t in gmsh.model.mesh.getElementTypes(2):
        etags, enodes = gmsh.model.mesh.getElementsByType(t)
        nodes = gmsh.model.mesh.getElementProperties(t)[3]
        corners.append(x[index[enodes.astype(int)].reshape(-1, nodes)[:, :3]])
        elements.append(etags)
    return np.concatenate(corners), np.concatenate(elements)


def homesh_view_min():
    """The minimum of the radius-ratio view the layers stage left on the model."""
    for v in gmsh.view.getTags():
        if gmsh.option.getString(f"View[{gmsh.view.getIndex(v)}].Name") == QUALITY_VIEW:
            _, _, data, _, _ = gmsh.view.getModelData(v, 0)
            return min(d[0] for d in data)
    raise RuntimeError("the layers stage left no radius-ratio view")


def curve(p, curver):
    """Curve the model to order p; returns (seconds, error message or '')."""
    t = time.perf_counter()
    try:
        if curver == "homesh":
            homesh.curve(p=p)
        else:
            gmsh.model.mesh.setOrder(p)
        error = ""
    except Exception as e:  # homesh.Error: no certified-valid mesh
        error = str(e).splitlines()[0] if str(e) else type(e).__name__
    return time.perf_counter() - t, error


def run(outdir):
    homesh.set_quiet(True)
    rows = []
    for case, geo, wall, fan in GEOMETRIES:
        for mesher in ["homesh", "gmsh"]:
            seconds = linear(geo, wall, fan, mesher)
            corners, _ = triangle_corners()
            q = radius_ratios(corners)
            if mesher == "homesh":
                assert abs(q.min() - homesh_view_min()) < 1e-9, "Eq 4.17 here and in homesh differ"
            te = ""
            if fan:
                point = gmsh.model.getValue(0, trailing_edge(wall_curves(wall)), [])[:2]
                at = (np.linalg.norm(corners - point, axis=2) < 1e-9).any(axis=1)
                te = q[at].min()
            gmsh.finalize()
            base = dict(case=case, layers=mesher, triangles=len(q), worst_radius_ratio=q.min(),
                        te_worst_radius_ratio=te, layer_seconds=seconds)
            print(f"{case} {mesher} layers: {len(q)} triangles, worst Q {q.min():.4f} "
                  f"(fan at the TE {te}), {seconds:.2f} s", flush=True)
            for p in ORDERS:
                for curver in ["gmsh", "homesh"]:
                    linear(geo, wall, fan, mesher)
                    secs, error = curve(p, curver)
                    curved = all(gmsh.model.mesh.getElementProperties(t)[2] == p
                                 for t in gmsh.model.mesh.getElementTypes(2))
                    invalid, worst, _ = referee() if curved else ("", "", "")
                    gmsh.finalize()
                    rows.append(dict(base, p=p, curving=curver, invalid=invalid,
                                     worst_minJ_maxJ=worst, curve_seconds=secs, error=error))
                    print(f"  p={p} {curver:6s}: invalid {invalid}, worst minJ/maxJ {worst}, "
                          f"{secs:.2f} s {error}", flush=True)
    with open(os.path.join(outdir, "layers_vs_gmsh.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    return rows


def plot(rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(13, 5), sharey=True)
    combos = [("homesh", "homesh"), ("gmsh", "gmsh"), ("gmsh", "homesh"), ("homesh", "gmsh")]
    colours = ["tab:blue", "tab:red", "tab:orange", "tab:cyan"]
    width = 0.2
    for ax, case in zip(axes, dict.fromkeys(r["case"] for r in rows)):
        for j, (layers, curving) in enumerate(combos):
            mine = {r["p"]: r for r in rows
                    if (r["case"], r["layers"], r["curving"]) == (case, layers, curving)}
            xs = [k + (j - 1.5) * width for k in range(len(ORDERS))]
            ys = [max(mine[p]["worst_minJ_maxJ"], -0.2) if mine[p]["invalid"] != "" else 0
                  for p in ORDERS]
            q, te = mine[ORDERS[0]]["worst_radius_ratio"], mine[ORDERS[0]]["te_worst_radius_ratio"]
            quality = f"worst Q {q:.3f}" + (f", TE fan {te:.3f}" if te != "" else "")
            ax.bar(xs, ys, width, color=colours[j], edgecolor="black", linewidth=0.3,
                   label=f"{layers} layers ({quality}), {curving} curving")
            for x, y, p in zip(xs, ys, ORDERS):
                if mine[p]["invalid"] not in ("", 0):
                    ax.text(x, min(y, 0) - 0.01, str(mine[p]["invalid"]), ha="center", va="top",
                            fontsize=8, color="red")
        ax.axhline(0, color="black", linewidth=0.8)
        ax.set_xticks(range(len(ORDERS)))
        ax.set_xticklabels([f"p = {p}" for p in ORDERS])
        ax.set_title(f"{case}: first {FIRST:g}, ratio {RATIO:g}, {LAYERS} layers")
        ax.set_ylim(-0.3, 1.4)
        ax.legend(fontsize=7, loc="upper center")
        ax.grid(axis="y", alpha=0.3)
    axes[0].set_ylabel("worst minJ/maxJ (AnalyseMeshQuality; clipped at -0.2)\n"
                       "red: invalid triangles (minJ/maxJ <= 0)")
    fig.tight_layout()
    fig.savefig(path, dpi=110)


TIMING_FACTORS = [0.5, 0.15]  # about 1e4 and 1e5 triangles before the layers
TIMING_FACTOR_1E6 = 0.05
TIMING_STACK = dict(n=15, first=1e-3, ratio=1.2)
TIMING_REPEATS = 3


def timed_homesh(factor):
    """(seconds of homesh.mesh, of homesh.layers, triangles before, after, worst radius ratio
    after) at this factor."""
    open_geo("geo/naca.geo")
    t = time.perf_counter()
    homesh.mesh(factor=factor)
    meshed = time.perf_counter() - t
    before = sum(len(gmsh.model.mesh.getElementsByType(k)[0])
                 for k in gmsh.model.mesh.getElementTypes(2))
    t = time.perf_counter()
    homesh.layers(walls="aerofoil", normals="multi", fan=FAN_NORMALS, fan_angle=FAN_ANGLE,
                  **TIMING_STACK)
    layered = time.perf_counter() - t
    after = sum(len(gmsh.model.mesh.getElementsByType(k)[0])
                for k in gmsh.model.mesh.getElementTypes(2))
    worst = radius_ratios(triangle_corners()[0]).min()
    gmsh.finalize()
    return meshed, layered, before, after, worst


def timed_gmsh(factor):
    """(seconds of generate(2) with the BoundaryLayer field, triangles, worst radius ratio) at
    this factor."""
    global FIRST, RATIO, LAYERS
    saved = FIRST, RATIO, LAYERS
    FIRST, RATIO, LAYERS = TIMING_STACK["first"], TIMING_STACK["ratio"], TIMING_STACK["n"]
    try:
        open_geo("geo/naca.geo")
        gmsh.option.setNumber("Mesh.MeshSizeFactor", factor)
        t = time.perf_counter()
        gmsh_layers("aerofoil", True)
        seconds = time.perf_counter() - t
        triangles = sum(len(gmsh.model.mesh.getElementsByType(k)[0])
                        for k in gmsh.model.mesh.getElementTypes(2))
        worst = radius_ratios(triangle_corners()[0]).min()
        gmsh.finalize()
    finally:
        FIRST, RATIO, LAYERS = saved
    return seconds, triangles, worst


def timing(outdir, factors):
    homesh.set_quiet(True)
    rows = []
    for factor in factors:
        h, g = [], []
        for _ in range(1 if factor == TIMING_FACTOR_1E6 else TIMING_REPEATS):
            h.append(timed_homesh(factor))
            g.append(timed_gmsh(factor))
        best_h = min(h, key=lambda r: r[1])
        best_g = min(g, key=lambda r: r[0])
        row = dict(factor=factor, triangles_before=best_h[2], homesh_triangles=best_h[3],
                   gmsh_triangles=best_g[1], homesh_mesh_seconds=min(r[0] for r in h),
                   homesh_layers_seconds=best_h[1], gmsh_bl_seconds=best_g[0],
                   ratio=best_h[1] / best_g[0], homesh_worst_rr=best_h[4],
                   gmsh_worst_rr=best_g[2], load=os.getloadavg()[0])
        rows.append(row)
        print(f"factor {factor}: {row['triangles_before']} triangles -> homesh "
              f"{row['homesh_triangles']} in {row['homesh_layers_seconds']:.2f} s (layers stage; "
              f"mesh {row['homesh_mesh_seconds']:.2f} s), Gmsh BoundaryLayer "
              f"{row['gmsh_triangles']} in {row['gmsh_bl_seconds']:.2f} s: ratio "
              f"{row['ratio']:.2f}; worst radius ratio homesh {row['homesh_worst_rr']:.4f}, Gmsh "
              f"{row['gmsh_worst_rr']:.4f} (load {row['load']:.1f})", flush=True)
    with open(os.path.join(outdir, "layers_timing.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    n = [r["triangles_before"] for r in rows]
    ax.loglog(n, [r["homesh_layers_seconds"] for r in rows], "o-", label="homesh layers stage")
    ax.loglog(n, [r["homesh_mesh_seconds"] + r["homesh_layers_seconds"] for r in rows], "o--",
              label="homesh mesh + layers")
    ax.loglog(n, [r["gmsh_bl_seconds"] for r in rows], "s-", label="Gmsh generate + BoundaryLayer")
    for r in rows:
        ax.annotate(f"x{r['ratio']:.2f}", (r["triangles_before"], r["homesh_layers_seconds"]),
                    textcoords="offset points", xytext=(5, -12), fontsize=8)
    ax.set_xlabel("triangles before the layers")
    ax.set_ylabel("wall time, s (best of %d)" % TIMING_REPEATS)
    ax.set_title("NACA-7526, 15 layers from 1e-3, ratio 1.2, TE fan of 5")
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, "layers_timing.png"), dpi=110)
    return rows


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    outdir = args[0] if args else os.path.join(ROOT, "out", "bench")
    os.makedirs(outdir, exist_ok=True)
    if "--timing" in sys.argv:
        timing(outdir, TIMING_FACTORS + ([TIMING_FACTOR_1E6] if "--timing-1e6" in sys.argv else []))
        return
    rows = run(outdir)
    print(f"\n{'case':<11} {'layers':<7} {'tri':>6} {'worst Q':>8} {'fan Q':>7} {'p':>2} "
          f"{'curving':<7} {'invalid':>7} {'worst minJ/maxJ':>15} {'seconds':>8}")
    for r in rows:
        worst = (f"{r['worst_minJ_maxJ']:>15.4f}" if r["invalid"] != "" else f"{'no mesh':>15}")
        te = f"{r['te_worst_radius_ratio']:>7.4f}" if r["te_worst_radius_ratio"] != "" else f"{'-':>7}"
        print(f"{r['case']:<11} {r['layers']:<7} {r['triangles']:>6} "
              f"{r['worst_radius_ratio']:>8.4f} {te} {r['p']:>2} {r['curving']:<7} "
              f"{r['invalid']:>7} {worst} {r['curve_seconds']:>8.2f}  {r['error'][:50]}")
    plot(rows, os.path.join(outdir, "layers_vs_gmsh.png"))


if __name__ == "__main__":
    main()
