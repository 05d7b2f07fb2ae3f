#!/usr/bin/python3
"""Pictures of the thesis chapter 3 study from the CSV tables homesh-study writes.

usage: plot_ch3.py OUTDIR

Reads OUTDIR/{gallery_samples,curvature,praxis_histories,interior_optimum,
interior_landscape,boundary_guidance}.csv and writes beside them:
  gallery.png            the elements T1-T12 (Fig 3.12) drawn curved, coloured by
                         det J / det J of the ideal element
  curvature.png          f against chi for every measure (Fig 3.32)
  praxis_histories.png   f at each PRAXIS evaluation, quadratic and cubic interior
                         cases (Figs 3.27(c), (e), 3.28)
  interior_landscape.png f of Q2 and Q8 over the free node of the quadratic case
                         (Fig 3.27(d), (f))
  boundary_optimum.png   the optimal boundary elements of Q4 and Q3 (Fig 3.29)
Only plotting happens here: every number comes from homesh-study.
"""
import csv
import math
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.tri as mtri  # noqa: E402
import numpy as np  # noqa: E402


def rows(path):
    with open(path) as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def number(text):
    return float(text) if text not in ("", "nan") else math.nan


def lattice_triangles(u, v):
    """Triangles (index triples) of the samples, a lattice (i, j) / n of the reference triangle."""
    n = int(round(1.0 / np.min(u[u > 1e-12])))
    index = {(int(round(a * n)), int(round(b * n))): k for k, (a, b) in enumerate(zip(u, v))}
    triangles = []
    for i in range(n):
        for j in range(n - i):
            triangles.append([index[(i, j)], index[(i + 1, j)], index[(i, j + 1)]])
            if i + j + 2 <= n:
                triangles.append([index[(i + 1, j)], index[(i + 1, j + 1)], index[(i, j + 1)]])
    return np.array(triangles)


def plot_gallery(out):
    samples = defaultdict(list)
    nodes = defaultdict(list)
    for r in rows(f"{out}/gallery_samples.csv"):
        (nodes if r["kind"] == "node" else samples)[r["element"]].append(r)
    names = list(samples)
    fig, axes = plt.subplots(3, 4, figsize=(13, 10))
    levels = np.linspace(0.0, 2.4, 25)
    for ax, name in zip(axes.flat, names):
        s = samples[name]
        u = np.array([number(r["u"]) for r in s])
        v = np.array([number(r["v"]) for r in s])
        x = np.array([number(r["x"]) for r in s])
        y = np.array([number(r["y"]) for r in s])
        omega = np.array([number(r["omega"]) for r in s])
        # The samples are a lattice of the reference triangle: its structured
        # triangles, drawn at the mapped points, fill the curved element exactly.
        tri = mtri.Triangulation(x, y, lattice_triangles(u, v))
        filled = ax.tricontourf(tri, np.clip(omega, levels[0], levels[-1]), levels=levels,
                                cmap="RdYlBu")
        boundary = np.isclose(v, 0) | np.isclose(u + v, 1) | np.isclose(u, 0)
        angle = np.where(np.isclose(v, 0), u, np.where(np.isclose(u + v, 1), 1 + v, 3 - v))
        order = np.argsort(angle[boundary])
        bx, by = x[boundary][order], y[boundary][order]
        ax.plot(np.append(bx, bx[0]), np.append(by, by[0]), "k-", lw=1.2)
        n = nodes[name]
        ax.plot([number(r["x"]) for r in n], [number(r["y"]) for r in n], "ko", ms=3)
        ax.set_title(f"{name} (p = {n[0]['order']})")
        ax.set_aspect("equal")
        ax.axis("off")
    fig.colorbar(filled, ax=axes, shrink=0.6, label="det J / det J of the ideal element")
    fig.suptitle("Gallery T1-T12 (thesis Fig 3.12), drawn from geo/gallery_t1_t12.csv")
    fig.savefig(f"{out}/gallery.png", dpi=110)
    plt.close(fig)


def plot_curvature(out):
    data = rows(f"{out}/curvature.csv")
    chi = [number(r["chi"]) for r in data]
    measures = [k for k in data[0] if k != "chi"]
    fig, axes = plt.subplots(4, 4, figsize=(13, 11), sharex=True)
    for ax, m in zip(axes.flat, measures):
        ax.plot(chi, [number(r[m]) for r in data], "b-")
        ax.axvline(0, color="0.7", lw=0.8)
        ax.set_title(m)
        ax.grid(alpha=0.3)
    for ax in axes[-1]:
        ax.set_xlabel("chi = d / c  (< 0 convex, > 0 concave)")
    for ax in axes[:, 0]:
        ax.set_ylabel("f (Eq 3.48, r = 2)")
    fig.suptitle("Distortion against boundary-edge curvature (thesis Fig 3.32)")
    fig.tight_layout()
    fig.savefig(f"{out}/curvature.png", dpi=110)
    plt.close(fig)


def plot_histories(out):
    history = defaultdict(list)
    for r in rows(f"{out}/praxis_histories.csv"):
        history[(r["case"], r["measure"])].append(number(r["f"]))
    cases = sorted({c for c, _ in history}, reverse=True)
    fig, axes = plt.subplots(1, len(cases), figsize=(13, 5), sharey=True)
    for ax, case in zip(np.atleast_1d(axes), cases):
        ax.set_prop_cycle(color=plt.get_cmap("tab20").colors)
        for (c, m), f in history.items():
            if c != case:
                continue
            best = np.minimum.accumulate(np.array(f))
            ax.semilogy(np.arange(1, len(best) + 1), np.maximum(best, 1e-16), label=m, lw=1)
        ax.set_title(f"{case}: best f so far")
        ax.set_xlabel("PRAXIS evaluation")
        ax.grid(alpha=0.3)
    np.atleast_1d(axes)[0].set_ylabel("f")
    np.atleast_1d(axes)[-1].legend(ncol=2, fontsize=8)
    fig.suptitle("PRAXIS convergence, interior elements (thesis Figs 3.27, 3.28, Tables 3.3, 3.5)")
    fig.tight_layout()
    fig.savefig(f"{out}/praxis_histories.png", dpi=110)
    plt.close(fig)


def plot_landscape(out):
    case = next(r for r in rows(f"{out}/interior_optimum.csv") if r["case"] == "quadratic_interior")
    data = defaultdict(list)
    for r in rows(f"{out}/interior_landscape.csv"):
        data[r["measure"]].append((number(r["x"]), number(r["y"]), number(r["f"])))
    fig, axes = plt.subplots(1, len(data), figsize=(12, 5))
    for ax, (m, pts) in zip(np.atleast_1d(axes), data.items()):
        a = np.array(pts)
        n = int(round(math.sqrt(len(a))))
        x, y = a[:, 0].reshape(n, n), a[:, 1].reshape(n, n)
        f = np.log10(np.clip(np.nan_to_num(a[:, 2].reshape(n, n), posinf=1e3), 1e-4, 1e3))
        c = ax.contourf(x, y, f, levels=30, cmap="viridis")
        ax.plot([0, 1, 0.5, 0], [0, 0, math.sqrt(3) / 2, 0], "w-", lw=1)
        ax.plot([number(case["ideal_x"])], [number(case["ideal_y"])], "r*", ms=12,
                label="equilateral position")
        ax.plot([number(case["start_x"])], [number(case["start_y"])], "wo", ms=5, label="start")
        ax.set_xlim(x.min(), x.max())
        ax.set_ylim(y.min(), y.max())
        ax.set_title(f"{m}: log10 f over the free mid-node")
        ax.set_aspect("equal")
        ax.legend(fontsize=8, loc="upper right")
        fig.colorbar(c, ax=ax, shrink=0.8)
    fig.suptitle("Distortion landscape of the quadratic interior case (thesis Fig 3.27(d), (f))")
    fig.savefig(f"{out}/interior_landscape.png", dpi=110)
    plt.close(fig)


def quadratic_edge(a, m, b, t):
    return np.outer((1 - t) * (1 - 2 * t), a) + np.outer(4 * t * (1 - t), m) + np.outer(t * (2 * t - 1), b)


def plot_boundary(out):
    data = {r["measure"]: r for r in rows(f"{out}/boundary_guidance.csv")}
    h = math.sqrt(3) / 2
    fig, axes = plt.subplots(1, 4, figsize=(15, 4.5))
    t = np.linspace(0, 1, 60)
    for ax, m in zip(axes, ["Q4", "Q3", "Q2", "Q8"]):
        r = data[m]
        a, b, c = np.array([0, 0]), np.array([1, 0]), np.array([0.5, h])
        d = np.array([number(r["x3"]), number(r["y3"])])
        for start, mid4, mid5, style in [
            (True, (b + c) / 2, (c + a) / 2, "0.6"),
            (False, np.array([number(r["x4"]), number(r["y4"])]),
             np.array([number(r["x5"]), number(r["y5"])]), "k"),
        ]:
            pts = np.vstack([quadratic_edge(a, d, b, t), quadratic_edge(b, mid4, c, t),
                             quadratic_edge(c, mid5, a, t)])
            ax.plot(pts[:, 0], pts[:, 1], color=style, lw=1 if start else 1.6,
                    ls="--" if start else "-")
            ax.plot([d[0], mid4[0], mid5[0]], [d[1], mid4[1], mid5[1]], "o", color=style, ms=4)
        ax.set_title(f"{m}: {r['praxis']} (thesis: {r['thesis']})\nf0 = {number(r['f0']):.3g}, "
                     f"f = {number(r['praxis_f']):.3g}, N = {r['praxis_N']}", fontsize=9)
        ax.set_aspect("equal")
        ax.axis("off")
    fig.suptitle("Optimal boundary elements (thesis Fig 3.29): start dashed, PRAXIS optimum solid")
    fig.savefig(f"{out}/boundary_optimum.png", dpi=110)
    plt.close(fig)


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    out = sys.argv[1]
    plot_gallery(out)
    plot_curvature(out)
    plot_histories(out)
    plot_landscape(out)
    plot_boundary(out)
    print(f"plot_ch3: wrote the pictures to {out}")


if __name__ == "__main__":
    main()
