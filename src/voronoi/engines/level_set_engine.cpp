#include "voronoi/engines/level_set_engine.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <set>
#include <string>
#include <vector>

#include "core/error.h"
#include "voronoi/engines/growth_field.h"
#include "voronoi/engines/level_set_crystal.h"

namespace homesh {
namespace {

// For each tile of kTile by kTile grid nodes, the crystals whose box meets it:
// the candidates k of Eq 2.10 at a crossing in that tile.
constexpr int kTile = 16;

class TileIndex {
 public:
  explicit TileIndex(const CartesianGrid& g)
      : tx_((g.nx + kTile - 1) / kTile), lists_(tx_ * ((g.ny + kTile - 1) / kTile)) {}

  void rebuild(const std::vector<LevelSetCrystal>& crystals) {
    for (auto& l : lists_) l.clear();
    for (int s = 0; s < static_cast<int>(crystals.size()); ++s) {
      const NodeBox& b = crystals[s].box();
      for (int tj = b.j0 / kTile; tj <= b.j1 / kTile; ++tj)
        for (int ti = b.i0 / kTile; ti <= b.i1 / kTile; ++ti) lists_[ti + tx_ * tj].push_back(s);
    }
  }
  const std::vector<int>& at(int i, int j) const { return lists_[i / kTile + tx_ * (j / kTile)]; }

 private:
  int tx_;
  std::vector<std::vector<int>> lists_;
};

struct Reset {
  int crystal, i, j;
  bool closes;  ///< a collision between crystals: the node is closed to all
};

// Eqs 2.9-2.12 along the grid lines through crystal s, in direction (di, dj):
// where phi_s changes sign between two nodes, the crossing x is interpolated
// linearly; a crystal k with phi_k(x) <= 0 has collided with s, and both are
// reset and frozen at the two nodes, which no third crystal may enter either
// (else it creeps along the gap left between the two frozen fronts). A
// crossing with domain(x) >= 0 touches the boundary crystal, which is wet
// (freezes s) or dry (Eq 2.13 acts instead).
void find_collisions(int s, int di, int dj, const std::vector<LevelSetCrystal>& crystals,
                     const TileIndex& tiles, const GrowthField& field,
                     std::set<std::array<int, 2>>& collisions, std::vector<char>& contacts,
                     std::vector<Reset>& resets) {
  const LevelSetCrystal& c = crystals[s];
  const NodeBox& b = c.box();
  const CartesianGrid& g = field.grid();
  const bool wet = field.contact_kind() == Contact::wet;
  for (int j = b.j0; j + dj <= b.j1; ++j) {
    for (int i = b.i0; i + di <= b.i1; ++i) {
      const double v0 = c.next(i, j), v1 = c.next(i + di, j + dj);
      if (v0 * v1 > 0.0) continue;
      const double theta = v0 == v1 ? 0.0 : v0 / (v0 - v1);
      const double d =
          (1 - theta) * field.domain(g.index(i, j)) + theta * field.domain(g.index(i + di, j + dj));
      for (const int k : tiles.at(i, j)) {
        if (k == s) continue;
        const NodeBox& bk = crystals[k].box();
        if (!bk.contains(i, j) || !bk.contains(i + di, j + dj)) continue;
        const LevelSetCrystal& o = crystals[k];
        if ((1 - theta) * o.next(i, j) + theta * o.next(i + di, j + dj) > 0.0) continue;
        // Crystals meeting inside the boundary crystal (across a thin part of
        // it) are stopped but are not neighbours.
        if (d < 0.0 || !field.has_domain()) collisions.insert({std::min(s, k), std::max(s, k)});
        for (const int m : {s, k}) {
          resets.push_back({m, i, j, true});
          resets.push_back({m, i + di, j + dj, true});
        }
      }
      if (!field.has_domain() || d < 0.0) continue;
      contacts[s] = 1;
      if (wet) {
        resets.push_back({s, i, j, false});
        resets.push_back({s, i + di, j + dj, false});
      }
    }
  }
}

// Extreme speeds over the metrics the crystals grow in, and whether they are
// all isotropic (M proportional to I).
struct Speeds {
  double max = 0.0;
  double min = std::numeric_limits<double>::infinity();
  bool isotropic = true;
};

Speeds speed_range(const VoronoiProblem& problem, const GrowthField& field) {
  const auto round = [](const Eigen::Matrix2d& M) {
    return std::abs(M(0, 1)) <= 1e-12 * M.norm() && std::abs(M(0, 0) - M(1, 1)) <= 1e-12 * M.norm();
  };
  Speeds out;
  if (problem.seed_metrics.empty()) {
    out.max = field.metric().max_speed();
    out.min = field.metric().min_speed();
    for (int k = 0; k < field.metric().coarse().node_count(); ++k)
      out.isotropic = out.isotropic && round(field.metric().metric(k));
    return out;
  }
  for (const Eigen::Matrix2d& M : problem.seed_metrics) {
    out.max = std::max(out.max, metric_max_speed(M));
    out.min = std::min(out.min, metric_min_speed(M));
    out.isotropic = out.isotropic && round(M);
  }
  return out;
}

// Metric radius of each seed crystal, a ball of the seed's metric M_s: the
// ball of smallest semi-axis `fixed` if fixed > 0; otherwise 0.3 times the
// M_s-distance to the nearest other seed, between the balls of smallest
// semi-axis 2 ds (the thesis' r_s ~ 2 ds) and 8 ds. The ball is the exact
// crystal at its birth time, and a larger one skips the steps where the
// first-order scheme is least accurate (a front of radius ~ ds).
std::vector<double> seed_radii(const Eigen::Matrix2Xd& seeds, const std::vector<Eigen::Matrix2d>& M,
                               double ds, double fixed) {
  const int S = static_cast<int>(seeds.cols());
  std::vector<double> radius(S);
  for (int s = 0; s < S; ++s) {
    const double cell = ds / metric_min_speed(M[s]);  // metric length of ds across
    if (fixed > 0.0) {
      radius[s] = fixed / ds * cell;
      continue;
    }
    double nearest = std::numeric_limits<double>::infinity();
    for (int k = 0; k < S; ++k) {
      const Eigen::Vector2d v = seeds.col(k) - seeds.col(s);
      if (k != s) nearest = std::min(nearest, std::sqrt(v.dot(M[s] * v)));
    }
    radius[s] = std::clamp(0.3 * nearest, 2.0 * cell, 8.0 * cell);
  }
  return radius;
}

// The crystal holding each domain node (smallest phi_s where crystals
// overlap). Once settled, the gaps left between frozen fronts are filled layer
// by layer from their labelled 4-neighbours, each gap node taking the
// neighbouring crystal of smallest phi_s there.
Eigen::VectorXi label_nodes(const std::vector<LevelSetCrystal>& crystals, const GrowthField& field,
                            bool settled, int& uncovered) {
  const CartesianGrid& g = field.grid();
  std::vector<double> best(g.node_count(), 0.0);
  Eigen::VectorXi labels = Eigen::VectorXi::Constant(g.node_count(), -1);
  for (int s = 0; s < static_cast<int>(crystals.size()); ++s) {
    const LevelSetCrystal& c = crystals[s];
    for (int j = c.box().j0; j <= c.box().j1; ++j)
      for (int i = c.box().i0; i <= c.box().i1; ++i) {
        const int node = g.index(i, j);
        if (field.zone(node) == GrowthField::inside && c.phi(i, j) <= best[node]) {
          best[node] = c.phi(i, j);
          labels(node) = s;
        }
      }
  }
  std::vector<int> gaps;
  for (int node = 0; node < g.node_count(); ++node)
    if (field.zone(node) == GrowthField::inside && labels(node) < 0) gaps.push_back(node);
  uncovered = static_cast<int>(gaps.size());
  if (!settled) return labels;
  const auto phi = [&](int s, int i, int j) {
    const LevelSetCrystal& c = crystals[s];
    return c.box().contains(i, j) ? c.phi(i, j) : std::numeric_limits<double>::infinity();
  };
  std::vector<std::array<int, 2>> layer;
  while (!gaps.empty()) {
    layer.clear();
    std::vector<int> rest;
    for (const int node : gaps) {
      const int i = node % g.nx, j = node / g.nx;
      int pick = -1;
      for (const auto& [a, b] :
           {std::array<int, 2>{i - 1, j}, {i + 1, j}, {i, j - 1}, {i, j + 1}}) {
        if (a < 0 || b < 0 || a >= g.nx || b >= g.ny) continue;
        const int l = labels(g.index(a, b));
        if (l >= 0 && (pick < 0 || phi(l, i, j) < phi(pick, i, j))) pick = l;
      }
      if (pick >= 0)
        layer.push_back({node, pick});
      else
        rest.push_back(node);
    }
    if (layer.empty()) break;
    for (const auto& [node, l] : layer) labels(node) = l;
    gaps.swap(rest);
  }
  return labels;
}

}  // namespace

CrystalPartition grow_crystals_level_set(const VoronoiProblem& problem,
                                         const VoronoiOptions& options) {
  const CartesianGrid& g = problem.grid;
  const int S = static_cast<int>(problem.seeds.cols());
  if (S == 0) throw Error("voronoi: no seeds");
  const bool own = !problem.seed_metrics.empty();
  if (own && static_cast<int>(problem.seed_metrics.size()) != S)
    throw Error("voronoi: " + std::to_string(problem.seed_metrics.size()) + " seed metrics for " +
                std::to_string(S) + " seeds");
  if (!(options.cfl >= 0.0 && options.cfl <= 1.0))
    throw Error("voronoi: cfl must be in [0, 1] (Section 2.3; 0: automatic)");
  const GrowthField field(problem);

  const Speeds speeds = speed_range(problem, field);
  const double max_f = speeds.max, min_f = speeds.min;
  // In a rotated anisotropic metric the scheme drifts ahead in the directions
  // between the axes at cfl ~ 1 (a few percent of the distance grown at an
  // aspect ratio of 3); cfl = 1/2 keeps it within a few cells. In an isotropic
  // metric cfl = 1 is the most accurate (the update is then exact along the
  // grid axes).
  const double cfl = options.cfl > 0.0 ? options.cfl : (speeds.isotropic ? 1.0 : 0.5);
  std::vector<Eigen::Matrix2d> shape(S);
  for (int s = 0; s < S; ++s) {
    const Eigen::Vector2d p = problem.seeds.col(s);
    const Eigen::Vector2d rel = p - g.origin;
    if (rel.x() < 0 || rel.y() < 0 || rel.x() > (g.nx - 1) * g.dx || rel.y() > (g.ny - 1) * g.dy)
      throw Error("voronoi: seed " + std::to_string(s) + " lies outside the grid");
    const Eigen::Vector2i n = g.nearest_node(p);
    if (field.zone(g.index(n.x(), n.y())) == GrowthField::outside)
      throw Error("voronoi: seed " + std::to_string(s) + " lies outside the domain");
    shape[s] = own ? problem.seed_metrics[s] : field.metric().metric_at(p);
  }
  const std::vector<double> radius = seed_radii(problem.seeds, shape, g.ds(), options.seed_radius);
  std::vector<LevelSetCrystal> crystals;
  crystals.reserve(S);
  double t = std::numeric_limits<double>::infinity();
  for (int s = 0; s < S; ++s) {
    crystals.emplace_back(field, problem.seeds.col(s), shape[s], radius[s], options.band,
                          own ? &problem.seed_metrics[s] : nullptr);
    t = std::min(t, crystals.back().birth_time());
  }

  // The crystal that took each node first (kFree: none yet; kClosed: a
  // collision node in no crystal), and the coverage of the domain for the
  // stopping test.
  std::vector<int> owner(g.node_count(), LevelSetCrystal::kFree);
  int covered_count = 0;
  const auto cover = [&](int node, int s) {
    if (owner[node] != LevelSetCrystal::kFree) return;
    owner[node] = s;
    covered_count += field.zone(node) == GrowthField::inside;
  };
  for (int s = 0; s < S; ++s) {
    const LevelSetCrystal& c = crystals[s];
    for (int j = c.box().j0; j <= c.box().j1; ++j)
      for (int i = c.box().i0; i <= c.box().i1; ++i)
        if (c.phi(i, j) <= 0.0) cover(g.index(i, j), s);
  }

  const double dt = cfl * g.ds() / max_f;
  const int patience = 2 * static_cast<int>(std::ceil(max_f / (cfl * min_f))) + 2;
  const double diagonal = std::hypot((g.nx - 1) * g.dx, (g.ny - 1) * g.dy);
  const int max_steps = options.max_steps > 0
                            ? options.max_steps
                            : 2 * static_cast<int>(std::ceil(diagonal / min_f / dt)) + patience;

  CrystalPartition out;
  std::set<std::array<int, 2>> collisions;
  std::vector<char> contacts(S, 0);
  TileIndex tiles(g);
  std::vector<Reset> resets;
  std::vector<int> newly;
  int idle = 0;
  const double stop =
      options.stop_time > 0.0 ? options.stop_time : std::numeric_limits<double>::infinity();
  while (out.steps < max_steps && t < stop) {
    const double step = std::min(dt, stop - t);
    bool waiting = false;
    for (int s = 0; s < S; ++s) {
      const bool born = t >= crystals[s].birth_time();
      waiting = waiting || !born;
      crystals[s].advance(step, born, owner, s);
    }
    tiles.rebuild(crystals);
    resets.clear();
    for (int s = 0; s < S; ++s) {
      if (crystals[s].dormant()) continue;
      find_collisions(s, 1, 0, crystals, tiles, field, collisions, contacts, resets);
      find_collisions(s, 0, 1, crystals, tiles, field, collisions, contacts, resets);
    }
    for (const Reset& r : resets) {
      crystals[r.crystal].freeze(r.i, r.j);
      int& o = owner[g.index(r.i, r.j)];
      if (r.closes && o == LevelSetCrystal::kFree) o = LevelSetCrystal::kClosed;
    }
    t += step;
    ++out.steps;
    bool moved = false;
    for (int s = 0; s < S; ++s) {
      newly.clear();
      crystals[s].commit(t, patience, newly);
      for (const int node : newly) cover(node, s);
      moved = moved || !newly.empty();
    }
    idle = moved ? 0 : idle + 1;
    if (covered_count == field.inside_count() || (!waiting && idle >= patience)) {
      out.settled = true;
      break;
    }
  }
  out.time = t;
  out.collisions.assign(collisions.begin(), collisions.end());
  for (int s = 0; s < S; ++s)
    if (contacts[s]) out.boundary_contacts.push_back(s);

  out.labels = label_nodes(crystals, field, out.settled, out.uncovered);
  return out;
}

}  // namespace homesh
