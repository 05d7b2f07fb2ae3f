"""The curving corpus (scripts/bench/corpus.py, issue 16) builds what it says: triangles only,
the wall group, first cells of the requested height. Three cases, one per kind of mesher that
makes layers or none, so the corpus cannot rot unnoticed."""
import os
import sys

import gmsh
import pytest

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "scripts", "bench"))
import corpus  # noqa: E402


@pytest.fixture
def session():
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    yield
    gmsh.finalize()


def wall_curves():
    for dim, tag in gmsh.model.getPhysicalGroups(1):
        if gmsh.model.getPhysicalName(dim, tag) == corpus.WALL:
            return list(gmsh.model.getEntitiesForPhysicalGroup(dim, tag))
    return []


def test_the_corpus_has_forty_named_cases_of_every_kind():
    names = [c.name for c in corpus.CASES]
    assert len(names) >= 40 and len(set(names)) == len(names)
    assert {c.mesher for c in corpus.CASES} == {"gmsh_bl", "layers", "none", "voronoi"}
    assert {c.shape for c in corpus.CASES} >= {"aerofoil", "multi", "ellipses", "star", "lshape"}
    assert min(c.first for c in corpus.CASES if c.first) <= 1e-5


@pytest.mark.parametrize("name", ["naca0012_bl_1e-3_coarse", "circles6_layers_1e-3",
                                  "circle_nolayer_coarse"])
def test_a_case_is_triangles_with_its_wall_and_first_cell(session, name):
    c = corpus.case(name)
    rec = corpus.build(c)
    types = gmsh.model.mesh.getElementTypes(2)
    assert [gmsh.model.mesh.getElementProperties(t)[0] for t in types] == ["Triangle 3"]
    assert rec["other_2d"] == 0 and rec["triangles"] > 500
    assert wall_curves() and rec["wall_edges"] > 10
    if c.first:
        # Every wall node's shortest edge off the wall is the first layer's height.
        assert abs(rec["first_min"] - c.first) <= 0.2 * c.first
        assert abs(rec["first_median"] - c.first) <= 0.2 * c.first
    else:
        assert 0.3 * c.h_wall < rec["first_min"] <= rec["first_median"] < 1.5 * c.h_wall
    assert 0 <= rec["turn_deg"] <= rec["turn_all_deg"] < 180
    assert rec["target"] == (0.9 if rec["turn_deg"] < 30 else 0.8)


def test_the_quad_family_is_listed_apart():
    # The triangle corpus's default list stays as it was; the quad family only on request.
    assert corpus.select() == corpus.CASES and corpus.select("naca0012") == [
        c for c in corpus.CASES if "naca0012" in c.name]
    quads = corpus.select(None, "quads")
    assert quads == corpus.QUAD_CASES and len(quads) >= 10
    assert not {c.name for c in quads} & {c.name for c in corpus.CASES}
    assert {c.mesher for c in quads} == set(corpus.QUAD_MESHERS)
    assert all(c.quads for c in quads) and not any(c.quads for c in corpus.CASES)


@pytest.mark.parametrize("name, mixed", [("naca0012_blq_1e-3_coarse", True),
                                         ("circle_ogrid_1e-3", False)])
def test_a_quad_case_has_its_quads_wall_and_first_cell(session, name, mixed):
    c = corpus.case(name)
    rec = corpus.build(c)
    types = [gmsh.model.mesh.getElementProperties(t)[0]
             for t in gmsh.model.mesh.getElementTypes(2)]
    assert types == (["Triangle 3", "Quadrilateral 4"] if mixed else ["Quadrilateral 4"])
    assert rec["other_2d"] == 0 and rec["quads"] > 500
    assert (rec["triangles"] > 500) == mixed
    assert wall_curves() and rec["wall_edges"] > 10
    # Counterclockwise and valid for homesh as for Gmsh (the same worst minJ/maxJ).
    import homesh
    v = homesh.validity()
    assert v["invalid"] == 0 and 0.4 < v["worst"] < 0.95
    # The first cells, quads on the wall, have the requested height (to the transfinite
    # grid's rounding of its number of cells).
    assert abs(rec["first_min"] - c.first) <= 0.1 * c.first
    assert abs(rec["first_median"] - c.first) <= 0.1 * c.first
