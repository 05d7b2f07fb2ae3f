#include "quality/bezier_jacobian.h"

#include <string>
#include <vector>

#include "core/error.h"
#include "element/reference_nodes.h"
#include "quality/bezier_triangle.h"
#include "quality/order_tables.h"

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
    to_bezier = lagrange_to_bezier(p, reference_nodes(p));
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

  Eigen::MatrixXd to_bezier;  // control points = X * transpose(this)
  // Control point e of the derivatives: d/du = b[du_plus[e]] - b[d_minus[e]],
  // d/dv = b[dv_plus[e]] - b[d_minus[e]] (times p, folded into `product`).
  std::vector<int> du_plus, dv_plus, d_minus;
  std::vector<ProductTerm> product;
};

void check_bezier_order(const char* who, int p) {
  if (p < 1 || p > kMaxBezierJacobianOrder) {
    throw Error(std::string(who) + ": order " + std::to_string(p) + " not in [1, " +
                std::to_string(kMaxBezierJacobianOrder) + "]");
  }
}

}  // namespace

void jacobian_control_points(const Eigen::Matrix2Xd& X, int p, Eigen::Ref<Eigen::Matrix2Xd> U,
                             Eigen::Ref<Eigen::Matrix2Xd> V) {
  check_bezier_order("jacobian_control_points", p);
  const int n = bezier_size(p), m = bezier_size(p - 1);
  if (X.cols() != n) {
    throw Error("jacobian_control_points: an order " + std::to_string(p) + " triangle has " +
                std::to_string(n) + " nodes, got " + std::to_string(X.cols()));
  }
  if (U.cols() != m || V.cols() != m) {
    throw Error("jacobian_control_points: order " + std::to_string(p) + " needs " +
                std::to_string(m) + " control points per derivative");
  }
  const JacobianTables& t = order_tables<JacobianTables>(p);
  // b = X * transpose(to_bezier), one node (column of to_bezier) at a time.
  double bx[kMaxBezierJacobianNodes] = {}, by[kMaxBezierJacobianNodes] = {};
  for (int i = 0; i < n; ++i) {
    const double* col = t.to_bezier.col(i).data();
    const double xi = X(0, i), yi = X(1, i);
    for (int k = 0; k < n; ++k) {
      bx[k] += xi * col[k];
      by[k] += yi * col[k];
    }
  }
  for (int e = 0; e < m; ++e) {
    U(0, e) = bx[t.du_plus[e]] - bx[t.d_minus[e]];
    U(1, e) = by[t.du_plus[e]] - by[t.d_minus[e]];
    V(0, e) = bx[t.dv_plus[e]] - bx[t.d_minus[e]];
    V(1, e) = by[t.dv_plus[e]] - by[t.d_minus[e]];
  }
}

void jacobian_determinant_bezier(const Eigen::Ref<const Eigen::Matrix2Xd>& U,
                                 const Eigen::Ref<const Eigen::Matrix2Xd>& V, int p,
                                 Eigen::Ref<Eigen::VectorXd> c) {
  check_bezier_order("jacobian_determinant_bezier", p);
  if (U.cols() != bezier_size(p - 1) || V.cols() != U.cols() ||
      c.size() != bezier_size(2 * (p - 1))) {
    throw Error("jacobian_determinant_bezier: sizes do not match order " + std::to_string(p));
  }
  const JacobianTables& t = order_tables<JacobianTables>(p);
  c.setZero();
  for (const ProductTerm& term : t.product) {
    c(term.g) += term.w * (U(0, term.a) * V(1, term.b) - V(0, term.a) * U(1, term.b));
  }
}

Eigen::VectorXd jacobian_determinant_bezier(const Eigen::Matrix2Xd& X, int p) {
  check_bezier_order("jacobian_determinant_bezier", p);
  JacobianControlPoints U(2, bezier_size(p - 1)), V(2, bezier_size(p - 1));
  jacobian_control_points(X, p, U, V);
  Eigen::VectorXd c(bezier_size(2 * (p - 1)));
  jacobian_determinant_bezier(U, V, p, c);
  return c;
}

}  // namespace homesh
