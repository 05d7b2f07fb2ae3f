#include "layers/edge_flips.h"

#include <algorithm>
#include <utility>
#include <vector>

#include "layers/edge_flip_sweep.h"
#include "layers/plane_geometry.h"
#include "layers/radius_ratio.h"

namespace homesh {
namespace {

double plain_radius_ratio(const Eigen::Matrix<double, 2, 3>& X) { return radius_ratio(X); }

// The flips with q(X) of counter-clockwise triangles X (a template: open_room
// flips after every load step, no call through a std::function per triangle
// for the radius ratio).
template <class Q>
int flip_edges_by(Mesh& m, const std::vector<int>& triangles, const Q& q, double gain,
                  int max_sweeps) {
  const auto quality = [&](int a, int b, int c) {
    Eigen::Matrix<double, 2, 3> X;
    X << m.x.col(a), m.x.col(b), m.x.col(c);
    return layers_detail::orient(X.col(0), X.col(1), X.col(2)) > 0 ? q(X) : -1.0;
  };
  // Triangles (a, b, c) and (b, a, d); the other diagonal gives (c, d, b) and (d, c, a).
  return flip_edges_where(
      m, triangles,
      [&](int a, int b, int c, int d) {
        const double now = std::min(quality(a, b, c), quality(b, a, d));
        const double then = std::min(quality(c, d, b), quality(d, c, a));
        return then > now + gain;
      },
      max_sweeps);
}

}  // namespace

int flip_edges(Mesh& m, double gain, int max_sweeps) {
  return flip_edges_by(m, all_triangles(m), plain_radius_ratio, gain, max_sweeps);
}

int flip_edges(Mesh& m, const std::vector<int>& triangles, double gain, int max_sweeps) {
  return flip_edges_by(m, triangles, plain_radius_ratio, gain, max_sweeps);
}

int flip_edges(Mesh& m, const TriangleQuality& quality, double gain, int max_sweeps) {
  return flip_edges_by(m, all_triangles(m), quality, gain, max_sweeps);
}

}  // namespace homesh
