#!/usr/bin/python3
"""Benchmark (issue 20): homesh's layers stage against Gmsh's BoundaryLayer field on every
geometry of the corpus that has Gmsh's layers, each then curved, p = 2..4.

Pairs: every gmsh_bl case of scripts/bench/corpus.py (Gmsh's BoundaryLayer field, fans at
sharp wall points) and its twin of the layers family (`corpus.py --family layers`: the same
CAD, size field, first cell, ratio, count and fans, the layers made by homesh's `layers` stage
on Gmsh's mesh of the domain). 17 geometries: aerofoils thin to thick, cambered, at incidence,
fine and coarse; main + flap and slat + main + flap; circles, ellipses, stars, an L-shape and a
plate with holes.

Linear layer meshes (each pair built afresh in its own process): triangles, worst radius ratio
(thesis Eq 4.17), seconds: Gmsh's generate(2) with the field (it builds its layers while it
meshes) against homesh's generate(2) + layers (the layers stage alone given apart).
Curved (the issue's target): homesh's layers + homesh's curve (run here by curving_corpus.py
--family layers --methods homesh, into OUT) against Gmsh's layers + Gmsh's best valid curving
(setOrder, HighOrderElastic with 6 and 20 layers, FastCurving, HighOrder: the rows of the
curving corpus' CSV, --gmsh-csv, for the gmsh_bl case; their run, same linear meshes) and, for
context, Gmsh's layers + homesh's curve from the same CSV. Referee: Gmsh's AnalyseMeshQuality.
A run meets the target when homesh's pair is valid with worst minJ/maxJ >= 0.8 and at least
Gmsh's best valid method's (no valid Gmsh method: >= 0.8 alone).

Usage:
  PYTHONPATH=build/python /usr/bin/python3 scripts/bench/layers_corpus.py
      [--cases PATTERN] [--orders 2,3,4] [--out out/bench/layers_corpus]
      [--gmsh-csv docs/bench/curving_corpus.csv] [--timeout 120] [--report-only]
Writes OUT/layers_linear.csv (per pair), OUT/curving_corpus.csv (homesh's curving of the
twins), OUT/layers_corpus.md (tables and the summary) and OUT/layers_corpus.png.
"""
import argparse
import csv
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
ROOT = os.path.dirname(os.path.dirname(HERE))

import corpus  # noqa: E402
import curving_corpus  # noqa: E402

LINEAR_FIELDS = ["geometry", "first", "ratio", "layers", "gmsh_triangles", "gmsh_worst_rr",
                 "gmsh_seconds", "homesh_triangles", "homesh_worst_rr", "homesh_seconds",
                 "homesh_layers_seconds", "error"]


def built(c):
    """corpus.build(c) in a fresh Gmsh session in a child process: its record, or an error."""
    return curving_corpus.in_child(lambda: corpus.build(c))


def geometry(name):
    return name.replace("_hl_", "_")


def linear(pairs, path):
    rows = []
    for hl, bl in pairs:
        g, h = built(bl), built(hl)
        row = dict(geometry=geometry(hl.name), first=hl.first, ratio=hl.ratio, layers=hl.n,
                   error="")
        for who, rec in (("gmsh", g), ("homesh", h)):
            if isinstance(rec, str):
                row["error"] += f"{who}: {rec} "
                continue
            row[f"{who}_triangles"] = rec["triangles"]
            row[f"{who}_worst_rr"] = rec["worst_radius_ratio"]
            row[f"{who}_seconds"] = rec["mesh_seconds"]
        if not isinstance(h, str):
            row["homesh_layers_seconds"] = h["layers_seconds"]
        rows.append(row)
        print(f"{row['geometry']}: Gmsh {row.get('gmsh_triangles')} triangles, worst RR "
              f"{row.get('gmsh_worst_rr', math.nan):.3f}, {row.get('gmsh_seconds', math.nan):.2f} s"
              f"; homesh {row.get('homesh_triangles')}, {row.get('homesh_worst_rr', math.nan):.3f}"
              f", {row.get('homesh_seconds', math.nan):.2f} s (layers "
              f"{row.get('homesh_layers_seconds', math.nan):.2f} s) {row['error']}", flush=True)
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=LINEAR_FIELDS, restval="")
        w.writeheader()
        w.writerows(rows)


def best(rows, case, p, methods):
    """The valid row of the highest worst minJ/maxJ among `methods` for (case, p), or None."""
    ok = [r for r in rows if r["case"] == case and r["p"] == p and r["method"] in methods
          and curving_corpus.valid(r)]
    return max(ok, key=lambda r: r["worst"]) if ok else None


def analyse(pairs, mine, gmsh_rows, orders):
    gmsh_methods = [m for m in curving_corpus.METHODS if m.startswith("gmsh")]
    E = []
    for hl, bl in pairs:
        for p in orders:
            h = best(mine, hl.name, p, ["homesh"])
            tried = [r for r in mine if r["case"] == hl.name and r["p"] == p
                     and r["method"] == "homesh"]
            g = best(gmsh_rows, bl.name, p, gmsh_methods)
            hb = best(gmsh_rows, bl.name, p, ["homesh"])
            bar = max(0.8, g["worst"] if g else 0.0)
            E.append(dict(geometry=geometry(hl.name), p=p, homesh=h, tried=bool(tried),
                          gmsh=g, homesh_on_gmsh=hb, meets=bool(h and h["worst"] >= bar)))
    return E


def cell(r, method=False):
    if r is None:
        return "none"
    text = f"{r['worst']:.3f}"
    return f"{text} ({r['method'].replace('gmsh ', '')})" if method else text


def report(args, pairs, orders):
    mine = curving_corpus.read_rows(os.path.join(args.out, "curving_corpus.csv"))
    gmsh_rows = curving_corpus.read_rows(args.gmsh_csv)
    E = analyse(pairs, mine, gmsh_rows, orders)
    lin = {r["geometry"]: r for r in csv.DictReader(open(os.path.join(args.out,
                                                                       "layers_linear.csv")))}
    met = sum(e["meets"] for e in E)
    valid = sum(e["homesh"] is not None for e in E)
    worst = min((e for e in E if e["homesh"]), key=lambda e: e["homesh"]["worst"], default=None)
    gmsh_valid = sum(e["gmsh"] is not None for e in E)
    summary = (f"homesh layers + curve: valid {valid}/{len(E)}, at least 0.8 and Gmsh's best "
               f"valid (its layers + its curving) {met}/{len(E)}; Gmsh's layers + its curving "
               f"valid in {gmsh_valid}/{len(E)}")
    if worst:
        summary += (f"; homesh's worst: {worst['geometry']} p = {worst['p']} "
                    f"{worst['homesh']['worst']:.3f}")
    lines = ["# homesh's layers against Gmsh's BoundaryLayer field, curved", "", summary, "",
             "## Linear layer meshes", "",
             "| geometry | stack | Gmsh triangles | Gmsh worst RR | Gmsh s | homesh triangles | "
             "homesh worst RR | homesh s (layers stage) |", "|---|---|---|---|---|---|---|---|"]

    def f(v, fmt):
        try:
            return format(float(v), fmt)
        except (TypeError, ValueError):
            return "-"
    for r in lin.values():
        lines.append(f"| {r['geometry']} | {r['layers']} from {r['first']}, x{r['ratio']} | "
                     f"{r['gmsh_triangles']} | {f(r['gmsh_worst_rr'], '.3f')} | "
                     f"{f(r['gmsh_seconds'], '.2f')} | {r['homesh_triangles']} | "
                     f"{f(r['homesh_worst_rr'], '.3f')} | {f(r['homesh_seconds'], '.2f')} "
                     f"({f(r['homesh_layers_seconds'], '.2f')}) |")
    lines += ["", "## Curved: worst minJ/maxJ (AnalyseMeshQuality)", "",
              "| geometry | p | homesh layers + homesh curve | s | Gmsh layers + Gmsh's best "
              "valid | Gmsh layers + homesh curve | meets |", "|---|---|---|---|---|---|---|"]
    for e in E:
        h = e["homesh"]
        hc = cell(h) if h else ("invalid/failed" if e["tried"] else "not run")
        lines.append(f"| {e['geometry']} | {e['p']} | {hc} | "
                     f"{h['seconds']:.2f} |" if h else f"| {e['geometry']} | {e['p']} | {hc} | - |")
        lines[-1] += (f" {cell(e['gmsh'], True)} | {cell(e['homesh_on_gmsh'])} | "
                      f"{'yes' if e['meets'] else '**no**'} |")
    with open(os.path.join(args.out, "layers_corpus.md"), "w") as fh:
        fh.write("\n".join(lines) + "\n")
    print("\n".join(lines))
    plot(E, orders, os.path.join(args.out, "layers_corpus.png"), summary)


def plot(E, orders, path, summary):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    geos = list(dict.fromkeys(e["geometry"] for e in E))
    fig, axes = plt.subplots(len(orders), 1, figsize=(14, 3.2 * len(orders)), sharex=True)
    width = 0.27
    for ax, p in zip(axes, orders):
        for j, (key, label, colour) in enumerate([
                ("homesh", "homesh layers + homesh curve", "tab:blue"),
                ("gmsh", "Gmsh layers + Gmsh's best valid curving", "tab:red"),
                ("homesh_on_gmsh", "Gmsh layers + homesh curve", "tab:gray")]):
            ys = [next((e[key]["worst"] if e[key] else 0.0) for e in E
                       if e["geometry"] == g and e["p"] == p) for g in geos]
            ax.bar([k + (j - 1) * width for k in range(len(geos))], ys, width, color=colour,
                   label=label, edgecolor="black", linewidth=0.3)
        ax.axhline(0.8, color="black", linestyle="--", linewidth=0.8)
        ax.set_ylim(0, 1.05)
        ax.set_ylabel(f"p = {p}: worst minJ/maxJ\n(0: no valid mesh)")
        ax.grid(axis="y", alpha=0.3)
    axes[0].legend(fontsize=8, loc="lower left", ncol=3)
    axes[0].set_title(summary, fontsize=8)
    axes[-1].set_xticks(range(len(geos)))
    axes[-1].set_xticklabels(geos, rotation=40, ha="right", fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=100)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cases", help="comma-separated patterns of layers-family case names")
    ap.add_argument("--orders", default="2,3,4")
    ap.add_argument("--out", default=os.path.join(ROOT, "out", "bench", "layers_corpus"))
    ap.add_argument("--gmsh-csv", default=os.path.join(ROOT, "docs", "bench",
                                                       "curving_corpus.csv"))
    ap.add_argument("--timeout", default="120")
    ap.add_argument("--report-only", action="store_true")
    args = ap.parse_args(argv)
    os.makedirs(args.out, exist_ok=True)
    orders = [int(p) for p in args.orders.split(",")]
    pairs = [(c, corpus.twin(c)) for c in corpus.select(args.cases, "layers")]
    if not args.report_only:
        linear(pairs, os.path.join(args.out, "layers_linear.csv"))
        curving_corpus.main(["--family", "layers", "--methods", "homesh", "--orders",
                             args.orders, "--out", args.out, "--timeout", args.timeout]
                            + (["--cases", args.cases] if args.cases else []))
    report(args, pairs, orders)
    return 0


if __name__ == "__main__":
    sys.exit(main())
