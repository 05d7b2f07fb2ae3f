#!/usr/bin/python3
"""Rotation benchmark of thesis Section 4.4.1 (Tables 4.1-4.8) with homesh's `rotate` stage.

The hole of a coarse quadratic plate mesh (geo/plate_hole_fig413.geo, our stand-in for the
thesis' Fig 4.13) turns anticlockwise 1 degree per step until the first step that would leave
an element not certified valid; theta_max is the last valid angle and N the mean CG
iterations per step. Five parts:

  heat      theta_max of every formulation with a `heat` scale (added body force, heat or
            metric stress) over a range of scales and both signs; the thesis does not give its
            scale, so each formulation takes the one with the largest mean theta_max over nu
            (one value for all nu), unless --heat fixes it;
  table     the 8 formulations of Table 4.9 x 7 Poisson ratios as the thesis ran them (one
            solve per degree on the current mesh, CG with a Jacobi preconditioner standing in
            for its element-by-element PCG), beside the thesis values;
  variants  homesh's own: each step posed on the initial mesh, and 2 or 4 solves per degree;
  homesh    homesh's stiffening formulations (stiff_shape, stiff_shear) at their benchmarked
            power, one solve per degree on the current mesh (direct solver), beside the
            thesis' best case at each nu;
  plot      theta_max against nu per formulation, ours solid, the thesis dashed; and the best
            of all runs per formulation against the thesis' best case.

Writes into --out (default out/rotation): rotation_table.csv, rotation_sweeps.csv (heat and
variants), rotation_homesh.csv, rotation_summary.md (the tables, and the thesis' orderings
reproduced or not) and rotation.png. The full run takes about a minute (71 triangles, 679
rotations).

Run from the repository root:
  PYTHONPATH=build/python /usr/bin/python3 scripts/rotation_benchmark.py [--quick]
"""
import argparse
import csv
import itertools
import os
import time

import gmsh
import homesh

# Table 4.9's cases 1-8 in the names of homesh's formulations (curving/analogy_formulation.h).
CASES = ["plain", "area", "force_q17", "heat_q17", "heat_q4", "metric_ref", "metric_ideal",
         "stiff_q17"]
NUS = [0.05, 0.15, 0.25, 0.30, 0.35, 0.40, 0.45]
# Formulations with a `heat` scale (added body force, heat or metric stress).
SCALED = ["force_q17", "heat_q17", "heat_q4", "metric_ref", "metric_ideal", "heat_area"]
# The added terms act in full at every solve (not in proportion to the step), so the useful
# scales are small: about 1e-3 for 1 degree per step.
HEATS = [-0.01, -0.001, 1e-4, 3e-4, 1e-3, 3e-3, 1e-2, 3e-2, 0.1, 0.3, 1]
THESIS_SOLVER = {"solver": "cg", "preconditioner": "jacobi"}
# homesh's stiffening formulations (curving/analogy_formulation.h) and the power each is run at.
HOMESH = [("stiff_shape", 2), ("stiff_shear", 3)]


def read_thesis(path):
    """{(case, nu): (theta_max, N)} from the oracle CSV."""
    rows = {}
    with open(path) as f:
        for row in csv.DictReader(line for line in f if not line.startswith("#")):
            rows[(int(row["case"]), float(row["nu"]))] = (int(row["theta_max"]), int(row["N"]))
    return rows


class Benchmark:
    def __init__(self, geo, numbers, max_angle):
        self.geo = geo
        self.numbers = numbers
        self.max_angle = max_angle
        self.runs = 0
        self.triangles = 0
        self.seconds = 0.0

    def rotate(self, **options):
        """theta_max, N, worst minJ/maxJ of one rotation of a freshly meshed plate."""
        gmsh.clear()
        for name, value in self.numbers:
            gmsh.onelab.setNumber(name, [value])
        gmsh.open(self.geo)
        gmsh.model.mesh.generate(2)
        gmsh.model.mesh.setOrder(2)
        start = time.time()
        r = homesh.rotate(wall="hole", step=1, max=self.max_angle, **options)
        self.seconds += time.time() - start
        self.runs += 1
        self.triangles = r["triangles"]
        res = r["results"]
        return {"theta_max": int(res["theta_max"]), "N": round(res["mean_iterations"], 1),
                "worst_ratio": round(res["worst"], 5)}


def run_table(bench, thesis, nus, heat):
    """The 8 cases x nus with the thesis' solver; heat[name] is the scale of case `name`."""
    rows = []
    for case, name in enumerate(CASES, start=1):
        for nu in nus:
            h = heat.get(name, 1)
            r = bench.rotate(formulation=name, nu=nu, heat=h, **THESIS_SOLVER)
            t_theta, t_n = thesis[(case, nu)]
            rows.append({"case": case, "formulation": name, "nu": nu, "heat": h,
                         "theta_max": r["theta_max"], "N": r["N"], "thesis_theta_max": t_theta,
                         "thesis_N": t_n, "worst_ratio": r["worst_ratio"]})
            print(f"case {case} {name:12s} nu {nu:.2f} heat {h:g}: theta_max {r['theta_max']:3d} "
                  f"(thesis {t_theta}), N {r['N']:.0f} (thesis {t_n})", flush=True)
    return rows


def run_heat_sweep(bench, nus, heats):
    """theta_max of every scaled formulation at every heat (direct solver)."""
    rows = []
    for formulation, nu, heat in itertools.product(SCALED, nus, heats):
        r = bench.rotate(formulation=formulation, nu=nu, heat=heat, solver="ldlt")
        rows.append({"formulation": formulation, "nu": nu, "heat": heat, "pose": "current",
                     "substeps": 1, "theta_max": r["theta_max"]})
        print(f"heat {formulation:12s} nu {nu:.2f} heat {heat:g}: theta_max {r['theta_max']}",
              flush=True)
    return rows


def tuned_heat(sweep):
    """Per formulation, the heat with the largest mean theta_max over nu (one value for all nu)."""
    totals = {}
    for r in sweep:
        key = (r["formulation"], r["heat"])
        totals[key] = totals.get(key, 0) + r["theta_max"]
    best = {}
    for (f, h), total in sorted(totals.items()):
        if f not in best or total > totals[(f, best[f])]:
            best[f] = h
    return best


def run_variants(bench, nus, heat):
    """homesh's variants beyond the thesis: each step posed on the initial mesh, and 2 or 4
    solves per degree, at the tuned heat."""
    rows = []

    def add(formulation, nu, pose, substeps):
        h = heat.get(formulation, 1)
        r = bench.rotate(formulation=formulation, nu=nu, heat=h, pose=pose, substeps=substeps,
                         solver="ldlt")
        rows.append({"formulation": formulation, "nu": nu, "heat": h, "pose": pose,
                     "substeps": substeps, "theta_max": r["theta_max"]})
        print(f"variant {formulation:12s} nu {nu:.2f} heat {h:g} {pose:7s} x{substeps}: "
              f"theta_max {r['theta_max']}", flush=True)

    for formulation, nu in itertools.product(["plain", "area", "stiff_q17"], nus):
        add(formulation, nu, "initial", 1)
    for formulation, nu, substeps in itertools.product(CASES + ["heat_area"], nus, [2, 4]):
        add(formulation, nu, "current", substeps)
    return rows


def run_homesh(bench, thesis, nus):
    """homesh's formulations of HOMESH at every nu, one solve per degree on the current mesh,
    beside the thesis' best of its 8 cases at that nu."""
    rows = []
    for (name, power), nu in itertools.product(HOMESH, nus):
        r = bench.rotate(formulation=name, nu=nu, power=power, solver="ldlt")
        best = max(theta for (_, n), (theta, _) in thesis.items() if n == nu)
        rows.append({"formulation": name, "power": power, "nu": nu, "theta_max": r["theta_max"],
                     "thesis_best": best, "worst_ratio": r["worst_ratio"]})
        print(f"homesh {name:12s} power {power:g} nu {nu:.2f}: theta_max {r['theta_max']:3d} "
              f"(thesis' best {best})", flush=True)
    return rows


def write_csv(path, rows):
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)


def by_case(rows, key):
    out = {}
    for r in rows:
        out.setdefault(r["case"], {})[r["nu"]] = r[key]
    return out


def orderings(rows, nus):
    """The thesis' claims about Tables 4.1-4.9 as (claim, thesis, ours): a claim about every nu
    reads "k/n", the nu values where it holds; one about nu = 0.45 reads yes or no."""
    hi = max(nus)
    low = [nu for nu in nus if nu <= 0.35]

    def claims(t, n):
        def count(holds, values=nus):
            return f"{sum(bool(holds(nu)) for nu in values)}/{len(values)}"

        def yes(holds):
            return "yes" if holds else "no"

        def best(nu):
            return max(t[c][nu] for c in range(1, 9))
        return [
            ("case 1: theta_max grows with nu (consecutive pairs)",
             count(lambda k: t[1][nus[k]] <= t[1][nus[k + 1]], range(len(nus) - 1))),
            ("case 2 (E = 1/Ae) > case 1", count(lambda nu: t[2][nu] > t[1][nu])),
            ("case 2 needs more CG iterations than case 1", count(lambda nu: n[2][nu] > n[1][nu])),
            ("case 3 (body force) = case 4 (heat)", count(lambda nu: t[3][nu] == t[4][nu])),
            ("case 3 (body force) > case 1", count(lambda nu: t[3][nu] > t[1][nu])),
            ("cases 4, 5 (heat) > case 1", count(lambda nu: min(t[4][nu], t[5][nu]) > t[1][nu])),
            ("cases 4, 5 (heat) > case 2", count(lambda nu: min(t[4][nu], t[5][nu]) > t[2][nu])),
            ("case 6 > case 1", count(lambda nu: t[6][nu] > t[1][nu])),
            ("case 7 (ideal) >= case 6 (reference)", count(lambda nu: t[7][nu] >= t[6][nu])),
            ("case 8 is the best case, nu <= 0.35", count(lambda nu: t[8][nu] >= best(nu), low)),
            (f"case 7 is the best case at nu = {hi}", yes(t[7][hi] >= best(hi))),
            (f"every added term beats case 1 at nu = {hi}",
             yes(all(t[c][hi] > t[1][hi] for c in range(2, 9)))),
        ]

    ours, theirs = by_case(rows, "theta_max"), by_case(rows, "thesis_theta_max")
    mine = claims(ours, by_case(rows, "N"))
    return [(a, b, d) for (a, b), (_, d) in zip(claims(theirs, by_case(rows, "thesis_N")), mine)]


def rank_at(rows, nu, key):
    vals = sorted(((r[key], r["case"]) for r in rows if r["nu"] == nu), reverse=True)
    return " > ".join(f"{c} ({v})" for v, c in vals)


def table_md(nus, rows, cell):
    lines = ["| case | formulation | " + " | ".join(f"nu {nu:.2f}" for nu in nus) + " |",
             "|---|---|" + "---|" * len(nus)]
    for case, name in enumerate(CASES, start=1):
        by_nu = {r["nu"]: r for r in rows if r["case"] == case}
        lines.append(f"| {case} | {name} | " + " | ".join(cell(by_nu[nu]) for nu in nus) + " |")
    return lines


def best_runs(rows, sweeps, homesh_rows):
    """Per formulation and nu, the run with the largest theta_max of the table, sweeps and
    homesh's formulations."""
    runs = [dict(r, pose="current", substeps=1) for r in rows] + sweeps
    runs += [dict(r, heat=1, pose="current", substeps=1) for r in homesh_rows]
    best = {}
    for r in runs:
        key = (r["formulation"], r["nu"])
        if key not in best or r["theta_max"] > best[key]["theta_max"]:
            best[key] = r
    return best


def homesh_md(nus, homesh_rows):
    """The table of homesh's formulations against the thesis' best case."""
    by = {(r["formulation"], r["nu"]): r for r in homesh_rows}
    lines = ["## homesh's stiffening formulations (1 solve per degree on the current mesh)", "",
             "| formulation | power | " + " | ".join(f"nu {nu:.2f}" for nu in nus) + " |",
             "|---|---|" + "---|" * len(nus)]
    for name, power in HOMESH:
        lines.append(f"| {name} | {power:g} | " +
                     " | ".join(str(by[(name, nu)]["theta_max"]) for nu in nus) + " |")
    lines.append("| thesis, best case | | " +
                 " | ".join(str(by[(HOMESH[0][0], nu)]["thesis_best"]) for nu in nus) + " |")
    return lines


def write_summary(path, rows, sweeps, homesh_rows, nus, bench, geo):
    heats = {r["formulation"]: r["heat"] for r in rows}
    lines = [f"# Rotation benchmark (thesis Tables 4.1-4.8) on {geo}", "",
             f"Mesh: {bench.triangles} quadratic triangles. {bench.runs} rotations, "
             f"{bench.seconds:.0f} s in homesh.rotate.", "",
             "## theta_max, ours / thesis (1 solve per degree on the current mesh)", "",
             "heat scale: " + ", ".join(f"{f} {h:g}" for f, h in heats.items() if f in SCALED), ""]
    lines += table_md(nus, rows, lambda r: f"{r['theta_max']} / {r['thesis_theta_max']}")
    lines += ["", "## N, mean CG iterations per degree, ours (Jacobi PCG) / thesis", ""]
    lines += table_md(nus, rows, lambda r: f"{r['N']:.0f} / {r['thesis_N']}")
    hi = max(nus)
    lines += ["", f"## Ranking of the cases at nu = {hi}", "",
              f"- thesis: {rank_at(rows, hi, 'thesis_theta_max')}",
              f"- ours:   {rank_at(rows, hi, 'theta_max')}", "",
              "## The thesis' orderings", "", "| claim | thesis | ours |", "|---|---|---|"]
    for claim, t, o in orderings(rows, nus):
        lines.append(f"| {claim} | {t} | {o} |")
    if homesh_rows:
        lines += [""] + homesh_md(nus, homesh_rows)
    if sweeps:
        at_one = {(s["formulation"], s["nu"]): s["theta_max"] for s in sweeps
                  if s["heat"] == 1 and s["pose"] == "current" and s["substeps"] == 1}
        if at_one:
            lines += ["", "## theta_max at heat = 1 (no scale tuning)", "",
                      "| formulation | " + " | ".join(f"nu {nu:.2f}" for nu in nus) + " |",
                      "|---|" + "---|" * len(nus)]
            for f in SCALED:
                lines.append(f"| {f} | " + " | ".join(str(at_one[(f, nu)]) for nu in nus) + " |")
        best = best_runs(rows, sweeps, homesh_rows)
        lines += ["", "## Best run per formulation: theta_max (heat, pose, solves per degree)", "",
                  "| formulation | " + " | ".join(f"nu {nu:.2f}" for nu in nus) + " |",
                  "|---|" + "---|" * len(nus)]
        for f in sorted({f for f, _ in best}):
            cells = [f"{b['theta_max']} ({b['heat']:g}, {b['pose']}, x{b['substeps']})"
                     for b in (best[(f, nu)] for nu in nus)]
            lines.append(f"| {f} | " + " | ".join(cells) + " |")
        theirs = by_case(rows, "thesis_theta_max")
        lines += ["", "| best of | " + " | ".join(f"nu {nu:.2f}" for nu in nus) + " |",
                  "|---|" + "---|" * len(nus),
                  "| ours | " + " | ".join(str(max(b["theta_max"] for (f, n), b in best.items()
                                                   if n == nu)) for nu in nus) + " |",
                  "| thesis | " + " | ".join(str(max(theirs[c][nu] for c in theirs))
                                            for nu in nus) + " |"]
    with open(path, "w") as out:
        out.write("\n".join(lines) + "\n")


def plot(path, rows, sweeps, homesh_rows, nus):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    ours, theirs = by_case(rows, "theta_max"), by_case(rows, "thesis_theta_max")
    panels = 2 if sweeps else 1
    fig, axes = plt.subplots(1, panels, figsize=(7 * panels, 5.5), squeeze=False)
    colours = plt.get_cmap("tab10")
    ax = axes[0][0]
    for case, name in enumerate(CASES, start=1):
        c = colours(case - 1)
        ax.plot(nus, [ours[case][nu] for nu in nus], "-o", color=c, ms=3, label=f"{case} {name}")
        ax.plot(nus, [theirs[case][nu] for nu in nus], "--", color=c, lw=1)
    ax.set_title("theta_max, thesis procedure, tuned heat (ours solid, thesis dashed)")
    ax.set_xlabel("Poisson's ratio nu")
    ax.set_ylabel("theta_max (degrees)")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    if sweeps:
        ax = axes[0][1]
        best = best_runs(rows, sweeps, homesh_rows)
        many = plt.get_cmap("tab20")  # more formulations than tab10 has colours: dark ones first
        for k, f in enumerate(sorted({f for f, _ in best})):
            ax.plot(nus, [best[(f, nu)]["theta_max"] for nu in nus], "-o", ms=3,
                    color=many((2 * k) % 20 + (2 * k) // 20 % 2), label=f)
        ax.plot(nus, [max(theirs[c][nu] for c in theirs) for nu in nus], "k--", lw=1.5,
                label="thesis, best case")
        ax.set_title("best run per formulation (heat scale, pose, solves per degree)")
        ax.set_xlabel("Poisson's ratio nu")
        ax.legend(fontsize=8)
        ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--geo", default=os.path.join(root, "geo", "plate_hole_fig413.geo"))
    ap.add_argument("--setnumber", nargs=2, action="append", default=[], metavar=("NAME", "VALUE"),
                    help="ONELAB parameter of the .geo, e.g. 'Mesh size/LcHole' 0.25 with "
                         "--geo geo/plate_hole.geo (repeatable)")
    ap.add_argument("--out", default=os.path.join(root, "out", "rotation"))
    ap.add_argument("--reference", default=os.path.join(
        root, "tests", "data", "thesis", "tables_4_1_to_4_8_rotation.csv"))
    ap.add_argument("--max", type=float, default=360, help="largest angle tried, degrees")
    ap.add_argument("--heat", type=float, help="one heat scale for every formulation (no sweep)")
    ap.add_argument("--no-variants", action="store_true", help="skip homesh's variants")
    ap.add_argument("--no-homesh", action="store_true",
                    help="skip homesh's stiffening formulations")
    ap.add_argument("--quick", action="store_true", help="nu = 0.05, 0.25, 0.45, four heats")
    args = ap.parse_args()

    nus = [0.05, 0.25, 0.45] if args.quick else NUS
    heats = [3e-4, 1e-3, 3e-3, 1] if args.quick else HEATS
    os.makedirs(args.out, exist_ok=True)
    thesis = read_thesis(args.reference)
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    homesh.set_quiet()
    bench = Benchmark(args.geo, [(n, float(v)) for n, v in args.setnumber], args.max)
    start = time.time()
    if args.heat is None:
        sweeps = run_heat_sweep(bench, nus, heats)
        heat = tuned_heat(sweeps)
    else:
        sweeps, heat = [], {f: args.heat for f in SCALED}
    rows = run_table(bench, thesis, nus, heat)
    if not args.no_variants:
        sweeps += run_variants(bench, nus, heat)
    homesh_rows = [] if args.no_homesh else run_homesh(bench, thesis, nus)
    gmsh.finalize()

    write_csv(os.path.join(args.out, "rotation_table.csv"), rows)
    if sweeps:
        write_csv(os.path.join(args.out, "rotation_sweeps.csv"), sweeps)
    if homesh_rows:
        write_csv(os.path.join(args.out, "rotation_homesh.csv"), homesh_rows)
    mesh = os.path.relpath(args.geo, root) + "".join(f", {n} = {v}" for n, v in args.setnumber)
    write_summary(os.path.join(args.out, "rotation_summary.md"), rows, sweeps, homesh_rows, nus,
                  bench, mesh)
    plot(os.path.join(args.out, "rotation.png"), rows, sweeps, homesh_rows, nus)
    print(f"{bench.runs} rotations, {time.time() - start:.0f} s; wrote {args.out}/")


if __name__ == "__main__":
    main()
