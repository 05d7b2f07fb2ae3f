#!/usr/bin/python3
"""Pictures of the boundary layers of thesis Section 4.3 (Figs 4.8-4.12).

usage: layers_pictures.py [OUTDIR]      (default out/layers)

Runs homesh ($HOMESH_BUILD_DIR/homesh, default build/homesh) on the geo/ fixtures:
  plate_hole.geo  3 layers around the hole (first 0.01, ratio 1.3), single normals
  naca.geo        15 layers (first 1e-3, ratio 1.2), single normals
  naca.geo        4 layers, single normals and 5 normals (fan_angle 320: the
                  trailing edge's domain angle is 326 deg)
keeps the .msh files, and writes beside them:
  plate_hole_layers.png       the plate and a close view of its hole (Fig 4.8)
  naca15_single.png           the aerofoil and its trailing edge, 15 layers (Fig 4.9)
  naca4_trailing_edge.png     the trailing edge, 4 layers, single and 5 normals (Fig 4.10)
  naca4_quality.png           the radius ratio Q of Eq 4.17 at the trailing edge, single
                              and 5 normals, on one colour scale (Fig 4.12)
Only plotting happens here: the meshes and Q (the view "radius ratio (Eq 4.17)" the
layers stage writes) come from homesh.
"""
import os
import subprocess
import sys

import gmsh
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
HOMESH = os.path.join(os.environ.get("HOMESH_BUILD_DIR", os.path.join(ROOT, "build")), "homesh")
RUNS = {
    "plate3": ("plate_hole.geo", "walls=hole:n=3:first=0.01:ratio=1.3"),
    "naca15": ("naca.geo", "walls=aerofoil:n=15:first=1e-3:ratio=1.2"),
    "naca4_single": ("naca.geo", "walls=aerofoil:n=4:first=1e-3:ratio=1.2"),
    "naca4_multi": ("naca.geo", "walls=aerofoil:n=4:first=1e-3:ratio=1.2:normals=multi:fan=5:"
                                "fan_angle=320"),
}
QUALITY_VIEW = "radius ratio (Eq 4.17)"


def run(out, name):
    geo, options = RUNS[name]
    msh = os.path.join(out, name + ".msh")
    log = subprocess.run([HOMESH, os.path.join(ROOT, "geo", geo), "-m", "mesh", "-m",
                          "layers:" + options, msh], capture_output=True, text=True)
    if log.returncode != 0:
        sys.exit(f"homesh failed on {name}:\n{log.stdout}{log.stderr}")
    print(f"{name}: " + " | ".join(line for line in log.stdout.splitlines()
                                    if line.startswith("layers: at") or "->" in line))
    return msh


def read(msh):
    """Node coordinates, triangles (node index triples) and Q per triangle of a linear .msh."""
    gmsh.clear()
    gmsh.open(msh)
    tags, coords, _ = gmsh.model.mesh.getNodes()
    index = {t: i for i, t in enumerate(tags)}
    x = np.reshape(coords, (-1, 3))[:, :2]
    etags, enodes = gmsh.model.mesh.getElementsByType(2)
    tri = np.array([index[t] for t in enodes]).reshape(-1, 3)
    q = np.full(len(etags), np.nan)
    for v in gmsh.view.getTags():
        if gmsh.option.getString(f"View[{gmsh.view.getIndex(v)}].Name") != QUALITY_VIEW:
            continue
        _, vtags, data, _, _ = gmsh.view.getModelData(v, 0)
        value = {t: d[0] for t, d in zip(vtags, data)}
        q = np.array([value[t] for t in etags])
    return x, tri, q


def draw(ax, mesh, centre, half_width, title, colour=None, aspect=0.75):
    x, tri, q = mesh
    ax.set_xlim(centre[0] - half_width, centre[0] + half_width)
    ax.set_ylim(centre[1] - aspect * half_width, centre[1] + aspect * half_width)
    ax.set_aspect("equal")
    ax.set_title(title, fontsize=10)
    ax.set_xticks([])
    ax.set_yticks([])
    if colour is None:
        ax.triplot(x[:, 0], x[:, 1], tri, lw=0.35, color="k")
        return None
    shown = ax.tripcolor(x[:, 0], x[:, 1], tri, facecolors=q, cmap="viridis", vmin=0, vmax=1,
                         edgecolors="k", linewidth=0.15)
    return shown


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "out", "layers")
    os.makedirs(out, exist_ok=True)
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    meshes = {name: read(run(out, name)) for name in RUNS}

    fig, axes = plt.subplots(1, 2, figsize=(12, 6))
    draw(axes[0], meshes["plate3"], (0, 0), 1.02, "3 layers around the hole", aspect=1)
    draw(axes[1], meshes["plate3"], (0.47, 0.17), 0.08, "close view", aspect=1)
    fig.savefig(os.path.join(out, "plate_hole_layers.png"), dpi=150, bbox_inches="tight")

    fig, axes = plt.subplots(1, 3, figsize=(16, 4.5))
    draw(axes[0], meshes["naca15"], (0.5, 0), 0.7, "NACA-7526, 15 layers, single normals")
    draw(axes[1], meshes["naca15"], (0.05, 0.05), 0.12, "leading edge")
    draw(axes[2], meshes["naca15"], (1.02, -0.01), 0.1, "trailing edge")
    fig.savefig(os.path.join(out, "naca15_single.png"), dpi=150, bbox_inches="tight")

    fig, axes = plt.subplots(1, 2, figsize=(12, 5))
    draw(axes[0], meshes["naca4_single"], (1.0, -0.002), 0.018, "4 layers, single normal")
    draw(axes[1], meshes["naca4_multi"], (1.0, -0.002), 0.018, "4 layers, 5 normals")
    fig.savefig(os.path.join(out, "naca4_trailing_edge.png"), dpi=150, bbox_inches="tight")

    fig, axes = plt.subplots(1, 2, figsize=(12.5, 5))
    for ax, name, title in ((axes[0], "naca4_single", "Q (Eq 4.17), single normal"),
                            (axes[1], "naca4_multi", "Q (Eq 4.17), 5 normals")):
        shown = draw(ax, meshes[name], (1.0, -0.002), 0.018, title, colour=True)
    fig.colorbar(shown, ax=axes, shrink=0.8, label="Q = 8 (p-a)(p-b)(p-c) / (abc)")
    fig.savefig(os.path.join(out, "naca4_quality.png"), dpi=150, bbox_inches="tight")
    gmsh.finalize()
    print(f"layers_pictures: wrote {out}/*.png")


if __name__ == "__main__":
    main()
