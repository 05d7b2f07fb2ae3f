#include "quality/jacobian_bounds.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "core/error.h"
#include "quality/bezier_jacobian.h"
#include "quality/bezier_quad.h"
#include "quality/bezier_subdivision.h"
#include "quality/bezier_tetrahedron.h"
#include "quality/bezier_triangle.h"
#include "quality/quad_bezier_jacobian.h"
#include "quality/tet_bezier_jacobian.h"

namespace homesh {
namespace {

// What the refinement needs of the domain's shape (triangle, square or
// tetrahedron): the coefficients per domain, which of them are corner values
// (exact values of the polynomial), and the split into `children` domains.
struct Shape {
  int n;
  std::array<int, 4> corners;
  int num_corners;
  int children;
  void (*split)(int d, const Eigen::Ref<const Eigen::VectorXd>& c, Eigen::Ref<Eigen::MatrixXd> sub);
};

Shape triangle(int d) {
  const int n = bezier_size(d);
  return {n, {0, d, n - 1, 0}, 3, 4, bezier_subdivide};
}

Shape square(int d) {
  const int n = quad_bezier_size(d, d);
  return {n, {0, d, n - 1, n - 1 - d}, 4, 4, quad_bezier_subdivide};
}

// Corners: (0,0,0) first, then (d,0,0), (0,d,0) opening the last layer i + j + l = d,
// (0,0,d) last (quality/bezier_tetrahedron.h).
Shape tetrahedron(int d) {
  const int n = tetrahedron_bezier_size(d), last = d > 0 ? tetrahedron_bezier_size(d - 1) : 0;
  return {n, {0, last, last + d, n - 1}, 4, 8, tetrahedron_bezier_subdivide};
}

// A sub-domain: its coefficients live at coeffs[offset, offset + n).
struct Domain {
  int offset;
  double min_b, max_b;  // bounds: the extreme coefficients
};

class Refinement {
 public:
  // `c` (shape.n coefficients) must outlive the object; it is copied only if
  // the whole domain needs splitting.
  Refinement(int d, const Shape& shape, const double* c, const BoundsOptions& opt)
      : d_(d), n_(shape.n), shape_(shape), opt_(opt), root_(c) {
    min_l_ = max_l_ = c[0];
    root_domain_ = bounds_of(c, 0);
  }

  JacobianBounds run() {
    const auto ok = [this](const Domain& D) { return min_ok(D) && max_ok(D); };
    // Most elements of a good mesh are decided by their own coefficients:
    // then no domain storage is made at all.
    if (ok(root_domain_)) return result(root_domain_, root_domain_);
    coeffs_.reserve(static_cast<std::size_t>(n_) * 64);
    live_.reserve(64);
    coeffs_.assign(root_, root_ + n_);
    live_.push_back(root_domain_);
    // Split the domain of lowest bound, then that of highest bound, until it
    // meets both criteria (as Gmsh does). Meanwhile the tolerance can only
    // grow and the bounds only tighten, so the minimum stays refined.
    const auto by_min = [](const Domain& a, const Domain& b) { return a.min_b > b.min_b; };
    const auto by_max = [](const Domain& a, const Domain& b) { return a.max_b < b.max_b; };
    refine(by_min, ok);
    refine(by_max, ok);
    const auto lowest = std::min_element(live_.begin(), live_.end(),
                                         [](auto& a, auto& b) { return a.min_b < b.min_b; });
    const auto highest = std::max_element(live_.begin(), live_.end(),
                                          [](auto& a, auto& b) { return a.max_b < b.max_b; });
    return result(*lowest, *highest);
  }

 private:
  JacobianBounds result(const Domain& lowest, const Domain& highest) const {
    JacobianBounds r;
    r.min_lower = lowest.min_b;
    r.min_upper = min_l_;
    r.max_lower = max_l_;
    r.max_upper = highest.max_b;
    r.tolerance = tolerance();
    r.converged = min_ok(lowest) && max_ok(highest);
    r.valid_certified = r.min_lower > 0;
    r.invalid_certified = r.min_upper <= 0;
    r.subdivisions = subdivisions_;
    return r;
  }

  double tolerance() const {
    return opt_.relative_tolerance * std::max(std::abs(min_l_), std::abs(max_l_));
  }
  bool min_ok(const Domain& D) const {
    return (min_l_ <= 0 || D.min_b > 0) && min_l_ - D.min_b <= tolerance();
  }
  bool max_ok(const Domain& D) const {
    return (max_l_ >= 0 || D.max_b < 0) && D.max_b - max_l_ <= tolerance();
  }

  // The bounds of the domain with coefficients c stored at `offset`; the
  // exact corner values update the extreme values found.
  Domain bounds_of(const double* c, int offset) {
    double lo = c[0], hi = c[0];
    for (int i = 1; i < n_; ++i) {
      lo = std::min(lo, c[i]);
      hi = std::max(hi, c[i]);
    }
    for (int k = 0; k < shape_.num_corners; ++k) {
      min_l_ = std::min(min_l_, c[shape_.corners[k]]);
      max_l_ = std::max(max_l_, c[shape_.corners[k]]);
    }
    return {offset, lo, hi};
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
      const int children = shape_.children;
      coeffs_.resize(coeffs_.size() + children * static_cast<std::size_t>(n_));
      shape_.split(d_, Eigen::Map<const Eigen::VectorXd>(coeffs_.data() + parent, n_),
                   Eigen::Map<Eigen::MatrixXd>(coeffs_.data() + first, n_, children));
      for (int s = 0; s < children; ++s) {
        const int offset = first + s * n_;
        live_.push_back(bounds_of(coeffs_.data() + offset, offset));
        std::push_heap(live_.begin(), live_.end(), cmp);
      }
      ++subdivisions_;
    }
  }

  int d_, n_;
  Shape shape_;
  BoundsOptions opt_;
  const double* root_;  // the coefficients of the whole domain
  Domain root_domain_;
  std::vector<double> coeffs_;  // the coefficients of every domain made
  std::vector<Domain> live_;    // the current partition of the domain
  double min_l_, max_l_;        // exact extreme values found so far
  int subdivisions_ = 0;
};

// Bounds over the domain of `shape`, the arguments checked first.
JacobianBounds bounds(const char* who, int d, const Shape& shape,
                      const Eigen::Ref<const Eigen::VectorXd>& c, const BoundsOptions& opt) {
  if (d < 0 || c.size() != shape.n) {
    throw Error(std::string(who) + ": degree " + std::to_string(d) + " needs " +
                std::to_string(shape.n) + " coefficients, got " + std::to_string(c.size()));
  }
  if (!c.allFinite()) throw Error(std::string(who) + ": non-finite coefficients (nodes)");
  if (!(opt.relative_tolerance >= 0) || opt.max_subdivisions < 0) {
    throw Error(std::string(who) + ": relative_tolerance and max_subdivisions must be >= 0");
  }
  return Refinement(d, shape, c.data(), opt).run();
}

}  // namespace

JacobianBounds bezier_bounds(int d, const Eigen::Ref<const Eigen::VectorXd>& c,
                             const BoundsOptions& opt) {
  return bounds("bezier_bounds", d, triangle(std::max(d, 0)), c, opt);
}

JacobianBounds quad_bezier_bounds(int d, const Eigen::Ref<const Eigen::VectorXd>& c,
                                  const BoundsOptions& opt) {
  return bounds("quad_bezier_bounds", d, square(std::max(d, 0)), c, opt);
}

JacobianBounds quad_jacobian_bounds(const Eigen::Matrix2Xd& X, int p, const BoundsOptions& opt) {
  return quad_bezier_bounds(2 * p - 1, quad_jacobian_determinant_bezier(X, p), opt);
}

JacobianBounds jacobian_bounds(const Eigen::Matrix2Xd& X, int p, const BoundsOptions& opt) {
  const int q = std::clamp(p, 1, kMaxBezierJacobianOrder) - 1;
  JacobianControlPoints U(2, bezier_size(q)), V(2, bezier_size(q));
  jacobian_control_points(X, p, U, V);
  return jacobian_bounds(U, V, p, opt);
}

JacobianBounds jacobian_bounds(const JacobianControlPoints& U, const JacobianControlPoints& V,
                               int p, const BoundsOptions& opt) {
  // bezier_size(2 (kMaxBezierJacobianOrder - 1)) coefficients at most.
  double c[(2 * kMaxBezierJacobianOrder - 1) * kMaxBezierJacobianOrder];
  const int d = 2 * (std::clamp(p, 1, kMaxBezierJacobianOrder) - 1);
  Eigen::Map<Eigen::VectorXd> coefficients(c, bezier_size(d));
  jacobian_determinant_bezier(U, V, p, coefficients);
  return bezier_bounds(d, coefficients, opt);
}

JacobianBounds tetrahedron_bezier_bounds(int d, const Eigen::Ref<const Eigen::VectorXd>& c,
                                         const BoundsOptions& opt) {
  if (d < 0 || d > kMaxTetBezierDegree)
    throw Error("tetrahedron_bezier_bounds: degree " + std::to_string(d) + " out of range 0.." +
                std::to_string(kMaxTetBezierDegree));
  return bounds("tetrahedron_bezier_bounds", d, tetrahedron(d), c, opt);
}

JacobianBounds tetrahedron_jacobian_bounds(const Eigen::Matrix3Xd& X, int p,
                                           const BoundsOptions& opt) {
  return tetrahedron_bezier_bounds(3 * (p - 1), tetrahedron_jacobian_bezier(X, p), opt);
}

double scaled_jacobian_ratio(const JacobianBounds& b) {
  if (b.max_upper > 0) return b.min_lower / b.max_upper;
  if (b.max_upper < 0) return b.max_upper / b.min_lower;
  return 0.0;
}

}  // namespace homesh
