#pragma once
// Certified bounds of the Jacobian determinant of a high-order triangle or
// quadrilateral by adaptive Bezier subdivision (Johnen, Remacle, Geuzaine,
// "Geometrical validity of curvilinear finite elements", JCP 233, 2013; Gmsh's
// jacobianBasedQuality::minMaxJacobianDeterminant and AnalyseMeshQuality plugin).
//
// det J is written in the Bernstein basis (bezier_jacobian.h; for a
// quadrilateral the tensor-product basis, quad_bezier_jacobian.h). On a (sub-)
// triangle or square the minimum and maximum Bezier coefficients bound det J
// from below and above, and the corner coefficients are exact values of det J.
// The domain with the lowest lower bound is split in four
// (bezier_subdivision.h, bezier_quad.h) until it meets
//   (a) the sign is decided: every coefficient of the domain > 0 (so det J > 0
//       there), or some exact value found is <= 0, and
//   (b) the gap between the bound and the best exact value is at most
//       tolerance = relative_tolerance * max(|exact min|, |exact max|),
// and the same with the signs mirrored for its upper bound; then the same for
// the domain with the highest upper bound. These are Gmsh's criteria
// (_coeffDataJac::boundsOk, _subdivideDomainsMinOrMax), so the results agree
// with Gmsh's to rounding, and a clockwise element (det J < 0) gets tight
// bounds too.
#include <Eigen/Core>

#include "quality/bezier_jacobian.h"

namespace homesh {

/// Stopping criteria of the subdivision.
struct BoundsOptions {
  /// Gaps are refined to relative_tolerance * max(|min det J|, |max det J|)
  /// (Gmsh uses 1e-3).
  double relative_tolerance = 1e-3;
  /// Most four-way subdivisions per element (Gmsh stops at 1000); reaching it
  /// leaves `converged` false, the bounds stay valid.
  int max_subdivisions = 1000;
};

/// Bounds of a polynomial f over the triangle:
/// min_lower <= min f <= min_upper and max_lower <= max f <= max_upper, where
/// min_upper and max_lower are values of f at subdivision corners.
struct JacobianBounds {
  double min_lower = 0, min_upper = 0, max_lower = 0, max_upper = 0;
  /// The absolute gap tolerance reached (or aimed at, if not converged).
  double tolerance = 0;
  /// Both gaps <= tolerance and the sign of the minimum (and of the maximum) decided.
  bool converged = false;
  /// min_lower > 0: f > 0 on the whole triangle (a valid, counter-clockwise element).
  bool valid_certified = false;
  /// min_upper <= 0: f <= 0 at a point of the triangle (an invalid or clockwise element).
  bool invalid_certified = false;
  /// Number of four-way subdivisions done.
  int subdivisions = 0;
};

/// Bounds of the degree-d polynomial with Bernstein coefficients c
/// (bezier_size(d), storage of bezier_triangle.h) over the reference triangle.
JacobianBounds bezier_bounds(int d, const Eigen::Ref<const Eigen::VectorXd>& c,
                             const BoundsOptions& opt = {});

/// Bounds of the polynomial of degrees (d, d) with tensor-product Bernstein
/// coefficients c ((d+1)^2, storage of bezier_quad.h) over the square [0, 1]^2:
/// the same refinement, the four corner coefficients as exact values and the
/// square split in four (quad_bezier_subdivide), as Gmsh does for TYPE_QUA.
JacobianBounds quad_bezier_bounds(int d, const Eigen::Ref<const Eigen::VectorXd>& c,
                                  const BoundsOptions& opt = {});

/// Bounds of det J over [0, 1]^2 (= area for a parallelogram) of the order-p
/// quadrilateral with nodes X (2 by (p+1)^2, Gmsh order;
/// quad_bezier_jacobian.h).
JacobianBounds quad_jacobian_bounds(const Eigen::Matrix2Xd& X, int p,
                                    const BoundsOptions& opt = {});

/// Bounds of det J (= 2 * area for a straight-sided triangle) of the order-p
/// triangle with nodes X (2 by (p+1)(p+2)/2, Gmsh order).
JacobianBounds jacobian_bounds(const Eigen::Matrix2Xd& X, int p, const BoundsOptions& opt = {});

/// The same from the element's derivative control points U, V
/// (jacobian_control_points in bezier_jacobian.h), for callers that use them
/// for more than the bounds. No heap allocation unless the triangle needs
/// subdividing.
JacobianBounds jacobian_bounds(const JacobianControlPoints& U, const JacobianControlPoints& V,
                               int p, const BoundsOptions& opt = {});

/// Bounds of the polynomial of degree d <= kMaxTetBezierDegree with Bernstein
/// coefficients c (quality/bezier_tetrahedron.h) over the reference tetrahedron: the
/// same refinement, its four corner coefficients the exact values, each domain split
/// in eight.
JacobianBounds tetrahedron_bezier_bounds(int d, const Eigen::Ref<const Eigen::VectorXd>& c,
                                         const BoundsOptions& opt = {});

/// Bounds of det J (= 6 * volume for a straight-sided tetrahedron) of the order-p
/// tetrahedron with nodes X (3 by (p+1)(p+2)(p+3)/6, Gmsh order), p <= 5
/// (quality/tet_bezier_jacobian.h). Issue 24: the certificate of 3D meshes.
JacobianBounds tetrahedron_jacobian_bounds(const Eigen::Matrix3Xd& X, int p,
                                           const BoundsOptions& opt = {});

/// Gmsh's "minJ/maxJ" (AnalyseMeshQuality plugin) from the bounds
/// minJ = min_lower and maxJ = max_upper: minJ / maxJ if maxJ > 0, maxJ / minJ
/// if maxJ < 0 (a wholly inverted element scores as its mirror image), 0 if
/// maxJ = 0. It is 1 for a straight-sided element, <= 0 if det J changes sign.
double scaled_jacobian_ratio(const JacobianBounds& b);

}  // namespace homesh
