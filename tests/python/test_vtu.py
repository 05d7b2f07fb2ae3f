"""homesh's .vtu read back by VTK 9.1 (Debian python3-vtk9), as ParaView reads it.

For p = 1..6 a coarse plate with a hole is meshed, curved to order p (p >= 2)
and its quality computed by `import homesh`, then written by homesh.write to
a .msh and to a .vtu. VTK reads the .vtu; Gmsh reads the .msh back from disk.
Each cell of the .vtu names its Gmsh element (cell data gmsh:element), and:
- its VTK type is the Lagrange triangle (69) of order p or a poly-line (4)
  (the linear triangle 5 and line 3 at p = 1), with that element's node count;
- VTK node k of a triangle is the element's node at the same reference point
  (VTK's own vtkLagrangeTriangle parametric coordinates against Gmsh's
  reference nodes), a line's run along it, at the .msh's coordinates;
- VTK's interpolation inside a triangle equals Gmsh's at random reference points;
- the fields equal the .msh's views: element fields as cell data, the
  per-node ones per element as "F at nodes" (VTK order) and their minimum over
  the elements at each point as point data, NaN on the lines; gmsh:geometrical
  and gmsh:physical are the element's entity and physical group.
"""
import os
import subprocess

import gmsh
import numpy as np
import pytest
import vtk
from vtk.util.numpy_support import vtk_to_numpy

import homesh

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
PLATE = os.path.join(ROOT, "geo", "plate_hole.geo")
# Lines are poly-lines: VTK 9.1 and ParaView 5.11 crash on Lagrange curves (io/vtk_node_order.h).
LAGRANGE = {2: vtk.VTK_LAGRANGE_TRIANGLE, 1: vtk.VTK_POLY_LINE}
LINEAR = {2: vtk.VTK_TRIANGLE, 1: vtk.VTK_LINE}
ASCII = 2e-15  # relative: Gmsh writes an ASCII .msh with 16 significant digits, the .vtu is exact


@pytest.fixture
def model():
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    homesh.set_quiet(True)
    gmsh.open(PLATE)
    yield
    gmsh.finalize()


def read_vtu(path):
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(str(path))
    reader.Update()
    grid = reader.GetOutput()
    assert grid.GetNumberOfCells() > 0, f"VTK read no cells from {path}"
    return grid


def cell_array(grid, name):
    array = grid.GetCellData().GetArray(name)
    assert array is not None, f"no cell data '{name}'"
    return vtk_to_numpy(array)


def msh_contents(path):
    """The .msh as Gmsh reads it from disk: node coordinates, elements by tag (type, nodes,
    entity), views by name (type, data by tag)."""
    gmsh.clear()
    gmsh.open(str(path))
    tags, coords, _ = gmsh.model.mesh.getNodes()
    xyz = dict(zip(tags, coords.reshape(-1, 3)))
    elements = {}
    for dim, entity in gmsh.model.getEntities():
        if dim == 0:
            continue
        for etype, etags, enodes in zip(*gmsh.model.mesh.getElements(dim, entity)):
            nodes = np.asarray(enodes).reshape(len(etags), -1)
            for tag, row in zip(etags, nodes):
                elements[int(tag)] = (etype, row, entity)
    views = {}
    for v in gmsh.view.getTags():
        name = gmsh.option.getString(f"View[{gmsh.view.getIndex(v)}].Name")
        kind, vtags, data, _, _ = gmsh.view.getModelData(v, 0)
        views[name] = (kind, dict(zip((int(t) for t in vtags), data)))
    return xyz, elements, views


def gmsh_to_vtk(etype, cell):
    """Gmsh node of each VTK node of `cell`, matched by reference position: VTK's parametric
    coordinates of a triangle against Gmsh's reference nodes; a line's nodes in order along it."""
    _, dim, _, n, local, _ = gmsh.model.mesh.getElementProperties(etype)
    gmsh_ref = np.asarray(local).reshape(n, dim)
    if dim == 1:
        return np.argsort(gmsh_ref[:, 0])
    vtk_pc = np.asarray(cell.GetParametricCoords()[:3 * n]).reshape(n, 3)[:, :dim]
    distance = np.linalg.norm(vtk_pc[:, None, :] - gmsh_ref[None, :, :], axis=2)
    match = distance.argmin(axis=1)
    assert (distance.min(axis=1) < 1e-14).all()
    assert sorted(match) == list(range(n)), "VTK's and Gmsh's nodes are not one to one"
    return match


# The field names: those of the .msh views (the measure registry's).
VALIDITY = "homesh: certified minJ/maxJ"
Q4_MIN = "homesh: Q4 Equal volume, element minimum"
Q4_NODES = "homesh: Q4 Equal volume, at nodes"
POOR = "homesh: elements of certified minJ/maxJ < 0.5"


def written(tmp_path, p, measures="Q4"):
    homesh.mesh(factor=4)
    if p > 1:
        homesh.curve(p=p)
    if measures:
        homesh.quality(measures=measures)
    msh, vtu = tmp_path / f"plate_p{p}.msh", tmp_path / f"plate_p{p}.vtu"
    homesh.write(str(msh))
    homesh.write(str(vtu))
    return msh, vtu


@pytest.mark.parametrize("p", range(1, 7))
def test_vtk_reads_the_cells_nodes_and_fields_of_the_msh(model, tmp_path, p):
    msh, vtu = written(tmp_path, p)
    grid = read_vtu(vtu)
    xyz, elements, views = msh_contents(msh)
    assert grid.GetNumberOfCells() == len(elements)  # every triangle and line
    points = vtk_to_numpy(grid.GetPoints().GetData())
    tags = cell_array(grid, "gmsh:element")
    assert sorted(tags) == sorted(elements)
    types = vtk_to_numpy(grid.GetCellTypesArray())
    geometrical, physical = cell_array(grid, "gmsh:geometrical"), cell_array(grid, "gmsh:physical")
    node_values = cell_array(grid, Q4_NODES)
    assert node_values.shape[1] == (p + 1) * (p + 2) // 2
    point_of = {}  # .msh node tag -> .vtu point
    smallest = {}  # .msh node tag -> smallest Q4 of the triangles there
    assert set(views) - {POOR} == {VALIDITY, Q4_MIN, Q4_NODES}
    rng = np.random.default_rng(p)
    for c in range(grid.GetNumberOfCells()):
        cell = grid.GetCell(c)
        etype, nodes, entity = elements[int(tags[c])]
        _, dim, order, n, _, _ = gmsh.model.mesh.getElementProperties(etype)
        assert order == p and cell.GetNumberOfPoints() == n
        assert types[c] == (LINEAR if p == 1 else LAGRANGE)[dim]
        if p > 1 and dim == 2:
            assert cell.GetOrder() == p
        match = gmsh_to_vtk(etype, cell)
        ids = [cell.GetPointId(k) for k in range(n)]
        for k in range(n):
            assert point_of.setdefault(nodes[match[k]], ids[k]) == ids[k]
            assert np.allclose(points[ids[k]], xyz[nodes[match[k]]], rtol=0, atol=ASCII)
        # VTK's interpolation in a triangle = Gmsh's, at random reference points.
        if dim == 2:
            uv = rng.dirichlet(np.ones(3), size=4)[:, :2]
            local = np.hstack([uv, np.zeros((4, 1))])
            _, basis, _ = gmsh.model.mesh.getBasisFunctions(etype, local.ravel(), "Lagrange")
            gmsh_x = np.asarray(basis).reshape(4, n) @ np.array([xyz[t] for t in nodes])
            for q in range(4):
                x, weights = [0.0, 0.0, 0.0], [0.0] * n
                cell.EvaluateLocation(vtk.reference(0), [uv[q, 0], uv[q, 1], 0.0], x, weights)
                assert np.allclose(x, gmsh_x[q], rtol=0, atol=1e-12)
        # The element's entity and physical group.
        assert geometrical[c] == entity
        groups = gmsh.model.getPhysicalGroupsForEntity(dim, entity)
        assert physical[c] == (min(groups) if len(groups) else 0)
        # Fields: the views' values, NaN on the lines.
        for name, (kind, data) in views.items():
            if name == POOR:  # a view of the few poor triangles: NaN on the others
                continue
            values = cell_array(grid, name)[c]
            if dim == 1:
                assert np.isnan(values).all()
            elif kind == "ElementData":
                assert values == pytest.approx(data[int(tags[c])][0], rel=ASCII, abs=ASCII)
            else:
                expected = np.asarray(data[int(tags[c])])[match]
                assert np.allclose(values, expected, rtol=ASCII, atol=ASCII)
                for k in range(n):
                    t = nodes[k]
                    smallest[t] = min(smallest.get(t, np.inf), data[int(tags[c])][k])
    assert sorted(point_of.values()) == list(range(grid.GetNumberOfPoints()))
    q4 = vtk_to_numpy(grid.GetPointData().GetArray(Q4_NODES + ", smallest at the point"))
    assert all(abs(q4[point_of[t]] - v) <= ASCII * (1 + abs(v)) for t, v in smallest.items())
    # The poor triangles' view: their certified minJ/maxJ at every node, NaN elsewhere.
    # (A view of no triangle is in neither file.)
    ratio = cell_array(grid, VALIDITY)
    assert (POOR in views) == (grid.GetCellData().GetArray(POOR) is not None) == (ratio < 0.5).any()
    if POOR in views:
        poor = cell_array(grid, POOR)
        listed = ~np.isnan(poor).all(axis=1)
        assert np.array_equal(listed, ratio < 0.5)
        assert np.allclose(poor[listed], ratio[listed][:, None])


def test_the_certified_validity_is_always_a_cell_field(model, tmp_path):
    _, vtu = written(tmp_path, 3, measures=None)
    grid = read_vtu(vtu)
    ratio = cell_array(grid, VALIDITY)
    triangles = vtk_to_numpy(grid.GetCellTypesArray()) == vtk.VTK_LAGRANGE_TRIANGLE
    assert triangles.sum() == homesh.validity()["triangles"]
    assert ratio[triangles].min() == pytest.approx(homesh.validity()["worst"], rel=1e-12)
    assert 0 < ratio[triangles].min() <= ratio[triangles].max() <= 1
    assert np.isnan(ratio[~triangles]).all()


def test_the_cli_writes_the_same_vtu_as_the_api(model, tmp_path):
    msh, vtu = written(tmp_path, 4)
    cli = os.path.join(os.path.dirname(homesh.__file__), "..", "homesh")
    out = tmp_path / "cli.vtu"
    subprocess.run([cli, "-q", str(msh), "-m", "quality:measures=Q4", str(out)], check=True)
    api, by_cli = read_vtu(vtu), read_vtu(out)
    for name in ("gmsh:element", "gmsh:geometrical", "gmsh:physical"):
        assert np.array_equal(cell_array(api, name), cell_array(by_cli, name))
    # The CLI read the nodes back from the ASCII .msh, to 16 digits.
    for name in (VALIDITY, Q4_MIN, Q4_NODES):
        assert np.allclose(cell_array(api, name), cell_array(by_cli, name), rtol=1e-12,
                           atol=1e-12, equal_nan=True)
    assert np.allclose(vtk_to_numpy(api.GetPoints().GetData()),
                       vtk_to_numpy(by_cli.GetPoints().GetData()), rtol=0, atol=ASCII)


def test_an_invalid_mesh_is_written_to_vtu_only_when_asked(model, tmp_path, fold_a_p2_triangle):
    homesh.mesh()
    homesh.order(p=2)
    fold_a_p2_triangle()
    out = tmp_path / "bad.vtu"
    with pytest.raises(homesh.Error, match=r"bad\.vtu: not written: \d+ triangles are not certified"):
        homesh.write(str(out))
    assert list(tmp_path.iterdir()) == []
    homesh.write(str(out), keep_invalid=True)
    assert np.nanmin(cell_array(read_vtu(out), VALIDITY)) < 0


def test_a_users_node_view_is_point_data_and_a_list_view_is_left_out(model, tmp_path, capfd):
    homesh.mesh(factor=4)
    homesh.curve(p=3)
    tags, coords, _ = gmsh.model.mesh.getNodes()
    view = gmsh.view.add("x + 2y")
    xyz = coords.reshape(-1, 3)
    gmsh.view.addModelData(view, 0, "", "NodeData", tags, [[x + 2 * y] for x, y, _ in xyz])
    gmsh.view.addListData(gmsh.view.add("a .pos view"), "SP", 1, [0.1, 0.2, 0.0, 5.0])
    gmsh.option.setNumber("General.Terminal", 1)
    out = tmp_path / "views.vtu"
    homesh.write(str(out))
    printed = capfd.readouterr()
    assert "Error" not in printed.out + printed.err  # Gmsh's, for the list view's missing model data
    grid = read_vtu(out)
    points = vtk_to_numpy(grid.GetPoints().GetData())
    values = vtk_to_numpy(grid.GetPointData().GetArray("x + 2y, smallest at the point"))
    assert np.allclose(values, points[:, 0] + 2 * points[:, 1], rtol=0, atol=1e-15)
    assert grid.GetCellData().GetArray("a .pos view") is None
    assert grid.GetPointData().GetArray("a .pos view") is None


@pytest.mark.parametrize("p", [1, 2, 3, 4])
def test_quadrilaterals_read_by_vtk_interpolate_as_gmsh(model, tmp_path, p):
    """A boundary layer of quadrilaterals in a triangle mesh (Gmsh's BoundaryLayer field,
    Quads = 1), order p: VTK reads each quadrilateral as a Lagrange quadrilateral (70; VTK_QUAD
    at p = 1) of (p+1)^2 nodes, and its map equals Gmsh's at reference points, as the
    triangles' does; the certified minJ/maxJ is cell data of every 2D cell (NaN on lines)."""
    gmsh.clear()
    gmsh.model.occ.addRectangle(0, 0, 0, 1, 1, 1)
    gmsh.model.occ.addDisk(0.5, 0.5, 0, 0.2, 0.2, 2)
    gmsh.model.occ.cut([(2, 1)], [(2, 2)])
    gmsh.model.occ.synchronize()
    field = gmsh.model.mesh.field.add("BoundaryLayer")
    gmsh.model.mesh.field.setNumbers(field, "CurvesList", [5])  # the hole
    for name, value in [("Size", 0.01), ("Ratio", 1.3), ("Thickness", 0.05), ("Quads", 1)]:
        gmsh.model.mesh.field.setNumber(field, name, value)
    gmsh.model.mesh.field.setAsBoundaryLayer(field)
    gmsh.option.setNumber("Mesh.MeshSizeMax", 0.2)
    gmsh.model.mesh.generate(2)
    if p > 1:
        gmsh.model.mesh.setOrder(p)
    homesh.quality(measures="Q4")
    path = tmp_path / "quads.vtu"
    homesh.write(str(path), keep_invalid=True)
    grid = read_vtu(path)
    tags = cell_array(grid, "gmsh:element")
    quad_type = gmsh.model.mesh.getElementType("Quadrangle", p)
    quads = set(gmsh.model.mesh.getElementsByType(quad_type)[0])
    assert len(quads) > 10
    seen = 0
    rng = np.random.default_rng(p)
    for c in range(grid.GetNumberOfCells()):
        cell = grid.GetCell(c)
        if cell.GetCellDimension() != 2:
            continue
        quad = int(tags[c]) in quads
        seen += quad
        if quad:
            assert cell.GetCellType() == (vtk.VTK_QUAD if p == 1 else
                                          vtk.VTK_LAGRANGE_QUADRILATERAL)
            assert cell.GetNumberOfPoints() == (p + 1) ** 2
        for u, v in rng.uniform(0, 1, (3, 2)):
            if not quad and u + v > 1:
                u, v = 1 - u, 1 - v
            x, weights = [0.0, 0.0, 0.0], [0.0] * cell.GetNumberOfPoints()
            cell.EvaluateLocation(vtk.mutable(0), [u, v, 0], x, weights)
            local = [2 * u - 1, 2 * v - 1, 0] if quad else [u, v, 0]
            _, _, expected = gmsh.model.mesh.getJacobian(int(tags[c]), local)
            assert np.allclose(x[:2], expected[:2], rtol=0, atol=1e-12)
    assert seen == len(quads)
    ratio = cell_array(grid, "homesh: certified minJ/maxJ")
    surface = [grid.GetCell(c).GetCellDimension() == 2 for c in range(grid.GetNumberOfCells())]
    assert not np.isnan(ratio[surface]).any() and np.isnan(ratio[np.logical_not(surface)]).all()


@pytest.mark.parametrize("p", [1, 2, 3, 4])
def test_curved_tetrahedra_read_by_vtk_interpolate_as_gmsh(model, tmp_path, p):
    """A unit ball cut out of a box, meshed in tetrahedra by Gmsh and curved by homesh at
    order p (issue 24): VTK reads each tetrahedron as a Lagrange tetrahedron (71; VTK_TETRA at
    p = 1) of (p+1)(p+2)(p+3)/6 nodes whose map equals Gmsh's at random reference points (the
    node order maps Gmsh's to VTK's, which differ from p = 2 on), and the certified minJ/maxJ
    is cell data of the tetrahedra (NaN on the surface triangles and lines)."""
    gmsh.clear()
    gmsh.model.occ.addBox(-2, -2, -2, 4, 4, 4, 1)
    gmsh.model.occ.addSphere(0, 0, 0, 1, 2)
    gmsh.model.occ.cut([(3, 1)], [(3, 2)])
    gmsh.model.occ.synchronize()
    gmsh.option.setNumber("Mesh.MeshSizeMax", 1.0)
    gmsh.model.mesh.generate(3)
    if p > 1:
        assert homesh.curve(p=p)["validity"]["invalid"] == 0
    path = tmp_path / "ball.vtu"
    homesh.write(str(path))
    grid = read_vtu(path)
    tags = cell_array(grid, "gmsh:element")
    tet_type = gmsh.model.mesh.getElementType("Tetrahedron", p)
    tets = set(gmsh.model.mesh.getElementsByType(tet_type)[0])
    rng = np.random.default_rng(p)
    seen, curved = 0, 0
    for c in range(grid.GetNumberOfCells()):
        cell = grid.GetCell(c)
        if cell.GetCellDimension() != 3:
            continue
        seen += 1
        assert int(tags[c]) in tets
        assert cell.GetCellType() == (vtk.VTK_TETRA if p == 1 else vtk.VTK_LAGRANGE_TETRAHEDRON)
        assert cell.GetNumberOfPoints() == (p + 1) * (p + 2) * (p + 3) // 6
        for u, v, w in rng.dirichlet([1, 1, 1, 1], 2)[:, 1:]:
            x, weights = [0.0, 0.0, 0.0], [0.0] * cell.GetNumberOfPoints()
            cell.EvaluateLocation(vtk.mutable(0), [u, v, w], x, weights)
            _, _, expected = gmsh.model.mesh.getJacobian(int(tags[c]), [u, v, w])
            assert np.allclose(x, expected, rtol=0, atol=1e-12)
            # Away from the box's flat sides some elements are curved.
            corners = [grid.GetPoint(cell.GetPointId(k)) for k in range(4)]
            straight = (1 - u - v - w) * np.array(corners[0]) + u * np.array(corners[1]) + \
                v * np.array(corners[2]) + w * np.array(corners[3])
            curved += np.linalg.norm(np.array(x) - straight) > 1e-6
    assert seen == len(tets)
    assert (curved > 0) == (p > 1)
    ratio = cell_array(grid, "homesh: certified minJ/maxJ")
    volume = np.array([grid.GetCell(c).GetCellDimension() == 3
                       for c in range(grid.GetNumberOfCells())])
    assert not np.isnan(ratio[volume]).any() and np.isnan(ratio[~volume]).all()
    assert ratio[volume].min() > 0
