#include "io/vtk_node_order.h"

#include <algorithm>
#include <numeric>
#include <string>

#include "core/error.h"
#include "core/mesh.h"
#include "element/quad_reference_nodes.h"
#include "element/reference_nodes.h"
#include "element/tet_reference_nodes.h"

namespace homesh {
namespace {

void check_vtk_order(int p, const char* what) {
  if (p < 1) throw Error(std::string(what) + ": order " + std::to_string(p) + " must be >= 1");
}

// Barycentric index (b0, b1, b2) of VTK node `index` of a triangle of order
// `order`, as vtkHigherOrderTriangle::BarycentricIndex computes it: whole
// rings of 3 * order nodes are skipped inwards, each ring a triangle of order
// 3 less, then the node is a corner or an edge node of its ring.
Eigen::Vector3i barycentric_index(int index, int order) {
  int max = order, min = 0;
  while (index != 0 && index >= 3 * order) {
    index -= 3 * order;
    max -= 2;
    ++min;
    order -= 3;
  }
  Eigen::Vector3i b;
  if (index < 3) {
    b[index] = b[(index + 1) % 3] = min;
    b[(index + 2) % 3] = max;
  } else {
    index -= 3;
    const int dim = index / (order - 1);
    const int offset = index - dim * (order - 1);
    b[(dim + 1) % 3] = min;
    b[(dim + 2) % 3] = (max - 1) - offset;
    b[dim] = (min + 1) + offset;
  }
  return b;
}

// vtkHigherOrderTetra's tables (VTK 9.1, vtkHigherOrderTetra.cxx): the corners
// of each edge (EdgeVertices, vtkTetra's edges); the barycentric coordinate that
// is maximal at each corner (VertexMaxCoords: b3 at the origin, b0 at (1,0,0),
// ...); the barycentric coordinates that take a face triangle's (t0, t1, t2)
// (FaceBCoords; the face's fourth coordinate, FaceMinCoord, stays minimal).
constexpr int kTetEdges[6][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
constexpr int kTetCornerMaxCoord[4] = {3, 0, 1, 2};
constexpr int kTetFaceCoords[4][3] = {{0, 2, 3}, {2, 0, 1}, {2, 1, 3}, {1, 0, 3}};

// Barycentric index (b0, b1, b2, b3) of VTK node `index` of a tetrahedron of
// order `order`, as vtkHigherOrderTetra::BarycentricIndex computes it: whole
// shells of 2 order^2 + 2 nodes are skipped inwards while order > 3, each shell
// a tetrahedron of order 4 less, then the node is a corner, an edge node or a
// face node of its shell (a face's nodes a triangle of order `order` - 3,
// vtkHigherOrderTriangle::BarycentricIndex).
Eigen::Vector4i tetrahedron_barycentric_index(int index, int order) {
  int max = order, min = 0;
  while (index >= 2 * (order * order + 1) && index != 0 && order > 3) {
    index -= 2 * (order * order + 1);
    max -= 3;
    ++min;
    order -= 4;
  }
  Eigen::Vector4i b = Eigen::Vector4i::Constant(min);
  if (index < 4) {
    b[kTetCornerMaxCoord[index]] = max;
    return b;
  }
  index -= 4;
  if (index < 6 * (order - 1)) {
    const int edge = index / (order - 1), offset = index % (order - 1);
    b[kTetCornerMaxCoord[kTetEdges[edge][0]]] += max - min - 1 - offset;
    b[kTetCornerMaxCoord[kTetEdges[edge][1]]] += 1 + offset;
    return b;
  }
  index -= 6 * (order - 1);
  const int per_face = (order - 2) * (order - 1) / 2;
  const int face = index / per_face;
  const Eigen::Vector3i t =
      order == 3 ? Eigen::Vector3i::Zero() : barycentric_index(index % per_face, order - 3);
  for (int c = 0; c < 3; ++c) b[kTetFaceCoords[face][c]] = min + 1 + t[c];
  return b;
}

// map[k] = the column of `gmsh` equal to column k of `vtk`: the Gmsh node at
// VTK node k's position. Throws homesh::Error if the two node sets differ.
template <int Dim>
std::vector<int> same_position_map(const Eigen::Matrix<int, Dim, Eigen::Dynamic>& vtk,
                                   const Eigen::Matrix<int, Dim, Eigen::Dynamic>& gmsh,
                                   const char* what, int p) {
  std::vector<int> map(static_cast<std::size_t>(vtk.cols()), -1);
  for (Eigen::Index k = 0; k < vtk.cols(); ++k)
    for (Eigen::Index g = 0; g < gmsh.cols(); ++g)
      if (gmsh.col(g) == vtk.col(k)) map[static_cast<std::size_t>(k)] = static_cast<int>(g);
  const bool all_found = std::find(map.begin(), map.end(), -1) == map.end();
  if (!all_found || vtk.cols() != gmsh.cols())
    throw Error(std::string(what) + ": order " + std::to_string(p) + ": node sets differ");
  return map;
}

}  // namespace

Eigen::Matrix2Xi vtk_triangle_node_indices(int p) {
  check_vtk_order(p, "vtk_triangle_node_indices");
  Eigen::Matrix2Xi ij(2, triangle_node_count(p));
  for (int k = 0; k < ij.cols(); ++k) ij.col(k) = barycentric_index(k, p).head<2>();
  return ij;
}

std::vector<int> gmsh_to_vtk_triangle(int p) {
  return same_position_map<2>(vtk_triangle_node_indices(p), reference_node_indices(p),
                              "gmsh_to_vtk_triangle", p);
}

Eigen::Matrix2Xi vtk_quad_node_indices(int p) {
  check_vtk_order(p, "vtk_quad_node_indices");
  Eigen::Matrix2Xi ij(2, quad_node_count(p));
  int k = 0;
  auto put = [&](int i, int j) { ij.col(k++) << i, j; };
  put(0, 0);
  put(p, 0);
  put(p, p);
  put(0, p);
  for (int i = 1; i < p; ++i) put(i, 0);
  for (int j = 1; j < p; ++j) put(p, j);
  for (int i = 1; i < p; ++i) put(i, p);
  for (int j = 1; j < p; ++j) put(0, j);
  for (int j = 1; j < p; ++j)
    for (int i = 1; i < p; ++i) put(i, j);
  return ij;
}

std::vector<int> gmsh_to_vtk_quad(int p) {
  return same_position_map<2>(vtk_quad_node_indices(p), quad_reference_node_indices(p),
                              "gmsh_to_vtk_quad", p);
}

Eigen::Matrix3Xi vtk_tetrahedron_node_indices(int p) {
  check_vtk_order(p, "vtk_tetrahedron_node_indices");
  Eigen::Matrix3Xi ijl(3, tetrahedron_node_count(p));
  for (int k = 0; k < ijl.cols(); ++k) ijl.col(k) = tetrahedron_barycentric_index(k, p).head<3>();
  return ijl;
}

std::vector<int> gmsh_to_vtk_tetrahedron(int p) {
  return same_position_map<3>(vtk_tetrahedron_node_indices(p), tetrahedron_node_indices(p),
                              "gmsh_to_vtk_tetrahedron", p);
}

std::vector<int> line_nodes_along(int p) {
  check_vtk_order(p, "line_nodes_along");
  const Eigen::RowVectorXd t = reference_line_nodes(p);
  std::vector<int> along(static_cast<std::size_t>(p + 1));
  std::iota(along.begin(), along.end(), 0);
  std::sort(along.begin(), along.end(), [&](int a, int b) { return t(a) < t(b); });
  return along;
}

}  // namespace homesh
