#pragma once
// The rotation benchmark of thesis Section 4.4 (Tables 4.1-4.8): a wall (the
// circular hole, the aerofoil) turns rigidly about a centre in equal angle
// steps while the rest of the boundary stays fixed; the interior follows the
// augmented elastic analogy, and the rotation stops at the first step that
// would leave an element not certified valid. theta_max is the last angle
// reached with every element valid. The loop is that of deform_mesh
// (curving/deform_mesh.h) with one difference: the formulations see the
// initial mesh of the whole rotation, not of the current step, as their
// `initial` mesh (the metric formulations measure distortion from it).
//
// Two ways of posing a step:
//  - incremental (the thesis): step k turns the wall from angle (k-1) h to k h
//    in `substeps` equal solves, each posed on the current mesh with the
//    formulation's coefficients evaluated on it (metric formulations measure
//    the change since the initial mesh of the whole rotation);
//  - total: step k is one solve on the initial mesh, its wall turned to k h
//    at once (a linear extension of the boundary motion; every added term
//    vanishes on the mesh it starts from, so the formulations with E = 1 all
//    coincide there).
// No halving: as in the thesis, the first solve leaving an element not
// certified valid ends the rotation (finer steps are asked for with
// `substeps`, which keeps theta_max on the grid of h). Wall targets are always
// the exact rotation of the initial wall, so no drift accumulates. Angles are
// in degrees, anticlockwise positive. CG starts from the previous solve's
// displacement. Each accepted step is reported as progress (core/progress.h).
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "core/mesh.h"
#include "curving/analogy_formulation.h"
#include "fem/linear_solver.h"

namespace homesh {

/// The most steps one rotation may take (max_angle / |step|).
constexpr int kMaxRotationSteps = 100000;

struct RotateOptions {
  /// Centre of the rotation; none: the centre of the circle fitted to the
  /// wall's nodes (fitted_circle_centre), the hole's centre in the thesis.
  std::optional<Eigen::Vector2d> centre;
  double step = 1.0;                  ///< angle step h, degrees (its sign gives the sense)
  double max_angle = 360;             ///< stop once |angle| reaches it, degrees
  int substeps = 1;                   ///< solves per step (incremental only)
  bool total = false;                 ///< pose each step on the initial mesh (see above)
  std::string formulation = "plain";  ///< a name of analogy_formulations()
  FormulationParams params;
  LinearSolverOptions solver;
};

struct RotateResult {
  Mesh mesh;                 ///< the state at theta_max, every element certified valid
  double theta_max = 0;      ///< last angle with a valid mesh, degrees (multiple of step)
  int steps = 0;             ///< accepted steps (theta_max / step)
  bool reached_max = false;  ///< max_angle reached without an invalid element
  int solves = 0;            ///< elasticity solves, the failing step's included
  double mean_iterations =
      0;  ///< CG iterations per attempted step (the thesis' N); 0 for direct solvers
  double worst_ratio = 1;      ///< worst certified minJ/maxJ of m and every accepted step
  int invalid_at_failure = 0;  ///< invalid elements of the first rejected state
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();  ///< the centre used
};

/// Rotates the nodes with wall[i] about opt.centre (or the fitted one) step
/// by step; nodes with prescribed[i] && !wall[i] stay where they are, the
/// others follow the analogy. m must be certified valid; wall must be a subset of prescribed. The
/// wall nodes of the result lose their curve parameter (u = NaN): it no longer matches their
/// position. Throws homesh::Error on an invalid m, bad sizes, an empty wall, a wall node not
/// prescribed, step = 0, max_angle < 0, substeps < 1, an unknown formulation, no opt.centre and
/// wall nodes fitting no circle (fewer than 3, collinear), or a failed solve.
RotateResult rotate_boundary(const Mesh& m, const std::vector<bool>& wall,
                             const std::vector<bool>& prescribed, const RotateOptions& opt = {});

/// #points 2 by n: centre c of the least-squares circle through them (Kasa's
/// fit: min sum (|x - c|^2 - r^2)^2, linear in c and r^2 - |c|^2), exact for
/// points on a circle whatever their spacing. Throws homesh::Error for fewer
/// than 3 points or collinear ones.
Eigen::Vector2d fitted_circle_centre(const Eigen::Matrix2Xd& points);

}  // namespace homesh
