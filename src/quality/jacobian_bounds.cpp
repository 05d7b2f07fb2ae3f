#include "quality/jacobian_bounds.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/error.h"
#include "quality/bezier_jacobian.h"
#include "quality/bezier_subdivision.h"
#include "quality/bezier_triangle.h"

namespace homesh {
namespace {

// A sub-triangle: its coefficients live at coeffs[offset, offset + n).
struct Domain {
  int offset;
  double min_b, max_b;  // bounds: the extreme coefficients
};

class Refinement {
 public:
  Refinement(int d, const Eigen::VectorXd& c, const BoundsOptions& opt)
      : d_(d), n_(bezier_size(d)), opt_(opt) {
    coeffs_.reserve(static_cast<std::size_t>(n_) * 64);
    live_.reserve(64);
    coeffs_.assign(c.data(), c.data() + n_);
    min_l_ = max_l_ = c(0);
    add(0);
  }

  JacobianBounds run() {
    // Split the domain of lowest bound, then that of highest bound, until it
    // meets both criteria (as Gmsh does). Meanwhile the tolerance can only
    // grow and the bounds only tighten, so the minimum stays refined.
    const auto by_min = [](const Domain& a, const Domain& b) { return a.min_b > b.min_b; };
    const auto by_max = [](const Domain& a, const Domain& b) { return a.max_b < b.max_b; };
    const auto ok = [this](const Domain& D) { return min_ok(D) && max_ok(D); };
    refine(by_min, ok);
    refine(by_max, ok);

    JacobianBounds r;
    const auto lowest = std::min_element(live_.begin(), live_.end(), [](auto& a, auto& b) {
      return a.min_b < b.min_b;
    });
    const auto highest = std::max_element(live_.begin(), live_.end(), [](auto& a, auto& b) {
      return a.max_b < b.max_b;
    });
    r.min_lower = lowest->min_b;
    r.min_upper = min_l_;
    r.max_lower = max_l_;
    r.max_upper = highest->max_b;
    r.tolerance = tolerance();
    r.converged = min_ok(*lowest) && max_ok(*highest);
    r.valid_certified = r.min_lower > 0;
    r.invalid_certified = r.min_upper <= 0;
    r.subdivisions = subdivisions_;
    return r;
  }

 private:
  double tolerance() const {
    return opt_.relative_tolerance * std::max(std::abs(min_l_), std::abs(max_l_));
  }
  bool min_ok(const Domain& D) const {
    return (min_l_ <= 0 || D.min_b > 0) && min_l_ - D.min_b <= tolerance();
  }
  bool max_ok(const Domain& D) const {
    return (max_l_ >= 0 || D.max_b < 0) && D.max_b - max_l_ <= tolerance();
  }

  // Registers the domain stored at `offset`: its bounds and exact corner values.
  void add(int offset) {
    const double* c = coeffs_.data() + offset;
    double lo = c[0], hi = c[0];
    for (int i = 1; i < n_; ++i) {
      lo = std::min(lo, c[i]);
      hi = std::max(hi, c[i]);
    }
    live_.push_back({offset, lo, hi});
    for (const int corner : {0, d_, n_ - 1}) {
      min_l_ = std::min(min_l_, c[corner]);
      max_l_ = std::max(max_l_, c[corner]);
    }
  }

  // Splits the heap top (the worst domain for `cmp`) until it satisfies `ok`.
  template <class Cmp, class Ok>
  void refine(Cmp cmp, Ok ok) {
    std::make_heap(live_.begin(), live_.end(), cmp);
    while (!ok(live_.front()) && subdivisions_ < opt_.max_subdivisions) {
      std::pop_heap(live_.begin(), live_.end(), cmp);
      const int parent = live_.back().offset;
      live_.pop_back();
      const int first = static_cast<int>(coeffs_.size());
      coeffs_.resize(coeffs_.size() + 4 * static_cast<std::size_t>(n_));
      bezier_subdivide(d_, Eigen::Map<const Eigen::VectorXd>(coeffs_.data() + parent, n_),
                       Eigen::Map<Eigen::MatrixXd>(coeffs_.data() + first, n_, 4));
      for (int s = 0; s < 4; ++s) {
        add(first + s * n_);
        std::push_heap(live_.begin(), live_.end(), cmp);
      }
      ++subdivisions_;
    }
  }

  int d_, n_;
  BoundsOptions opt_;
  std::vector<double> coeffs_;  // the coefficients of every domain made
  std::vector<Domain> live_;    // the current partition of the triangle
  double min_l_, max_l_;        // exact extreme values found so far
  int subdivisions_ = 0;
};

}  // namespace

JacobianBounds bezier_bounds(int d, const Eigen::VectorXd& c, const BoundsOptions& opt) {
  if (d < 0 || c.size() != bezier_size(d)) {
    throw Error("bezier_bounds: degree " + std::to_string(d) + " needs " +
                std::to_string(bezier_size(d)) + " coefficients, got " + std::to_string(c.size()));
  }
  if (!c.allFinite()) throw Error("bezier_bounds: non-finite coefficients (nodes)");
  if (!(opt.relative_tolerance >= 0) || opt.max_subdivisions < 0) {
    throw Error("bezier_bounds: relative_tolerance and max_subdivisions must be >= 0");
  }
  return Refinement(d, c, opt).run();
}

JacobianBounds jacobian_bounds(const Eigen::Matrix2Xd& X, int p, const BoundsOptions& opt) {
  return bezier_bounds(2 * (p - 1), jacobian_determinant_bezier(X, p), opt);
}

double scaled_jacobian_ratio(const JacobianBounds& b) {
  if (b.max_upper > 0) return b.min_lower / b.max_upper;
  if (b.max_upper < 0) return b.max_upper / b.min_lower;
  return 0.0;
}

}  // namespace homesh
