#pragma once
// Fitting the layer stack where the walls leave too little room (gaps between
// bodies, slots, concave corners): along each normal line the distance D to
// the nearest boundary edge it meets (any curve, the node's own two wall edges
// excepted) bounds the stack's depth to fill * D (fill = 0.4 leaves room for
// the other wall's stack and the mesh between them). Where d_n * s, d_n the
// stack's depth and s the line's miter scale, exceeds that, every layer of the
// line is thinned by the same factor t = fill D / (d_n s) < 1, so the count and
// the growth ratio are kept. Along the walls t changes by at most `slope` times
// the wall distance over d_n from line to line (the thinning spreads to the
// neighbours), so the layers stay smooth. A line where even the first layer
// does not fit (fill D < first s) cannot be thinned into a valid stack: the
// caller fails there, at once.
//
// Concave walls (a wall curving towards the domain, a concave corner) make
// neighbouring normals converge: the layer cell between consecutive lines
// folds at the depth D* where its outer edge has no length left along the wall
// edge. The discrete form of limiting the stack by the wall's radius of
// curvature (a circle of radius R: D* = R): the stack takes at most cross D*
// on both lines (cross = 0.6: the outer cells keep 40 % of the wall edge's
// length), thinned and reported as above (`crossing`), and a first layer
// beyond cross D* fails at once the same way.
#include <Eigen/Core>
#include <vector>

#include "core/mesh.h"

namespace homesh {

/// A stretch of consecutive thinned lines.
struct ThinnedStretch {
  int first = -1, last = -1;  ///< its first and last line
  int lines = 0;              ///< lines in it
  int tightest = -1;          ///< the line with the smallest factor
  double factor = 1;          ///< that factor t, in (0, 1)
  double gap = 0;             ///< D at that line
  int curve = -1;             ///< the curve the normal meets there (-1 if crossing)
  /// The limit there is the neighbouring normals' crossing (a concave wall), gap
  /// the distance along the normal to it, not another boundary.
  bool crossing = false;
};

struct StackFit {
  std::vector<double> factor;  ///< #lines thinning factor t in (0, 1]
  std::vector<ThinnedStretch> thinned;
  int no_room = -1;       ///< a line where the first layer does not fit, else -1
  double gap = 0;         ///< D at no_room
  int curve = -1;         ///< the curve met there (-1 if crossing)
  bool crossing = false;  ///< no_room is where neighbouring normals cross (gap: how far)
};

/// Fits the stack of depth `depth` (d_n) and first layer `first` on the lines
/// starting at wall node origin[k] of the linear mesh m, unit direction
/// direction.col(k) (2 by #lines), miter scale scale[k], next[k] the following
/// line along the wall (-1 at the end of an open wall).
StackFit fit_stack(const Mesh& m, const std::vector<int>& origin, const Eigen::Matrix2Xd& direction,
                   const std::vector<double>& scale, const std::vector<int>& next, double depth,
                   double first, double fill = 0.4, double cross = 0.6, double slope = 0.5);

}  // namespace homesh
