#include "layers/open_room.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.h"
#include "curving/analogy_formulation.h"
#include "fem/solve_elasticity.h"
#include "layers/edge_flips.h"
#include "layers/plane_geometry.h"
#include "layers/star_smoothing.h"
#include "quality/mesh_validity.h"

namespace homesh {
namespace {

std::vector<std::vector<int>> node_triangles(const Mesh& m) {
  std::vector<std::vector<int>> around(m.num_nodes());
  for (int e = 0; e < m.num_triangles(); ++e)
    for (int i = 0; i < 3; ++i) around[m.tri(i, e)].push_back(e);
  return around;
}

}  // namespace

double available_push(const Mesh& m, const std::vector<int>& triangles, int node,
                      const Eigen::Vector2d& d) {
  double delta = std::numeric_limits<double>::infinity();
  for (int e : triangles) {
    int p = 0;
    while (p < 3 && m.tri(p, e) != node) ++p;
    if (p == 3) continue;
    const Eigen::Vector2d a = m.x.col(m.tri((p + 1) % 3, e)), b = m.x.col(m.tri((p + 2) % 3, e));
    // Unit normal of a -> b towards the node (on its left for a counter-clockwise triangle).
    const Eigen::Vector2d n = Eigen::Vector2d(a(1) - b(1), b(0) - a(0)).normalized();
    const double height = n.dot(m.x.col(node) - a);
    const double closing = -n.dot(d);
    if (closing > 0) delta = std::min(delta, std::max(height, 0.0) / closing);
  }
  return delta;
}

RoomResult open_room(const Mesh& m, const std::vector<int>& moving, const Eigen::Matrix2Xd& target,
                     const std::vector<bool>& fixed, const RoomOptions& opt) {
  const int count = static_cast<int>(moving.size());
  if (target.cols() != count || fixed.size() != static_cast<std::size_t>(m.num_nodes()))
    throw Error("open_room: one target per moving node and one fixed flag per node are needed");
  if (!(opt.cap > 0 && opt.cap <= 1)) throw Error("open_room: cap must be in (0, 1]");
  std::vector<std::vector<int>> around = node_triangles(m);

  const AnalogyFormulation& formulation = analogy_formulation(opt.formulation);
  const FormulationParams& params = opt.params;
  ElasticityOptions eo;
  eo.assembly = params.assembly;
  eo.solver = opt.solver;

  Mesh current = m;
  const Eigen::Matrix2Xd start = m.x;
  RoomResult r;
  double scale = 1;
  for (int k = 0; k < count; ++k) scale = std::max(scale, (target.col(k) - start.col(k)).norm());
  const double tolerance = 1e-12 * scale;

  while (true) {
    // The common fraction of the remaining motion that respects every node's cap.
    double fraction = 1;
    bool left = false;
    for (int k = 0; k < count; ++k) {
      const Eigen::Vector2d rest = target.col(k) - current.x.col(moving[k]);
      const double length = rest.norm();
      if (length <= tolerance) continue;
      left = true;
      const double f =
          opt.cap * available_push(current, around[moving[k]], moving[k], rest / length) / length;
      if (f < fraction) {
        fraction = f;
        r.bottleneck = k;
      }
    }
    if (!left) {
      for (int k = 0; k < count; ++k) current.x.col(moving[k]) = target.col(k);
      r.complete = true;
      r.reached = 1;
      break;
    }
    if (r.steps >= opt.max_steps || !(fraction > 1e-9)) break;
    bool accepted = false;
    for (int h = 0; h <= opt.max_halvings && !accepted; ++h, fraction *= 0.5) {
      DirichletBC bc;
      for (int i = 0; i < m.num_nodes(); ++i)
        if (fixed[i]) bc.fix(i, Eigen::Vector2d::Zero());
      for (int k = 0; k < count; ++k)
        bc.fix(moving[k], Eigen::Vector2d(fraction * (target.col(k) - current.x.col(moving[k]))));
      const ElasticitySolution s =
          solve_elasticity(current, formulation.coefficients(current, m, params), bc, eo);
      ++r.solves;
      Mesh trial = current;
      trial.x += s.u;
      if (mesh_validity(trial).invalid > 0) continue;
      current = std::move(trial);
      r.reached += fraction * (1 - r.reached);
      accepted = true;
      if (opt.flips && flip_edges(current) > 0) around = node_triangles(current);
    }
    if (!accepted) break;
    ++r.steps;
  }
  if (r.complete && opt.smoothing) {
    std::vector<bool> free(fixed.size());
    for (int i = 0; i < m.num_nodes(); ++i) free[i] = !fixed[i];
    for (int k = 0; k < count; ++k) free[moving[k]] = false;
    r.smoothed = smooth_stars(current, free, star_quality(m));
    if (r.smoothed > 0 && opt.flips) flip_edges(current);
  }
  r.mesh = std::move(current);
  return r;
}

}  // namespace homesh
