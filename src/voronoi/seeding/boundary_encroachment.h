#pragma once
// Interior seeds that encroach on a boundary segment: inside its diametral
// circle, so that the segment is no edge of the seeds' Delaunay triangulation
// and no grid puts it in the crystal dual (Ruppert, "A Delaunay refinement
// algorithm for quality 2-dimensional mesh generation", J Algorithms 18(3)
// 1995, calls such a segment encroached).
#include <Eigen/Core>
#include <array>
#include <vector>

namespace homesh {

class MetricField;

/// seeds: 2 by S, of which 0..fixed-1 are the boundary seeds; segments: the
/// boundary seed pairs. Returns the indices (>= fixed, increasing) of the
/// seeds strictly inside the diametral circle of some segment; with a
/// metric, inside it in the metric at the segment's midpoint (the segment is
/// then no edge of the seeds' Delaunay triangulation in that metric).
std::vector<int> encroaching_seeds(const Eigen::Matrix2Xd& seeds, int fixed,
                                   const std::vector<std::array<int, 2>>& segments,
                                   const MetricField* metric = nullptr);

}  // namespace homesh
