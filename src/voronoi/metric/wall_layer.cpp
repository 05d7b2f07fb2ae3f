#include "voronoi/metric/wall_layer.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.h"

namespace homesh {
namespace {

// The box of the polylines' points.
std::pair<Eigen::Vector2d, Eigen::Vector2d> box_of(const std::vector<Eigen::Matrix2Xd>& walls) {
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector2d hi = -lo;
  for (const Eigen::Matrix2Xd& w : walls)
    if (w.cols() > 0) {
      lo = lo.cwiseMin(w.rowwise().minCoeff());
      hi = hi.cwiseMax(w.rowwise().maxCoeff());
    }
  if (!(lo.array() <= hi.array()).all()) throw Error("wall distance: no wall polyline has a point");
  return {lo, hi};
}

double longest_segment(const std::vector<Eigen::Matrix2Xd>& walls) {
  double longest = 0;
  for (const Eigen::Matrix2Xd& w : walls)
    for (Eigen::Index k = 0; k + 1 < w.cols(); ++k)
      longest = std::max(longest, (w.col(k + 1) - w.col(k)).norm());
  if (!(longest > 0)) throw Error("wall distance: no wall segment has a positive length");
  return longest;
}

}  // namespace

WallDistance::WallDistance(const std::vector<Eigen::Matrix2Xd>& walls)
    : half_(0.5 * longest_segment(walls)),
      mids_(box_of(walls).first, box_of(walls).second, 2 * half_) {
  for (const Eigen::Matrix2Xd& w : walls)
    for (Eigen::Index k = 0; k + 1 < w.cols(); ++k) {
      if (w.col(k + 1) == w.col(k)) continue;
      a_.push_back(w.col(k));
      b_.push_back(w.col(k + 1));
      mids_.add(0.5 * (w.col(k) + w.col(k + 1)));
    }
}

WallDistance::Nearest WallDistance::nearest(const Eigen::Vector2d& p, double reach) const {
  Nearest out;
  out.distance = std::numeric_limits<double>::infinity();
  int best = -1;
  // Rings of doubling radius r: a segment within r of p has its midpoint
  // within r + half of it.
  for (double r = 4 * half_;; r *= 2) {
    mids_.all_of_near_index(p, r + half_, [&](int k) {
      const Eigen::Vector2d e = b_[k] - a_[k];
      const double t = std::clamp((p - a_[k]).dot(e) / e.squaredNorm(), 0.0, 1.0);
      const double d = (a_[k] + t * e - p).norm();
      if (d < out.distance) {
        out.distance = d;
        best = k;
      }
      return true;
    });
    if (out.distance <= r || r >= reach) break;
  }
  if (best < 0 || out.distance > reach) {
    out.distance = std::numeric_limits<double>::infinity();
    return out;
  }
  // The distance's gradient is (p - foot) / d: across the segment where the
  // foot is inside it, radial round its end where it is not (a sharp
  // trailing edge's fan); on the wall, the segment's direction.
  const Eigen::Vector2d e = b_[best] - a_[best];
  const Eigen::Vector2d foot =
      a_[best] + std::clamp((p - a_[best]).dot(e) / e.squaredNorm(), 0.0, 1.0) * e;
  out.tangent = e.normalized();
  if (out.distance > 1e-9 * e.norm()) {
    const Eigen::Vector2d n = (p - foot) / out.distance;
    out.tangent = Eigen::Vector2d(n.y(), -n.x());
  }
  return out;
}

WallLayer::WallLayer(MetricField iso, const std::vector<Eigen::Matrix2Xd>& walls, double aspect,
                     double thickness)
    : iso_(std::move(iso)), walls_(walls), aspect_(aspect), thickness_(thickness) {}

// The tensor of boundary_layer_metric (size_metric.h) at p, from p's own
// distance to the walls (Eq 2.7 with the semi-axes h along the wall, h_n
// across).
Eigen::Matrix2d WallLayer::at(const Eigen::Vector2d& p) const {
  const Eigen::Matrix2d M = iso_.metric_at(p);
  const double h = 1.0 / std::sqrt(M(0, 0));
  const WallDistance::Nearest w = walls_.nearest(p, thickness_ * h);
  if (!(w.distance < thickness_ * h)) return M;
  const double hn = h * (1.0 / aspect_ + (1.0 - 1.0 / aspect_) * w.distance / (thickness_ * h));
  const Eigen::Vector2d t = w.tangent, n(-t.y(), t.x());
  return t * t.transpose() / (h * h) + n * n.transpose() / (hn * hn);
}

}  // namespace homesh
