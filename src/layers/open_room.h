#pragma once
// Opening the room for the boundary layers (thesis Section 4.3, Eq 4.16): the
// front nodes are pushed from the walls into the domain by the elastic analogy
// (by default the thesis' E = 1, nu = 0.4, no added terms), the displacement
// delta_p = x_Omega - x_Gamma prescribed on them (Eq 4.16), every other
// boundary node fixed.
//
// The push goes in steps. All front nodes advance by the same fraction of
// their remaining motion, so the front keeps its shape: cap times the largest
// fraction at which no triangle with a front node would fold if its other
// nodes stood still (fold_fraction; for one moving node this is the distance
// along its path to the opposite edge's line, Fig 4.5a, cap = 1 the thesis'
// bound), so the thinnest element at the front sizes the step, not a count;
// or, if larger, `growth` times the share of the remaining motion the last step
// took: the fold bound holds the free nodes still, where the solve moves them
// out of the way (22 steps -> 7 for NACA-7526's 15 layers on 1e6 triangles).
// Each step is the elastic deformation of curving/deform_mesh.h posed on the
// triangles within `reach` of the front (its increments halved until every
// element is certified valid); the push stops short once a step would move
// less than min_fraction of what is left.
// After each accepted step, edges flip where that raises the worst radius ratio
// (edge_flips.h) among the moved triangles below flip_below and their
// neighbours: the triangles keep their number and surface, not their nodes.
// Once the front is in place, the free nodes whose triangles the push left worse
// than they were in the input are smoothed (star_smoothing.h), then flipped again.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/mesh.h"
#include "curving/analogy_formulation.h"
#include "fem/linear_solver.h"
#include "layers/clear_room.h"

namespace homesh {

struct RoomOptions {
  /// Formulation of curving/analogy_formulation.h, re-evaluated on the current
  /// mesh at every step; "plain" (E = 1, no added terms) is the thesis' choice.
  std::string formulation = "plain";
  FormulationParams params;  ///< nu, added-term scale and power of the analogy
  double cap = 1;            ///< fraction of the folding step a step may take, in (0, 1]
  /// Solve each step within reach * h of the front (deform_mesh.h's reach);
  /// 0: on the whole mesh.
  double reach = 4;
  double min_fraction = 1e-3;  ///< smallest step, as a fraction of the motion left
  int max_steps = 500;         ///< accepted steps before giving up
  /// > 0: a step takes at least growth times the fraction of the remaining
  /// motion the last step took (deform_mesh halves it until valid, and a step it
  /// cannot complete ends short, not the push); 0: the fold bound alone.
  double growth = 2;
  int max_halvings = 8;  ///< halvings of a failing step before giving up
  /// > 0: the free nodes within `clear` times the stack's depth of the wall
  /// are removed (clear_room.h) as the front comes; 0: pushed ahead of it.
  double clear = 1.2;
  bool flips = true;  ///< flip edges after each step (edge_flips.h)
  /// Flip only round the moved triangles of radius ratio below this (1: all moved).
  double flip_below = 0.8;
  bool smoothing = true;  ///< smooth the squeezed free nodes at the end (star_smoothing.h)
  LinearSolverOptions solver;
};

struct RoomResult {
  Mesh mesh;              ///< the last certified-valid state (positions, flipped triangles)
  bool complete = false;  ///< every moving node reached its target
  double reached = 0;     ///< fraction of the motion done, in [0, 1]
  int steps = 0;          ///< accepted steps
  int solves = 0;         ///< elasticity solves, rejected ones included
  int bottleneck = -1;    ///< index into `moving` of the node that set the last step
  int smoothed = 0;       ///< node moves of the final smoothing
  int cleared = 0;        ///< free nodes removed from the room (clear_room.h)
};

/// The smallest t > 0 at which triangle x (2 by 3, counter-clockwise) moved to
/// x + t u turns flat; +infinity if it never does, 0 if x is not
/// counter-clockwise.
double fold_fraction(const Eigen::Matrix<double, 2, 3>& x, const Eigen::Matrix<double, 2, 3>& u);

/// Moves nodes moving[k] of the valid linear mesh m to target.col(k) (2 by
/// #moving) as above; nodes with fixed[i] stay, the rest follow the analogy.
/// The final smoothing moves the free nodes whose star quality is below
/// floor (#nodes; empty: star_quality(m)). Given the room (its front and
/// target moving and target) and opt.clear > 0, the free nodes in it are
/// removed (clear_room.h) before the first step and after each one.
/// Stops short (complete = false) after max_steps steps, a step below
/// min_fraction or one deform_mesh could not complete. Throws homesh::Error on bad sizes or
/// options.
RoomResult open_room(const Mesh& m, const std::vector<int>& moving, const Eigen::Matrix2Xd& target,
                     const std::vector<bool>& fixed, const RoomOptions& opt = {},
                     const std::vector<double>& floor = {}, const Room* room = nullptr);

}  // namespace homesh
