#pragma once
// Quality measures (quality/measure_registry.h) over every triangle of a mesh:
// values at each element's own nodes (for ElementNodeData views, drawn curved)
// and the minimum over the nodes and a reference lattice (thesis Section 3.6
// shows measures at ~200 points per element; the lattice order is a choice);
// with the certified bounds of det J (quality/mesh_validity.h) in the same pass.
//
// One pass per element: its nodes are gathered once and turned into the Bezier
// control points of J (quality/bezier_jacobian.h); det J's Bernstein
// coefficients (the bounds) and J at every sample point (the measures, through
// W = J inv(J_ri)) both come from those, and W is shared by all measures.
// Elements are processed in parallel (OpenMP), each independently, so results
// do not depend on the thread count.
#include <Eigen/Core>
#include <vector>

#include "core/mesh.h"
#include "quality/element_quality.h"
#include "quality/jacobian_bounds.h"
#include "quality/measure_registry.h"
#include "quality/mesh_validity.h"

namespace homesh {

struct MeshMeasure {
  /// #triangles minimum of the measure over each element's sample points.
  Eigen::VectorXd element_min;
  /// nodes-per-triangle by #triangles values at the element nodes, Gmsh order.
  Eigen::MatrixXd node_values;
};

/// The default sampling lattice order for an order-p mesh: 2p (a multiple of p,
/// so the lattice contains the element nodes).
inline int default_lattice_order(int p) { return 2 * p; }

/// Each measure of `qs` over every triangle of m, sampled at the nodes of the
/// order-`lattice` reference lattice and at the element nodes, with
/// normalisation `ref`. One result per measure, in the order of `qs`.
std::vector<MeshMeasure> mesh_measures(const Mesh& m, const std::vector<const Measure*>& qs,
                                       int lattice, Reference ref);

/// Certified validity and measures of one mesh.
struct MeshQuality {
  MeshValidity validity;              ///< as mesh_validity(m, opt)
  std::vector<MeshMeasure> measures;  ///< as mesh_measures(m, qs, lattice, ref)
};

/// mesh_validity and mesh_measures in one pass over the triangles. With `qs`
/// empty only the bounds are computed (lattice and ref are then unused).
/// `threads` > 0 sets the number of OpenMP threads, 0 keeps OpenMP's current
/// default (which gmsh::initialize sets to Gmsh's General.NumThreads, 1).
MeshQuality mesh_quality(const Mesh& m, const std::vector<const Measure*>& qs, int lattice,
                         Reference ref, const BoundsOptions& opt = {}, int threads = 0);

}  // namespace homesh
