#pragma once
// Seeds in columns across an anisotropic wall: where the metric is much finer
// across a wall than along it (a boundary layer), the seeds stand on the
// wall's normals, one column per boundary seed, at unit metric steps, so that
// their triangulation is the layer's stack of cells (the points of an
// advancing-layer mesher, Pirzadeh, "Unstructured viscous grid generation by
// the advancing-layers method", AIAA J 32(8), 1994, placed by the metric as in
// Marcum and Weatherill, AIAA J 33(9), 1995, and Loseille's metric-aligned
// points). Rows of apexes (metric_front_seeds) cannot: at 100:1 a wall chord
// sags by several first-cell heights, so each row's apex above the chord
// below would fall below the row before.
#include <Eigen/Core>
#include <array>
#include <vector>

#include "voronoi/grid/cartesian_grid.h"
#include "voronoi/metric/metric_field.h"
#include "voronoi/seeding/metric_seeding.h"

namespace homesh {

struct ColumnSeeds {
  Eigen::Matrix2Xd seeds{2, 0};  ///< row by row
  int columns = 0;               ///< columns started (boundary seeds with one)
  int rows = 0;                  ///< the longest column's seeds
  std::vector<int> bases;        ///< the boundary seeds that start columns, increasing
  std::vector<char> in_fan;      ///< per seed: in a fan's column
};

/// grid, domain: as for metric_front_seeds; segments: pairs of
/// boundary_seeds, the domain on their left. A boundary seed s between
/// segments (p, s) and (s, q), where M(s) has semi-axes in a ratio of at
/// least options.column_anisotropy, starts
/// - where the wall is smooth at s (see `sharp`), one column along M's short
///   axis e, if that is within column_turn of the wall's normal n (the
///   bisector of the two segments' left normals), oriented with n, e
///   following M's short axis at each point;
/// - at a corner where the wall turns away from the domain (its angle over
///   180 degrees, a sharp trailing edge), a fan: columns along fixed
///   directions at most column_turn apart from one segment's normal to the
///   other's, not spaced from each other (their first seeds lie within a
///   first cell of the corner);
/// - at a corner where the domain's angle is below 180 degrees, none.
/// Each step is x_{k+1} = x_k + h e, h = 1 / |e|_M at x_k + h e / 2 (unit
/// metric length). The columns advance row by row together; a column ends at
/// the first point where M's ratio is below options.column_end, that lies
/// outside the domain (beyond 2 grid cells from the wall) or that is closer
/// to a seed placed before it (boundary seeds included; in the metric at the
/// pair's midpoint, SpacedSeeds) than options.front_spacing times the metric
/// length of the shorter of s's segments, at most 1.
///
/// sharp: per boundary seed, whether the wall has a corner there (the CAD's
/// tangents turn by more than column_turn); a seed whose segments turn more
/// where the wall is smooth (a leading edge of radius 0.004 between seeds
/// 0.013 apart) gets one column on the bisector, not a fan. Empty: the
/// segments' turn decides.
ColumnSeeds metric_column_seeds(const CartesianGrid& grid, const Eigen::VectorXd& domain,
                                const MetricField& metric, const Eigen::Matrix2Xd& boundary_seeds,
                                const std::vector<std::array<int, 2>>& segments,
                                const SeedingOptions& options = {},
                                const std::vector<char>& sharp = {});

}  // namespace homesh
