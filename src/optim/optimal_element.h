#pragma once
// Optimal element shapes (thesis Section 3.8): the free nodes of an element
// placed where the element distortion function f (Eq 3.48,
// optim/free_node_distortion.h) is smallest, by PRAXIS (Section 3.8.1) or by
// brute force on a grid (the thesis's verification, Section 3.8.2).
#include <Eigen/Core>
#include <string>
#include <vector>

#include "optim/free_node_distortion.h"
#include "optim/grid_search.h"
#include "optim/praxis.h"

namespace homesh {

/// What PRAXIS sees where f is +infinity (the measure is 0 at a Gauss point,
/// det J <= 0 there): a finite wall, so that its line searches stay finite.
constexpr double kInvalidDistortion = 1e30;

/// A search problem of Section 3.8: an order-p element whose free nodes
/// start displaced, the others fixed.
struct OptimisationCase {
  std::string name;         ///< e.g. "quadratic_interior"
  std::string description;  ///< the setup in one sentence
  int order = 0;
  Eigen::Matrix2Xd start;  ///< 2 by (p+1)(p+2)/2 nodes, Gmsh order
  std::vector<int> free_nodes;
};

struct OptimalElement {
  Eigen::Matrix2Xd nodes;       ///< the element with its free nodes at the minimum
  double f0 = 0;                ///< f of the starting element
  double f = 0;                 ///< f at the minimum
  int evaluations = 0;          ///< evaluations of f (PRAXIS: the thesis' N)
  std::vector<double> history;  ///< f at every PRAXIS evaluation (empty for the grid)
};

/// PRAXIS from f.start() (t0, h0 of `opt`).
OptimalElement optimise_praxis(const FreeNodeDistortion& f, const PraxisOptions& opt = {});

/// Brute force: the smallest f on a grid over the box [lo, hi] of the free
/// coordinates (f.dimension() each), refined as in grid_search.h.
OptimalElement optimise_grid(const FreeNodeDistortion& f, const Eigen::VectorXd& lo,
                             const Eigen::VectorXd& hi, const GridSearchOptions& opt = {});

}  // namespace homesh
