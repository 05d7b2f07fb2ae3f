#pragma once
// Opening the room for the boundary layers (thesis Section 4.3, Eq 4.16): the
// front nodes are pushed from the walls into the domain by the elastic analogy
// (by default the thesis' E = 1, nu = 0.4, no added terms), the displacement
// delta_p = x_Omega - x_Gamma prescribed on them (Eq 4.16), every other
// boundary node fixed.
//
// The push goes in steps capped per node as in Fig 4.5a: a node moving along d
// meets the line of the opposite edge of one of its triangles after
// delta_i = available_push(...), and a step moves it by at most
// cap * min(delta_1, delta_2, ...), cap = 1 being the thesis' bound (an element
// would degenerate there only if its other nodes stood still). All front nodes
// advance by the same fraction of their remaining motion, the tightest node
// setting it, so the front keeps its shape. After each elasticity solve on the
// current mesh the result must be certified valid, else the step is halved.
// After each accepted step, edges flip where that raises the worst radius ratio
// (edge_flips.h): the triangles keep their number and surface, not their nodes.
// Once the front is in place, the free nodes whose triangles the push left worse
// than they were in the input are smoothed (star_smoothing.h), then flipped again.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/mesh.h"
#include "curving/analogy_formulation.h"
#include "fem/linear_solver.h"

namespace homesh {

struct RoomOptions {
  /// Formulation of curving/analogy_formulation.h, re-evaluated on the current
  /// mesh at every step; "plain" (E = 1, no added terms) is the thesis' choice.
  std::string formulation = "plain";
  FormulationParams params;  ///< nu, added-term scale and power of the analogy
  double cap = 1;            ///< fraction of min(delta_i) a node may move per step, in (0, 1]
  int max_steps = 200;       ///< accepted steps before giving up
  int max_halvings = 8;      ///< halvings of a failing step before giving up
  bool flips = true;         ///< flip edges after each step (edge_flips.h)
  bool smoothing = true;     ///< smooth the squeezed free nodes at the end (star_smoothing.h)
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
};

/// delta: how far `node` of m can move along the unit direction d before it
/// reaches the line through the opposite edge of one of `triangles` (those
/// around it); +infinity if it moves away from all of them.
double available_push(const Mesh& m, const std::vector<int>& triangles, int node,
                      const Eigen::Vector2d& d);

/// Moves nodes moving[k] of the valid linear mesh m to target.col(k) (2 by
/// #moving) as above; nodes with fixed[i] stay, the rest follow the analogy.
/// Stops short (complete = false) after max_steps steps or a step halved
/// max_halvings times. Throws homesh::Error on bad sizes or options.
RoomResult open_room(const Mesh& m, const std::vector<int>& moving, const Eigen::Matrix2Xd& target,
                     const std::vector<bool>& fixed, const RoomOptions& opt = {});

}  // namespace homesh
