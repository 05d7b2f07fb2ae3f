#include "layers/open_room.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.h"
#include "core/progress.h"
#include "curving/analogy_formulation.h"
#include "curving/deform_mesh.h"
#include "layers/clear_room.h"
#include "layers/edge_flips.h"
#include "layers/plane_geometry.h"
#include "layers/radius_ratio.h"
#include "layers/star_smoothing.h"
#include "quality/mesh_validity.h"

namespace homesh {
namespace {

using layers_detail::cross;

// The triangles of m with a node away from where it was (before: 2 by #nodes).
std::vector<int> moved_triangles(const Mesh& m, const Eigen::Matrix2Xd& before) {
  std::vector<int> moved;
  for (int e = 0; e < m.num_triangles(); ++e)
    for (int i = 0; i < 3; ++i)
      if (m.x.col(m.tri(i, e)) != before.col(m.tri(i, e))) {
        moved.push_back(e);
        break;
      }
  return moved;
}

// Of `moved`, the triangles whose radius ratio (Eq 4.17) is below `below` and
// those with two nodes of such a triangle (its edge neighbours, and a few
// more): where a flip can raise the worst, at the cost of the poor triangles,
// not of every triangle the step moved (flip_edges sorts their edges).
std::vector<int> poor_and_neighbours(const Mesh& m, const std::vector<int>& moved, double below) {
  if (!(below < 1)) return moved;
  std::vector<unsigned char> poor_node(m.num_nodes(), 0);
  for (int e : moved) {
    Eigen::Matrix<double, 2, 3> X;
    for (int i = 0; i < 3; ++i) X.col(i) = m.x.col(m.tri(i, e));
    if (radius_ratio(X) < below)
      for (int i = 0; i < 3; ++i) poor_node[m.tri(i, e)] = 1;
  }
  std::vector<int> set;
  for (int e : moved)
    if (poor_node[m.tri(0, e)] + poor_node[m.tri(1, e)] + poor_node[m.tri(2, e)] >= 2)
      set.push_back(e);
  return set;
}

}  // namespace

double fold_fraction(const Eigen::Matrix<double, 2, 3>& x, const Eigen::Matrix<double, 2, 3>& u) {
  // orient(x + t u) = a t^2 + b t + c, c > 0 for a counter-clockwise triangle.
  const Eigen::Vector2d e1 = x.col(1) - x.col(0), e2 = x.col(2) - x.col(0);
  const Eigen::Vector2d d1 = u.col(1) - u.col(0), d2 = u.col(2) - u.col(0);
  const double a = cross(d1, d2), b = cross(e1, d2) + cross(d1, e2), c = cross(e1, e2);
  const double inf = std::numeric_limits<double>::infinity();
  if (!(c > 0)) return 0;
  double t = inf;
  if (std::abs(a) <= 1e-14 * (std::abs(b) + c)) {
    if (b < 0) t = -c / b;
  } else {
    const double disc = b * b - 4 * a * c;
    if (disc >= 0) {
      const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
      for (double root : {q / a, c / q})
        if (root > 0) t = std::min(t, root);
    }
  }
  return t;
}

RoomResult open_room(const Mesh& m, const std::vector<int>& moving, const Eigen::Matrix2Xd& target,
                     const std::vector<bool>& fixed, const RoomOptions& opt,
                     const std::vector<double>& floor, const Room* room) {
  const int count = static_cast<int>(moving.size());
  if (target.cols() != count || fixed.size() != static_cast<std::size_t>(m.num_nodes()))
    throw Error("open_room: one target per moving node and one fixed flag per node are needed");
  if (!floor.empty() && floor.size() != fixed.size())
    throw Error("open_room: one smoothing floor per node is needed");
  if (!(opt.cap > 0 && opt.cap <= 1)) throw Error("open_room: cap must be in (0, 1]");
  if (!(opt.min_fraction > 0 && opt.min_fraction < 1))
    throw Error("open_room: min_fraction must be in (0, 1)");
  std::vector<int> index(m.num_nodes(), -1);
  for (int k = 0; k < count; ++k) index[moving[k]] = k;
  auto front_triangles = [&](const Mesh& mesh) {
    std::vector<int> tris;
    for (int e = 0; e < mesh.num_triangles(); ++e)
      if (index[mesh.tri(0, e)] >= 0 || index[mesh.tri(1, e)] >= 0 || index[mesh.tri(2, e)] >= 0)
        tris.push_back(e);
    return tris;
  };
  std::vector<int> tris = front_triangles(m);

  DeformOptions deform;
  deform.formulation = opt.formulation;
  deform.params = opt.params;
  deform.solver = opt.solver;
  deform.max_halvings = opt.max_halvings;
  deform.reach = opt.reach;
  std::vector<bool> prescribed = fixed;
  for (int v : moving) prescribed[v] = true;

  Mesh current = m;
  RoomResult r;
  std::vector<bool> free(prescribed.size());
  for (std::size_t i = 0; i < free.size(); ++i) free[i] = !prescribed[i];
  // Free nodes in the room ahead of the front go, before and after each step.
  auto clear = [&] {
    if (room == nullptr || !(opt.clear > 0)) return;
    const std::vector<int> gone = clear_room(current, *room, free, opt.clear);
    for (int v : gone) {
      free[v] = false;
      prescribed[v] = true;  // in no triangle now: held, so a whole-mesh solve stays regular
    }
    r.cleared += static_cast<int>(gone.size());
    if (!gone.empty()) tris = front_triangles(current);
  };
  clear();
  double scale = 0;
  for (int k = 0; k < count; ++k)
    scale = std::max(scale, (target.col(k) - m.x.col(moving[k])).norm());
  const double tolerance = 1e-12 * std::max(scale, 1.0);
  Progress progress("room", 100);
  double last = 0;  // the fraction of the remaining motion the last step took

  while (true) {
    // The common fraction of the remaining motion that folds no triangle of
    // the front, its free nodes held still, times cap.
    Eigen::Matrix2Xd rest = Eigen::Matrix2Xd::Zero(2, current.num_nodes());
    bool left = false;
    for (int k = 0; k < count; ++k) {
      rest.col(moving[k]) = target.col(k) - current.x.col(moving[k]);
      left = left || rest.col(moving[k]).norm() > tolerance;
    }
    // Straight to the targets if the free nodes are out of the way already.
    Mesh jump = current;
    for (int k = 0; k < count; ++k) jump.x.col(moving[k]) = target.col(k);
    if (!left || mesh_validity(jump).invalid == 0) {
      current = std::move(jump);
      r.complete = true;
      r.reached = 1;
      break;
    }
    double fraction = 1;
    for (int e : tris) {
      Eigen::Matrix<double, 2, 3> x, u;
      for (int i = 0; i < 3; ++i) {
        x.col(i) = current.x.col(current.tri(i, e));
        u.col(i) = rest.col(current.tri(i, e));
      }
      const double f = opt.cap * fold_fraction(x, u);
      if (f < fraction) {
        fraction = f;
        for (int i = 0; i < 3; ++i)
          if (index[current.tri(i, e)] >= 0) r.bottleneck = index[current.tri(i, e)];
      }
    }
    // The elastic solve moves the free nodes out of the way, so a step twice the
    // last accepted one is tried when the fold bound is smaller (deform_mesh
    // halves it until valid).
    fraction = std::min(1.0, std::max(fraction, opt.growth * last));
    if (r.steps >= opt.max_steps || !(fraction >= opt.min_fraction)) break;
    progress.update(std::lround(100 * r.reached), "% pushed, step " + std::to_string(r.steps + 1));
    Eigen::Matrix2Xd goal = current.x + fraction * rest;
    const DeformResult s = deform_mesh(current, goal, prescribed, deform);
    r.solves += s.solves;
    if (!(s.reached > 0)) break;
    // Flips where the step moved nodes: the solve's region, not the whole mesh.
    const std::vector<int> moved = moved_triangles(s.mesh, current.x);
    current = s.mesh;
    r.reached += s.reached * fraction * (1 - r.reached);
    last = s.reached * fraction;
    ++r.steps;
    if (opt.flips && flip_edges(current, poor_and_neighbours(current, moved, opt.flip_below)) > 0)
      tris = front_triangles(current);
    clear();
    if (!s.complete && !(opt.growth > 0)) break;
  }
  if (r.complete && opt.smoothing) {
    const Eigen::Matrix2Xd before = current.x;
    progress.update(100, "% pushed, smoothing squeezed triangles");
    r.smoothed = smooth_stars(current, free, floor.empty() ? star_quality(m) : floor);
    if (r.smoothed > 0 && opt.flips)
      flip_edges(current,
                 poor_and_neighbours(current, moved_triangles(current, before), opt.flip_below));
  }
  r.mesh = std::move(current);
  return r;
}

}  // namespace homesh
