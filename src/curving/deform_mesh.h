#pragma once
// Mesh deformation by the augmented elastic analogy (thesis Section 4.2): the
// prescribed nodes move to their targets in load increments; at each increment
// the interior follows the solution of the elasticity problem posed on the
// current (already deformed) mesh, with the coefficients of the chosen
// formulation re-evaluated on it. Validity is certified after every increment
// (Bezier bounds of det J); an increment that would break it is halved, and
// once a step below the first increment / 2^max_halvings would be needed the
// deformation gives up and returns the last valid state; after an accepted
// increment the step doubles again, up to its initial size. The stiffness
// changes with the mesh at every accepted increment (it is posed on the
// deformed mesh), so each one is assembled and factorised anew on the same
// pattern and symbolic analysis; a halved increment re-solves with the factor
// it already has.
//
// Meshes of triangles, quadrilaterals or both: elements are named by their 2D
// index (triangles 0..T-1, then quadrilaterals T..T+Q-1, core/mesh.h) in
// regions and counts.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/mesh.h"
#include "curving/analogy_formulation.h"
#include "fem/linear_solver.h"
#include "quality/mesh_validity.h"

namespace homesh {

// The defaults are the curve stage's (measured on the boundary-layer meshes of
// scripts/bench/curving_vs_gmsh.py, plate and NACA-7526, first cell 1e-3 and
// 1e-4, p = 2-4: worst minJ/maxJ 0.96-0.99, against 0.89-0.95 for the thesis'
// E = 1, nu = 0.4; scripts/bench/README.md): E = 1/Ae ("area"), nearly
// incompressible, one increment, solved within 2 wall-triangle sizes. A nearly
// incompressible material keeps the thin layer elements' areas, so the wall's
// curvature is carried up through the layers instead of squashing the first
// one; 1/Ae makes the small elements stiff as well.
struct DeformOptions {
  std::string formulation = "area";  ///< a name of analogy_formulations()
  FormulationParams params = [] {    // nu = 0.49, the other parameters as FormulationParams
    FormulationParams p;
    p.poisson = 0.49;
    return p;
  }();
  LinearSolverOptions solver;
  int increments = 1;    ///< equal load increments from start to target
  int max_halvings = 6;  ///< smallest step: the first increment / 2^max_halvings
  /// 0: no effect. k > 0: solve only on the elements within k element layers of
  /// the moving nodes (prescribed nodes whose target differs from their
  /// position), the rest held still, as Gmsh's Mesh.HighOrderNumLayers; cheaper
  /// on large meshes, the result differs. Replaces `reach`.
  int layers = 0;
  /// 0: the elasticity is solved on the whole mesh. r > 0: only on the
  /// elements with a vertex within r h_t of the corner centroid of some
  /// element t with a moving node, h_t its longest edge, the rest held still. The
  /// displacement of a curved wall edge decays over about one edge length into
  /// the mesh (Saint-Venant), whatever the number of thin layer elements
  /// stacked there, so unlike `layers` the region does not shrink to a sliver
  /// in a boundary layer. Ignored when layers > 0.
  double reach = 2;
  /// Non-empty: solve only on these 2D elements (ascending; triangles 0..T-1,
  /// then quadrilaterals T..T+Q-1), the rest held still but for the prescribed
  /// nodes in none of them, which go straight to their targets; replaces
  /// layers and reach.
  std::vector<int> region;
};

struct DeformResult {
  Mesh mesh;                   ///< the last certified-valid state
  double reached = 0;          ///< fraction of the prescribed motion applied, in [0, 1]
  bool complete = false;       ///< reached == 1 with every element certified valid
  int solves = 0;              ///< elasticity solves (including rejected increments)
  int iterations = 0;          ///< total CG iterations (0 for direct solvers)
  double worst_ratio = 1;      ///< worst certified minJ/maxJ of the result
  int invalid_at_failure = 0;  ///< invalid elements of the first rejected state, if it failed
  /// 2D elements (triangles and quadrilaterals) the elasticity was posed on
  /// (layers, reach, region); the name predates quadrilaterals.
  int solved_triangles = 0;
  /// The certified validity of `mesh` (default bounds); empty (no ratios) if no
  /// increment was accepted.
  MeshValidity validity;
};

/// Deforms m so that each node i with prescribed[i] moves from m.x.col(i) to
/// target.col(i); other nodes follow the elastic analogy. m (triangles,
/// quadrilaterals or both) must be valid. Throws homesh::Error on bad
/// arguments (sizes, increments < 1, a region element out of range, unknown
/// formulation) or a failed solve.
DeformResult deform_mesh(const Mesh& m, const Eigen::Matrix2Xd& target,
                         const std::vector<bool>& prescribed, const DeformOptions& opt = {});

/// As above, given `known`: a mesh with m's elements and its validity by the
/// default bounds, from which a solve on a region reuses the bounds of the
/// elements it leaves where they are in it (a speed-up only: the same result).
DeformResult deform_mesh(const Mesh& m, const Eigen::Matrix2Xd& target,
                         const std::vector<bool>& prescribed, const DeformOptions& opt,
                         const KnownValidity& known);

/// The 2D elements within `layers` >= 1 element layers of the nodes with
/// moving[i]: layer 1 holds every element with a moving node, layer k + 1
/// adds those sharing a node with layer k. Ascending 2D element indices
/// (triangles, then quadrilaterals).
std::vector<int> moving_region(const Mesh& m, const std::vector<bool>& moving, int layers);

/// The 2D elements with a vertex (corner) within reach * h_t of the corner
/// centroid of some element t with a node where moving[i], h_t the longest
/// corner-to-corner edge of t. Ascending 2D element indices (triangles, then
/// quadrilaterals).
std::vector<int> reach_region(const Mesh& m, const std::vector<bool>& moving, double reach);

/// prescribed[i] = node i lies on a model point or curve (dim 0 or 1).
std::vector<bool> boundary_nodes(const Mesh& m);

/// vertex[i] = node i is a corner of some triangle or quadrilateral (a node of
/// the linear mesh).
std::vector<bool> vertex_nodes(const Mesh& m);

}  // namespace homesh
