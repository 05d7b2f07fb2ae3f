"""The worked scripts of scripts/examples/ run and print a certified-valid mesh."""
import csv
import os
import re
import subprocess
import sys

import homesh

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
EXAMPLES = os.path.join(ROOT, "scripts", "examples")


def run(script, *args):
    """Runs an example with this interpreter and PYTHONPATH; returns its standard output."""
    result = subprocess.run([sys.executable, os.path.join(EXAMPLES, script), *args],
                            capture_output=True, text=True, timeout=300)
    assert result.returncode == 0, result.stdout + result.stderr
    return result.stdout


def validity(log):
    """(invalid, triangles) from the quality stage's validity line."""
    m = re.search(r"validity: (\d+) invalid of (\d+) triangles", log)
    assert m, log
    return int(m.group(1)), int(m.group(2))


def views(msh):
    return re.findall(r'^\$Element(?:Node)?Data\n\d+\n"([^"]+)"', msh.read_text(), re.M)


def test_plate_hole_curves_the_hole_onto_the_circle(tmp_path):
    msh = tmp_path / "plate.msh"
    log = run("plate_hole.py", "--msh", str(msh))
    # Same sizes as geo/plate_hole.geo: 344 triangles, all certified valid at order 4.
    assert validity(log) == (0, 344)
    m = re.search(r"straight-sided error (\S+), curved error (\S+)", log)
    straight, curved = float(m.group(1)), float(m.group(2))
    # 32 chords on a circle of radius 0.5 miss 0.5^2 (pi - 16 sin(pi/16)) = 5.04e-3 of area.
    assert abs(straight - 5.04e-3) < 0.01e-3
    assert abs(curved) < 1e-8
    assert {"homesh: certified minJ/maxJ", "homesh: Q4 Equal volume, at nodes",
            "homesh: Q17 Idealised Jacobian, at nodes"} <= set(views(msh))
    assert (tmp_path / "plate.msh.opt").exists()


def test_naca7526_boundary_layers_curved_to_order_4(tmp_path):
    msh = tmp_path / "naca.msh"
    log = run("naca7526.py", "--msh", str(msh))
    invalid, triangles = validity(log)
    assert invalid == 0
    assert "physical curve 1 \"aerofoil\"" in log and "order 4:" in log
    if "layers" in [s["name"] for s in homesh.stages()]:
        # The main job's quality (thesis: kept): the solve within reach, 0.9937 measured.
        worst = float(re.search(r"validity: .*worst minJ/maxJ (\d\.\d+)", log).group(1))
        assert worst > 0.99, log
        assert "15 layers on aerofoil (1 loop(s), 121 wall edges, 1 fans)" in log
        # 15 layers of 2 triangles on each of the 121 wall edges and 2 x 15 between each
        # of the fan's 5 normals; 2 triangles fewer for each node removed from the room.
        cleared = int(re.search(r"(\d+) free node\(s\) in the room removed", log).group(1))
        assert cleared > 0
        assert triangles == 2747 - 2 * cleared + 2 * 15 * 121 + 2 * 15 * 4
    else:
        assert "no 'layers' stage" in log and triangles == 2747
    assert "homesh: Q4 Equal volume, at nodes" in views(msh)


def test_plate_rotation_matches_the_cli_and_carries_the_thesis_values(tmp_path):
    log = run("plate_rotation.py", "--out", str(tmp_path))
    assert "geo/plate_hole_fig413.geo: 71 quadratic triangles" in log
    with open(tmp_path / "plate_rotation.csv") as f:
        rows = {(r["formulation"], float(r["nu"])): r for r in csv.DictReader(f)}
    assert len(rows) == 16 and (tmp_path / "plate_rotation.png").stat().st_size > 10000
    # Case 1 at nu = 0.4 is the CLI's rotate stage on the same pipeline, to the degree.
    binary = os.path.join(os.path.dirname(homesh.__file__), "..", "homesh")
    cli = subprocess.run([binary, os.path.join(ROOT, "geo", "plate_hole_fig413.geo"), "-m", "mesh",
                          "-m", "curve:p=2:rings=0", "-m", "rotate:nu=0.4:formulation=plain"],
                         capture_output=True, text=True, check=True).stdout
    theta = int(re.search(r"rotate: theta_max = (\d+) deg", cli).group(1))
    assert int(rows[("plain", 0.4)]["theta_max"]) == theta == 91
    # The thesis' Table 4.1 and 4.2 values beside ours (thesis 90 and 110).
    assert int(rows[("plain", 0.4)]["thesis_theta_max"]) == 90
    assert int(rows[("area", 0.45)]["thesis_theta_max"]) == 110
    # As in the thesis: theta_max grows with nu for case 1, and E = 1/Ae (case 2) and the
    # added heat (case 4) turn the hole further than case 1 at every nu.
    plain = [int(rows[("plain", nu)]["theta_max"]) for nu in (0.05, 0.25, 0.4, 0.45)]
    assert plain == sorted(plain) and plain[0] >= 80
    for nu in (0.05, 0.25, 0.4, 0.45):
        assert int(rows[("area", nu)]["theta_max"]) > int(rows[("plain", nu)]["theta_max"])
        assert int(rows[("heat_q17", nu)]["theta_max"]) > int(rows[("plain", nu)]["theta_max"])
        assert 0 < float(rows[("plain", nu)]["worst_ratio"]) < 1


def test_gen_reference_lists_every_stage_and_measure():
    script = os.path.join(ROOT, "scripts", "gen_reference.py")
    out = subprocess.run([sys.executable, script], capture_output=True, text=True,
                         check=True).stdout
    for s in homesh.stages():
        assert f"| `{s['name']}` | {s['summary']} |" in out
        for option in s["options"]:
            assert f"| `{option}` |" in out
    binary = os.path.join(os.path.dirname(homesh.__file__), "..", "homesh")
    measures = subprocess.run([binary, "--measures"], capture_output=True, text=True,
                              check=True).stdout
    ids = re.findall(r"^\s*(Q\d+) ", measures, re.M)
    rows = re.findall(r"^\| (Q\d+) \|", out, re.M)
    assert rows == ids and "Q17" in rows


def test_voronoi_mesh_follows_the_users_metric_view(tmp_path):
    msh = tmp_path / "voronoi.msh"
    log = run("voronoi_metric.py", "--msh", str(msh))
    invalid, triangles = validity(log)
    assert invalid == 0 and triangles > 300
    # Every triangle comes from the dual: the seeds' Delaunay triangulation in the view's metric.
    m = re.search(r"(\d+) triangles, (\d+) from the dual, 0 from the fill", log)
    assert m and m.group(1) == m.group(2)
    # Edges are of unit length in the user's metric, at the anisotropic line and away from
    # it (measured 1.032 and 0.987), and the short ones cross the line (measured 0.853).
    m = re.search(r"median metric edge length: (\S+) at the line, (\S+) away", log)
    assert 0.85 < float(m.group(1)) < 1.2 and 0.85 < float(m.group(2)) < 1.2
    m = re.search(r"mean \|cos\| to the line's normal (\S+)", log)
    assert float(m.group(1)) > 0.8
    assert msh.exists() and (tmp_path / "voronoi.msh.opt").exists()
