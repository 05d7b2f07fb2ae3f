#pragma once
// Input and output of a crystal-growth Voronoi engine (thesis Chapter 2): the
// seeds, the metric field and the domain on a Cartesian grid in; a label per
// grid node and the pairs of crystals that collided out.
#include <Eigen/Core>
#include <array>
#include <memory>
#include <vector>

#include "voronoi/grid/cartesian_grid.h"
#include "voronoi/metric/metric_field.h"

namespace homesh {

class StencilField;

/// How a crystal meets the domain boundary (Section 2.6).
enum class Contact {
  /// The boundary is a stationary crystal and collides like any other
  /// (Eqs 2.9-2.12): the front freezes where it touches it. The thesis finds
  /// it creates isolated regions (Fig 2.3a).
  wet,
  /// Eq 2.13: in the boundary crystal's first cell (0 < domain <= ds) a
  /// crystal's speed loses the component along the boundary normal,
  /// F~ = max(0, F(N_s) - (N_b . N_s) F(N_b)), so it slides along the
  /// boundary (F as in metric_field.h). N_b is the outward normal of the
  /// domain: the thesis' grad phi_b / |grad phi_b| points into the domain
  /// when phi_b <= 0 is the boundary crystal, and would speed a crystal up
  /// into the boundary; with the outward normal F~ = 0 head-on.
  dry,
};

struct VoronoiProblem {
  CartesianGrid grid;      ///< the fine grid the crystals grow on
  Eigen::Matrix2Xd seeds;  ///< 2 by S, one crystal per column
  MetricField metric = MetricField::constant(Eigen::Matrix2d::Identity());
  /// Optional, S metrics: crystal s grows in the constant metric
  /// seed_metrics[s] (the Labelle-Shewchuk example, Fig 2.4) instead of `metric`.
  std::vector<Eigen::Matrix2d> seed_metrics;
  /// Optional, grid.node_count() values: a signed distance (or level set with
  /// |grad| ~ 1) of the domain at the grid nodes, < 0 inside, > 0 outside.
  /// The fast-marching engine takes |domain| as a lower bound of the distance
  /// to the boundary (a segment whose ends' clearances add up to its length
  /// is inside): a distance capped to a band, or the max/min of distances,
  /// qualify.
  /// Empty: the domain is the whole grid. The boundary crystal of Section 2.6
  /// is {domain >= 0}, i.e. phi_b = -domain, and N_b = grad(domain) / |grad|
  /// is the outward normal of the domain. Walls thinner than 3 cells may let
  /// crystals through.
  Eigen::VectorXd domain;
  Contact contact = Contact::dry;
  /// Optional: the fast-marching engine's stencils, built once for several
  /// growths on the same grid, domain and metric with other seeds (Lloyd's
  /// iteration, refinement rounds: share_stencils in fast_marching_engine.h).
  /// The engine uses them only if built for this problem, else its own.
  std::shared_ptr<const StencilField> stencils;
};

/// Throws homesh::Error unless problem.domain is empty or holds one value
/// per grid node.
void check_domain_size(const VoronoiProblem& problem);

/// Options shared by the engines; an engine ignores those it has no use for.
struct VoronoiOptions {
  /// Smallest semi-axis of the initial seed crystal, a ball of the metric at
  /// the seed, for every seed (the thesis: r_s ~ 2 ds, Section 2.7). 0: per
  /// seed, 0.3 times the metric distance to the nearest other seed, clamped
  /// to smallest semi-axes between 2 ds and 8 ds (more accurate: the scheme
  /// is least accurate while a front is a few cells wide).
  double seed_radius = 0.0;
  /// level_set: time step dt = cfl ds / max F (Section 2.3 needs cfl <= 1).
  /// 0: 1 in an isotropic metric field, 1/2 otherwise.
  double cfl = 0.0;
  /// level_set: cells kept around each crystal's bounding box and its front.
  int band = 5;
  /// Stop after this many steps even if not settled; 0 = automatic.
  int max_steps = 0;
  /// Stop at this time (metric length grown) even if not settled; 0 = never.
  double stop_time = 0.0;
};

/// The partition of the grid into crystals.
struct CrystalPartition {
  /// grid.node_count(): the crystal holding each node, or -1 for nodes outside
  /// the domain or reached by no crystal. Once settled, a node left in a gap
  /// between frozen fronts takes the crystal of the nearest front.
  Eigen::VectorXi labels;
  /// Pairs {s, k}, s < k, of crystals that collided (Eq 2.10), sorted.
  std::vector<std::array<int, 2>> collisions;
  /// Crystals that reached the domain boundary, sorted.
  std::vector<int> boundary_contacts;
  /// Domain nodes inside no crystal at the end: gaps left between frozen
  /// fronts (labelled from their neighbours once settled) or not reached.
  int uncovered = 0;
  int steps = 0;
  double time = 0.0;     ///< final time (metric length grown)
  bool settled = false;  ///< false if stopped by max_steps or stop_time
};

}  // namespace homesh
