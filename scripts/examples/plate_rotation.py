#!/usr/bin/python3
"""Plate with a hole: the rotation benchmark of thesis Section 4.4.1 driven from Python.

A worked example of `import homesh` (run with PYTHONPATH=build/python):

  1. gmsh.open("geo/plate_hole_fig413.geo"): the coarse plate of the thesis' Fig 4.13 (our
     stand-in, see geo/README.md); homesh.mesh() meshes it (71 triangles) and
     homesh.curve(p=2, rings=0) makes it quadratic with the hole's nodes on the circle, the
     elastic solve on the whole mesh (the thesis' setting: curve's default solves first
     only round the poor elements, and the hole then turns a few degrees less);
  2. homesh.rotate turns the hole anticlockwise 1 degree per step until the first step that
     would leave a triangle not certified valid; theta_max is the last valid angle. Each
     formulation of the elastic analogy (thesis Table 4.9's cases) at each Poisson ratio nu
     starts again from step 1;
  3. theta_max against nu per formulation, ours solid and the thesis' Tables 4.1-4.8 dashed,
     as a PNG, and the numbers as CSV.

Exactly the CLI's pipeline: case 1 at nu = 0.4 is
  homesh geo/plate_hole_fig413.geo -m mesh -m curve:p=2:rings=0 -m rotate:nu=0.4:formulation=plain
By default 4 formulations x 4 Poisson ratios (a few seconds); --all runs the thesis' 8 x 7.
The heat-type formulations take the scales scripts/rotation_benchmark.py found best (the
thesis does not give its scale). scripts/rotation_benchmark.py is the full study (scale
sweeps, the thesis' CG solver, variants).

Usage: plate_rotation.py [--all] [--solver cg] [--out out/examples/plate_rotation]
"""
import argparse
import csv
import os
import sys
import time

import gmsh

import homesh

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
# Table 4.9's cases 1-8 in the names of homesh's formulations (curving/analogy_formulation.h).
CASES = ["plain", "area", "force_q17", "heat_q17", "heat_q4", "metric_ref", "metric_ideal",
         "stiff_q17"]
NUS = [0.05, 0.15, 0.25, 0.30, 0.35, 0.40, 0.45]
# The scale of the added term per formulation (option heat), as tuned by
# scripts/rotation_benchmark.py on this mesh; the others ignore it.
HEAT = {"force_q17": -1e-3, "heat_q17": 3e-3, "heat_q4": 3e-4, "metric_ref": 1e-4,
        "metric_ideal": 1e-4}
QUICK_CASES = ["plain", "area", "heat_q17", "stiff_q17"]
QUICK_NUS = [0.05, 0.25, 0.40, 0.45]


def read_thesis(path):
    """{(case, nu): theta_max} of the thesis' Tables 4.1-4.8."""
    with open(path) as f:
        rows = csv.DictReader(line for line in f if not line.startswith("#"))
        return {(int(r["case"]), float(r["nu"])): int(r["theta_max"]) for r in rows}


def quadratic_plate(geo):
    """The current model: the plate of `geo`, meshed and curved to order 2 by homesh, the
    elastic solve on the whole mesh (the thesis' setting)."""
    gmsh.clear()
    gmsh.open(geo)
    homesh.mesh()
    return homesh.curve(p=2, rings=0)["triangles"]


def rotate(geo, formulation, nu, solver):
    """One rotation of a fresh quadratic plate: homesh.rotate's result dict."""
    quadratic_plate(geo)
    options = {"formulation": formulation, "nu": nu, "heat": HEAT.get(formulation, 1)}
    if solver == "cg":
        options.update(solver="cg", preconditioner="jacobi")
    return homesh.rotate(wall="hole", step=1, **options)


def plot(path, rows, cases, nus):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(7, 5))
    colours = plt.get_cmap("tab10")
    for name in cases:
        case = CASES.index(name) + 1
        mine = [r for r in rows if r["formulation"] == name]
        c = colours(case - 1)
        ax.plot([r["nu"] for r in mine], [r["theta_max"] for r in mine], "-o", color=c, ms=4,
                label=f"case {case}: {name}")
        ax.plot([r["nu"] for r in mine], [r["thesis_theta_max"] for r in mine], "--", color=c,
                lw=1)
    ax.set_title("Plate with a hole: theta_max (homesh solid, thesis Tables 4.1-4.8 dashed)")
    ax.set_xlabel("Poisson's ratio nu")
    ax.set_ylabel("theta_max (degrees)")
    ax.set_xticks(nus)
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--all", action="store_true", help="the thesis' 8 cases x 7 nu")
    parser.add_argument("--solver", choices=["ldlt", "cg"], default="ldlt",
                        help="ldlt (direct) or Jacobi CG (the thesis' kind)")
    parser.add_argument("--geo", default=os.path.join(ROOT, "geo", "plate_hole_fig413.geo"))
    parser.add_argument("--reference", default=os.path.join(
        ROOT, "tests", "data", "thesis", "tables_4_1_to_4_8_rotation.csv"))
    parser.add_argument("--out", default=os.path.join(ROOT, "out", "examples", "plate_rotation"))
    args = parser.parse_args()
    cases, nus = (CASES, NUS) if args.all else (QUICK_CASES, QUICK_NUS)
    thesis = read_thesis(args.reference)
    os.makedirs(args.out, exist_ok=True)

    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    homesh.set_quiet()
    triangles = quadratic_plate(args.geo)
    print(f"{os.path.relpath(args.geo, ROOT)}: {triangles} quadratic triangles", flush=True)
    rows = []
    start = time.time()
    for name in cases:
        case = CASES.index(name) + 1
        for nu in nus:
            res = rotate(args.geo, name, nu, args.solver)["results"]
            rows.append({"case": case, "formulation": name, "nu": nu,
                         "heat": HEAT.get(name, 1), "theta_max": int(res["theta_max"]),
                         "thesis_theta_max": thesis[(case, nu)],
                         "worst_ratio": round(res["worst"], 5),
                         "mean_iterations": round(res["mean_iterations"], 1)})
            print(f"case {case} {name:12s} nu {nu:.2f}: theta_max {rows[-1]['theta_max']:3d} "
                  f"(thesis {rows[-1]['thesis_theta_max']})", flush=True)
    gmsh.finalize()

    table = os.path.join(args.out, "plate_rotation.csv")
    with open(table, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    picture = os.path.join(args.out, "plate_rotation.png")
    plot(picture, rows, cases, nus)
    print(f"{len(rows)} rotations, {time.time() - start:.1f} s; wrote {table} and {picture}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
