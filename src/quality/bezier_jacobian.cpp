#include "quality/bezier_jacobian.h"

#include <array>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "core/error.h"
#include "element/reference_nodes.h"
#include "quality/bezier_triangle.h"

namespace homesh {
namespace {

// Trinomial coefficient q! / (i! j! k!), i = q - j - k.
double trinomial(int q, int j, int k) {
  double r = 1.0;
  for (int s = 1; s <= k; ++s) r = r * (q - k + s) / s;      // C(q, k)
  for (int s = 1; s <= j; ++s) r = r * (q - k - j + s) / s;  // C(q - k, j)
  return r;
}

// One term of the Bernstein product: c[g] += w * f[a] * h[b].
struct ProductTerm {
  int a, b, g;
  double w;
};

// Everything that depends on the order p only.
struct JacobianTables {
  explicit JacobianTables(int p) {
    const int q = p - 1, m = bezier_size(q);
    to_bezier_transposed = lagrange_to_bezier(p, reference_nodes(p)).transpose();
    du_plus.resize(m);
    dv_plus.resize(m);
    d_minus.resize(m);
    for (int k = 0; k <= q; ++k) {
      for (int j = 0; j + k <= q; ++j) {
        const int e = bezier_index(q, j, k);
        du_plus[e] = bezier_index(p, j + 1, k);
        dv_plus[e] = bezier_index(p, j, k + 1);
        d_minus[e] = bezier_index(p, j, k);
      }
    }
    // The derivative factors p * p are folded into the weights.
    for (int ka = 0; ka <= q; ++ka) {
      for (int ja = 0; ja + ka <= q; ++ja) {
        for (int kb = 0; kb <= q; ++kb) {
          for (int jb = 0; jb + kb <= q; ++jb) {
            const double w = double(p) * p * trinomial(q, ja, ka) * trinomial(q, jb, kb) /
                             trinomial(2 * q, ja + jb, ka + kb);
            product.push_back({bezier_index(q, ja, ka), bezier_index(q, jb, kb),
                               bezier_index(2 * q, ja + jb, ka + kb), w});
          }
        }
      }
    }
  }

  Eigen::MatrixXd to_bezier_transposed;  // control points = X * this
  // Control point e of the derivatives: d/du = b[du_plus[e]] - b[d_minus[e]],
  // d/dv = b[dv_plus[e]] - b[d_minus[e]] (times p, folded into `product`).
  std::vector<int> du_plus, dv_plus, d_minus;
  std::vector<ProductTerm> product;
};

const JacobianTables& jacobian_tables(int p) {
  static std::array<std::once_flag, kMaxBezierJacobianOrder + 1> once;
  static std::array<std::unique_ptr<const JacobianTables>, kMaxBezierJacobianOrder + 1> tables;
  std::call_once(once[p], [p] { tables[p] = std::make_unique<const JacobianTables>(p); });
  return *tables[p];
}

}  // namespace

Eigen::VectorXd jacobian_determinant_bezier(const Eigen::Matrix2Xd& X, int p) {
  if (p < 1 || p > kMaxBezierJacobianOrder) {
    throw Error("jacobian_determinant_bezier: order " + std::to_string(p) + " not in [1, " +
                std::to_string(kMaxBezierJacobianOrder) + "]");
  }
  if (X.cols() != bezier_size(p)) {
    throw Error("jacobian_determinant_bezier: an order " + std::to_string(p) + " triangle has " +
                std::to_string(bezier_size(p)) + " nodes, got " + std::to_string(X.cols()));
  }
  const JacobianTables& t = jacobian_tables(p);
  const Eigen::Matrix2Xd b = X.lazyProduct(t.to_bezier_transposed);
  const int m = bezier_size(p - 1);
  Eigen::Matrix2Xd du(2, m), dv(2, m);
  for (int e = 0; e < m; ++e) {
    du.col(e) = b.col(t.du_plus[e]) - b.col(t.d_minus[e]);
    dv.col(e) = b.col(t.dv_plus[e]) - b.col(t.d_minus[e]);
  }
  Eigen::VectorXd c = Eigen::VectorXd::Zero(bezier_size(2 * (p - 1)));
  for (const ProductTerm& term : t.product) {
    c(term.g) += term.w * (du(0, term.a) * dv(1, term.b) - dv(0, term.a) * du(1, term.b));
  }
  return c;
}

}  // namespace homesh
