#include "quality/quad_bezier_jacobian.h"

#include <string>
#include <vector>

#include "core/error.h"
#include "core/mesh.h"
#include "element/quad_reference_nodes.h"
#include "quality/bezier_quad.h"
#include "quality/order_tables.h"

namespace homesh {
namespace {

double binomial(int n, int k) {
  double r = 1.0;
  for (int s = 1; s <= k; ++s) r = r * (n - k + s) / s;
  return r;
}

// One term of the Bernstein product: c[g] += w * (x_u[a] y_v[b] - x_v[b] y_u[a]).
struct ProductTerm {
  int a, b, g;
  double w;
};

// Everything that depends on the order p only.
struct QuadJacobianTables {
  explicit QuadJacobianTables(int p) {
    to_bezier = line_lagrange_to_bezier(p);
    grid = quad_reference_node_indices(p);
    const int d = 2 * p - 1;
    // x_u: degrees (p-1, p), index j p + i; x_v: degrees (p, p-1), index j (p+1) + i.
    for (int j = 0; j <= p; ++j)
      for (int i = 0; i < p; ++i)
        for (int jb = 0; jb < p; ++jb)
          for (int ib = 0; ib <= p; ++ib) {
            const double w = double(p) * p * binomial(p - 1, i) * binomial(p, ib) /
                             binomial(d, i + ib) * binomial(p, j) * binomial(p - 1, jb) /
                             binomial(d, j + jb);
            product.push_back(
                {j * p + i, jb * (p + 1) + ib, quad_bezier_index(d, i + ib, j + jb), w});
          }
  }

  Eigen::MatrixXd to_bezier;  // 1D Lagrange values -> Bernstein coefficients
  Eigen::Matrix2Xi grid;      // (i, j) of each node, Gmsh order
  std::vector<ProductTerm> product;
};

}  // namespace

Eigen::VectorXd quad_jacobian_determinant_bezier(const Eigen::Matrix2Xd& X, int p) {
  if (p < 1 || p > kMaxBezierJacobianOrder)
    throw Error("quad_jacobian_determinant_bezier: order " + std::to_string(p) + " not in [1, " +
                std::to_string(kMaxBezierJacobianOrder) + "]");
  if (X.cols() != quad_node_count(p))
    throw Error("quad_jacobian_determinant_bezier: an order " + std::to_string(p) +
                " quadrilateral has " + std::to_string(quad_node_count(p)) + " nodes, got " +
                std::to_string(X.cols()));
  const QuadJacobianTables& t = order_tables<QuadJacobianTables>(p);
  // Control points b = T G T^T per coordinate, G the nodes on their (i, j) grid.
  Eigen::MatrixXd bx(p + 1, p + 1), by(p + 1, p + 1);
  for (Eigen::Index k = 0; k < X.cols(); ++k) {
    bx(t.grid(0, k), t.grid(1, k)) = X(0, k);
    by(t.grid(0, k), t.grid(1, k)) = X(1, k);
  }
  bx = t.to_bezier * bx * t.to_bezier.transpose();
  by = t.to_bezier * by * t.to_bezier.transpose();
  // Derivative control points without the factor p (folded into the weights).
  Eigen::VectorXd ux(p * (p + 1)), uy(p * (p + 1)), vx(p * (p + 1)), vy(p * (p + 1));
  for (int j = 0; j <= p; ++j)
    for (int i = 0; i < p; ++i) {
      ux(j * p + i) = bx(i + 1, j) - bx(i, j);
      uy(j * p + i) = by(i + 1, j) - by(i, j);
    }
  for (int j = 0; j < p; ++j)
    for (int i = 0; i <= p; ++i) {
      vx(j * (p + 1) + i) = bx(i, j + 1) - bx(i, j);
      vy(j * (p + 1) + i) = by(i, j + 1) - by(i, j);
    }
  Eigen::VectorXd c = Eigen::VectorXd::Zero(4 * p * p);
  for (const ProductTerm& term : t.product)
    c(term.g) += term.w * (ux(term.a) * vy(term.b) - vx(term.b) * uy(term.a));
  return c;
}

}  // namespace homesh
