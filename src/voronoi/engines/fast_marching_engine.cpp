#include "voronoi/engines/fast_marching_engine.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/error.h"
#include "voronoi/engines/crystal_entries.h"
#include "voronoi/engines/label_contacts.h"
#include "voronoi/engines/morton_order.h"
#include "voronoi/engines/stencil_field.h"
#include "voronoi/engines/time_heap.h"

namespace homesh {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Smallest semi-axis, in cells, of the block of exact times round a seed.
constexpr double kSeedBlockCells = 3.0;
// In a varying metric field a time is measured straight from a source (the
// metric taken as the mean of the two ends') within this many cells, and
// farther where the metric is the same at both ends and at the middle, to a
// relative difference of kSameMetric cells over the segment's length in cells
// (a time error of about kSameMetric / 2 cells).
constexpr double kTrustCells = 8.0;
constexpr double kSameMetric = 0.2;
// The sweep's schedule (class Sweep): slabs per window, and grid nodes per
// block of crystals (about their area; their entries then fit a core's
// cache, ~1 MB).
constexpr int kWindowSlabs = 4;
constexpr long kBlockNodes = 20000;

using Entry = CrystalEntry;

// The sweep. Each crystal's entries are accepted in increasing time from its
// own heap, and a crystal's times depend on its own entries only; crystals
// meet only through the winner of each node, the accepted entry of least
// time so far. So the crystals need not take turns entry by entry: the sweep
// goes through time in slabs one cell's crossing time wide and, within a
// slab, grows the crystals one after the other, in the Morton order of their
// seeds (neighbouring crystals in turn: their fronts share cache lines).
// Blocks of crystals consecutive in that order, about kBlockNodes nodes in
// all, go through a window of kWindowSlabs slabs before the next block
// starts, so that a block's entries stay in cache from slab to slab.
// Where two crystals reach a node in the same slab (or, across the border of
// two blocks, in the same window), the one grown first may win it for a while
// and spread from it before the other takes it with a smaller time: at most a
// window of extra growth past an interface, which only adds entries of that
// crystal (about 2 % more steps with 1e5 seeds on 2000 x 2000). Along the
// geodesic from its seed to a node of its region, a crystal holds the least
// time at every node, so it wins each at acceptance and reaches the node, as
// in one heap of all crystals: the labels are those of exact time order
// (ties go to the crystal first in that order).
//
// Inside the sweep the crystals are numbered in that order (crystal c is
// seed original[c]): their heaps and the entries of their seed blocks then
// lie in memory in the order they are visited.
class Sweep {
 public:
  Sweep(const StencilField& field, const Eigen::Matrix2Xd& seeds,
        const std::vector<Eigen::Matrix2d>& M, std::vector<int> original)
      : field_(field),
        original_(std::move(original)),
        seeds_(2, seeds.cols()),
        seed_grid_(2, seeds.cols()),
        seed_metric_(M.size()),
        seed_stencil_(M.size()),
        seed_clearance_(M.size()),
        entries_(field.grid().node_count()),
        queue_(seeds.cols()),
        slab_(slab_width(field.grid(), M)),
        block_(std::max<long>(1, kBlockNodes * seeds.cols() / field.grid().node_count())) {
    for (int c = 0; c < seeds.cols(); ++c) {
      const CartesianGrid& g = field.grid();
      seeds_.col(c) = seeds.col(original_[c]);
      seed_grid_.col(c) = (seeds_.col(c) - g.origin).cwiseQuotient(Eigen::Vector2d(g.dx, g.dy));
      seed_metric_[c] = M[original_[c]];
      seed_stencil_[c] = lattice_stencil(M[original_[c]], g.dx, g.dy);
      seed_clearance_[c] = -field.domain_at(seeds_.col(c));
    }
  }

  // Exact times |x - p_s|_{M_s} on the nodes of the metric ball of smallest
  // semi-axis `cells` cells round the seed of crystal s that see the seed
  // through the domain, but for those an earlier block already reaches in
  // less time (with dense seeds the balls overlap: the crystal would only lose
  // them). Returns the number of nodes of the ball that see the seed.
  int seed_block(int s, double cells) {
    const CartesianGrid& g = field_.grid();
    const Eigen::Vector2d p = seeds_.col(s);
    const Eigen::Matrix2d& M = seed_metric_[s];
    const Eigen::Matrix2d Minv = M.inverse();
    const double R = cells * g.ds() / metric_min_speed(M);
    const double hx = R * std::sqrt(Minv(0, 0)), hy = R * std::sqrt(Minv(1, 1));
    const auto lo = [](double v) { return static_cast<int>(std::floor(v)); };
    const auto up = [](double v) { return static_cast<int>(std::ceil(v)); };
    const int i0 = std::max(0, lo((p.x() - hx - g.origin.x()) / g.dx));
    const int i1 = std::min(g.nx - 1, up((p.x() + hx - g.origin.x()) / g.dx));
    const int j0 = std::max(0, lo((p.y() - hy - g.origin.y()) / g.dy));
    const int j1 = std::min(g.ny - 1, up((p.y() + hy - g.origin.y()) / g.dy));
    int placed = 0;
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) {
        const int x = g.index(i, j);
        const Eigen::Vector2d v = g.point(i, j) - p;
        const double t = std::sqrt(v.dot(M * v));
        if (t > R || !field_.inside(x) ||
            !field_.segment_clear(p, seed_clearance_[s], g.point(i, j), field_.clearance(x),
                                  v.norm()))
          continue;
        ++placed;
        if (entries_.any_below(x, t)) continue;
        const int e = entries_.add(x, s);
        entries_[e].set_hop(0);
        lower(e, t, -1 - s, 0.0);
      }
    return placed;
  }

  // Accepts every crystal's entries in increasing time up to `stop`, window
  // by window, block by block, slab by slab; false if stopped early (at
  // `stop`, or after max_steps entries).
  bool run(double stop, long max_steps) {
    std::vector<int> active;
    double first = kInf;
    for (int c = 0; c < static_cast<int>(queue_.size()); ++c)
      if (!queue_[c].empty()) {
        active.push_back(c);
        first = std::min(first, queue_[c].top().first);
      }
    while (!active.empty()) {
      if (first > stop) return false;
      const double last = std::min(first + kWindowSlabs * slab_, std::nextafter(stop, kInf));
      for (std::size_t b = 0; b < active.size();) {
        std::size_t b1 = b;
        while (b1 < active.size() && active[b1] / block_ == active[b] / block_) ++b1;
        for (double end = first + slab_;; end += slab_) {
          end = std::min(end, last);
          for (std::size_t k = b; k < b1; ++k)
            if (!grow(queue_[active[k]], end, max_steps)) return false;
          if (end >= last) break;
        }
        b = b1;
      }
      first = kInf;
      std::size_t kept = 0;
      for (const int c : active) {
        TimeHeap& heap = queue_[c];
        if (heap.empty()) {
          heap.release();
          continue;
        }
        first = std::min(first, heap.top().first);
        active[kept++] = c;
      }
      active.resize(kept);
    }
    return true;
  }

  // Nodes the hexagons never reach (at the grid corners, where every offset
  // into the grid is too long): a Dijkstra over the 8 neighbours from the
  // labelled nodes, each step costing its length in the metric of the
  // crystal taking it.
  void fill_unreached() {
    const CartesianGrid& g = field_.grid();
    TimeHeap heap;
    const auto offer = [&](int x) {
      const int i = x % g.nx, j = x / g.nx;
      const int from = entries_.winner(x);
      const double from_time = time(x);
      for (int dj = -1; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di) {
          const int a = i + di, b = j + dj;
          if ((di == 0 && dj == 0) || a < 0 || b < 0 || a >= g.nx || b >= g.ny) continue;
          const int z = g.index(a, b);
          if (entries_.winner(z) >= 0 || !field_.inside(z)) continue;
          const double t =
              from_time +
              std::sqrt(field_.stencil(original_[from], z).norm2(Eigen::Vector2d(di, dj)));
          int e = entries_.find(z, from);
          if (e < 0) e = entries_.add(z, from);
          if (assign(e, t, z, t)) heap.push({t, e});
        }
    };
    bool missing = false;
    for (int x = 0; x < g.node_count() && !missing; ++x)
      missing = entries_.winner(x) < 0 && field_.inside(x);
    if (!missing) return;
    for (int x = 0; x < g.node_count(); ++x)
      if (entries_.winner(x) >= 0) offer(x);
    while (!heap.empty()) {
      const auto [t, e] = heap.top();
      heap.pop();
      Entry& en = entries_[e];
      const int x = entries_.node(e);
      if (en.accepted() || en.time != t || entries_.winner(x) >= 0) continue;
      en.accept();
      en.set_hop(0);
      entries_.winner(x) = en.label();
      offer(x);
    }
  }

  long steps() const { return steps_; }

  // Slabs of the time a front takes to cross a cell at the seeds' largest
  // speed: about one layer of each front per slab.
  static double slab_width(const CartesianGrid& g, const std::vector<Eigen::Matrix2d>& M) {
    double fastest = 0.0;
    for (const Eigen::Matrix2d& m : M) fastest = std::max(fastest, metric_max_speed(m));
    return g.ds() / fastest;
  }

  /// The seed whose crystal holds node x (-1: none) and its time there.
  int label(int x) const {
    const int c = entries_.winner(x);
    return c < 0 ? -1 : original_[c];
  }
  double time(int x) const {
    const int c = entries_.winner(x);
    return c < 0 ? kInf : entries_[entries_.find(x, c)].time;
  }

 private:
  // Accepts the entries of one crystal's heap below time `end`; false once
  // max_steps entries are accepted.
  bool grow(TimeHeap& heap, double end, long max_steps) {
    while (!heap.empty() && heap.top().first < end) {
      const auto [t, e] = heap.top();
      heap.pop();
      // The next entry to accept, most likely: its cache line loads while
      // this one spreads.
      if (!heap.empty()) __builtin_prefetch(&entries_[heap.top().second]);
      Entry& en = entries_[e];
      if (en.accepted() || en.time != t) continue;
      if (max_steps > 0 && steps_ >= max_steps) return false;
      en.accept();
      ++steps_;
      const int x = entries_.node(e);
      // The node's winner so far, if any, holds an accepted (final) entry.
      const int w = entries_.winner(x);
      const double held = w < 0 ? kInf : time(x);
      if (w < 0 || t < held || (t == held && en.label() < w)) {
        entries_.winner(x) = en.label();
        en.set_hop(0);
      }
      if (en.hop() < kOwnTimeBand) (this->*spread_)(e);
    }
    return true;
  }
  // Lowers entry e's time to t (measured from `source`); whether it did.
  bool assign(int e, double t, int source, double source_time) {
    Entry& en = entries_[e];
    if (t >= en.time) return false;
    en.time = t;
    en.source = source;
    en.source_time = source_time;
    return true;
  }
  void lower(int e, double t, int source, double source_time) {
    if (assign(e, t, source, source_time)) queue_[entries_[e].label()].push({t, e});
  }
  // The stencil of crystal s at node x.
  template <bool kVarying>
  const LatticeStencil& stencil(int s, int x) const {
    return kVarying ? field_.node_stencil(x) : field_.crystal_stencil(original_[s]);
  }
  // The time of crystal s at node x = (ix, jx), of stencil st, measured
  // straight from `source` (a node, or -1 - c for the seed of crystal c)
  // reached at source_time: that time plus the length of the segment in the
  // crystal's metric (in a varying field, the mean of the metrics at its
  // ends, within kTrustCells cells or where the metric is the same along it,
  // else +infinity). Lengths in grid units through the stencils' Gram values.
  // Whether the segment stays in the domain is sees(), apart: only a time
  // that would win is worth its test.
  template <bool kVarying>
  double from_source(int s, int ix, int jx, const LatticeStencil& st, int source,
                     double source_time) const {
    const CartesianGrid& g = field_.grid();
    const Eigen::Vector2d from = source_point(source);
    const Eigen::Vector2d v = Eigen::Vector2d(ix, jx) - from;
    double length2 = st.norm2(v);
    if constexpr (kVarying) {
      const LatticeStencil& so = source < 0 ? seed_stencil_[s] : field_.node_stencil(source);
      const double other2 = so.norm2(v);
      const double euclid2 = v.x() * v.x() * g.dx * g.dx + v.y() * v.y() * g.dy * g.dy;
      if (euclid2 > trust2_) {
        const double tolerance = kSameMetric * g.ds() / std::sqrt(euclid2) * length2;
        const Eigen::Vector2d m = from + 0.5 * v;
        const int mid = g.index(static_cast<int>(m.x() + 0.5), static_cast<int>(m.y() + 0.5));
        if (std::abs(other2 - length2) > tolerance ||
            std::abs(field_.node_stencil(mid).norm2(v) - length2) > tolerance)
          return kInf;
      }
      length2 = 0.5 * (length2 + other2);
    }
    return source_time + std::sqrt(length2);
  }
  // A source's position in grid units from the origin.
  Eigen::Vector2d source_point(int source) const {
    const int nx = field_.grid().nx;
    return source < 0 ? Eigen::Vector2d(seed_grid_.col(-1 - source))
                      : Eigen::Vector2d(source % nx, source / nx);
  }
  // Whether the segment from `source` to node x = (ix, jx) stays in the
  // domain.
  bool sees(int x, int ix, int jx, int source) const {
    const CartesianGrid& g = field_.grid();
    const bool seed = source < 0;
    const Eigen::Vector2d from = source_point(source);
    const Eigen::Vector2d p = seed
                                  ? Eigen::Vector2d(seeds_.col(-1 - source))
                                  : g.point(static_cast<int>(from.x()), static_cast<int>(from.y()));
    const double clear = seed ? seed_clearance_[-1 - source] : field_.clearance(source);
    const Eigen::Vector2d q = g.point(ix, jx);
    return field_.segment_clear(p, clear, q, field_.clearance(x), (q - p).norm());
  }
  // The accepted entry of crystal s at node x = (ix, jx) + o, if it is a node
  // the update from x may use, else -1.
  template <bool kDomain>
  int upwind(int s, int x, int ix, int jx, const LatticeStencil& st, int k) const {
    const CartesianGrid& g = field_.grid();
    const Eigen::Vector2i o = st.offset(k);
    const int i = ix + o.x(), j = jx + o.y();
    if (static_cast<unsigned>(i) >= static_cast<unsigned>(g.nx) ||
        static_cast<unsigned>(j) >= static_cast<unsigned>(g.ny))
      return -1;
    const int z = g.index(i, j);
    const int e = entries_.find(z, s);
    if (e < 0 || !entries_[e].accepted()) return -1;
    if constexpr (kDomain)
      if (!field_.passable_step(original_[s], x, k)) return -1;
    return e;
  }
  // Entry e (crystal s at node y) was accepted: update the nodes whose
  // stencil holds y, from the one-sided step and the two sectors next to it
  // (Hopf-Lax), and from the sources of the entries used; the time measured
  // from a source wins if not larger, else x becomes a source itself.
  // Shortcuts with the same result, since a crystal accepts its entries in
  // increasing time and every update of x from y is at least y's time a:
  // the time from the source x already holds is skipped (it gave at most x's
  // time, and a new one could only be max(that, a), not less), and so is a
  // source met twice. Also skipped, a little apart from the result in a
  // metric field: an entry that is its own source (one stencil step away,
  // an end of the Hopf-Lax segment, the one-sided update already). In a
  // metric constant per crystal without a domain (kStraight) every source is
  // the seed and every time the exact |x - p|_M, which the Hopf-Lax update
  // never undercuts (the linear interpolation of a convex function
  // overestimates it): the update is that time, computed once per entry.
  // One instance per kind of problem (a metric field or not, a domain or
  // not), without the tests the others need.
  template <bool kVarying, bool kDomain>
  void spread(int e) {
    constexpr bool kStraight = !kVarying && !kDomain;
    static constexpr int kPrev[6] = {5, 0, 1, 2, 3, 4}, kNext[6] = {1, 2, 3, 4, 5, 0};
    const CartesianGrid& g = field_.grid();
    // Copies: adding entries below may move entry e.
    const int s = entries_[e].label(), y = entries_.node(e);
    const double a = entries_[e].time;
    const int hop = entries_[e].hop() + 1;
    const int e_source = entries_[e].source;
    const double e_source_time = entries_[e].source_time;
    field_.for_each_reverse(original_[s], y, [&](int x, int k) {
      if constexpr (kDomain)
        if (!field_.inside(x)) return;
      const int w = entries_.winner(x);
      if (w >= 0 && (w == s || hop > kOwnTimeBand)) return;
      int target = entries_.find(x, s);
      if (target >= 0 && entries_[target].accepted()) return;
      if constexpr (kDomain)
        if (!field_.passable_step(original_[s], x, k)) return;
      if (target < 0) target = entries_.add(x, s);
      Entry& to = entries_[target];  // no entry is added below
      to.set_hop(std::min(to.hop(), hop));
      const int ix = x % g.nx, jx = x / g.nx;
      if constexpr (kStraight) {
        if (to.time < kInf) return;
        const Eigen::Vector2d v = Eigen::Vector2d(ix, jx) - seed_grid_.col(s);
        lower(target, std::max(std::sqrt(seed_stencil_[s].norm2(v)), a), -1 - s, 0.0);
        return;
      }
      const LatticeStencil& st = stencil<kVarying>(s, x);
      const int kp = kPrev[k], kn = kNext[k];
      double t = a + st.length(k);
      const int before = upwind<kDomain>(s, x, ix, jx, st, kp);
      if (before >= 0) t = std::min(t, hopf_lax(st.sector(kp), entries_[before].time, a));
      const int after = upwind<kDomain>(s, x, ix, jx, st, kn);
      if (after >= 0) t = std::min(t, hopf_lax(st.sector(k), a, entries_[after].time));
      int source = x;
      double source_time = t, best = kInf;
      // (In a varying field a seed block's time, in the seed's metric, is not
      // from_source's, in the mean of the two ends' metrics: not skipped.)
      const int known = kVarying && to.source < 0 ? x : to.source;
      // The least time from a source seeing x, if not above t: else the
      // time is t. Sources at x's time or later are skipped (with t, as
      // large, they would not lower it), and so is the domain test of one
      // that would not win.
      const double held = to.time;
      const auto consider = [&](int from, double from_time) {
        if (from == known) return;
        const double ts = from_source<kVarying>(s, ix, jx, st, from, from_time);
        if (ts < best && ts <= t && ts < held && (!kDomain || sees(x, ix, jx, from)))
          best = ts, source = from, source_time = from_time;
      };
      if (e_source != y) consider(e_source, e_source_time);
      const int before_source = before >= 0 ? entries_[before].source : e_source;
      if (before_source != e_source && before_source != entries_.node(before))
        consider(before_source, entries_[before].source_time);
      if (after >= 0) {
        const int after_source = entries_[after].source;
        if (after_source != e_source && after_source != before_source &&
            after_source != entries_.node(after))
          consider(after_source, entries_[after].source_time);
      }
      if (best <= t)
        t = std::max(best, a);
      else
        source = x, source_time = t;
      lower(target, t, source, source_time);
    });
  }
  using Spread = void (Sweep::*)(int);
  static Spread spread_for(const StencilField& field) {
    if (field.varying())
      return field.has_domain() ? &Sweep::spread<true, true> : &Sweep::spread<true, false>;
    return field.has_domain() ? &Sweep::spread<false, true> : &Sweep::spread<false, false>;
  }

  const StencilField& field_;
  const Spread spread_ = spread_for(field_);
  const double trust2_ = std::pow(kTrustCells * field_.grid().ds(), 2);
  std::vector<int> original_;
  Eigen::Matrix2Xd seeds_;      ///< in the sweep's order, as the next five
  Eigen::Matrix2Xd seed_grid_;  ///< in grid units from the origin
  std::vector<Eigen::Matrix2d> seed_metric_;
  std::vector<LatticeStencil> seed_stencil_;  ///< the seed metric's, for its Gram matrix
  std::vector<double> seed_clearance_;        ///< minus the domain's level set at the seed
  // Per node, its crystals' entries and the winner (its time: the winner's
  // accepted entry's).
  CrystalEntries entries_;
  std::vector<TimeHeap> queue_;  ///< per crystal, its pending entries
  double slab_;
  long block_;  ///< crystals per block
  long steps_ = 0;
};

}  // namespace

CrystalPartition grow_crystals_fast_marching(const VoronoiProblem& problem,
                                             const VoronoiOptions& options) {
  const CartesianGrid& g = problem.grid;
  const int S = static_cast<int>(problem.seeds.cols());
  if (S == 0) throw Error("voronoi: no seeds");
  if (S > CrystalEntry::kMaxCrystals)
    throw Error("voronoi: " + std::to_string(S) + " seeds, more than the fast_marching engine's " +
                std::to_string(CrystalEntry::kMaxCrystals));
  if (problem.contact == Contact::wet)
    throw Error("voronoi: the fast_marching engine meets the boundary dry only (use level_set)");
  std::optional<StencilField> own;
  if (!(problem.stencils && problem.stencils->built_for(problem))) own.emplace(problem);
  const StencilField& field = own ? *own : *problem.stencils;
  std::vector<Eigen::Matrix2d> M(S);
  for (int s = 0; s < S; ++s) {
    const Eigen::Vector2d p = problem.seeds.col(s);
    const Eigen::Vector2d rel = p - g.origin;
    if (!(rel.x() >= 0 && rel.y() >= 0 && rel.x() <= (g.nx - 1) * g.dx &&
          rel.y() <= (g.ny - 1) * g.dy))
      throw Error("voronoi: seed " + std::to_string(s) + " lies outside the grid");
    if (field.domain_at(p) > g.ds())
      throw Error("voronoi: seed " + std::to_string(s) + " lies outside the domain");
    M[s] = field.metric(s, p);
  }
  const std::vector<int> order = morton_order(g, problem.seeds);
  Sweep sweep(field, problem.seeds, M, order);
  const double cells = options.seed_radius > 0.0 ? options.seed_radius / g.ds() : kSeedBlockCells;
  for (int c = 0; c < S; ++c)
    if (sweep.seed_block(c, cells) == 0)
      throw Error("voronoi: seed " + std::to_string(order[c]) + " sees no grid node of the domain");
  const double stop = options.stop_time > 0.0 ? options.stop_time : kInf;
  CrystalPartition out;
  out.settled = sweep.run(stop, options.max_steps);
  if (out.settled) sweep.fill_unreached();
  out.steps = static_cast<int>(std::min<long>(sweep.steps(), std::numeric_limits<int>::max()));
  out.labels = Eigen::VectorXi::Constant(g.node_count(), -1);
  for (int x = 0; x < g.node_count(); ++x) {
    if (sweep.label(x) < 0) {
      out.uncovered += field.inside(x);
      continue;
    }
    out.labels(x) = sweep.label(x);
    out.time = std::max(out.time, sweep.time(x));
  }
  LabelContacts contacts = label_contacts(field, out.labels, S);
  out.collisions = std::move(contacts.collisions);
  out.boundary_contacts = std::move(contacts.boundary_contacts);
  return out;
}

void share_stencils(VoronoiProblem& problem, const std::string& engine) {
  if (engine != "fast_marching" || (problem.stencils && problem.stencils->built_for(problem)))
    return;
  problem.stencils = std::make_shared<const StencilField>(problem);
}

}  // namespace homesh
