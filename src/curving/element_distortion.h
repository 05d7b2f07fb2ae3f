#pragma once
// Per-element quantities that drive the augmented elastic analogy (thesis
// Section 4.4.1): element area and the variation of the idealised Jacobian.
#include <Eigen/Core>

#include "core/mesh.h"

namespace homesh {

struct ElementDistortion {
  /// #triangles area A_e = integral of det J over the element.
  Eigen::VectorXd area;
  /// #triangles min Q17 / max Q17 over the element, Q17 = omega = det W
  /// (Eq 3.47): since W = J inv(J_ri) with J_ri constant, it is min det J /
  /// max det J, sampled at the nodes of the order-2p reference lattice
  /// (corners included). 1 for a straight-sided element, <= 0 if invalid.
  Eigen::VectorXd q17_ratio;
  /// #triangles min over the same lattice of the shape quality Q11 =
  /// 2 / (|W|_F |W^-1|_F) (Eq 3.44; 1 for the equilateral element), 0 where
  /// det J <= 0.
  Eigen::VectorXd shape;
};

/// Area and Q17 variation of every triangle of m.
ElementDistortion element_distortion(const Mesh& m);

}  // namespace homesh
