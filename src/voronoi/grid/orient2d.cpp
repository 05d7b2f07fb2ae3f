#include "voronoi/grid/orient2d.h"

#include <cmath>
#include <limits>
#include <vector>

namespace homesh {
namespace {

// x + y = s + e exactly, |e| <= ulp(s) / 2 (Knuth's TwoSum).
void two_sum(double x, double y, double& s, double& e) {
  s = x + y;
  const double bv = s - x;
  const double av = s - bv;
  e = (x - av) + (y - bv);
}

// x * y = p + e exactly (fused multiply-add).
void two_product(double x, double y, double& p, double& e) {
  p = x * y;
  e = std::fma(x, y, -p);
}

// Adds b to the non-overlapping expansion h (components by increasing
// magnitude, zeros dropped), keeping it exact and non-overlapping
// (Shewchuk's GROW-EXPANSION with zero elimination).
void grow_expansion(std::vector<double>& h, double b) {
  std::vector<double> out;
  out.reserve(h.size() + 1);
  double q = b;
  for (double e : h) {
    double s, r;
    two_sum(q, e, s, r);
    if (r != 0.0) out.push_back(r);
    q = s;
  }
  if (q != 0.0) out.push_back(q);
  h.swap(out);
}

int sign(double v) { return (v > 0.0) - (v < 0.0); }

}  // namespace

int orient2d(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  const double left = (a.x() - c.x()) * (b.y() - c.y());
  const double right = (a.y() - c.y()) * (b.x() - c.x());
  const double det = left - right;
  // Shewchuk's ccwerrboundA = (3 + 16 eps) eps, eps = 2^-53.
  constexpr double eps = std::numeric_limits<double>::epsilon() / 2.0;
  constexpr double bound = (3.0 + 16.0 * eps) * eps;
  if (std::abs(det) > bound * (std::abs(left) + std::abs(right))) return sign(det);

  // Exact: each difference is a two-component expansion, each product of two
  // such differences four exact two-component products.
  double ax[2], ay[2], bx[2], by[2];
  two_sum(a.x(), -c.x(), ax[1], ax[0]);
  two_sum(a.y(), -c.y(), ay[1], ay[0]);
  two_sum(b.x(), -c.x(), bx[1], bx[0]);
  two_sum(b.y(), -c.y(), by[1], by[0]);
  std::vector<double> h;
  for (int p = 0; p < 2; ++p) {
    for (int q = 0; q < 2; ++q) {
      double hi, lo;
      two_product(ax[p], by[q], hi, lo);
      grow_expansion(h, lo);
      grow_expansion(h, hi);
      two_product(-ay[p], bx[q], hi, lo);
      grow_expansion(h, lo);
      grow_expansion(h, hi);
    }
  }
  return h.empty() ? 0 : sign(h.back());
}

}  // namespace homesh
