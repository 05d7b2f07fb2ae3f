#include "quality/bezier_triangle.h"

#include <Eigen/LU>
#include <string>
#include <vector>

#include "core/error.h"

namespace homesh {

Eigen::VectorXd bernstein_basis(int d, const Eigen::Vector2d& uv) {
  const double l[3] = {1.0 - uv(0) - uv(1), uv(0), uv(1)};
  // pw[m][e] = l_m^e, e = 0..d.
  std::vector<double> pw[3];
  for (int m = 0; m < 3; ++m) {
    pw[m].assign(d + 1, 1.0);
    for (int e = 1; e <= d; ++e) pw[m][e] = pw[m][e - 1] * l[m];
  }
  // binom[n][r] = n choose r, n <= d, built by Pascal's rule.
  std::vector<std::vector<double>> binom(d + 1);
  for (int n = 0; n <= d; ++n) {
    binom[n].assign(n + 1, 1.0);
    for (int r = 1; r < n; ++r) binom[n][r] = binom[n - 1][r - 1] + binom[n - 1][r];
  }
  Eigen::VectorXd B(bezier_size(d));
  for (int k = 0; k <= d; ++k) {
    for (int j = 0; j + k <= d; ++j) {
      const int i = d - j - k;
      // d! / (i! j! k!) = C(d, k) C(d - k, j).
      B(bezier_index(d, j, k)) = binom[d][k] * binom[d - k][j] * pw[0][i] * pw[1][j] * pw[2][k];
    }
  }
  return B;
}

double bezier_value(int d, const Eigen::VectorXd& c, const Eigen::Vector2d& uv) {
  return bernstein_basis(d, uv).dot(c);
}

Eigen::MatrixXd lagrange_to_bezier(int d, const Eigen::Matrix2Xd& nodes) {
  const int n = bezier_size(d);
  if (d < 0 || nodes.cols() != n) {
    throw Error("lagrange_to_bezier: degree " + std::to_string(d) + " needs " + std::to_string(n) +
                " nodes, got " + std::to_string(nodes.cols()));
  }
  Eigen::MatrixXd A(n, n);
  for (int m = 0; m < n; ++m) A.row(m) = bernstein_basis(d, nodes.col(m)).transpose();
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(A);
  if (!lu.isInvertible()) {
    throw Error("lagrange_to_bezier: the nodes are not unisolvent for degree " + std::to_string(d));
  }
  return lu.inverse();
}

}  // namespace homesh
