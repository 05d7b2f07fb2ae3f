"""The real Gmsh GUI, under Xvfb, draws homesh's output curved.

The CLI curves a coarse plate with a hole (8 edges on the hole) to order 4 and
writes its quality views; scripts/examples/gui_shot.py opens it in `gmsh` under
xvfb-run and prints the Q4 view, once as a user sees it (the .msh.opt sidecar
sets AdaptVisualizationGrid = 1) and once with AdaptVisualizationGrid = 0, the
view drawn on the straight triangles through the corner nodes. Pictures are
kept in pytest's temporary folder of the run (gui/, the last three runs kept).

Curved drawing is checked geometrically on the hole, the one background
region inside the plate: its edge is a circle (every edge pixel at the same
distance from the hole's centre, to pixel size) whose radius is a quarter of
the plate's side, as in geo/plate_hole.geo. Straight drawing shows the
inscribed octagon instead: edge distances spread over R (1 - cos(pi / 8)),
7.6 % of R.
"""
import os
import shutil
import subprocess
import sys

import matplotlib.image
import numpy as np
import pytest

import homesh

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "scripts", "examples"))
import gui_shot  # noqa: E402

pytestmark = pytest.mark.skipif(shutil.which("xvfb-run") is None,
                                reason="xvfb-run not installed (Debian package xvfb)")

HOLE_SEGMENTS = 8  # plate_hole.geo at Mesh.MeshSizeFactor 4: LcHole = 0.4 on a circle of radius 0.5


def cli():
    """The homesh binary of the build whose python/ folder provides `import homesh`."""
    return os.path.join(os.path.dirname(homesh.__file__), "..", "homesh")


@pytest.fixture(scope="module")
def pictures(tmp_path_factory):
    out = tmp_path_factory.mktemp("gui")
    msh = str(out / "plate_p4.msh")
    log = subprocess.run([cli(), os.path.join(ROOT, "geo", "plate_hole.geo"), "-m", "mesh:factor=4",
                          "-m", "curve:p=4", "-m", "quality", msh],
                         check=True, capture_output=True, text=True).stdout
    assert "validity: 0 invalid of" in log
    shots = {}
    for name, adapt in (("curved", None), ("straight", 0)):
        png = gui_shot.render(msh, str(out / f"plate_p4_{name}.png"), view="homesh: Q4 Equal volume, at nodes",
                              size=(700, 700), adapt=adapt, scale_bar=False)
        shots[name] = (matplotlib.image.imread(png)[:, :, :3] * 255).round().astype(np.uint8)
    return shots


def region(mask, seed):
    """The 4-connected component of `mask` holding pixel `seed`, by repeated dilation."""
    grown = np.zeros_like(mask)
    grown[seed] = True
    while True:
        wider = grown.copy()
        wider[1:] |= grown[:-1]
        wider[:-1] |= grown[1:]
        wider[:, 1:] |= grown[:, :-1]
        wider[:, :-1] |= grown[:, 1:]
        wider &= mask
        if (wider == grown).all():
            return grown
        grown = wider


def hole_edge(image):
    """Plate side (pixels), and the distances of the hole's edge pixels from its centroid.

    The hole is the background region at the plate's centre (the picture may hold
    a few background-coloured specks elsewhere, cracks of the adaptive grid).
    """
    background = np.all(image == 255, axis=2)
    rows, cols = np.nonzero(~background)
    top, bottom, left, right = rows.min(), rows.max(), cols.min(), cols.max()
    hole = region(background, ((top + bottom) // 2, (left + right) // 2))
    assert not hole[top].any() and not hole[:, left].any(), "the hole reaches the plate's edge"
    inner = hole[1:-1, 1:-1] & hole[:-2, 1:-1] & hole[2:, 1:-1] & hole[1:-1, :-2] & hole[1:-1, 2:]
    edge = hole.copy()
    edge[1:-1, 1:-1] &= ~inner
    y, x = np.nonzero(hole)
    ey, ex = np.nonzero(edge)
    side = (right - left + bottom - top + 2) / 2
    return side, np.hypot(ey - y.mean(), ex - x.mean())


@pytest.mark.parametrize("name", ["curved", "straight"])
def test_picture_shows_the_quality_view(pictures, name):
    image = pictures[name]
    colours = np.unique(image.reshape(-1, 3), axis=0)
    assert len(colours) > 50, f"{len(colours)} distinct colours"
    drawn = np.count_nonzero(~np.all(image == 255, axis=2))
    side, _ = hole_edge(image)
    # Gmsh fits the plate in the window: the drawn pixels are the plate less the hole,
    # side^2 (1 - pi/16), within the polygon's missing segments (2.5 % of the hole).
    assert drawn > 0.3 * image.shape[0] * image.shape[1]
    assert abs(drawn / (side**2 * (1 - np.pi / 16)) - 1) < 0.03, f"{drawn} pixels drawn"


def test_sidecar_makes_gmsh_draw_the_hole_round(pictures):
    side, r = hole_edge(pictures["curved"])
    assert r.max() - r.min() < 3, f"edge radius {r.min():.1f} to {r.max():.1f} px"
    assert abs(r.mean() - side / 4) < 0.02 * side / 4, f"radius {r.mean():.1f}, side {side:.1f}"


def test_without_adaptive_grid_gmsh_draws_the_inscribed_polygon(pictures):
    side, r = hole_edge(pictures["straight"])
    sagitta = side / 4 * (1 - np.cos(np.pi / HOLE_SEGMENTS))
    spread = r.max() - r.min()
    assert spread > 0.7 * sagitta, f"spread {spread:.1f} px, sagitta {sagitta:.1f}"
    assert spread < sagitta + 3
