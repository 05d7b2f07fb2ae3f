#!/usr/bin/python3
"""Benchmark (issue 24): homesh's curving of tetrahedral meshes against Gmsh's, on the 3D
corpus of scripts/bench/corpus3d.py, every case at p = 2..4.

Methods, each in its own child process (multiprocessing, spawn: a fresh interpreter and a
fresh Gmsh session) that builds the case (CAD + linear mesh, corpus3d.build) itself:
  homesh           : homesh.curve(p=P) with its defaults (boundary nodes on the CAD, the 3D
                     elastic analogy round them);
  gmsh setOrder    : gmsh.model.mesh.setOrder(P) alone (boundary nodes on the CAD, interior
                     nodes straight);
  gmsh elastic     : setOrder(P) + optimize("HighOrderElastic");
  gmsh optimize    : setOrder(P) + optimize("HighOrder") (default thresholds);
  gmsh fastcurving : setOrder(P) + optimize("HighOrderFastCurving").
Gmsh's options are its defaults (Mesh.HighOrderNumLayers 6) but General.NumThreads 1, which
corpus3d sets, as it sets the deterministic mesher: each child's tetrahedron count is checked
against the case's first (a mismatch is flagged in the report). A Gmsh optimiser that raises
keeps the mesh it left, which is refereed as it is (its error goes to the CSV); so is homesh's
mesh when curve raises.

Referee: Gmsh's AnalyseMeshQuality plugin (JacobianDeterminant, DimensionOfElements 3) per
tetrahedron minJ/maxJ: invalid = count <= 0, worst = the minimum (one value per tetrahedron,
checked). homesh's own certified figures (r["validity"]) are kept beside it.

Seconds: wall time of the curving call(s) only (homesh.curve; setOrder + optimize); every
child imports gmsh and homesh, and builds the linear mesh, before the clock starts. Memory:
the child's peak resident set (resource.getrusage ru_maxrss) once curving returns (before the
referee), and before the clock (base_mb: Python, the libraries, the CAD and the linear mesh;
the same for every method of a case). A method still running after --timeout seconds
(curving and referee) is killed and recorded as "timeout", and not run at the case's higher
orders. --repeat runs a valid run under --repeat-under seconds again in fresh processes and
keeps its least time (corpus.least_time; default: once).

Targets (issue 24), per case and p: 0 invalid; worst minJ/maxJ at least that of Gmsh's best
valid method (the highest worst among Gmsh's methods with 0 invalid); time at most that
method's time.

Usage:
  PYTHONPATH=build/python /usr/bin/python3 scripts/bench/volume_corpus.py
      [--cases PATTERN] [--orders 2,3,4] [--methods homesh,gmsh*] [--variant k=v:k=v ...]
      [--out out/bench/volume_corpus] [--timeout 300] [--repeat 1] [--report-only]
--variant adds a method "homesh k=v:k=v" (homesh.curve with those options, e.g.
tet_rings=2); its summary is reported beside the defaults' against the same Gmsh rows.
Writes OUT/volume_corpus.csv (one row per case, p and method, appended as it goes: a stopped
run keeps its rows and a rerun skips them; --report-only remakes the report from it),
OUT/volume_corpus.png and OUT/volume_corpus.md.
"""
import argparse
import csv
import fnmatch
import multiprocessing as mp
import os
import resource
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
ROOT = os.path.dirname(os.path.dirname(HERE))

import corpus  # noqa: E402 (method_options, least_time)
import corpus3d  # noqa: E402

METHODS = {
    "homesh": None,
    "gmsh setOrder": None,
    "gmsh elastic": "HighOrderElastic",
    "gmsh optimize": "HighOrder",
    "gmsh fastcurving": "HighOrderFastCurving",
}
FIELDS = ["case", "tetrahedra", "worst_shape", "wall_caps", "p", "method", "status", "invalid",
          "worst", "seconds", "homesh_invalid", "homesh_worst", "seconds_place", "seconds_solve", "unknowns",
          "region", "split", "peak_mb", "base_mb", "error"]


def first_line(e):
    return str(e).splitlines()[0] if str(e) else type(e).__name__


def peak_mb():
    """This process's peak resident set so far, MB (Linux reports ru_maxrss in kB)."""
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024


# ---------------------------------------------------------------- one run (in the child)

def curved_to(gmsh, p):
    types = gmsh.model.mesh.getElementTypes(3)
    return bool(len(types)) and all(gmsh.model.mesh.getElementProperties(t)[2] == p
                                    for t in types)


def referee3d(gmsh):
    """(invalid, worst, values) of Gmsh's AnalyseMeshQuality per-tetrahedron minJ/maxJ."""
    plugin = "AnalyseMeshQuality"
    for name, value in [("JacobianDeterminant", 1), ("IGEMeasure", 0), ("ICNMeasure", 0),
                        ("CreateView", 1), ("Recompute", 1), ("DimensionOfElements", 3)]:
        gmsh.plugin.setNumber(plugin, name, value)
    old = set(gmsh.view.getTags())
    gmsh.plugin.run(plugin)
    for tag in sorted(set(gmsh.view.getTags()) - old):
        if gmsh.option.getString(f"View[{gmsh.view.getIndex(tag)}].Name").startswith("minJ/maxJ"):
            values = [d[0] for d in gmsh.view.getModelData(tag, 0)[2]]
            return sum(1 for v in values if v <= 0), min(values), len(values)
    raise RuntimeError(f"{plugin} made no minJ/maxJ view")


def curve_homesh(homesh, p, method):
    """homesh.curve on the current model: the CSV fields of its own results."""
    r = homesh.curve(p=p, **corpus.method_options(method))
    v, res = r.get("validity") or {}, r.get("results") or {}
    return dict(homesh_invalid=v.get("invalid", ""), homesh_worst=v.get("worst", ""),
                **{k: res.get(k, "") for k in ("seconds_place", "seconds_solve", "unknowns",
                                               "region", "split")})


def curve_gmsh(gmsh, p, method):
    gmsh.model.mesh.setOrder(p)
    if METHODS[method]:
        gmsh.model.mesh.optimize(METHODS[method])
    return {}


def child(conn, name, p, method):
    """One method on one case in this (child) process; sends ("built", record) then
    ("done", result), or ("failed", error)."""
    import gmsh
    import homesh  # before the clock, as gmsh is: loading a library is not curving
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    homesh.set_quiet(True)
    try:
        rec = corpus3d.build(name)
    except Exception as e:
        conn.send(("failed", first_line(e)))
        return
    base = peak_mb()
    conn.send(("built", rec))
    out, error = {}, ""
    start = time.perf_counter()
    try:
        if method.split(" ")[0] == "homesh":
            out = curve_homesh(homesh, p, method)
        else:
            out = curve_gmsh(gmsh, p, method)
    except Exception as e:  # homesh.Error or a Gmsh error: the mesh left is refereed
        error = first_line(e)
    seconds = time.perf_counter() - start
    out.update(seconds=seconds, peak_mb=round(peak_mb(), 1), base_mb=round(base, 1), error=error)
    if curved_to(gmsh, p):
        invalid, worst, n = referee3d(gmsh)
        # homesh splits wall caps (tet_split_caps): each adds tetrahedra
        expected = sum(len(t) for t in gmsh.model.mesh.getElements(3)[1])
        if not out.get("split") and expected != rec["tetrahedra"]:
            raise RuntimeError(f"{expected} tetrahedra after curving, {rec['tetrahedra']} before")
        if n != expected:
            raise RuntimeError(f"referee: {n} values for {expected} tetrahedra")
        out.update(status="ok" if invalid == 0 else "invalid", invalid=invalid, worst=worst)
    else:
        out.update(status="no mesh", invalid="", worst="")
    conn.send(("done", out))
    gmsh.finalize()


# ---------------------------------------------------------------- one run (the parent)

def run_one(name, p, method, timeout, build_timeout=600):
    """(record, result) of one method in a spawned child, killed after `timeout` seconds of
    curving and refereeing (or build_timeout seconds of building)."""
    ctx = mp.get_context("spawn")
    here, there = ctx.Pipe(duplex=False)
    proc = ctx.Process(target=child, args=(there, name, p, method))
    proc.start()
    there.close()
    rec, result = None, None
    try:
        if not here.poll(build_timeout):
            result = dict(status="timeout", error="building the linear mesh")
        else:
            kind, rec = here.recv()
            if kind == "failed":
                rec, result = None, dict(status="build failed", error=rec)
            elif here.poll(timeout):
                result = here.recv()[1]
            else:
                result = dict(status="timeout", seconds=timeout,
                              error=f"killed after {timeout:g} s")
    except EOFError:
        proc.join(5)
        result = dict(status="crashed", error=f"child exit code {proc.exitcode}")
    if proc.is_alive():
        proc.kill()
    proc.join()
    return rec, result


# ---------------------------------------------------------------- report

def num(v):
    try:
        return float(v)
    except (TypeError, ValueError):
        return None


def read_rows(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    for r in rows:
        for k in FIELDS:
            if k not in ("case", "method", "status", "error"):
                r[k] = num(r.get(k))
        r["p"] = int(r["p"])
    return rows


def valid(r):
    return r is not None and r["status"] == "ok" and r["invalid"] == 0


def analyse(rows, mine="homesh"):
    """One entry per (case, p) with a row of method `mine` (homesh or a variant)."""
    out = []
    for key in dict.fromkeys((r["case"], r["p"]) for r in rows):
        these = [r for r in rows if (r["case"], r["p"]) == key]
        h = next((r for r in these if r["method"] == mine), None)
        if h is None:
            continue
        gm = [r for r in these if r["method"].startswith("gmsh")]
        good = [r for r in gm if valid(r)]
        best = max(good, key=lambda r: r["worst"]) if good else None
        e = dict(case=key[0], p=key[1], h=h, best=best, gmsh=gm, valid=valid(h),
                 setorder=next((r for r in gm if r["method"] == "gmsh setOrder"), None),
                 timeouts=[r["method"] for r in gm if r["status"] == "timeout"],
                 tets={r["tetrahedra"] for r in these if r["tetrahedra"] is not None})
        # Quality: None where no Gmsh method ran; a homesh mesh that is not valid misses.
        e["ge_best"] = None if not gm else e["valid"] and (best is None
                                                          or h["worst"] >= best["worst"])
        # Time: None where Gmsh has no valid method; the ratio shown even where homesh's
        # mesh is not valid, which misses.
        e["ratio"] = (h["seconds"] / best["seconds"]
                      if best and h["seconds"] is not None else None)
        e["time_ok"] = None if best is None else (e["valid"] and e["ratio"] <= 1)
        out.append(e)
    return out


def where(e):
    return f"{e['case']} p={e['p']}"


def target_invalid(E):
    bad = [e for e in E if not e["valid"]]
    text = f"0 invalid: {len(E) - len(bad)}/{len(E)}"
    if bad:
        most = max(bad, key=lambda e: (e["h"]["invalid"] or 0, -(e["h"]["worst"] or 0)))
        text += (f"; worst: {where(most)} ({homesh_short(most['h'])}); misses: "
                 + ", ".join(f"{where(e)} ({homesh_short(e['h'])})" for e in bad))
    return text


def target_quality(E):
    ran = [e for e in E if e["ge_best"] is not None]
    miss = [e for e in ran if not e["ge_best"]]
    text = f"worst minJ/maxJ >= Gmsh's best valid: {len(ran) - len(miss)}/{len(ran)}"
    low = min((e for e in E if e["valid"]), key=lambda e: e["h"]["worst"], default=None)
    if low:
        text += f"; homesh's lowest valid: {where(low)} {low['h']['worst']:.3f}"
    lower = [e for e in miss if e["valid"]]
    if lower:
        text += "; lower than Gmsh's (homesh / Gmsh): " + ", ".join(
            f"{where(e)} {e['h']['worst']:.3f} / {e['best']['worst']:.3f} = "
            f"{e['h']['worst'] / e['best']['worst']:.2f}" for e in lower)
    invalid = [e for e in miss if not e["valid"]]
    if invalid:
        beaten = [e for e in invalid if e["best"]]
        text += (f"; {len(invalid)} misses where homesh is not valid, {len(beaten)} of them "
                 f"where Gmsh has a valid method")
        if beaten:
            text += " (" + ", ".join(f"{where(e)}: {e['best']['method'].replace('gmsh ', '')} "
                                     f"{e['best']['worst']:.3f}" for e in beaten) + ")"
    return text


def target_time(E):
    timed = [e for e in E if e["time_ok"] is not None]
    slow = [e for e in timed if not e["time_ok"]]
    text = f"time <= Gmsh's best valid method's: {len(timed) - len(slow)}/{len(timed)}"
    if len(timed) < len(E):
        text += f" ({len(E) - len(timed)} runs without a valid Gmsh method)"
    top = max((e for e in timed if e["valid"]), key=lambda e: e["ratio"], default=None)
    if top:
        text += f"; largest ratio (homesh valid): {where(top)} {top['ratio']:.2f}x"
    slower = [e for e in slow if e["valid"]]
    if slower:
        text += "; slower: " + ", ".join(
            f"{where(e)} {e['ratio']:.2f}x (vs {e['best']['method'].replace('gmsh ', '')}"
            + (f"; {', '.join(m.replace('gmsh ', '') for m in e['timeouts'])} timed out"
               if e["timeouts"] else "") + ")" for e in slower)
    invalid = [e for e in slow if not e["valid"]]
    if invalid:
        text += f"; {len(invalid)} misses where homesh is not valid"
    return text


def targets(E):
    """The three targets' counts, misses and worst cases, as text lines."""
    lines = [target_invalid(E), target_quality(E), target_time(E)]
    split = [e for e in E if (e["h"].get("split") or 0) > 0]
    if split:
        lines.append("wall caps homesh split (tet_split_caps; at an edge on the wall, or at "
                     "the centroid): " + ", ".join(f"{where(e)} {int(e['h']['split'])}" for e in split))
    mismatch = sorted({e["case"] for e in E if len(e["tets"]) > 1})
    if mismatch:
        lines.append("tetrahedron counts differ between methods: " + ", ".join(mismatch))
    return lines


def homesh_short(h):
    if h["status"] in ("ok", "invalid"):
        return f"{int(h['invalid'])} invalid, worst {h['worst']:.3f}"
    return h["status"]


def run_cell(r):
    """invalid / worst / seconds of a row."""
    if r is None:
        return "-"
    if r["status"] not in ("ok", "invalid"):
        return r["status"]
    return f"{int(r['invalid'])} / {r['worst']:.3f} / {r['seconds']:.3g} s"


def markdown(E):
    yn = lambda b: "-" if b is None else ("yes" if b else "**MISS**")
    lines = ["| case | tets | p | homesh: invalid / worst / s | MB | homesh certified worst | "
             "Gmsh best valid: worst / s | MB | setOrder: invalid / worst | >= best | "
             "time / best |", "|---|---|---|---|---|---|---|---|---|---|---|"]
    for e in E:
        h, b, s = e["h"], e["best"], e["setorder"]
        tets = "/".join(str(int(t)) for t in sorted(e["tets"]))
        best = (f"{b['method'].replace('gmsh ', '')}: {b['worst']:.3f} / {b['seconds']:.3g} s"
                if b else "none valid")
        if e["timeouts"]:
            best += " (timeout: " + ", ".join(m.replace("gmsh ", "") for m in e["timeouts"]) + ")"
        ratio = f"{e['ratio']:.2f}" if e["ratio"] is not None else "-"
        if e["time_ok"] is False:
            ratio = f"**{ratio}**" + ("" if e["valid"] else " (not valid)")
        so = f"{int(s['invalid'])} / {s['worst']:.3f}" if s and s["worst"] is not None else "-"
        cw = f"{h['homesh_worst']:.3f}" if h["homesh_worst"] is not None else "-"
        lines.append(f"| {e['case']} | {tets} | {e['p']} | {run_cell(h)} | {mb(h)} | {cw} | "
                     f"{best} | {mb(b)} | {so} | {yn(e['ge_best'])} | {ratio} |")
    return "\n".join(lines) + "\n"


def mb(r):
    return f"{r['peak_mb']:.0f}" if r and r["peak_mb"] is not None else "-"


def method_order(rows):
    """The methods of the rows, homesh's (the defaults, then the variants) first."""
    return sorted(dict.fromkeys(r["method"] for r in rows),
                  key=lambda m: (m != "homesh", not m.startswith("homesh")))


def all_methods(rows, E):
    """Every method's invalid / worst / seconds per case and p."""
    methods = method_order(rows)
    lines = ["| case | p | " + " | ".join(methods) + " |", "|---|---|" + "---|" * len(methods)]
    for e in E:
        these = {r["method"]: r for r in rows if (r["case"], r["p"]) == (e["case"], e["p"])}
        lines.append(f"| {e['case']} | {e['p']} | "
                     + " | ".join(run_cell(these.get(m)) for m in methods) + " |")
    return "\n".join(lines) + "\n"


def linear_table(rows):
    """Per case: its tetrahedron count(s) over the runs (one, unless a run's mesh differed),
    the worst linear shape and the wall caps (corpus3d's record)."""
    lines = ["| case | tetrahedra | worst linear shape (6 sqrt2 V / e_rms^3) | wall caps |",
             "|---|---|---|---|"]
    for c in dict.fromkeys(r["case"] for r in rows):
        these = [r for r in rows if r["case"] == c and r["tetrahedra"] is not None]
        if not these:
            continue
        tets = "/".join(str(int(t)) for t in sorted({r["tetrahedra"] for r in these}))
        lines.append(f"| {c} | {tets} | {these[0]['worst_shape']:.3f} | "
                     f"{int(these[0]['wall_caps'])} |")
    return "\n".join(lines) + "\n"


def plot(rows, E, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    methods = method_order(rows)
    x = range(len(E))
    fig, (a, b) = plt.subplots(2, 1, figsize=(max(10, 0.42 * len(E) + 3), 9), sharex=True)
    floor = -0.25
    width = 0.7 / max(1, len(methods))
    for k, m in enumerate(methods):
        xs, ys = [], []
        for i, e in enumerate(E):
            r = next((r for r in rows if (r["case"], r["p"], r["method"])
                      == (e["case"], e["p"], m)), None)
            if r is not None and r["worst"] is not None:
                xs.append(i + (k - (len(methods) - 1) / 2) * width)
                ys.append(max(r["worst"], floor))
        a.scatter(xs, ys, s=22, label=m,
                  marker="o" if m == "homesh" else ("D" if m.startswith("homesh") else "s"),
                  zorder=3 if m.startswith("homesh") else 2)
    a.axhline(0, color="k", lw=0.6)
    a.set_ylim(floor - 0.05, 1.02)
    a.set_ylabel(f"worst minJ/maxJ (Gmsh's referee; <= {floor}: at {floor})")
    a.set_title("Worst minJ/maxJ per case and order")
    a.legend(fontsize=7, ncol=3)
    ratios = [e["ratio"] if e["ratio"] is not None else float("nan") for e in E]
    b.bar(list(x), ratios, color=["tab:grey" if not e["valid"] else
                                  ("tab:green" if e["time_ok"] else "tab:red") for e in E])
    b.axhline(1, color="k", lw=0.8)
    b.set_yscale("log")
    b.set_ylabel("homesh's time / Gmsh's best valid method's\n(grey: homesh not valid)")
    b.set_xticks(list(x))
    b.set_xticklabels([f"{e['case']} p{e['p']}" for e in E], rotation=75, fontsize=7)
    fig.suptitle("Volume corpus (issue 24)\n" + "\n".join(t[:160] for t in targets(E)[:3]),
                 fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=100)


def report(csv_path, outdir):
    rows = read_rows(csv_path)
    E = analyse(rows)
    if not E:
        print("no homesh rows yet")
        return
    md = ["# Volume corpus (issue 24)\n",
          "Cells: invalid count / worst minJ/maxJ (Gmsh's AnalyseMeshQuality, 3D) / wall "
          "seconds of the curving call(s); MB: the child's peak resident set once curving "
          "returned; Gmsh best valid: the Gmsh method with 0 invalid and the highest worst; "
          "time / best: homesh's seconds over that method's.\n",
          "## Targets\n", *[f"- {t}" for t in targets(E)], "",
          "## Linear meshes\n", linear_table(rows),
          "## homesh against Gmsh's best valid method\n", markdown(E),
          "## Every method\n", all_methods(rows, E)]
    variants = sorted({r["method"] for r in rows if r["method"].startswith("homesh ")})
    if variants:
        md.append("## Variants of homesh's defaults, on the same Gmsh rows\n")
        md += [f"- `{v}`: " + "; ".join(targets(analyse(rows, v))) for v in variants]
    with open(os.path.join(outdir, "volume_corpus.md"), "w") as f:
        f.write("\n".join(md) + "\n")
    plot(rows, E, os.path.join(outdir, "volume_corpus.png"))
    print("\n".join(targets(E)))
    for v in variants:
        print(f"{v}: " + "; ".join(targets(analyse(rows, v))))


# ---------------------------------------------------------------- main

def append_row(csv_path, row):
    with open(csv_path, "a", newline="") as f:
        csv.DictWriter(f, fieldnames=FIELDS).writerow(row)
    w = f"{row['worst']:.4f}" if isinstance(row["worst"], float) else row["worst"]
    s = f"{row['seconds']:.3f}" if isinstance(row["seconds"], float) else row["seconds"]
    print(f"   p={row['p']} {row['method']:<18} {row['status']:<8} inv {row['invalid']!s:<5} "
          f"worst {w:<8} {s:>8} s {row['peak_mb']!s:>7} MB {row['error'][:60]}", flush=True)


def run_case(c, orders, methods, args, csv_path, done):
    """Every (p, method) of case c not in `done`, a row each."""
    timed_out = {(m, q) for (n, q, m), status in done.items()
                 if n == c.name and status == "timeout"}
    for p in orders:
        for m in methods:
            if (c.name, p, m) in done:
                continue
            if any(q < p for (n, q) in timed_out if n == m):
                rec, res = None, dict(status="timeout", error="not run: timed out at a lower p")
            else:
                rec, res = run_one(c.name, p, m, args.timeout)
                if args.repeat > 1:
                    res = corpus.least_time(lambda: run_one(c.name, p, m, args.timeout)[1],
                                            args.repeat, args.repeat_under, first=res)
            if res["status"] == "timeout":
                timed_out.add((m, p))
            row = {k: "" for k in FIELDS}
            row.update(res)
            row.update(case=c.name, p=p, method=m,
                       **{k: rec[k] if rec else "" for k in ("tetrahedra", "worst_shape",
                                                             "wall_caps")})
            append_row(csv_path, row)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cases", help="comma-separated case name patterns (substring or glob)")
    ap.add_argument("--orders", default="2,3,4")
    ap.add_argument("--methods", default=",".join(METHODS),
                    help="comma-separated method names or globs (default: all)")
    ap.add_argument("--variant", action="append", default=[],
                    help="also run homesh with these curve options, k=v:k=v (repeatable); "
                         "its rows are method 'homesh k=v:k=v'")
    ap.add_argument("--out", default=os.path.join(ROOT, "out", "bench", "volume_corpus"))
    ap.add_argument("--timeout", type=float, default=300.0,
                    help="seconds a method may take (curving + referee) before it is killed")
    ap.add_argument("--repeat", type=int, default=1,
                    help="runs in all of a valid method under --repeat-under seconds, its "
                         "least time kept")
    ap.add_argument("--repeat-under", type=float, default=1.0)
    ap.add_argument("--report-only", action="store_true",
                    help="only remake the table and plot from OUT/volume_corpus.csv")
    args = ap.parse_args(argv)
    os.makedirs(args.out, exist_ok=True)
    csv_path = os.path.join(args.out, "volume_corpus.csv")
    if args.report_only:
        report(csv_path, args.out)
        return 0
    orders = [int(p) for p in args.orders.split(",")]
    methods = [m for m in METHODS
               if any(fnmatch.fnmatch(m, pat) for pat in args.methods.split(",") if pat)]
    methods += ["homesh " + v for v in args.variant]
    done = {}
    if os.path.exists(csv_path):   # resume: keep the rows of an earlier, stopped run
        done = {(r["case"], int(r["p"]), r["method"]): r["status"]
                for r in csv.DictReader(open(csv_path))}
    else:
        with open(csv_path, "w", newline="") as f:
            csv.DictWriter(f, fieldnames=FIELDS).writeheader()
    start = time.time()
    cases = corpus3d.select(args.cases)
    for i, c in enumerate(cases):
        print(f"[{i + 1}/{len(cases)} {time.time() - start:.0f} s] {c.name}", flush=True)
        run_case(c, orders, methods, args, csv_path, done)
    print(f"run: {time.time() - start:.0f} s")
    report(csv_path, args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
