#include "layers/star_smoothing.h"

#include <algorithm>
#include <set>

#include "core/error.h"
#include "layers/plane_geometry.h"
#include "layers/radius_ratio.h"

namespace homesh {
namespace {

// Worst Q of the triangles `star` of m with `node` placed at p (-1 if one turns clockwise).
double worst_with(const Mesh& m, const std::vector<int>& star, int node, const Eigen::Vector2d& p) {
  double worst = 1;
  for (int e : star) {
    Eigen::Matrix<double, 2, 3> X;
    for (int i = 0; i < 3; ++i)
      X.col(i) = m.tri(i, e) == node ? p : Eigen::Vector2d(m.x.col(m.tri(i, e)));
    if (layers_detail::orient(X.col(0), X.col(1), X.col(2)) <= 0) return -1;
    worst = std::min(worst, radius_ratio(X));
  }
  return worst;
}

std::vector<std::vector<int>> stars(const Mesh& m) {
  std::vector<std::vector<int>> around(m.num_nodes());
  for (int e = 0; e < m.num_triangles(); ++e)
    for (int i = 0; i < 3; ++i) around[m.tri(i, e)].push_back(e);
  return around;
}

}  // namespace

std::vector<double> star_quality(const Mesh& m) {
  const std::vector<std::vector<int>> around = stars(m);
  std::vector<double> q(m.num_nodes(), 1.0);
  for (int i = 0; i < m.num_nodes(); ++i)
    if (!around[i].empty()) q[i] = worst_with(m, around[i], i, m.x.col(i));
  return q;
}

int smooth_stars(Mesh& m, const std::vector<bool>& movable, const std::vector<double>& floor,
                 int max_sweeps) {
  const std::size_t n = static_cast<std::size_t>(m.num_nodes());
  if (movable.size() != n || floor.size() != n)
    throw Error("smooth_stars: one movable flag and one floor per node are needed");
  const std::vector<std::vector<int>> around = stars(m);
  int moves = 0;
  for (int sweep = 0; sweep < max_sweeps; ++sweep) {
    int moved = 0;
    for (int i = 0; i < m.num_nodes(); ++i) {
      if (!movable[i] || around[i].empty()) continue;
      const double now = worst_with(m, around[i], i, m.x.col(i));
      if (!(now < floor[i])) continue;
      std::set<int> neighbours;
      for (int e : around[i])
        for (int j = 0; j < 3; ++j)
          if (m.tri(j, e) != i) neighbours.insert(m.tri(j, e));
      Eigen::Vector2d c = Eigen::Vector2d::Zero();
      for (int j : neighbours) c += m.x.col(j);
      c /= static_cast<double>(neighbours.size());
      for (double t : {1.0, 0.5, 0.25}) {
        const Eigen::Vector2d p = m.x.col(i) + t * (c - m.x.col(i));
        if (worst_with(m, around[i], i, p) > now) {
          m.x.col(i) = p;
          ++moved;
          break;
        }
      }
    }
    moves += moved;
    if (moved == 0) break;
  }
  return moves;
}

}  // namespace homesh
