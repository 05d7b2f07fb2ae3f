#pragma once
// The fast engine (thesis Section 2.8's suggestion): all crystals grow in one
// event-driven sweep, an anisotropic fast marching of the arrival times of
// all seeds at once (Sethian's fast marching with Mirebeau's FM-LBR stencils,
// voronoi/engines/lattice_stencil.h). Cost O(N log N) in the grid nodes N, whatever
// the number of seeds. Each crystal accepts its times in increasing order
// from its own heap; the crystals take turns in time slabs one cell's
// crossing wide, in the spatial (Morton) order of their seeds, so that
// consecutive steps touch neighbouring memory (fast_marching_engine.cpp).
//
// Each crystal keeps its own arrival time at the nodes where crystals meet:
// a node takes the label of the first crystal to arrive, but the others go on
// computing their own times there, a band of kOwnTimeBand stencil steps into
// the neighbouring regions, so that the times compared at an interface are
// each computed from their own crystal's values only (copying the label of
// the upwind neighbour instead leaks labels along grid lines where a front
// runs nearly parallel to an interface).
//
// Source tracking: each arrival time also carries the point it is measured
// from, first the seed. A node's time is the smaller of the Hopf-Lax update
// and the time measured straight from the sources of the upwind values used,
// source time + |x - source|_M, provided the segment stays in the domain;
// where the Hopf-Lax update is smaller (behind an obstacle, or where the
// metric bends the geodesics) the node becomes a source itself. In a
// constant metric this is exact wherever the seed is visible (the vector
// distance transforms of Danielsson 1980 and Mullikin 1992 do the same for
// the Euclidean distance); the first-order update alone shifts interfaces by
// up to a few cells where two fronts meet nearly parallel (measured at 1:10
// anisotropy: 0.5 % of the nodes mislabelled, up to 6 cells from the exact
// interface). In a varying metric field a source is trusted within
// kTrustCells cells, and beyond where the metric is the same at both ends and
// at the middle of the segment (so a field that is constant in a region is
// exact there too; a test holds the full update to the exact diagram at 1:1,
// 1:10 and 1:100, as the constant-metric shortcut). Around each seed the times are exact in the
// metric ball of smallest semi-axis 3 ds (or VoronoiOptions::seed_radius).
//
// Differences from the level-set engine: a metric field enters as the
// Riemannian metric M(x) = Shepard average of the corner tensors
// (MetricField::metric_at) rather than as the Shepard average of the corner
// speeds; the domain boundary is met dry in the sense of a geodesic distance:
// paths stay inside the domain (domain <= 0) and slide along the boundary.
// Wet contact is not modelled.
#include "voronoi/engines/voronoi_problem.h"

namespace homesh {

/// Stencil steps a crystal's own arrival time reaches past its region.
constexpr int kOwnTimeBand = 1;

/// Labels: the crystal of least arrival time at each domain node (-1 outside
/// the domain or unreachable). Collisions: pairs of labels met across a grid
/// edge. boundary_contacts: crystals holding a node next to the outside
/// (with a domain). steps: arrival times accepted; time: the largest label
/// time. With options.stop_time > 0 the sweep stops there (settled = false
/// if nodes are left). Throws homesh::Error for no seeds, a seed outside the grid, a
/// seed that sees no domain node, wet contact, or seed_metrics of the wrong
/// count.
CrystalPartition grow_crystals_fast_marching(const VoronoiProblem& problem,
                                             const VoronoiOptions& options);

/// For several growths of `problem` with other seeds by `engine`: if it is
/// fast_marching, its stencils built once into problem.stencils (unless
/// already built for it). Building them is a sweep of the grid with a
/// lattice basis reduction at every node, 9 % of the voronoi stage when
/// Lloyd's iteration rebuilt them at every step.
void share_stencils(VoronoiProblem& problem, const std::string& engine);

}  // namespace homesh
