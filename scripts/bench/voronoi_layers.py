#!/usr/bin/python3
"""Benchmark (issue 22): boundary layers from a metric, the voronoi mesher with metric=bl against
Gmsh's BoundaryLayer field, on every corpus model that Gmsh's layers mesh (scripts/bench/corpus.py,
mesher gmsh_bl: first cells 1e-3..1e-5 of the chord, 20:1 to 2000:1 at the walls).

For each model, in one run, each in a fresh process:
  gmsh bl      : the corpus's own mesh, Gmsh's BoundaryLayer field (first cell `first`, ratio,
                 fans at sharp points) then generate(2);
  voronoi bl   : homesh.voronoi(metric="bl", bl_aspect=h_wall/first, bl_thickness=1/(ratio-1)),
                 the same size field (Gmsh's sizes away from the walls), the first cell and the
                 growth per cell of the Gmsh layers (h_n grows by (1 - 1/A)/T per unit step);
then each mesh curved by homesh.curve(p=3) and refereed by Gmsh's AnalyseMeshQuality plugin.

Writes voronoi_layers.csv and voronoi_layers.png to --out (default out/bench/voronoi):
triangles, mesh seconds (the mesher's call), filled triangles (voronoi), the voronoi mesh's
worst and mean shape in the metric, and after curve:p=3 the invalid count, worst minJ/maxJ and
curve seconds. Times are the least of --repeat runs.

  /usr/bin/python3 scripts/bench/voronoi_layers.py [--cases PATTERN] [--repeat N] [--out DIR]
(with PYTHONPATH=build/python)
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

METHODS = ["gmsh bl", "voronoi bl"]
FIELDS = ["case", "method", "aspect", "status", "triangles", "seconds", "filled", "columns",
          "metric_min", "metric_mean", "invalid", "worst", "curve_seconds", "error"]


def child(conn, name, method):
    import gmsh
    from gmsh_referee import referee
    c = corpus.case(name)
    row = dict(case=name, method=method, status="ok", aspect=round(c.h_wall / c.first))
    try:
        gmsh.initialize()
        gmsh.option.setNumber("General.Terminal", 0)
        _, walls, _ = corpus.unmeshed(c)
        import homesh
        homesh.set_quiet(True)
        start = time.perf_counter()
        if method == "gmsh bl":
            corpus._gmsh_bl(c, walls)
            row["seconds"] = time.perf_counter() - start
        else:
            r = homesh.voronoi(metric="bl", bl_aspect=str(c.h_wall / c.first),
                               bl_thickness=str(1 / (c.ratio - 1)))
            row["seconds"] = time.perf_counter() - start
            res = r["results"]
            row.update(filled=res["filled_triangles"], columns=res["column_seeds"],
                       metric_min=res["metric_quality_min"],
                       metric_mean=res["metric_quality_mean"])
        row["triangles"] = sum(len(t) for t in gmsh.model.mesh.getElements(2)[1])
        start = time.perf_counter()
        try:
            homesh.curve(p=3)
        except Exception as e:  # noqa: BLE001 (homesh writes no mesh it cannot certify)
            row.update(status="curve failed", error=str(e).splitlines()[0][:200])
        row["curve_seconds"] = time.perf_counter() - start
        if row["status"] == "ok":
            invalid, worst, _ = referee()
            row.update(invalid=invalid, worst=worst)
            if invalid:
                row["status"] = "invalid"
    except Exception as e:  # noqa: BLE001 (recorded, the run goes on)
        row.update(status="error", error=str(e).splitlines()[0][:200])
    conn.send(row)


def plot(rows, cases, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
    by = {(r["case"], r["method"]): r for r in rows}
    fig, ax = plt.subplots(2, 1, figsize=(12, 8), sharex=True)
    x = np.arange(len(cases))
    for k, m in enumerate(METHODS):
        worst = [float(by[(c, m)].get("worst") or 0) for c in cases]
        ax[0].bar(x + (k - 0.5) * 0.4, worst, 0.4, label=m)
        g = [float(by[(c, "gmsh bl")].get("seconds") or np.nan) for c in cases]
        if m == "voronoi bl":
            v = [float(by[(c, m)].get("seconds") or np.nan) for c in cases]
            ax[1].bar(x, np.array(v) / np.array(g), 0.6, color="C1", label="voronoi / gmsh bl")
    ax[0].axhline(0.8, color="k", lw=0.8, ls="--")
    ax[0].set_ylabel("worst minJ/maxJ after curve:p=3")
    ax[0].set_ylim(0, 1)
    ax[0].legend()
    ax[1].axhline(3, color="k", lw=0.8, ls="--")
    ax[1].set_ylabel("mesh time / Gmsh BoundaryLayer's")
    ax[1].set_yscale("log")
    ax[1].set_xticks(x)
    ax[1].set_xticklabels([f"{c} ({by[(c, 'voronoi bl')]['aspect']}:1)" for c in cases],
                          rotation=70, ha="right", fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=100)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--cases", default="*")
    parser.add_argument("--out", default=os.path.join(ROOT, "out", "bench", "voronoi"))
    parser.add_argument("--timeout", type=float, default=600)
    parser.add_argument("--repeat", type=int, default=1,
                        help="runs of each method on each model; the least time is kept")
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    cases = [c.name for c in corpus.CASES if c.mesher == "gmsh_bl" and
             any(fnmatch.fnmatch(c.name, p) for p in args.cases.split(","))]
    rows = []
    for c in cases:
        for m in METHODS:
            r = corpus.least_time(lambda: corpus.run_method(child, c, m, args.timeout), args.repeat)
            rows.append(r)
            if r["status"] in ("ok", "invalid"):
                print(f"{c:26s} {m:11s} {r['aspect']:5d}:1 {r['triangles']:6d} tri "
                      f"{r['seconds']:6.2f} s  filled {r.get('filled', '-')!s:>2}  p=3 worst "
                      f"{r['worst']:.3f} invalid {r['invalid']} ({r['curve_seconds']:.2f} s)"
                      f" {r.get('error', '')}", flush=True)
            else:
                print(f"{c:26s} {m:11s} {r['status']} ({r.get('seconds', 0):.2f} s): "
                      f"{r.get('error', '')}", flush=True)
    path = os.path.join(args.out, "voronoi_layers.csv")
    corpus.write_rows(path, FIELDS, rows)
    plot(rows, cases, os.path.join(args.out, "voronoi_layers.png"))
    print(f"wrote {path}")


if __name__ == "__main__":
    main()
