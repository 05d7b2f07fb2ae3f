#include "quality/bezier_quad.h"

#include <Eigen/LU>
#include <string>
#include <vector>

#include "core/error.h"

namespace homesh {
namespace {

// B^m_i(t), i = 0..m, into B.
void line_bernstein(int m, double t, double* B) {
  // Pascal's triangle in place: after step r, B[i] = B^r_i(t).
  B[0] = 1.0;
  for (int r = 1; r <= m; ++r) {
    B[r] = t * B[r - 1];
    for (int i = r - 1; i >= 1; --i) B[i] = t * B[i - 1] + (1.0 - t) * B[i];
    B[0] *= 1.0 - t;
  }
}

constexpr int kMaxLine = 64;

// De Casteljau at 1/2 of the d+1 coefficients line[0], line[stride], ...:
// the left half's coefficients to `left`, the right half's to `right` (same stride).
void halve(int d, const double* line, int stride, double* left, double* right) {
  double t[kMaxLine] = {};
  for (int i = 0; i <= d; ++i) t[i] = line[i * stride];
  left[0] = t[0];
  right[d * stride] = t[d];
  for (int r = 1; r <= d; ++r) {
    for (int i = 0; i <= d - r; ++i) t[i] = 0.5 * (t[i] + t[i + 1]);
    left[r * stride] = t[0];
    right[(d - r) * stride] = t[d - r];
  }
}

}  // namespace

Eigen::VectorXd quad_bernstein_basis(int m, int n, const Eigen::Vector2d& uv) {
  std::vector<double> Bu(static_cast<std::size_t>(m + 1)), Bv(static_cast<std::size_t>(n + 1));
  line_bernstein(m, uv(0), Bu.data());
  line_bernstein(n, uv(1), Bv.data());
  Eigen::VectorXd B(quad_bezier_size(m, n));
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= m; ++i) B(quad_bezier_index(m, i, j)) = Bu[i] * Bv[j];
  return B;
}

Eigen::MatrixXd line_lagrange_to_bezier(int p) {
  if (p < 1) throw Error("line_lagrange_to_bezier: order " + std::to_string(p) + " must be >= 1");
  Eigen::MatrixXd A(p + 1, p + 1);
  std::vector<double> B(static_cast<std::size_t>(p + 1));
  for (int k = 0; k <= p; ++k) {
    line_bernstein(p, k * (1.0 / p), B.data());
    for (int i = 0; i <= p; ++i) A(k, i) = B[i];
  }
  return A.fullPivLu().inverse();
}

void quad_bezier_subdivide(int d, const Eigen::Ref<const Eigen::VectorXd>& c,
                           Eigen::Ref<Eigen::MatrixXd> sub) {
  if (d < 0 || d >= kMaxLine || c.size() != quad_bezier_size(d, d) || sub.rows() != c.size() ||
      sub.cols() != 4)
    throw Error("quad_bezier_subdivide: sizes do not match degree " + std::to_string(d));
  const int w = d + 1;
  double *s0 = sub.col(0).data(), *s1 = sub.col(1).data(), *s2 = sub.col(2).data(),
         *s3 = sub.col(3).data();
  // In u, row by row: the left half to S0, the right half to S1.
  for (int j = 0; j <= d; ++j) halve(d, c.data() + j * w, 1, s0 + j * w, s1 + j * w);
  // In v, column by column: S0 -> S0 (lower), S3 (upper); S1 -> S1, S2. The
  // line is copied inside halve before it is overwritten.
  for (int i = 0; i <= d; ++i) {
    halve(d, s0 + i, w, s0 + i, s3 + i);
    halve(d, s1 + i, w, s1 + i, s2 + i);
  }
}

}  // namespace homesh
