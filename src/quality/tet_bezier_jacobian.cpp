#include "quality/tet_bezier_jacobian.h"

#include <Eigen/LU>
#include <array>
#include <memory>
#include <mutex>
#include <string>

#include "core/error.h"
#include "core/mesh.h"
#include "element/tet_lagrange_basis.h"
#include "quality/bezier_tetrahedron.h"

namespace homesh {
namespace {

// Per order: the basis gradients at the degree-3(p-1) lattice, 3 n by #points.
const Eigen::MatrixXd& lattice_gradients(int p) {
  static std::array<std::unique_ptr<Eigen::MatrixXd>, kMaxTetJacobianOrder + 1> made;
  static std::array<std::once_flag, kMaxTetJacobianOrder + 1> once;
  std::call_once(once[p], [p] {
    const int d = 3 * (p - 1);
    const TetLagrangeBasis basis(p);
    const Eigen::Matrix3Xd lattice = tetrahedron_bezier_indices(d).cast<double>() / std::max(d, 1);
    auto G = std::make_unique<Eigen::MatrixXd>(3 * basis.size(), lattice.cols());
    for (Eigen::Index q = 0; q < lattice.cols(); ++q)
      basis.evaluate(lattice.col(q), nullptr, G->col(q).data());
    made[p] = std::move(G);
  });
  return *made[p];
}

}  // namespace

Eigen::VectorXd tetrahedron_jacobian_bezier(const Eigen::Matrix3Xd& X, int p) {
  if (p < 1 || p > kMaxTetJacobianOrder)
    throw Error("tetrahedron_jacobian_bezier: order " + std::to_string(p) + " out of range 1.." +
                std::to_string(kMaxTetJacobianOrder));
  if (X.cols() != tetrahedron_node_count(p))
    throw Error("tetrahedron_jacobian_bezier: " + std::to_string(X.cols()) + " nodes for order " +
                std::to_string(p) + " (needs " + std::to_string(tetrahedron_node_count(p)) + ")");
  if (!X.allFinite()) throw Error("tetrahedron_jacobian_bezier: non-finite node coordinates");
  const Eigen::MatrixXd& G = lattice_gradients(p);
  const Eigen::Index n = X.cols(), points = G.cols();
  Eigen::VectorXd det(points);
  for (Eigen::Index q = 0; q < points; ++q) {
    // J = X * dN, dN (n by 3): node k's gradient at rows 3k..3k+2 of column q.
    const Eigen::Map<const Eigen::Matrix<double, 3, Eigen::Dynamic>> dN(G.col(q).data(), 3, n);
    const Eigen::Matrix3d J = X * dN.transpose();
    det(q) = J.determinant();
  }
  return tetrahedron_bezier_from_values(3 * (p - 1), det);
}

}  // namespace homesh
