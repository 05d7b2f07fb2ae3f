"""homesh in a user's Gmsh script: its messages reach Python (logging,
redirected stdout) and follow General.Verbosity; writing keeps the user's Gmsh
options and honours their MSH version and encoding; only .msh and .vtu are
written, and never an invalid mesh unless asked."""
import contextlib
import io
import logging
import os

import gmsh
import pytest

import homesh

GEO = os.path.join(os.path.dirname(__file__), "..", "..", "geo")


@pytest.fixture
def plate():
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    homesh.set_quiet(False)
    gmsh.open(os.path.join(GEO, "plate_hole.geo"))
    gmsh.model.mesh.generate(2)
    yield
    homesh.set_quiet(True)
    gmsh.finalize()


@pytest.fixture
def no_logging(monkeypatch):
    """Python's logging as in a plain script: no handler above "homesh" (pytest adds one)."""
    monkeypatch.setattr(logging.getLogger("homesh"), "propagate", False)


def test_messages_reach_redirected_stdout(plate, no_logging):
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        homesh.info()
    assert "triangles" in out.getvalue()


def test_messages_reach_python_logging(plate, caplog):
    caplog.set_level(logging.INFO, logger="homesh")
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        homesh.info()
    assert any("triangles" in r.getMessage() and r.name == "homesh" for r in caplog.records)
    assert out.getvalue() == ""  # once, through logging


def test_verbosity_below_4_silences_reports(plate, no_logging):
    gmsh.option.setNumber("General.Verbosity", 3)
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        homesh.quality(measures="Q4")
    assert out.getvalue() == ""
    gmsh.option.setNumber("General.Verbosity", 5)
    with contextlib.redirect_stdout(out):
        homesh.quality(measures="Q4")
    assert out.getvalue() != ""


@pytest.mark.parametrize("version,binary", [(2.2, 1), (2.2, 0), (4.1, 1)])
def test_write_honours_and_restores_the_users_options(plate, tmp_path, version, binary):
    homesh.curve(p=2)
    homesh.quality(measures="Q4")  # views to write
    gmsh.option.setNumber("Mesh.MshFileVersion", version)
    gmsh.option.setNumber("Mesh.Binary", binary)
    gmsh.option.setNumber("Mesh.SaveAll", 0)
    gmsh.option.setNumber("PostProcessing.SaveMesh", 1)
    out = tmp_path / "plate.msh"
    homesh.write(str(out))
    assert gmsh.option.getNumber("Mesh.MshFileVersion") == version
    assert gmsh.option.getNumber("Mesh.Binary") == binary
    assert gmsh.option.getNumber("Mesh.SaveAll") == 0
    assert gmsh.option.getNumber("PostProcessing.SaveMesh") == 1
    head = out.read_bytes()[:40].decode("ascii", "replace")
    assert head.startswith(f"$MeshFormat\n{version:g} {binary} 8\n")
    assert out.read_bytes().endswith(b"$EndHomeshProvenance\n")
    # Gmsh reads it back, views included.
    gmsh.clear()
    gmsh.open(str(out))
    assert gmsh.model.mesh.getElementTypes(2) == [gmsh.model.mesh.getElementType("Triangle", 2)]
    assert len(gmsh.view.getTags()) >= 1


def test_other_extensions_are_refused_with_the_clis_message(plate, tmp_path):
    with pytest.raises(homesh.Error,
                       match=r"x\.vtk: unknown output format '\.vtk' \(homesh writes \.msh or \.vtu\)"):
        homesh.write(str(tmp_path / "x.vtk"))
    assert list(tmp_path.iterdir()) == []


def test_an_invalid_mesh_is_written_only_when_asked(plate, tmp_path, fold_a_p2_triangle):
    homesh.order(p=2)
    fold_a_p2_triangle()
    out = tmp_path / "bad.msh"
    with pytest.raises(homesh.Error, match="not certified valid"):
        homesh.write(str(out))
    assert not out.exists()
    homesh.write(str(out), keep_invalid=True)
    assert out.exists()
