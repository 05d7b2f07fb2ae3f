#include "voronoi/metric/wall_layer.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.h"

namespace homesh {
namespace {

// The polyline w as chords from sample to sample that leave out no sample
// between by more than `tolerance` and are at most `longest` long.
std::vector<Eigen::Vector2d> decimated(const Eigen::Matrix2Xd& w, double tolerance,
                                       double longest) {
  std::vector<Eigen::Vector2d> out;
  if (w.cols() == 0) return out;
  out.push_back(w.col(0));
  Eigen::Index i = 0;
  while (i + 1 < w.cols()) {
    Eigen::Index j = i + 1;
    // Extend the chord (i, j + 1) while every sample between is close to it.
    while (j + 1 < w.cols()) {
      const Eigen::Vector2d a = w.col(i), e = w.col(j + 1) - a;
      if (e.norm() > longest) break;
      bool close = true;
      for (Eigen::Index k = i + 1; k <= j && close; ++k) {
        const double t = e.squaredNorm() > 0
                             ? std::clamp((w.col(k) - a).dot(e) / e.squaredNorm(), 0.0, 1.0)
                             : 0.0;
        close = (a + t * e - w.col(k)).norm() <= tolerance;
      }
      if (!close) break;
      ++j;
    }
    out.push_back(w.col(j));
    i = j;
  }
  return out;
}

}  // namespace

WallDistance::WallDistance(const std::vector<Eigen::Matrix2Xd>& walls, double tolerance,
                           double longest)
    : mids_({0, 0}, {1, 1}, 1) {
  if (!(longest > 0)) longest = std::numeric_limits<double>::infinity();
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector2d hi = -lo;
  for (const Eigen::Matrix2Xd& w : walls) {
    const std::vector<Eigen::Vector2d> p = decimated(w, tolerance, longest);
    for (std::size_t k = 0; k + 1 < p.size(); ++k) {
      if (p[k + 1] == p[k]) continue;
      a_.push_back(p[k]);
      b_.push_back(p[k + 1]);
      half_ = std::max(half_, 0.5 * (p[k + 1] - p[k]).norm());
      lo = lo.cwiseMin(p[k]).cwiseMin(p[k + 1]);
      hi = hi.cwiseMax(p[k]).cwiseMax(p[k + 1]);
    }
  }
  if (a_.empty()) throw Error("wall distance: no wall segment has a positive length");
  mids_ = PointBuckets(lo, hi, 2 * half_);
  for (std::size_t k = 0; k < a_.size(); ++k) mids_.add(0.5 * (a_[k] + b_[k]));
}

WallDistance::Nearest WallDistance::nearest_within(const Eigen::Vector2d& p, double bound) const {
  Nearest out;
  out.distance = std::numeric_limits<double>::infinity();
  int best = -1;
  double best2 = std::numeric_limits<double>::infinity();
  Eigen::Vector2d foot = p;
  // A segment within `bound` of p has its midpoint within bound + half of it.
  mids_.all_of_near_index(p, bound + half_, [&](int k) {
    const Eigen::Vector2d e = b_[k] - a_[k];
    const double t = std::clamp((p - a_[k]).dot(e) / e.squaredNorm(), 0.0, 1.0);
    const Eigen::Vector2d f = a_[k] + t * e;
    const double d2 = (f - p).squaredNorm();
    if (d2 < best2) {
      best2 = d2;
      best = k;
      foot = f;
    }
    return true;
  });
  if (best < 0) return out;
  out.distance = std::sqrt(best2);
  // The distance's gradient is (p - foot) / d: across the segment where the
  // foot is inside it, radial round its end where it is not (a sharp
  // trailing edge's fan); on the wall, the segment's direction.
  const Eigen::Vector2d e = b_[best] - a_[best];
  out.tangent = e.normalized();
  if (out.distance > 1e-9 * e.norm()) {
    const Eigen::Vector2d n = (p - foot) / out.distance;
    out.tangent = Eigen::Vector2d(n.y(), -n.x());
  }
  return out;
}

WallLayer::WallLayer(MetricField iso, const std::vector<Eigen::Matrix2Xd>& walls, double aspect,
                     double thickness, std::vector<double> coarse_distance, double slack)
    : iso_(std::move(iso)),
      tolerance_(0.01 * iso_.min_speed() / aspect),
      walls_(walls, tolerance_, iso_.min_speed()),
      aspect_(aspect),
      thickness_(thickness),
      distance_(std::move(coarse_distance)),
      slack_(slack) {
  if (static_cast<int>(distance_.size()) != iso_.coarse().node_count())
    throw Error("wall layer: " + std::to_string(distance_.size()) + " distances for " +
                std::to_string(iso_.coarse().node_count()) + " coarse nodes");
}

// The tensor of boundary_layer_metric (size_metric.h) at p, from p's own
// distance to the walls (Eq 2.7 with the semi-axes h along the wall, h_n
// across).
Eigen::Matrix2d WallLayer::at(const Eigen::Vector2d& p) const {
  const Eigen::Matrix2d M = iso_.metric_at(p);
  const double h = 1.0 / std::sqrt(M(0, 0));
  // Bounds of p's distance from its coarse cell's corners (the distance is
  // 1-Lipschitz): below, none of the layer is within reach; above, the
  // search radius.
  const CartesianGrid& g = iso_.coarse();
  const int i = std::clamp(static_cast<int>((p.x() - g.origin.x()) / g.dx), 0, g.nx - 2);
  const int j = std::clamp(static_cast<int>((p.y() - g.origin.y()) / g.dy), 0, g.ny - 2);
  double lower = 0, upper = std::numeric_limits<double>::infinity();
  const double diagonal = std::hypot(g.dx, g.dy);
  for (const int b : {j, j + 1})
    for (const int a : {i, i + 1}) {
      const double r = (p - g.point(a, b)).norm(), d = distance_[g.index(a, b)];
      upper = std::min(upper, d + r);
      // Less a cell's diagonal: the coarse distances come from a vector
      // distance transform, which may miss the nearest sample by that much.
      lower = std::max(lower, d - slack_ - tolerance_ - r - diagonal);
    }
  const double reach = thickness_ * h;
  if (lower >= reach) return M;
  const WallDistance::Nearest w =
      walls_.nearest_within(p, std::min(upper, reach) + slack_ + tolerance_);
  if (!(w.distance < reach)) return M;
  const double hn = h * (1.0 / aspect_ + (1.0 - 1.0 / aspect_) * w.distance / reach);
  const Eigen::Vector2d t = w.tangent, n(-t.y(), t.x());
  return t * t.transpose() / (h * h) + n * n.transpose() / (hn * hn);
}

}  // namespace homesh
