#include "element/tet_reference_nodes.h"

#include <array>
#include <string>

#include "core/error.h"
#include "core/mesh.h"
#include "element/reference_nodes.h"

namespace homesh {
namespace {

// Gmsh's MTetrahedron::edges_tetra and faces_tetra.
constexpr int kEdges[6][2] = {{0, 1}, {1, 2}, {2, 0}, {3, 0}, {3, 2}, {3, 1}};
constexpr int kFaces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {3, 1, 2}};

// Columns from k on of `ijl`: the integer node coordinates of a tetrahedron of
// order p >= 0, shifted by (shift, shift, shift).
void fill_tet_indices(int p, int shift, int& k, Eigen::Matrix3Xi& ijl) {
  const std::array<Eigen::Vector3i, 4> corner = {Eigen::Vector3i(0, 0, 0), Eigen::Vector3i(p, 0, 0),
                                                 Eigen::Vector3i(0, p, 0),
                                                 Eigen::Vector3i(0, 0, p)};
  auto put = [&](const Eigen::Vector3i& x) { ijl.col(k++) = x + Eigen::Vector3i::Constant(shift); };
  put(corner[0]);
  if (p == 0) return;
  for (int c = 1; c < 4; ++c) put(corner[c]);
  for (const auto& e : kEdges) {
    const Eigen::Vector3i step = (corner[e[1]] - corner[e[0]]) / p;
    for (int i = 1; i < p; ++i) put(corner[e[0]] + i * step);
  }
  if (p < 3) return;
  // The face's interior: a triangle of order p - 3 shifted by (1, 1) (order 0: one node).
  Eigen::Matrix2Xi ab = Eigen::Matrix2Xi::Zero(2, 1);
  if (p > 3) ab = reference_node_indices(p - 3);
  ab.array() += 1;
  for (const auto& f : kFaces) {
    const Eigen::Vector3i u = (corner[f[1]] - corner[f[0]]) / p,
                          v = (corner[f[2]] - corner[f[0]]) / p;
    for (Eigen::Index n = 0; n < ab.cols(); ++n) put(corner[f[0]] + ab(0, n) * u + ab(1, n) * v);
  }
  if (p >= 4) fill_tet_indices(p - 4, shift + 1, k, ijl);
}

void check_order(int p, const char* what) {
  if (p < 1) throw Error(std::string(what) + ": order " + std::to_string(p) + " must be >= 1");
}

}  // namespace

Eigen::Matrix3Xi tetrahedron_node_indices(int p) {
  check_order(p, "tetrahedron_node_indices");
  Eigen::Matrix3Xi ijl(3, tetrahedron_node_count(p));
  int k = 0;
  fill_tet_indices(p, 0, k, ijl);
  return ijl;
}

Eigen::Matrix3Xd tetrahedron_nodes(int p) {
  check_order(p, "tetrahedron_nodes");
  return tetrahedron_node_indices(p).cast<double>() * (1.0 / p);
}

}  // namespace homesh
