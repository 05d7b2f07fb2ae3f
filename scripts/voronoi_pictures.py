#!/usr/bin/python3
"""PNG pictures of the Voronoi regions and dual triangulations of the thesis
examples (thesis Section 2.7: Fig 2.2 five seeds under three metrics, the
Labelle-Shewchuk ten seeds of Figs 2.4 and 2.5, the 17 seeds of Fig 2.6, the
aerofoil with 130 seeds of Figs 2.7 and 2.8).

usage: scripts/voronoi_pictures.py BUILD_DIR [OUT_DIR]

Runs BUILD_DIR/tests/test_numeric "[.voronoi_pictures]" (the examples are
built in tests/voronoi/thesis_examples.h), which writes CSV files into OUT_DIR
(default BUILD_DIR/voronoi_pictures), then draws one PNG per example and
engine: the metric as ellipses of its unit ball (scaled) on the left, the
regions with the seeds, the dual triangles and the faults the refinement left
(red crosses) on the right.
Needs Debian's python3 with numpy and matplotlib.
"""
import csv
import glob
import os
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.patches import Ellipse  # noqa: E402


def read_rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def ellipse(x, y, m11, m12, m22, scale):
    """The unit ball of M = [[m11, m12], [m12, m22]] (semi-axes 1/sqrt(lambda))."""
    lam, vec = np.linalg.eigh(np.array([[m11, m12], [m12, m22]]))
    axes = scale / np.sqrt(lam)
    angle = np.degrees(np.arctan2(vec[1, 0], vec[0, 0]))
    return Ellipse((x, y), 2 * axes[0], 2 * axes[1], angle=angle, fill=False, lw=0.6, color="k")


def draw(prefix, out_png):
    g = read_rows(prefix + "_grid.csv")[0]
    x0, y0, dx, dy = (float(g[k]) for k in ("x0", "y0", "dx", "dy"))
    nx, ny = int(g["nx"]), int(g["ny"])
    extent = (x0 - dx / 2, x0 + (nx - 0.5) * dx, y0 - dy / 2, y0 + (ny - 0.5) * dy)
    labels = np.loadtxt(prefix + "_labels.csv", delimiter=",", dtype=int).reshape(ny, nx)
    seeds = np.array([[float(r["x"]), float(r["y"])] for r in read_rows(prefix + "_seeds.csv")])
    tris = np.array([[int(r["a"]), int(r["b"]), int(r["c"])]
                     for r in read_rows(prefix + "_triangles.csv")], dtype=int).reshape(-1, 3)
    metric = read_rows(prefix + "_metric.csv")
    if len(metric) > 400:  # at most about 20 by 20 ellipses
        step = int(np.ceil(np.sqrt(len(metric) / 400)))
        side = int(round(np.sqrt(len(metric))))
        metric = [r for k, r in enumerate(metric) if (k % side) % step == 0 and (k // side) % step == 0]
    faults = read_rows(prefix + "_faults.csv")
    boundary = read_rows(prefix + "_boundary.csv")

    fig, (left, right) = plt.subplots(1, 2, figsize=(13, 6.5))
    scale = 0.5 * min(extent[1] - extent[0], extent[3] - extent[2]) / max(
        1.0, np.sqrt(len(metric))) / max(1e-300, max(
            1 / np.sqrt(np.linalg.eigvalsh([[float(r["m11"]), float(r["m12"])],
                                            [float(r["m12"]), float(r["m22"])]])[0])
            for r in metric))
    for r in metric:
        left.add_patch(ellipse(float(r["x"]), float(r["y"]), float(r["m11"]), float(r["m12"]),
                               float(r["m22"]), scale))
    rng = np.random.default_rng(3)
    colours = np.vstack([[1, 1, 1], 0.35 + 0.65 * rng.random((len(seeds) + 1, 3))])
    right.imshow(colours[labels + 1], origin="lower", extent=extent, interpolation="nearest")
    for t in tris:
        loop = np.append(t, t[0])
        right.plot(seeds[loop, 0], seeds[loop, 1], "k-", lw=0.6)
    for r in faults:
        right.plot(float(r["x"]), float(r["y"]), "rx", ms=8, mew=2)
    for ax in (left, right):
        loops = {}
        for r in boundary:
            loops.setdefault(r["loop"], []).append((float(r["x"]), float(r["y"])))
        for pts in loops.values():
            p = np.array(pts + pts[:1])
            ax.plot(p[:, 0], p[:, 1], "b-", lw=1.0)
        ax.plot(seeds[:, 0], seeds[:, 1], "k.", ms=3)
        ax.set_xlim(extent[0], extent[1])
        ax.set_ylim(extent[2], extent[3])
        ax.set_aspect("equal")
    name = os.path.basename(prefix)
    left.set_title(f"{name}: metric (unit balls, scaled)")
    right.set_title(f"regions and dual: {len(tris)} triangles, {float(g['seconds']):.2f} s, "
                    f"check {'ok' if g['check_ok'] == '1' else 'FAILED'}, "
                    f"+{g['added']} seeds, {g['isolated']} isolated")
    fig.tight_layout()
    fig.savefig(out_png, dpi=110)
    plt.close(fig)


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    build = sys.argv[1]
    out = sys.argv[2] if len(sys.argv) > 2 else os.path.join(build, "voronoi_pictures")
    os.makedirs(out, exist_ok=True)
    env = dict(os.environ, HOMESH_VORONOI_OUT=out)
    subprocess.run([os.path.join(build, "tests", "test_numeric"), "[.voronoi_pictures]"],
                   check=True, env=env)
    for grid in sorted(glob.glob(os.path.join(out, "*_grid.csv"))):
        prefix = grid[: -len("_grid.csv")]
        draw(prefix, prefix + ".png")
        print("wrote", prefix + ".png")


if __name__ == "__main__":
    main()
