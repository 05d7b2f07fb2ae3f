#pragma once
// What the voronoi stage asks of the CAD of the current Gmsh model: the
// plane surfaces with their boundary loops, and points along the curves.
#include <Eigen/Core>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "core/mesh.h"

namespace homesh::gmsh_adapter {

/// A CAD curve: its parameter range, the model points at its ends (the same
/// point twice for a closed curve) and whether it closes on itself.
struct CadCurve {
  int tag = -1;
  double u0 = 0.0, u1 = 1.0;
  int start_point = -1, end_point = -1;
  bool closed = false;
};

/// A curve as a boundary loop runs along it: backwards if `reversed`.
struct LoopCurve {
  int tag = -1;
  bool reversed = false;
};

/// A surface and its boundary loops, each a closed chain of curves in
/// Gmsh's orientation (the surface on the left if its normal is +z).
struct SurfaceBoundary {
  int tag = -1;
  std::vector<std::vector<LoopCurve>> loops;
};

/// Every surface of the current model. Throws homesh::Error if a surface's
/// boundary curves do not chain into closed loops.
std::vector<SurfaceBoundary> surface_boundaries();

/// Curve `tag` of the current model.
CadCurve cad_curve(int tag);

/// Points of curve `tag` at parameters u: 2 by u.size().
Eigen::Matrix2Xd curve_points(int tag, const std::vector<double>& u);

/// The position of model point `tag`.
Eigen::Vector2d model_point(int tag);

/// The curves in physical groups whose name equals `name` ignoring case.
std::vector<int> curves_in_group(const std::string& name);

/// Every curve of the model that bounds a surface.
std::vector<int> boundary_curves();

/// The surfaces' boundary curves, sampled finely and seeded.
struct SeededBoundary {
  std::vector<SurfaceBoundary> surfaces;
  /// Boundary seeds (2 by B) and where each lies: on a model point (dim 0)
  /// or inside a curve (dim 1, with its parameter u).
  Eigen::Matrix2Xd seeds;
  std::vector<NodeClass> classes;
  /// Per curve, its seeds from its start to its end, ends included (a closed
  /// curve's point at both ends).
  std::map<int, std::vector<int>> curve_seeds;
  /// Per curve, `samples` + 1 points from start to end, uniform in u.
  std::map<int, Eigen::Matrix2Xd> curve_samples;
};

/// Samples each boundary curve at `samples` + 1 parameters and seeds it at
/// the parameters divide(u, x, closed) returns (increasing, both ends
/// included); seeds at the curves' ends are the model points, shared.
SeededBoundary seed_boundary(
    int samples,
    const std::function<std::vector<double>(const Eigen::VectorXd&, const Eigen::Matrix2Xd&, bool)>&
        divide);

}  // namespace homesh::gmsh_adapter
