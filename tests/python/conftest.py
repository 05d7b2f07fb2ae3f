"""Fixtures shared by the Python tests."""
import gmsh
import pytest


@pytest.fixture
def fold_a_p2_triangle():
    """A function that makes the current order-2 mesh invalid: the first triangle's
    mid-edge node 3 moved beyond its corner 2, so the corners stay counter-clockwise
    but det J changes sign inside (not certified valid)."""
    def fold():
        triangle6 = gmsh.model.mesh.getElementType("Triangle", 2)
        _, nodes = gmsh.model.mesh.getElementsByType(triangle6)
        corner = gmsh.model.mesh.getNode(nodes[2])[0]
        middle = gmsh.model.mesh.getNode(nodes[3])[0]
        gmsh.model.mesh.setNode(nodes[3], list(corner + 1.5 * (corner - middle)), [])
    return fold
