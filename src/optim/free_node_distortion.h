#pragma once
// The element distortion function f of thesis Eq 3.48 as a function of the
// coordinates of some free nodes of an element, the others fixed: the
// objective of the optimal-element searches of Section 3.8 ("x symbolises the
// vector of nodes to be optimised").
//
//   f(x) = ( (1/|A_e|) sum_i w_i Theta_i^r |J_i| )^(1/r),   Theta = 1/Q - 1,
//
// (quality/distortion.h) at the points of a Gauss rule, with the thesis's
// normalisation Q / Qmax over those points for Q1-Q5 and Q17
// (Reference::element_max, text after Eq 3.49) unless told otherwise.
#include <Eigen/Core>
#include <vector>

#include "quality/element_quality.h"
#include "quality/element_sampling.h"
#include "quality/measure_registry.h"

namespace homesh {

struct DistortionSettings {
  double r = 2.0;  ///< exponent of Eq 3.48 (r = 2 throughout Section 3.8)
  Reference reference = Reference::element_max;
  /// Degree of the Gauss rule (element/quadrature.h). The thesis used a
  /// 12-point rule, exact to degree 6; ours of degree 6 has 16 points.
  int quadrature_degree = 6;
};

class FreeNodeDistortion {
 public:
  /// Measure m over the order-p element with nodes X (2 by (p+1)(p+2)/2, Gmsh
  /// order) whose nodes `free_nodes` (indices into X) move. Throws
  /// homesh::Error on a bad node count or free-node index.
  FreeNodeDistortion(const Measure& m, Eigen::Matrix2Xd X, int p, std::vector<int> free_nodes,
                     const DistortionSettings& settings = {});

  const Measure& measure() const { return *m_; }
  int order() const { return p_; }
  const std::vector<int>& free_nodes() const { return free_; }
  /// 2 * number of free nodes: x = (x_0, y_0, x_1, y_1, ...) in free_nodes() order.
  int dimension() const { return 2 * static_cast<int>(free_.size()); }

  /// The free coordinates x of an element with nodes X.
  Eigen::VectorXd coordinates(const Eigen::Matrix2Xd& X) const;
  /// The free coordinates of the element given to the constructor.
  Eigen::VectorXd start() const { return coordinates(nodes_); }
  /// The element with its free nodes at x.
  Eigen::Matrix2Xd element(const Eigen::VectorXd& x) const;

  /// f(x), Eq 3.48; +infinity if the measure is 0 at a Gauss point.
  double operator()(const Eigen::VectorXd& x) const;

 private:
  const Measure* m_;
  Eigen::Matrix2Xd nodes_;
  int p_;
  std::vector<int> free_;
  DistortionSettings settings_;
  ElementSampling rule_;
};

}  // namespace homesh
