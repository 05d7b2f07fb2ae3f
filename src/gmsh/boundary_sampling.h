#pragma once
// What the voronoi stage asks of the CAD of the current Gmsh model: the
// plane surfaces with their boundary loops, and points along the curves.
#include <Eigen/Core>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "core/mesh.h"
#include "voronoi/seeding/seeded_boundary.h"

namespace homesh::gmsh_adapter {

using homesh::LoopCurve;
using homesh::SeededBoundary;
using homesh::SurfaceBoundary;

/// A CAD curve: its parameter range, the model points at its ends (the same
/// point twice for a closed curve) and whether it closes on itself.
struct CadCurve {
  int tag = -1;
  double u0 = 0.0, u1 = 1.0;
  int start_point = -1, end_point = -1;
  bool closed = false;
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

/// Samples each boundary curve at `samples` + 1 parameters and seeds it at
/// the parameters divide(u, x, closed) returns (increasing, both ends
/// included); seeds at the curves' ends are the model points, shared.
SeededBoundary seed_boundary(
    int samples,
    const std::function<std::vector<double>(const Eigen::VectorXd&, const Eigen::Matrix2Xd&, bool)>&
        divide);

}  // namespace homesh::gmsh_adapter
