"""homesh's quality views in the real Gmsh GUI (under Xvfb), as a user sees them.

The CLI curves the coarse plate with a hole ([-1, 1]^2, 8 edges on the hole) to
order 4: the elements along the hole are poorer than the straight ones. Gmsh
opens the file with nothing but the window set (gui_shot.render_as_opened):
- exactly one colour scale shows, the certified minJ/maxJ's ten bands;
- the fill follows the curved hole (its edge a circle to pixel size: no
  sliver between the curved boundary and a straight fill) and has no cracks
  (no background pixel inside the plate but the hole);
- the worst element (by the Gmsh tag and centroid the report gives) and the
  best one are drawn in different colours;
the same for two homesh files opened together (each styled by its own
sidecar), and for the Gmsh GUI a Python script opens after homesh's stages in
the same process, which draws what opening the written file draws.
"""
import os
import re
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
from test_gui_render import hole_edge, region  # noqa: E402

pytestmark = pytest.mark.skipif(shutil.which("xvfb-run") is None,
                                reason="xvfb-run not installed (Debian package xvfb)")

GEO = os.path.join(ROOT, "geo", "plate_hole.geo")
# The optimiser off: the test needs a poor element (0.79) beside good ones.
STAGES = ["-m", "mesh:factor=4", "-m", "curve:p=4:optimise=off"]
SIZE = (500, 500)


def cli(*args):
    exe = os.path.join(os.path.dirname(homesh.__file__), "..", "homesh")
    return subprocess.run([exe, *args], check=True, capture_output=True, text=True).stdout


def pixels(png):
    return (matplotlib.image.imread(png)[:, :, :3] * 255).round().astype(np.int32)


@pytest.fixture(scope="module")
def out(tmp_path_factory):
    return tmp_path_factory.mktemp("gui_views")


@pytest.fixture(scope="module")
def plate(out):
    """The CLI's output and its log."""
    msh = str(out / "plate.msh")
    log = cli(GEO, *STAGES, "-m", "quality:measures=Q4:worst=1", msh)
    return msh, log


def legends(image):
    """Colour scales drawn: connected stretches of rows where 8 or more colours follow
    each other in runs of 6+ pixels, with no background between them."""
    mask = np.zeros(image.shape[:2], dtype=bool)
    for i, row in enumerate(image):
        change = np.any(row[1:] != row[:-1], axis=1)
        starts = np.concatenate(([0], np.nonzero(change)[0] + 1))
        ends = np.concatenate((starts[1:], [len(row)]))
        segment = []  # runs since the last background run
        for a, b in list(zip(starts, ends)) + [(len(row), len(row))]:
            if a == len(row) or (row[a] == 255).all():
                colours = {tuple(row[c]) for c, d in segment if d - c >= 6}
                if len(colours) >= 8:
                    mask[i, segment[0][0]:segment[-1][1]] = True
                segment = []
            else:
                segment.append((a, b))
    count = 0
    while mask.any():
        seed = tuple(np.argwhere(mask)[0])
        mask &= ~region(mask, seed)
        count += 1
    return count


def plate_box(image):
    """Top, left and side (pixels) of the plate: its top row is the first drawn row."""
    drawn = ~np.all(image == 255, axis=2)
    top = np.nonzero(drawn.any(axis=1))[0][0]
    cols = np.nonzero(drawn[top + 2])[0]
    return top, cols[0], cols[-1] - cols[0] + 1


def check_curved_and_whole(image):
    side, r = hole_edge(image)
    assert r.max() - r.min() < 3, f"hole edge radius {r.min():.1f} to {r.max():.1f} px"
    top, left, s = plate_box(image)
    inside = image[top + 2:top + s - 2, left + 2:left + s - 2]
    background = np.all(inside == 255, axis=2)
    hole = region(background, (s // 2 - 2, s // 2 - 2))
    cracks = np.count_nonzero(background & ~hole)
    assert cracks == 0, f"{cracks} background pixels inside the plate"


def colour_at(image, x, y):
    top, left, side = plate_box(image)  # the plate is [-1, 1]^2
    i, j = int(round(top + (1 - y) / 2 * side)), int(round(left + (x + 1) / 2 * side))
    return image[i - 1:i + 2, j - 1:j + 2].reshape(-1, 3).mean(axis=0)


def test_file_opens_with_one_scale_curved_and_whole(plate, out):
    image = pixels(gui_shot.render_as_opened([plate[0]], str(out / "opened.png"), SIZE))
    assert legends(image) == 1
    check_curved_and_whole(image)


def test_poor_and_good_elements_differ_in_colour(plate, out):
    msh, log = plate
    worst = re.search(r"worst minJ/maxJ ([0-9.]+) at triangle \d+ \(([-0-9.e]+), ([-0-9.e]+)\)",
                      log)
    assert float(worst.group(1)) < 0.8, log
    image = pixels(str(out / "opened.png"))
    poor = colour_at(image, float(worst.group(2)), float(worst.group(3)))
    good = colour_at(image, -0.9, -0.9)  # a straight element off the hole: minJ/maxJ 1
    assert np.abs(poor - good).sum() > 150, f"poor {poor}, good {good}"


def test_two_files_opened_together_each_styled(plate, out):
    other = str(out / "other.msh")
    cli(GEO, "-m", "mesh:factor=4", "-m", "curve:p=3", "-m", "quality:measures=Q17", other)
    image = pixels(gui_shot.render_as_opened([plate[0], other], str(out / "merged.png"), SIZE))
    assert legends(image) == 1
    check_curved_and_whole(image)


def test_python_script_draws_what_the_file_draws(out):
    script = out / "in_process.py"
    msh, png = out / "in_process.msh", out / "in_process.png"
    script.write_text(f"""
import gmsh, homesh
gmsh.initialize()
gmsh.option.setNumber("General.Terminal", 0)
homesh.set_quiet(True)
gmsh.open({GEO!r})
gmsh.option.setNumber("Mesh.MeshSizeFactor", 4)
gmsh.model.mesh.generate(2)
homesh.curve(p=4, optimise=False)
homesh.quality(measures="Q4")
homesh.write({str(msh)!r})
gmsh.fltk.initialize()
gmsh.option.setNumber("Geometry.Curves", 0)  # the CAD, which the written file does not hold
gmsh.option.setNumber("Geometry.Points", 0)
for line in {gui_shot.window(SIZE)!r}:
    name, value = line.rstrip(";").split(" = ")
    if value.startswith("{{"):
        gmsh.option.setColor(name, *map(int, value.strip("{{}}").split(",")))
    else:
        gmsh.option.setNumber(name, float(value))
gmsh.graphics.draw()
gmsh.write({str(png)!r})
gmsh.finalize()
""")
    env = dict(os.environ, PYTHONPATH=os.path.dirname(homesh.__file__))
    screen = f"-screen 0 {SIZE[0] + 64}x{SIZE[1] + 64}x24"
    subprocess.run(["xvfb-run", "-a", "-s", screen, sys.executable, str(script)], check=True,
                   env=env, timeout=120, capture_output=True)
    in_process = pixels(str(png))
    opened = pixels(gui_shot.render_as_opened([str(msh)], str(out / "reopened.png"), SIZE))
    assert in_process.shape == opened.shape
    differ = np.count_nonzero(np.any(in_process != opened, axis=2))
    assert differ < 0.005 * in_process[:, :, 0].size, f"{differ} pixels differ"
