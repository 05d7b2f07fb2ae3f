#pragma once
// Lloyd's iteration on exact cells: each free seed moves to the centroid of
// its Euclidean Voronoi cell (CGAL's Delaunay dual, no grid), weighted as
// region_centroids weights a grown region (lloyd_relaxation.h),
//
//   z = (int_cell W)^-1 int_cell W x,  W(x) = sqrt(det M(x)) M(x),
//
// which for an isotropic metric M = I / h^2 is the density rho = h^-4 of the
// centroidal Voronoi tessellation whose cells have diameters ~ h (Du, Faber,
// Gunzburger, SIAM Review 41(4), 1999, Section 2.3: rho ~ h^-(d+2)). Where
// the metric is isotropic, the metric's regions and the Euclidean cells
// differ only by the size's variation across a cell, so one Delaunay
// triangulation per step replaces a growth of the crystals on a grid (the
// issue's "exact centroidal step where the metric is constant"); the
// crystals are grown once, after it, for the dual. Each cell is integrated
// as the fan of triangles from its seed, by the three-point edge-midpoint
// rule (exact for quadratics).
#include <Eigen/Core>
#include <functional>
#include <vector>

#include "voronoi/metric/metric_field.h"
#include "voronoi/seeding/lloyd_relaxation.h"

namespace homesh {

/// Seeds 0..fixed-1 stay, and so does every seed s with held[s] != 0 (held
/// empty or one flag per seed); the others move to the centroids above,
/// options.iterations times (kExactIterations for kAutoIterations; Jacobi:
/// every centroid from the same seeds), or until no seed moves by more than
/// 1e-3 of its size. domain(x) < 0 inside the domain. A seed whose cell is
/// unbounded stays that step; a cell with a vertex outside the domain is
/// integrated over its inside only (its fan triangles split in 36, their
/// centroids tested). A centroid is taken only if it lies
/// options.exact_clearance sizes (the metric's smallest semi-axis there)
/// inside the domain and from every Delaunay neighbour.
Eigen::Matrix2Xd exact_lloyd(Eigen::Matrix2Xd seeds, int fixed, const MetricField& metric,
                             const std::function<double(const Eigen::Vector2d&)>& domain,
                             const LloydOptions& options = {}, const std::vector<char>& held = {});

}  // namespace homesh
