#include "io/vtk_node_order.h"

#include <algorithm>
#include <numeric>
#include <string>

#include "core/error.h"
#include "core/mesh.h"
#include "element/quad_reference_nodes.h"
#include "element/reference_nodes.h"

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

}  // namespace

Eigen::Matrix2Xi vtk_triangle_node_indices(int p) {
  check_vtk_order(p, "vtk_triangle_node_indices");
  Eigen::Matrix2Xi ij(2, triangle_node_count(p));
  for (int k = 0; k < ij.cols(); ++k) ij.col(k) = barycentric_index(k, p).head<2>();
  return ij;
}

std::vector<int> gmsh_to_vtk_triangle(int p) {
  const Eigen::Matrix2Xi vtk = vtk_triangle_node_indices(p);
  const Eigen::Matrix2Xi gmsh = reference_node_indices(p);
  std::vector<int> map(static_cast<std::size_t>(vtk.cols()), -1);
  for (int k = 0; k < vtk.cols(); ++k)
    for (int g = 0; g < gmsh.cols(); ++g)
      if (gmsh.col(g) == vtk.col(k)) map[static_cast<std::size_t>(k)] = g;
  for (int g : map)
    if (g < 0)
      throw Error("gmsh_to_vtk_triangle: order " + std::to_string(p) + ": node sets differ");
  return map;
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
  const Eigen::Matrix2Xi vtk = vtk_quad_node_indices(p);
  const Eigen::Matrix2Xi gmsh = quad_reference_node_indices(p);
  std::vector<int> map(static_cast<std::size_t>(vtk.cols()), -1);
  for (int k = 0; k < vtk.cols(); ++k)
    for (int g = 0; g < gmsh.cols(); ++g)
      if (gmsh.col(g) == vtk.col(k)) map[static_cast<std::size_t>(k)] = g;
  return map;
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
