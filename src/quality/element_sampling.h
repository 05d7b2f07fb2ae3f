#pragma once
// The basis gradients of an order-p triangle (or quadrilateral) tabulated once
// at fixed points of the reference triangle (0,0), (1,0), (0,1) (or of the
// reference square [0, 1]^2, element/quad_lagrange_basis.h), so that the Jacobians of many
// elements (or of one element whose nodes an optimiser moves) cost one small
// product per point. Sampling the measures at ~200 points shows them over an
// element (thesis Section 3.6); the points of a quadrature rule, with its
// weights, serve the distortion function (Eq 3.48).
#include <Eigen/Core>

#include "element/quadrature.h"

namespace homesh {

/// The reference element of a sampling.
enum class ElementShape { triangle, quadrilateral };

class ElementSampling {
 public:
  /// At the columns of `uv` (2 by m reference points), without weights; p >= 1.
  ElementSampling(int p, const Eigen::Matrix2Xd& uv, ElementShape shape = ElementShape::triangle);
  /// At the points of `rule`, keeping its weights (they sum to 1/2).
  ElementSampling(int p, const QuadratureRule& rule);

  int order() const { return p_; }
  ElementShape shape() const { return shape_; }
  /// Number of element nodes, (p+1)(p+2)/2 (a quadrilateral's (p+1)^2).
  int node_count() const { return static_cast<int>(dNdu_.rows()); }
  /// Number of points m.
  int size() const { return static_cast<int>(points_.cols()); }
  /// 2 by m reference points.
  const Eigen::Matrix2Xd& points() const { return points_; }
  /// m quadrature weights, empty when built from bare points.
  const Eigen::VectorXd& weights() const { return weights_; }

  /// J (2 by 2, Eq 3.3) at point k of the element with nodes X (2 by
  /// node_count(), Gmsh order). No allocation.
  Eigen::Matrix2d jacobian(const Eigen::Matrix2Xd& X, int k) const {
    Eigen::Matrix2d J;
    J.col(0).noalias() = X * dNdu_.col(k);
    J.col(1).noalias() = X * dNdv_.col(k);
    return J;
  }

  /// Throws homesh::Error unless X has node_count() columns.
  void check_nodes(const Eigen::Matrix2Xd& X) const;

 private:
  int p_;
  ElementShape shape_;
  Eigen::Matrix2Xd points_;
  Eigen::VectorXd weights_;
  Eigen::MatrixXd dNdu_, dNdv_;  // node_count() by m
};

}  // namespace homesh
