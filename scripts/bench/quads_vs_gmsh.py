#!/usr/bin/python3
"""Benchmark (issue 21): curving Gmsh's quad boundary-layer meshes, homesh against Gmsh.

Cases: the quad family of scripts/bench/corpus.py (`corpus.py --family quads --list`): Gmsh's
BoundaryLayer field with Quads = 1 (quads in the layers, triangles outside and in the
trailing-edge fans) and recombined all-quad meshes. Orders p = 2, 3, 4.

Methods, each on the same linear mesh of the case (its CAD kept) in a fresh Gmsh session in its
own child process, as scripts/bench/curving_corpus.py runs them:
  homesh                : homesh.curve(p=P) with its defaults;
  gmsh setOrder         : gmsh.model.mesh.setOrder(P) alone          (Mesh.HighOrderOptimize 0);
  gmsh optimize         : setOrder + optimize("HighOrder")            (1: optimization);
  gmsh elastic+optimize : setOrder + optimize("HighOrderElastic") then optimize("HighOrder")
                                                                      (2: elastic+optimization);
  gmsh elastic          : setOrder + optimize("HighOrderElastic")     (3: elastic);
  gmsh fastcurving      : setOrder + optimize("HighOrderFastCurving") (4: fast curving).
The numbers are Gmsh 4.8.4's Mesh.HighOrderOptimize values (its option's help: "0: none,
1: optimization, 2: elastic+optimization, 3: elastic, 4: fast curving"); setOrder ignores that
option (checked: the same mesh with it at 3), hence the explicit optimize calls, all with
Mesh.HighOrderNumLayers 6 and Gmsh's default thresholds. A Gmsh optimiser that raises (HighOrder
when it misses its target) keeps the mesh it left, refereed as it is (its error in the CSV);
homesh raising (a stage that does not take quads yet, or a mesh not certified valid) leaves no
mesh of order p: status "error", its message in the CSV.

Referee: Gmsh's AnalyseMeshQuality per-element minJ/maxJ, which covers triangles and quads
(the plugin of scripts/bench/gmsh_referee.py; here split by element type too): invalid = count
<= 0, worst = the minimum, over all 2D elements and per type; linear_worst: the linear mesh's
own worst (before curving; for recombined quads it is low already, and curving moves no
vertex). Seconds: wall time of the curving
call(s) only. A method still running after --timeout seconds (curving and referee) is killed
and recorded as "timeout" (and not run at the higher orders of that case).

Usage:
  PYTHONPATH=build/python /usr/bin/python3 scripts/bench/quads_vs_gmsh.py
      [--cases PATTERN] [--orders 2,3,4] [--methods homesh,gmsh*] [--out docs/bench]
      [--meshes out/bench/quads/meshes] [--timeout 120] [--report-only]
Writes OUT/quads_vs_gmsh.csv (one row per case, p and method, appended as it goes: a stopped
run keeps its rows and a new run skips them; delete the CSV to start afresh), then
OUT/quads_vs_gmsh.png (worst minJ/maxJ per case and p of every method, homesh beside Gmsh's)
and OUT/quads_vs_gmsh.md (per case and p: setOrder's invalid count, Gmsh's best valid method,
homesh), and prints that table's summary with the worst case.
"""
import argparse
import csv
import fnmatch
import multiprocessing as mp
import os
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
ROOT = os.path.dirname(os.path.dirname(HERE))

import corpus  # noqa: E402
import curving_corpus  # noqa: E402
from curving_corpus import append_row, curved_to, first_line, prepare  # noqa: E402

METHODS = {
    "homesh": None,
    "gmsh setOrder": (),
    "gmsh optimize": ("HighOrder",),
    "gmsh elastic+optimize": ("HighOrderElastic", "HighOrder"),
    "gmsh elastic": ("HighOrderElastic",),
    "gmsh fastcurving": ("HighOrderFastCurving",),
}
FIELDS = ["case", "mesher", "triangles", "quads", "turn_deg", "linear_worst", "p", "method",
          "status",
          "invalid", "worst", "invalid_tri", "worst_tri", "invalid_quad", "worst_quad",
          "seconds", "error"]
TARGET = 0.5   # issue 21: worst minJ/maxJ after homesh's curve, every case and order


def referee_by_type():
    """Gmsh's AnalyseMeshQuality minJ/maxJ on the current model (as gmsh_referee.referee),
    over all 2D elements and per type: {invalid, worst, invalid_tri, worst_tri, invalid_quad,
    worst_quad} ("" for a type the mesh has none of)."""
    import gmsh
    for name, value in [("JacobianDeterminant", 1), ("IGEMeasure", 0), ("ICNMeasure", 0),
                        ("CreateView", 1), ("Recompute", 1), ("DimensionOfElements", 2)]:
        gmsh.plugin.setNumber("AnalyseMeshQuality", name, value)
    before = set(gmsh.view.getTags())
    gmsh.plugin.run("AnalyseMeshQuality")
    kind = {}
    for t, tags, _ in zip(*gmsh.model.mesh.getElements(2)):
        family = gmsh.model.mesh.getElementProperties(t)[0].split()[0]
        kind.update(dict.fromkeys(tags.tolist(), "tri" if family == "Triangle" else "quad"))
    for tag in set(gmsh.view.getTags()) - before:
        if not gmsh.option.getString(f"View[{gmsh.view.getIndex(tag)}].Name").startswith(
                "minJ/maxJ"):
            continue
        _, elements, data, _, _ = gmsh.view.getModelData(tag, 0)
        if len(elements) != len(kind):
            raise RuntimeError(f"minJ/maxJ view has {len(elements)} values, {len(kind)} "
                               "2D elements")
        values = {"tri": [], "quad": []}
        for e, d in zip(elements.tolist(), data):
            values[kind[e]].append(d[0])
        out = {}
        for suffix, vs in [("", values["tri"] + values["quad"]), ("_tri", values["tri"]),
                           ("_quad", values["quad"])]:
            out["invalid" + suffix] = sum(v <= 0 for v in vs) if vs else ""
            out["worst" + suffix] = min(vs) if vs else ""
        return out
    raise RuntimeError("AnalyseMeshQuality made no minJ/maxJ view")


def child(conn, name, msh, p, method):
    """One method on one case in this (child) process: sends ("built", record) then
    ("done", result)."""
    import gmsh
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    try:
        rec = corpus.load(name, msh)
    except Exception as e:
        conn.send(("failed", first_line(e)))
        return
    rec["linear_worst"] = referee_by_type()["worst"]
    conn.send(("built", rec))
    error = ""
    if method == "homesh":
        import homesh  # before the clock, as gmsh is: loading a library is not curving
        homesh.set_quiet(True)
    t = time.perf_counter()
    try:
        if method == "homesh":
            homesh.curve(p=p)
        else:
            gmsh.option.setNumber("Mesh.HighOrderNumLayers", 6)
            gmsh.model.mesh.setOrder(p)
            for optimiser in METHODS[method]:
                gmsh.model.mesh.optimize(optimiser)
    except Exception as e:  # homesh.Error or a Gmsh error
        error = first_line(e)
    seconds = time.perf_counter() - t
    result = dict(seconds=seconds, error=error)
    if curved_to(gmsh, p):
        result.update(referee_by_type())
        result["status"] = "ok" if result["invalid"] == 0 else "invalid"
    else:   # nothing curved: the method raised before it made a mesh of order p
        result["status"] = "error" if error else "no mesh"
    conn.send(("done", result))
    gmsh.finalize()


def run_one(name, msh, p, method, timeout, build_timeout=600):
    """(record, result) of one method in a child process, killed after `timeout` seconds of
    curving and refereeing."""
    ctx = mp.get_context("fork")
    here, there = ctx.Pipe(duplex=False)
    proc = ctx.Process(target=child, args=(there, name, msh, p, method))
    proc.start()
    there.close()
    rec, result = None, None
    try:
        if not here.poll(build_timeout):
            result = dict(status="timeout", error="loading the linear mesh")
        else:
            kind, rec = here.recv()
            if kind == "failed":
                rec, result = None, dict(status="load failed", error=rec)
            elif here.poll(timeout):
                result = here.recv()[1]
            else:
                result = dict(status="timeout", seconds=timeout, error=f"killed after {timeout} s")
    except EOFError:
        result = dict(status="crashed", error=f"child exit code {proc.exitcode}")
    if proc.is_alive():
        proc.kill()
    proc.join()
    return rec, result


# ---------------------------------------------------------------- report

def read_rows(path):
    return curving_corpus.read_rows(
        path, ("invalid", "worst", "seconds", "triangles", "quads", "linear_worst"))


def valid(r):
    return r is not None and r["status"] == "ok" and r["invalid"] == 0


def analyse(rows):
    """Per (case, p): setOrder's row, Gmsh's best valid method (highest worst), homesh's row."""
    out = []
    for key in dict.fromkeys((r["case"], r["p"]) for r in rows):
        these = {r["method"]: r for r in rows if (r["case"], r["p"]) == key}
        g = [r for m, r in these.items() if m.startswith("gmsh") and valid(r)]
        h = these.get("homesh")
        # The highest worst (to 1e-6), then the fastest.
        best = max(g, key=lambda r: (round(r["worst"], 6), -r["seconds"])) if g else None
        any_row = next(iter(these.values()))
        linear = [r["linear_worst"] for r in these.values() if r["linear_worst"] is not None]
        e = dict(case=key[0], p=key[1], mesher=any_row["mesher"], triangles=any_row["triangles"],
                 quads=any_row["quads"], linear=linear[0] if linear else None,
                 setorder=these.get("gmsh setOrder"), best=best, h=h,
                 gmsh_tried=any(m.startswith("gmsh") for m in these))
        e["h_valid"] = valid(h)
        e["h_target"] = e["h_valid"] and h["worst"] >= TARGET and (
            best is None or h["worst"] > best["worst"])
        out.append(e)
    return out


def short(r):
    return r["method"].replace("gmsh ", "")


def row_cell(r):
    if r is None:
        return "not run"
    if r["status"] in ("ok", "invalid"):
        return f"{int(r['invalid'])} / {r['worst']:.3f} / {r['seconds']:.3g} s"
    return r["status"] + (f": {r['error'][:70]}" if r.get("error") else "")


def best_cell(e):
    if not e["gmsh_tried"]:
        return "not run"
    b = e["best"]
    return f"{short(b)}: 0 / {b['worst']:.3f} / {b['seconds']:.3g} s" if b else "none valid"


def setorder_cell(e):
    s = e["setorder"]
    return str(int(s["invalid"])) if s and s["invalid"] is not None else (
        s["status"] if s else "-")


def markdown(E):
    lines = ["| case | mesher | tri / quad | linear worst | p | setOrder invalid | "
             "Gmsh best valid: invalid / worst / s | homesh: invalid / worst / s | "
             "homesh >= 0.5 and > Gmsh |",
             "|---|---|---|---|---|---|---|---|---|"]
    for e in E:
        lin = f"{e['linear']:.3f}" if e["linear"] is not None else "-"
        met = "yes" if e["h_target"] else ("-" if e["h"] is None else "no")
        lines.append(f"| {e['case']} | {e['mesher']} | {e['triangles']:.0f} / {e['quads']:.0f} | "
                     f"{lin} | {e['p']} | {setorder_cell(e)} | {best_cell(e)} | "
                     f"{row_cell(e['h'])} | {met} |")
    return "\n".join(lines) + "\n\n" + summary(E) + "\n"


def summary(E):
    n = len(E)
    so = [e for e in E if e["setorder"] and e["setorder"]["invalid"] is not None]
    g = [e for e in E if e["best"]]
    lines = [f"{n} case x p runs ({len(set(e['case'] for e in E))} cases): Gmsh setOrder leaves "
             f"invalid elements in {sum(e['setorder']['invalid'] > 0 for e in so)}/{len(so)}; "
             f"some Gmsh method valid in {len(g)}/{n}"]
    if g:
        w = min(g, key=lambda e: e["best"]["worst"])
        lines[-1] += (f"; worst case for Gmsh's best valid method: {w['case']} p={w['p']}, "
                      f"{short(w['best'])} {w['best']['worst']:.3f}")
    hs = [e for e in E if e["h"] is not None]
    if hs:
        hv = [e for e in hs if e["h_valid"]]
        lines.append(f"homesh: valid {len(hv)}/{len(hs)}, >= {TARGET} and above Gmsh's best "
                     f"valid {sum(e['h_target'] for e in hs)}/{len(hs)}")
        if hv:
            w = min(hv, key=lambda e: e["h"]["worst"])
            lines[-1] += f"; its worst case: {w['case']} p={w['p']}, {w['h']['worst']:.3f}"
        errors = {e["h"]["error"] for e in hs if e["h"]["error"]}
        if errors:
            lines[-1] += f"; errors: {'; '.join(sorted(errors))[:200]}"
    return "\n".join(lines)


def plot(rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
    orders = sorted({r["p"] for r in rows})
    cases = list(dict.fromkeys(r["case"] for r in rows))
    methods = [m for m in METHODS if any(r["method"] == m for r in rows)]
    colours = dict(zip(METHODS, ["black", "tab:grey", "tab:blue", "tab:cyan", "tab:orange",
                                 "tab:green"]))
    fig, axes = plt.subplots(len(orders), 1, figsize=(max(10, 1.0 * len(cases) + 3),
                                                      3.2 * len(orders)), squeeze=False)
    width = 0.8 / len(methods)
    linear = {r["case"]: r["linear_worst"] for r in rows if r["linear_worst"] is not None}
    for ax, p in zip(axes[:, 0], orders):
        for i, c in enumerate(cases):
            if c in linear:
                ax.hlines(linear[c], i - 0.45, i + 0.45, color="red", lw=1.2,
                          label="linear mesh" if i == 0 else None)
        for j, m in enumerate(methods):
            for i, c in enumerate(cases):
                r = next((r for r in rows if (r["case"], r["p"], r["method"]) == (c, p, m)), None)
                x = i - 0.4 + (j + 0.5) * width
                if r is None:
                    continue
                if valid(r):
                    ax.bar(x, r["worst"], width, color=colours[m],
                           label=m if i == 0 else None)
                else:   # invalid, error, timeout: a cross below the axis
                    ax.plot(x, -0.05, "x", color=colours[m], label=m if i == 0 else None)
        ax.axhline(TARGET, color="red", lw=0.8, ls=":")
        ax.set_ylim(-0.1, 1.0)
        ax.set_xlim(-0.6, len(cases) - 0.4)
        ax.set_xticks(np.arange(len(cases)))
        ax.set_xticklabels(cases if p == orders[-1] else [], rotation=35, ha="right",
                           fontsize=7)
        ax.set_ylabel(f"p = {p}: worst minJ/maxJ")
    handles, labels = axes[0, 0].get_legend_handles_labels()
    fig.legend(handles, labels, fontsize=7, ncol=len(labels), loc="upper center",
               bbox_to_anchor=(0.5, 0.955))
    fig.suptitle("Curving Gmsh's quad boundary-layer meshes: worst minJ/maxJ (x below 0: "
                 "invalid, error or timeout; red line: the linear mesh's worst; dotted: "
                 "homesh's target 0.5)\n" + summary(analyse(rows)), fontsize=8, y=0.995)
    fig.tight_layout(rect=(0, 0, 1, 0.93))
    fig.savefig(path, dpi=100)


def report(csv_path, outdir):
    rows = read_rows(csv_path)
    if not rows:
        print("no rows yet")
        return
    E = analyse(rows)
    md = ("# Curving Gmsh's quad boundary-layer meshes (issue 21)\n\n"
          "Made by scripts/bench/quads_vs_gmsh.py. Cells: invalid count / worst minJ/maxJ "
          "(Gmsh's AnalyseMeshQuality, triangles and quads) / wall seconds of the curving "
          "call(s).\n\n" + markdown(E))
    with open(os.path.join(outdir, "quads_vs_gmsh.md"), "w") as f:
        f.write(md)
    plot(rows, os.path.join(outdir, "quads_vs_gmsh.png"))
    print(f"{'case':<28} linear p  setOrder  {'Gmsh best valid: inv / worst / s':<40} homesh")
    for e in E:
        lin = f"{e['linear']:.3f}" if e["linear"] is not None else "-"
        print(f"{e['case']:<28} {lin:<6} {e['p']}  {setorder_cell(e):<8}  {best_cell(e):<40} "
              f"{row_cell(e['h'])[:60]}")
    print(summary(E))


# ---------------------------------------------------------------- main

def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cases", help="comma-separated case name patterns (substring or glob) of "
                                    "the quad family (default: all of it)")
    ap.add_argument("--orders", default="2,3,4")
    ap.add_argument("--methods", default=",".join(METHODS),
                    help="comma-separated method names or globs (default: all)")
    ap.add_argument("--out", default=os.path.join(ROOT, "docs", "bench"),
                    help="where quads_vs_gmsh.{csv,png,md} go")
    ap.add_argument("--meshes", default=os.path.join(ROOT, "out", "bench", "quads", "meshes"),
                    help="where the linear meshes are built (NAME.msh, NAME.brep)")
    ap.add_argument("--timeout", type=float, default=120.0,
                    help="seconds a method may take (curving + referee) before it is killed")
    ap.add_argument("--report-only", action="store_true",
                    help="only remake the table and plot from OUT/quads_vs_gmsh.csv")
    args = ap.parse_args(argv)
    os.makedirs(args.out, exist_ok=True)
    csv_path = os.path.join(args.out, "quads_vs_gmsh.csv")
    if args.report_only:
        report(csv_path, args.out)
        return 0
    cases = corpus.select(args.cases, family="quads")
    orders = [int(p) for p in args.orders.split(",")]
    methods = [m for m in METHODS
               if any(fnmatch.fnmatch(m, pat) for pat in args.methods.split(",") if pat)]
    os.makedirs(args.meshes, exist_ok=True)
    done, counts = {}, {}
    if os.path.exists(csv_path):   # resume: keep the rows of an earlier, stopped run
        for r in csv.DictReader(open(csv_path)):
            done[(r["case"], int(r["p"]), r["method"])] = r["status"]
            counts[r["case"]] = (r["triangles"], r["quads"])
    else:
        with open(csv_path, "w", newline="") as f:
            csv.DictWriter(f, fieldnames=FIELDS).writeheader()
    start = time.time()
    for i, c in enumerate(cases):
        todo = [(p, m) for p in orders for m in methods if (c.name, p, m) not in done]
        if not todo:
            continue
        msh = os.path.join(args.meshes, c.name + ".msh")
        rec = prepare(c, args.meshes)
        if isinstance(rec, str):
            print(f"{c.name}: building failed: {rec}", flush=True)
            continue
        print(f"[{i + 1}/{len(cases)} {time.time() - start:.0f} s] {c.name}: {rec['triangles']} "
              f"triangles, {rec['quads']} quads", flush=True)
        # The mesh is rebuilt in every run (Gmsh's meshes of these cases are the same from run
        # to run, numbered differently); rows of a different mesh are not comparable.
        if c.name in counts and counts[c.name] != (str(rec["triangles"]), str(rec["quads"])):
            print(f"   warning: {csv_path} has rows of {c.name} with {counts[c.name]} triangles "
                  "and quads: another mesh", flush=True)
        timed_out = {m for (n, _, m), status in done.items()
                     if n == c.name and status == "timeout"}
        for p, m in sorted(todo):
            if m in timed_out:   # it took longer than the timeout at a lower order
                r, res = None, dict(status="timeout", seconds=args.timeout,
                                    error="not run: timed out at a lower p")
            else:
                r, res = run_one(c.name, msh, p, m, args.timeout)
            if res.get("status") == "timeout":
                timed_out.add(m)
            r = r or rec
            row = dict(case=c.name, mesher=c.mesher, triangles=r["triangles"], quads=r["quads"],
                       turn_deg=r["turn_deg"], linear_worst=r.get("linear_worst", ""), p=p,
                       method=m)
            append_row(csv_path, FIELDS, row, res, 21)
    report(csv_path, args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
