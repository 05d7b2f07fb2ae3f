#pragma once
// The boundary-layer metric evaluated exactly at any point, not through the
// coarse grid: at 100:1 the size across a wall is 1/100 of the wall's, far
// below the coarse grid's spacing (at most 400 nodes a side), so the coarse
// nodes' tensors, Shepard-averaged, lose the layer's grading wherever no node
// lies within its first cells. WallLayer keeps the walls as polylines and the
// iso field, and gives boundary_layer_metric's tensor at the point itself
// from its exact distance to the nearest wall segment.
#include <Eigen/Core>
#include <vector>

#include "voronoi/metric/metric_field.h"
#include "voronoi/seeding/point_buckets.h"

namespace homesh {

/// The distance from a point to a set of polylines, and a unit tangent:
/// perpendicular to the gradient of the distance (p - foot) / d, or, at a
/// point on a segment, along it.
class WallDistance {
 public:
  /// walls: polylines, 2 by n each (n >= 2), kept as chords that leave out
  /// no sample by more than `tolerance` and are at most `longest` long (0,
  /// inf: every segment as sampled). Throws homesh::Error if none has a
  /// segment of positive length.
  explicit WallDistance(const std::vector<Eigen::Matrix2Xd>& walls, double tolerance = 0,
                        double longest = 0);
  struct Nearest {
    double distance = 0;  ///< infinity if no segment was found
    Eigen::Vector2d tangent = Eigen::Vector2d::UnitX();
  };
  /// The nearest segment to p if it lies within `bound` of p (one search of
  /// that radius); else some farther one, or none (distance infinity).
  Nearest nearest_within(const Eigen::Vector2d& p, double bound) const;
  int segments() const { return static_cast<int>(a_.size()); }

 private:
  std::vector<Eigen::Vector2d> a_, b_;  // segment ends
  double half_ = 0;                     // the longest segment's half length
  PointBuckets mids_;
};

/// The boundary-layer metric of boundary_layer_metric (size_metric.h) at any
/// point: h from the iso field, h_n = h (1/A + (1 - 1/A) min(1, d / (T h)))
/// across the nearest wall segment's tangent t, d the exact distance to it:
/// M = t t^T / h^2 + n n^T / h_n^2 (Eq 2.7), n perpendicular to t.
class WallLayer {
 public:
  /// coarse_distance: at each node of iso's coarse grid, an upper bound of
  /// its distance to the walls within `slack` of it (the nearest wall
  /// sample's distance, slack the samples' half spacing), so that a point's
  /// search starts at the right radius and a point far from the walls needs
  /// none (the walls' chords leave out no sample by more than 1 % of the
  /// first cell, h_min / A, and are at most the smallest size long).
  WallLayer(MetricField iso, const std::vector<Eigen::Matrix2Xd>& walls, double aspect,
            double thickness, std::vector<double> coarse_distance, double slack);
  Eigen::Matrix2d at(const Eigen::Vector2d& p) const;
  double aspect() const { return aspect_; }
  const MetricField& iso() const { return iso_; }
  const WallDistance& walls() const { return walls_; }

 private:
  MetricField iso_;
  double tolerance_;  // of the walls' chords (before walls_, which takes it)
  WallDistance walls_;
  double aspect_, thickness_;
  std::vector<double> distance_;  // at iso_'s coarse nodes
  double slack_;
};

}  // namespace homesh
