#include "element/barycentric_indices.h"

#include <cmath>
#include <string>

#include "core/error.h"
#include "element/reference_nodes.h"
#include "element/tet_reference_nodes.h"

namespace homesh {

Eigen::MatrixXi barycentric_indices(int corners, int p) {
  if (corners == 4) {
    const Eigen::Matrix3Xi ijl = tetrahedron_node_indices(p);
    Eigen::MatrixXi b(4, ijl.cols());
    for (Eigen::Index k = 0; k < ijl.cols(); ++k)
      b.col(k) << p - ijl(0, k) - ijl(1, k) - ijl(2, k), ijl(0, k), ijl(1, k), ijl(2, k);
    return b;
  }
  if (corners == 3) {
    const Eigen::Matrix2Xi ij = reference_node_indices(p);
    Eigen::MatrixXi b(3, ij.cols());
    for (Eigen::Index k = 0; k < ij.cols(); ++k)
      b.col(k) << p - ij(0, k) - ij(1, k), ij(0, k), ij(1, k);
    return b;
  }
  if (corners != 2)
    throw Error("barycentric_indices: " + std::to_string(corners) +
                " corners (2: line, 3: triangle, 4: tetrahedron)");
  if (p < 1) throw Error("barycentric_indices: order " + std::to_string(p) + " < 1");
  const Eigen::RowVectorXd s = reference_line_nodes(p);
  Eigen::MatrixXi b(2, s.size());
  for (Eigen::Index k = 0; k < s.size(); ++k) {
    const int t = static_cast<int>(std::lround(s(k) * p));
    b.col(k) << p - t, t;
  }
  return b;
}

}  // namespace homesh
