#!/usr/bin/python3
"""Benchmark (issue 16, point 1): homesh's curving against Gmsh's on the corpus of
scripts/bench/corpus.py, every case at p = 2..5.

Methods, each on the same linear mesh of the case (its CAD kept) in its own child process:
  homesh            : homesh.curve(p=P) with its defaults;
  gmsh setOrder     : gmsh.model.mesh.setOrder(P) alone;
  gmsh elastic L6   : setOrder(P) + optimize("HighOrderElastic"), Mesh.HighOrderNumLayers 6;
  gmsh elastic L20  : the same with 20 layers;
  gmsh fastcurving  : setOrder(P) + optimize("HighOrderFastCurving");
  gmsh optimize     : setOrder(P) + optimize("HighOrder") (default thresholds).
A Gmsh optimiser that raises (4.8.4: FastCurving at p >= 3, HighOrder when it misses its
target) keeps the mesh it left, which is refereed as it is (its error goes to the CSV).

Linear meshes: each case is built once per run by corpus.write (CAD + mesher) into
OUT/meshes/NAME.msh; every method then starts from a fresh Gmsh session in a child process that
recreates the CAD and merges that file (corpus.load: the same model as corpus.build, see
corpus.write); --rebuild: corpus.build in every child.

Referee: Gmsh's AnalyseMeshQuality per-element minJ/maxJ (scripts/bench/gmsh_referee.py):
invalid = count <= 0, worst = the minimum. Seconds: wall time of the curving call(s) only
(homesh.curve; setOrder + optimize), each library imported before the clock starts (a
fresh process's `import homesh` takes about 20 ms; the runs so far had it from the parent,
which imports it through corpus.py's NACA example); stage_seconds: the time the curve stage
reports in its results, if it reports any. A method still running after --timeout seconds (curving and
referee) is killed and recorded as "timeout". A valid run under --repeat-under seconds (1)
is repeated in fresh processes, --repeat (3) in all, for every method alike, and its least
time kept: this VM's speed varies by up to 1.5x within minutes, which alone moved the small
runs across the targets' lines.

Usage:
  PYTHONPATH=build/python /usr/bin/python3 scripts/bench/curving_corpus.py
      [--cases PATTERN] [--family default|layers] [--orders 2,3,4,5] [--out out/bench/corpus] [--timeout 120]
      [--methods homesh,gmsh*] [--variant k=v:k=v ...] [--repeat 3] [--repeat-under 1] [--rebuild] [--report-only]
--variant adds a method "homesh k=v:k=v" (homesh.curve with those options): choosing a
default on the corpus, its summary is reported beside the defaults' against the same Gmsh
rows (--methods '' runs the variants alone, into an OUT that holds a run's rows).
Writes OUT/curving_corpus.csv (one row per case, p and method, appended as it goes: a run
stopped halfway keeps its rows, and --report-only remakes the table and plot from it),
OUT/curving_corpus.png and OUT/curving_corpus.md (per case and p: homesh, Gmsh's best valid
and fastest valid methods, the targets, and a summary line).
"""
import argparse
import csv
import fnmatch
import math
import multiprocessing as mp
import os
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
ROOT = os.path.dirname(os.path.dirname(HERE))

import corpus  # noqa: E402

METHODS = {
    "homesh": None,
    "gmsh setOrder": (None, 6),
    "gmsh elastic L6": ("HighOrderElastic", 6),
    "gmsh elastic L20": ("HighOrderElastic", 20),
    "gmsh fastcurving": ("HighOrderFastCurving", 6),
    "gmsh optimize": ("HighOrder", 6),
}
FIELDS = ["case", "mesher", "triangles", "turn_deg", "target", "p", "method", "status",
          "invalid", "worst", "seconds", "stage_seconds", "error"]


def first_line(e):
    return str(e).splitlines()[0] if str(e) else type(e).__name__


def curved_to(gmsh, p):
    return all(gmsh.model.mesh.getElementProperties(t)[2] == p
               for t in gmsh.model.mesh.getElementTypes(2))


def child(conn, name, msh, p, method, rebuild):
    """One method on one case in this (child) process; sends ("built", record) then
    ("done", result)."""
    import gmsh
    from gmsh_referee import referee
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    try:
        rec = corpus.build(name) if rebuild else corpus.load(name, msh)
    except Exception as e:
        conn.send(("failed", first_line(e)))
        return
    conn.send(("built", rec))
    error, stage = "", ""
    by_homesh = method.split(" ")[0] == "homesh"
    if by_homesh:
        import homesh  # before the clock, as gmsh is: loading a library is not curving
        homesh.set_quiet(True)
    t = time.perf_counter()
    try:
        if by_homesh:
            r = homesh.curve(p=p, **corpus.method_options(method))
            stage = (r.get("results") or {}).get("seconds", "")  # the whole curving
        else:
            optimiser, layers = METHODS[method]
            gmsh.option.setNumber("Mesh.HighOrderNumLayers", layers)
            gmsh.model.mesh.setOrder(p)
            if optimiser:
                gmsh.model.mesh.optimize(optimiser)
    except Exception as e:  # homesh.Error (not certified valid) or a Gmsh error
        error = first_line(e)
    seconds = time.perf_counter() - t
    if curved_to(gmsh, p):
        invalid, worst, _ = referee()
        status = "ok" if invalid == 0 else "invalid"
    else:
        invalid, worst, status = "", "", "no mesh"
    conn.send(("done", dict(status=status, invalid=invalid, worst=worst, seconds=seconds,
                            stage_seconds=stage, error=error)))
    gmsh.finalize()


def run_one(name, msh, p, method, timeout, rebuild, build_timeout=600):
    """(record, result) of one method in a child process, killed after `timeout` seconds of
    curving and refereeing."""
    ctx = mp.get_context("fork")
    here, there = ctx.Pipe(duplex=False)
    proc = ctx.Process(target=child, args=(there, name, msh, p, method, rebuild))
    proc.start()
    there.close()
    rec, result = None, None
    try:
        if here.poll(build_timeout):
            kind, rec = here.recv()
            if kind == "failed":
                result = dict(status="build failed", error=rec)
                rec = None
            elif here.poll(timeout):
                result = here.recv()[1]
            else:
                result = dict(status="timeout", seconds=timeout, error=f"killed after {timeout} s")
        else:
            result = dict(status="timeout", error="building the linear mesh")
    except EOFError:
        result = dict(status="crashed", error=f"child exit code {proc.exitcode}")
    if proc.is_alive():
        proc.kill()
    proc.join()
    return rec, result


def in_child(make):
    """make() in a fresh Gmsh session in a forked child process: its value, or the first line
    of its error (or the child's exit code) as a string."""
    ctx = mp.get_context("fork")
    q = ctx.SimpleQueue()

    def work():
        import gmsh
        gmsh.initialize()
        gmsh.option.setNumber("General.Terminal", 0)
        try:
            q.put(make())
        except Exception as e:
            q.put(first_line(e))
        gmsh.finalize()
    proc = ctx.Process(target=work)
    proc.start()
    proc.join()
    return q.get() if not q.empty() else f"exit code {proc.exitcode}"


def prepare(c, meshes):
    """Build case c once in a child process and write its linear mesh; its record."""
    return in_child(lambda: corpus.write(c, os.path.join(meshes, c.name + ".msh")))


# ---------------------------------------------------------------- report

def num(v):
    try:
        return float(v)
    except (TypeError, ValueError):
        return None


def read_rows(path, numeric=("invalid", "worst", "seconds", "stage_seconds", "turn_deg",
                               "target", "triangles")):
    """The CSV's rows, p an int and the `numeric` columns floats (None where empty)."""
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    for r in rows:
        r["p"] = int(r["p"])
        for k in numeric:
            r[k] = num(r[k])
    return rows


def valid(r):
    return r["status"] == "ok" and r["invalid"] == 0


def analyse(rows, mine="homesh"):
    """One entry per (case, p) that has a row of method `mine` (homesh or a variant)."""
    out = []
    me = mine
    keys = list(dict.fromkeys((r["case"], r["p"]) for r in rows))
    for key in keys:
        mine = [r for r in rows if (r["case"], r["p"]) == key]
        h = next((r for r in mine if r["method"] == me), None)
        if h is None:
            continue
        g = [r for r in mine if r["method"].startswith("gmsh") and valid(r)]
        best = max(g, key=lambda r: r["worst"]) if g else None
        fast = min(g, key=lambda r: r["seconds"]) if g else None
        hv = valid(h)
        e = dict(case=key[0], p=key[1], mesher=h["mesher"], turn=h["turn_deg"],
                 target=h["target"], triangles=h["triangles"], h=h, best=best, fast=fast,
                 valid=hv, gmsh_tried=len([r for r in mine if r["method"].startswith("gmsh")]))
        # None where no Gmsh method was run for this case and order (a partial run).
        e["ge_best"] = (hv and (best is None or h["worst"] >= best["worst"])
                        if e["gmsh_tried"] else None)
        e["ge_08"] = hv and h["worst"] >= 0.8
        e["ge_target"] = hv and h["worst"] >= h["target"]
        e["ratio"] = h["seconds"] / fast["seconds"] if (hv and fast) else None
        e["within_1x"] = e["ratio"] is not None and e["ratio"] <= 1
        e["within_2x"] = e["ratio"] is not None and e["ratio"] <= 2
        out.append(e)
    return out


def cell(r, tried=True):
    if not tried:
        return "not run"
    if r is None:
        return "none valid"
    short = r["method"].replace("gmsh ", "")
    return f"{short}: {r['worst']:.3f} / {r['seconds']:.3g} s"


def homesh_cell(h):
    if h["status"] in ("ok", "invalid"):
        s = f"{int(h['invalid'])} / {h['worst']:.3f} / {h['seconds']:.3g} s"
        if h["stage_seconds"] is not None:
            s += f" ({h['stage_seconds']:.3g} s logged)"
        return s
    return h["status"]


def summary_line(E):
    n = len(E)
    with_fast = [e for e in E if e["fast"] is not None]
    ran = [e for e in E if e["gmsh_tried"]]
    c = lambda k: sum(1 for e in E if e[k])
    return (f"{n} case x p runs ({len(set(e['case'] for e in E))} cases): homesh valid {c('valid')}/{n}; "
            f">= Gmsh's best valid {c('ge_best')}/{len(ran)} (runs where Gmsh ran); "
            f">= 0.8 {c('ge_08')}/{n}; "
            f">= its target (0.9 where the wall turns < 30 deg, else 0.8) {c('ge_target')}/{n}; "
            f"within Gmsh's fastest valid time {c('within_1x')}/{len(with_fast)}, "
            f"within 2x {c('within_2x')}/{len(with_fast)} (of the runs where Gmsh has a valid "
            f"method)")


def markdown(E):
    yn = lambda b: "-" if b is None else ("yes" if b else "**MISS**")
    lines = ["| case | mesher | turn deg | p | homesh: invalid / worst / s | Gmsh best valid | "
             "Gmsh fastest valid | >= best | >= 0.8 | >= target | time / fastest |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    for e in E:
        ratio = f"{e['ratio']:.2f}" if e["ratio"] is not None else "-"
        if e["ratio"] is not None and e["ratio"] > 2:
            ratio = f"**{ratio}**"
        lines.append(f"| {e['case']} | {e['mesher']} | {e['turn']:.0f} | {e['p']} | "
                     f"{homesh_cell(e['h'])} | {cell(e['best'], e['gmsh_tried'])} | "
                     f"{cell(e['fast'], e['gmsh_tried'])} | "
                     f"{yn(e['ge_best'])} | {yn(e['ge_08'])} | {yn(e['ge_target'])} "
                     f"({e['target']:g}) | {ratio} |")
    return "\n".join(lines) + "\n\n" + summary_line(E) + "\n"


def per_case_markdown(E):
    """One row per case: homesh's lowest worst over the orders, Gmsh's best, the orders
    homesh misses, its time ratio range."""
    lines = ["| case | mesher | turn deg | target | homesh worst (p=2..5) | Gmsh best valid (p=2..5) "
             "| p below Gmsh best | p below target | time / Gmsh fastest valid |",
             "|---|---|---|---|---|---|---|---|---|"]
    for name in dict.fromkeys(e["case"] for e in E):
        es = [e for e in E if e["case"] == name]
        hw = " ".join(f"{e['h']['worst']:.2f}" if e["valid"] else
                      (f"{int(e['h']['invalid'])} inv" if e['h']['status'] == "invalid"
                       else e['h']['status']) for e in es)
        gw = " ".join(f"{e['best']['worst']:.2f}" if e["best"] else
                      ("none" if e["gmsh_tried"] else "n/r") for e in es)
        below = ",".join(str(e["p"]) for e in es if e["ge_best"] is False) or "-"
        miss = ",".join(str(e["p"]) for e in es if not e["ge_target"]) or "-"
        ratios = [e["ratio"] for e in es if e["ratio"] is not None]
        rr = f"{min(ratios):.2f}-{max(ratios):.2f}" if ratios else "-"
        e0 = es[0]
        lines.append(f"| {name} | {e0['mesher']} | {e0['turn']:.0f} | {e0['target']:g} | {hw} | "
                     f"{gw} | {below} | {miss} | {rr} |")
    return "\n".join(lines) + "\n"


def plot(E, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (a, b) = plt.subplots(1, 2, figsize=(15, 6.5))
    colours = {2: "tab:blue", 3: "tab:orange", 4: "tab:green", 5: "tab:red"}
    for p, col in colours.items():
        es = [e for e in E if e["p"] == p and e["valid"] and e["gmsh_tried"]]
        xs = [e["best"]["worst"] if e["best"] else -0.05 for e in es]
        a.scatter(xs, [e["h"]["worst"] for e in es], s=18, color=col, label=f"p = {p}",
                  alpha=0.8)
        bad = [e for e in E if e["p"] == p and not e["valid"] and e["gmsh_tried"]]
        a.scatter([e["best"]["worst"] if e["best"] else -0.05 for e in bad], [0.0] * len(bad),
                  marker="x", color=col)
    a.plot([0, 1], [0, 1], "k--", lw=0.8)
    a.axhline(0.8, color="grey", lw=0.6, ls=":")
    a.axhline(0.9, color="grey", lw=0.6, ls=":")
    a.set_xlim(-0.1, 1.02)
    a.set_ylim(-0.05, 1.02)
    a.set_xlabel("Gmsh's best valid method: worst minJ/maxJ (-0.05: none valid)")
    a.set_ylabel("homesh curve (defaults): worst minJ/maxJ (x at 0: not valid)")
    a.set_title("Quality, per case and order (above the diagonal: homesh better)")
    a.legend()
    for p, col in colours.items():
        es = [e for e in E if e["p"] == p and e["ratio"] is not None]
        b.scatter([e["fast"]["seconds"] for e in es], [e["h"]["seconds"] for e in es], s=18,
                  color=col, label=f"p = {p}", alpha=0.8)
    times = [v for e in E if e["ratio"] is not None
             for v in (e["fast"]["seconds"], e["h"]["seconds"])] or [1e-2, 1e2]
    lim = [min(times) / 2, max(times) * 2]
    b.plot(lim, lim, "k--", lw=0.8, label="equal")
    b.plot(lim, [2 * v for v in lim], "k:", lw=0.8, label="2x")
    b.set_xscale("log")
    b.set_yscale("log")
    b.set_xlabel("Gmsh's fastest valid method: seconds")
    b.set_ylabel("homesh curve: seconds")
    b.set_title("Wall time of the curving call(s)")
    b.legend()
    words, lines = ("Curving corpus (issue 16): " + summary_line(E)).split(), [""]
    for w in words:
        lines[-1] += (" " if lines[-1] else "") + w
        if len(lines[-1]) > 150:
            lines.append("")
    fig.suptitle("\n".join(lines), fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=100)


def report(csv_path, outdir):
    rows = read_rows(csv_path)
    E = analyse(rows)
    if not E:
        print("no homesh rows yet")
        return
    md = ("# Curving corpus (issue 16)\n\nColumns: homesh's invalid count / worst minJ/maxJ / "
          "wall seconds; Gmsh's best valid method (highest worst minJ/maxJ) and fastest valid "
          "method as method: worst / seconds; targets; homesh's time over Gmsh's fastest valid "
          "method's.\n\n## Per case\n\n" + per_case_markdown(E) + "\n## Per case and order\n\n"
          + markdown(E))
    variants = sorted({r["method"] for r in rows if r["method"].startswith("homesh ")})
    if variants:
        md += "\n## Variants of homesh's defaults, on the same Gmsh rows\n\n"
        for v in variants:
            md += f"- `{v}`: " + summary_line(analyse(rows, v)) + "\n"
    with open(os.path.join(outdir, "curving_corpus.md"), "w") as f:
        f.write(md)
    plot(E, os.path.join(outdir, "curving_corpus.png"))
    print(summary_line(E))
    for v in variants:
        print(f"{v}: " + summary_line(analyse(rows, v)))


# ---------------------------------------------------------------- main

def reuse(csv_path, other, pattern):
    """Appends to csv_path the rows of `other` whose method matches `pattern`, for the
    (case, p) pairs csv_path has and lacks that method for; the same linear meshes are
    checked by their triangle counts."""
    mine = list(csv.DictReader(open(csv_path)))
    have = {(r["case"], r["p"], r["method"]) for r in mine}
    triangles = {(r["case"], r["p"]): r["triangles"] for r in mine}
    added = 0
    with open(csv_path, "a", newline="") as f:
        w = csv.DictWriter(f, fieldnames=FIELDS)
        for r in csv.DictReader(open(other)):
            key = (r["case"], r["p"])
            if (not fnmatch.fnmatch(r["method"], pattern) or key not in triangles
                    or (r["case"], r["p"], r["method"]) in have):
                continue
            if r["triangles"] != triangles[key]:
                print(f"reuse: {r['case']} has {r['triangles']} triangles in {other}, "
                      f"{triangles[key]} here: not reused")
                continue
            note = f"reused from {os.path.basename(other)}"
            if not r["error"].startswith("reused from "):  # a reused row keeps its first note
                r["error"] = (note + "; " + r["error"]).strip("; ")
            w.writerow({k: r.get(k, "") for k in FIELDS})
            have.add((r["case"], r["p"], r["method"]))
            added += 1
    print(f"reuse: {added} rows of '{pattern}' from {other}")


def append_row(csv_path, fields, row, res, width):
    """Completes row from the method's result res, appends it to the CSV and prints it (the
    method's name padded to width)."""
    row.update({k: res.get(k, "") for k in fields if k not in row})
    with open(csv_path, "a", newline="") as f:
        csv.DictWriter(f, fieldnames=fields).writerow(row)
    w = f"{row['worst']:.4f}" if isinstance(row["worst"], float) else row["worst"]
    s = f"{row['seconds']:.3f}" if isinstance(row["seconds"], float) else row["seconds"]
    print(f"   p={row['p']} {row['method']:<{width}} {row['status']:<8} inv {row['invalid']!s:<4} "
          f"worst {w:<8} {s:>8} s {row['error'][:70]}", flush=True)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cases", help="comma-separated case name patterns (substring or glob)")
    ap.add_argument("--family", choices=sorted(corpus.FAMILIES), default="default",
                    help="the corpus family (corpus.py): default, the triangle corpus; layers, "
                         "its gmsh_bl cases with homesh's layers (issue 20)")
    ap.add_argument("--orders", default="2,3,4,5")
    ap.add_argument("--methods", default=",".join(METHODS),
                    help="comma-separated method names or globs (default: all)")
    ap.add_argument("--variant", action="append", default=[],
                    help="also run homesh with these curve options, k=v:k=v (repeatable); "
                         "its rows are method 'homesh k=v:k=v'")
    ap.add_argument("--out", default=os.path.join(ROOT, "out", "bench", "corpus"))
    ap.add_argument("--timeout", type=float, default=60.0,
                    help="seconds a method may take (curving + referee) before it is killed")
    ap.add_argument("--repeat", type=int, default=3,
                    help="a method's run that took less than --repeat-under seconds is run "
                         "again, up to this many times in all, each in a fresh process, and "
                         "its least time kept (the same mesh each time: noise only adds time; "
                         "this VM's speed varies by up to 1.5x within minutes)")
    ap.add_argument("--repeat-under", type=float, default=1.0,
                    help="seconds under which a run is repeated (see --repeat)")
    ap.add_argument("--rebuild", action="store_true",
                    help="build each case afresh in every method's process (default: once)")
    ap.add_argument("--reuse", metavar="CSV:PATTERN", action="append", default=[],
                    help="before reporting, copy the rows of the methods matching PATTERN "
                         "(e.g. 'gmsh elastic*': deterministic, but slow) from an earlier run's "
                         "CSV for the cases and orders this run has and they lack, marked "
                         "'reused from CSV' (their seconds are that run's); repeatable")
    ap.add_argument("--report-only", action="store_true",
                    help="only remake the table and plot from OUT/curving_corpus.csv")
    args = ap.parse_args(argv)
    os.makedirs(args.out, exist_ok=True)
    csv_path = os.path.join(args.out, "curving_corpus.csv")
    for spec in args.reuse:
        reuse(csv_path, *spec.rsplit(":", 1))
    if args.report_only:
        report(csv_path, args.out)
        return 0
    cases = corpus.select(args.cases, args.family)
    orders = [int(p) for p in args.orders.split(",")]
    methods = [m for m in METHODS
               if any(fnmatch.fnmatch(m, pat) for pat in args.methods.split(",") if pat)]
    methods += ["homesh " + v for v in args.variant]
    meshes = os.path.join(args.out, "meshes")
    os.makedirs(meshes, exist_ok=True)
    done = {}
    if os.path.exists(csv_path):   # resume: keep the rows of an earlier, stopped run
        done = {(r["case"], int(r["p"]), r["method"]): r["status"]
                for r in csv.DictReader(open(csv_path))}
    else:
        with open(csv_path, "w", newline="") as f:
            csv.DictWriter(f, fieldnames=FIELDS).writeheader()
    start = time.time()
    for i, c in enumerate(cases):
        todo = [(p, m) for p in orders for m in methods if (c.name, p, m) not in done]
        if not todo:
            continue
        msh = os.path.join(meshes, c.name + ".msh")
        rec = prepare(c, meshes)
        if isinstance(rec, str):
            print(f"{c.name}: building failed: {rec}", flush=True)
            continue
        print(f"[{i + 1}/{len(cases)} {time.time() - start:.0f} s] {c.name}: {rec['triangles']} "
              f"triangles, wall turns {rec['turn_deg']} deg, target {rec['target']}", flush=True)
        timed_out = {m for (n, _, m), status in done.items()
                     if n == c.name and status == "timeout"}
        for p, m in sorted(todo):
            if m in timed_out:   # it took longer than the timeout at a lower order
                r, res = None, dict(status="timeout", seconds=args.timeout,
                                    error="not run: timed out at a lower p")
            else:
                r, res = run_one(c.name, msh, p, m, args.timeout, args.rebuild)
                res = corpus.least_time(
                    lambda: run_one(c.name, msh, p, m, args.timeout, args.rebuild)[1],
                    args.repeat, args.repeat_under, first=res)
            if res.get("status") == "timeout":
                timed_out.add(m)
            r = r or rec
            row = dict(case=c.name, mesher=c.mesher, triangles=r["triangles"],
                       turn_deg=r["turn_deg"], target=r["target"], p=p, method=m)
            append_row(csv_path, FIELDS, row, res, 17)
    report(csv_path, args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
