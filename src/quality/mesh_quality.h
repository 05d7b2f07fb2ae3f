#pragma once
// Quality measures (quality/measure_registry.h) over every triangle and
// quadrilateral of a mesh (the 2D elements, numbered as in core/mesh.h):
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
  /// #2D elements minimum of the measure over each element's sample points.
  Eigen::VectorXd element_min;
  /// nodes-per-element by #2D elements values at the element nodes, Gmsh
  /// order; with quadrilaterals (p+1)^2 rows, a triangle's values in the top
  /// (p+1)(p+2)/2, NaN below (core/field.h).
  Eigen::MatrixXd node_values;
};

/// The default sampling lattice order for an order-p mesh: 2p (a multiple of p,
/// so the lattice contains the element nodes).
inline int default_lattice_order(int p) { return 2 * p; }

/// Each measure of `qs` over every triangle and quadrilateral of m, sampled at
/// the nodes of the order-`lattice` reference lattice (of the triangle, or of
/// the square: (lattice+1)^2 points) and at the element nodes, with
/// normalisation `ref`. One result per measure, in the order of `qs`. On a
/// quadrilateral the ideal element is the unit square: W = J on the reference
/// square [0, 1]^2 (README, "Quality measures").
std::vector<MeshMeasure> mesh_measures(const Mesh& m, const std::vector<const Measure*>& qs,
                                       int lattice, Reference ref);

/// Certified validity and measures of one mesh.
struct MeshQuality {
  MeshValidity validity;              ///< as mesh_validity(m, opt)
  std::vector<MeshMeasure> measures;  ///< as mesh_measures(m, qs, lattice, ref)
};

/// mesh_validity and mesh_measures in one pass over the 2D elements. With `qs`
/// empty only the bounds are computed (lattice and ref are then unused).
/// `threads` > 0 sets the number of OpenMP threads, 0 keeps OpenMP's current
/// default (which gmsh::initialize sets to Gmsh's General.NumThreads, 1).
MeshQuality mesh_quality(const Mesh& m, const std::vector<const Measure*>& qs, int lattice,
                         Reference ref, const BoundsOptions& opt = {}, int threads = 0);

/// mesh_validity(m, opt) with the bounds of every element none of whose nodes
/// moved (moved: #nodes) copied from `known`, a validity by the same options of
/// a mesh with m's elements (mesh_validity.h's overload checks that).
MeshValidity moved_elements_validity(const Mesh& m, const std::vector<char>& moved,
                                     const MeshValidity& known, const BoundsOptions& opt);

}  // namespace homesh
