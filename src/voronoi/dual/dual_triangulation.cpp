#include "voronoi/dual/dual_triangulation.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <map>
#include <set>

#include "voronoi/grid/orient2d.h"

namespace homesh {
namespace {

using Pair = std::array<int, 2>;
using Triple = std::array<int, 3>;

Pair pair_of(int a, int b) { return {std::min(a, b), std::max(a, b)}; }

// Votes for the two cyclic orders of a triple: [0] sorted order, [1] reversed,
// [2] seen without an order; and the sum of the centres of the cells voting.
struct Votes {
  std::array<int, 3> count{};
  Eigen::Vector2d centre_sum = Eigen::Vector2d::Zero();
  int cells = 0;
  void add(int kind, const Eigen::Vector2d& centre) {
    ++count[kind];
    centre_sum += centre;
    ++cells;
  }
  Eigen::Vector2d centre() const { return centre_sum / cells; }
};

void vote(std::map<Triple, Votes>& votes, int a, int b, int c, const Eigen::Vector2d& centre) {
  Triple t{a, b, c};
  std::sort(t.begin(), t.end());
  // (a, b, c) is an even permutation of the sorted triple iff, rotated to
  // start at its smallest label, the middle label is the second smallest.
  const int m = a == t[0] ? b : (b == t[0] ? c : a);
  votes[t].add(m == t[1] ? 0 : 1, centre);
}

// Sign of the in-circle determinant: > 0 iff d is inside the circle through
// a, b, c when they turn counter-clockwise.
double incircle(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                const Eigen::Vector2d& d) {
  const Eigen::Vector2d p = a - d, q = b - d, r = c - d;
  return p.squaredNorm() * (q.x() * r.y() - q.y() * r.x()) -
         q.squaredNorm() * (p.x() * r.y() - p.y() * r.x()) +
         r.squaredNorm() * (p.x() * q.y() - p.y() * q.x());
}

}  // namespace

DualTriangulation dual_triangulation(const CartesianGrid& g, const Eigen::VectorXi& labels,
                                     const Eigen::Matrix2Xd& seeds,
                                     const std::vector<std::array<int, 2>>& collisions,
                                     const std::vector<std::array<int, 2>>& adjacent,
                                     const MetricField& metric) {
  DualTriangulation out;
  std::set<Pair> edges(collisions.begin(), collisions.end());
  for (const Pair& e : adjacent)
    if (edges.insert(e).second) ++out.adjacency_edges;
  std::set<Pair> added, dropped;
  std::map<Triple, Votes> votes;
  for (int j = 0; j + 1 < g.ny; ++j) {
    for (int i = 0; i + 1 < g.nx; ++i) {
      // Labels counter-clockwise round the cell, unlabelled corners skipped,
      // repeats of a neighbouring corner merged.
      std::vector<int> seq;
      for (const int n :
           {g.index(i, j), g.index(i + 1, j), g.index(i + 1, j + 1), g.index(i, j + 1)})
        if (labels(n) >= 0 && (seq.empty() || seq.back() != labels(n))) seq.push_back(labels(n));
      while (seq.size() > 1 && seq.front() == seq.back()) seq.pop_back();
      std::set<int> distinct(seq.begin(), seq.end());
      const Eigen::Vector2d centre = g.point(i, j) + Eigen::Vector2d(g.dx, g.dy) / 2;
      if (distinct.size() == 3 && seq.size() == 3) {
        ++out.triple_cells;
        vote(votes, seq[0], seq[1], seq[2], centre);
      } else if (distinct.size() == 3) {
        ++out.ambiguous_cells;
        const std::vector<int> t(distinct.begin(), distinct.end());
        votes[{t[0], t[1], t[2]}].add(2, centre);
      } else if (distinct.size() == 4) {
        ++out.quad_cells;
        const int a = seq[0], b = seq[1], c = seq[2], d = seq[3];
        const bool ac = edges.count(pair_of(a, c)) > 0, bd = edges.count(pair_of(b, d)) > 0;
        bool use_bd = bd;
        if (ac == bd) {
          const Eigen::Matrix2d Lt = metric.metric_at(centre).llt().matrixL().transpose();
          const Eigen::Vector2d pa = Lt * seeds.col(a), pb = Lt * seeds.col(b);
          const Eigen::Vector2d pc = Lt * seeds.col(c), pd = Lt * seeds.col(d);
          use_bd = orient2d(pa, pb, pc) * incircle(pa, pb, pc, pd) > 0.0;
        }
        const Pair chosen = use_bd ? pair_of(b, d) : pair_of(a, c);
        const Pair other = use_bd ? pair_of(a, c) : pair_of(b, d);
        if (!edges.count(chosen)) added.insert(chosen);
        if (edges.count(other)) dropped.insert(other);
        if (use_bd) {
          vote(votes, a, b, d, centre);
          vote(votes, b, c, d, centre);
        } else {
          vote(votes, a, b, c, centre);
          vote(votes, a, c, d, centre);
        }
      }
    }
  }
  for (const Pair& e : added) edges.insert(e);
  for (const Pair& e : dropped) edges.erase(e);
  out.edges.assign(edges.begin(), edges.end());
  out.added_edges.assign(added.begin(), added.end());
  out.dropped_edges.assign(dropped.begin(), dropped.end());

  std::vector<Eigen::Vector2d> vertices, defects;
  for (const auto& [t, v] : votes) {
    if (!edges.count({t[0], t[1]}) || !edges.count({t[1], t[2]}) || !edges.count({t[0], t[2]})) {
      ++out.unjoined_triples;
      defects.push_back(v.centre());
      continue;
    }
    const std::array<int, 3>& n = v.count;
    if (n[0] > 0 && n[1] > 0) {
      ++out.orientation_conflicts;
      defects.push_back(v.centre());
    }
    bool sorted_order = n[0] >= n[1];
    if (n[0] == 0 && n[1] == 0)
      sorted_order = orient2d(seeds.col(t[0]), seeds.col(t[1]), seeds.col(t[2])) >= 0;
    out.triangles.push_back(sorted_order ? t : Triple{t[0], t[2], t[1]});
    vertices.push_back(v.centre());
  }
  out.vertices.resize(2, static_cast<Eigen::Index>(vertices.size()));
  for (std::size_t k = 0; k < vertices.size(); ++k) out.vertices.col(k) = vertices[k];
  out.defects.resize(2, static_cast<Eigen::Index>(defects.size()));
  for (std::size_t k = 0; k < defects.size(); ++k) out.defects.col(k) = defects[k];
  return out;
}

}  // namespace homesh
