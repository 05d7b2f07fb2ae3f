#pragma once
// The objective of the high-order mesh optimiser (curving/optimise_mesh.h) on
// one element: the thesis' element distortion function (Eq 3.48) raised to r,
//
//   E_e = f^r = (1 / A_e) sum_i w_i Theta_i^r |J_i|,   A_e = sum_i w_i |J_i|,
//
// at the points i of a Gauss rule, with the pointwise distortion (Eq 3.49,
// Theta = 1/Q - 1) of two measures of W = J * T, T = inv(J_target):
//
//   Theta = Theta_shape + alpha * Theta_size,
//   Theta_shape = |W|_F^2 / (2 det W) - 1        (1/Q7 - 1, Eq 3.41: conformal
//                                                  distortion, 0 iff W is a similarity)
//   Theta_size  = (v + 1/v) / 2 - 1,  v = |J_i| / (2 A_e)   (|J_i| / A_e on a quadrilateral)
//                                                 (1/Q13 - 1, Eq 3.45, Branets & Carey,
//                                                  with V the element's mean |J|)
//
// Theta_shape is the distortion energy of Turner, Peiro & Moxey (CAD 2018,
// Sec 3.3; NekMesh's varopti) and the "shape" metric of TMOP (Dobrev et al.,
// SISC 2019, mu_2); Theta_size vanishes exactly when det J is constant over
// the element, i.e. when the certified minJ/maxJ (quality/jacobian_bounds.h)
// is 1, which is the number the optimiser is judged by. Both terms grow as
// 1/det J when det J -> 0+ at a point, and with r = 2 the |J_i| weight leaves
// E_e ~ 1/det J: the objective is its own barrier (Toulorge et al., JCP 2013,
// need a log-barrier only because their objective stays finite). E_e is
// +infinity if det J <= 0 at any point. The target T is the thesis' ideal map
// inv(J_ri) (quality/ideal_jacobian.h; Theta_shape is then invariant to the
// element's size and orientation) or the element's own straight-sided
// Jacobian (TMOP's target-matrix idea): then Theta_shape = 0 for the
// straight-sided element, whatever its aspect ratio.
//
// Quadrilaterals (a tabulation with quad = true, fem/element_tabulation.h):
// the same measure on the reference square [0, 1]^2, whose ideal element is
// the unit square itself (W = J as in quality/mesh_quality.h: the ideal
// target is T = I; the straight one, curving/optimise_mesh.h, is the inverse
// of the Jacobian at the centre of the element's straight, bilinear shape,
// exact for a parallelogram), the mean |J| being A_e (the square's area is 1).
#include <Eigen/Core>
#include <vector>

#include "fem/element_tabulation.h"

namespace homesh {

struct DistortionEnergyOptions {
  double r = 2.0;  ///< exponent of Eq 3.48 (the thesis' r = 2); >= 2 keeps the barrier
  /// Weight of Theta_size against Theta_shape (0: shape only). Measured on the
  /// thin annulus of tests/curving/optimise_mesh_test.cpp with 16 wall segments (p = 2, start
  /// 0.886, straight target): alpha = 0, 1, 10, 30, 100, 1000 give a worst
  /// minJ/maxJ of 0.82, 0.86, 0.93, 0.95, 0.96, 0.96 (p = 4: 0.74, 0.81, 0.91,
  /// 0.94, 0.96, 0.96; r = 4 or 8 no better): the shape term alone trades the
  /// worst element for the average; it stays as a regulariser.
  double alpha = 100.0;
  /// Barrier floor (Toulorge et al.'s epsilon): E_e is +infinity where |J_i|
  /// <= epsilon times the element's mean |J| (2 A_e). 0: only det J > 0.
  double epsilon = 0.0;
};

/// E_e of the element with nodes X (2 by (p+1)(p+2)/2, Gmsh order; a
/// quadrilateral's 2 by (p+1)^2 if tab.quad) whose basis is tabulated in `tab`, with target inverse
/// T (2 by 2, det T > 0). If `gradient` is given it receives dE_e/dX (2 by n, column k the
/// derivative by node k's (x, y)), unless E_e is +infinity; with node >= 0 only that column (the
/// others zero: what a node-by-node sweep needs, at a fraction of the cost).
double distortion_energy(const Eigen::Matrix2Xd& X, const ElementTabulation& tab,
                         const Eigen::Matrix2d& T, const DistortionEnergyOptions& opt,
                         Eigen::Matrix2Xd* gradient = nullptr, int node = -1);

/// E_e as above with its gradient (2 by n) and its exact Hessian by the 2 n node
/// coordinates (node k's (x, y) at rows and columns 2 k, 2 k + 1), both left untouched
/// if E_e is +infinity. The chain rule through the per-point Jacobians J_i = X D_i and
/// the element's A: with Phi(J, A) = N / A and A(J) = sum_i w_i det J_i,
///   d2E/dJ_i dJ_k = delta_ik (w_i f_i,JJ / A + Phi_A w_i d2(det)/dJ2)
///                 + c_i a_k^T + a_i c_k^T + Phi_AA a_i a_k^T,
/// a_i = w_i cof J_i (dA/dJ_i), c_i = d2Phi/dJ_i dA, f_i = |J_i| Theta_i^r; the
/// per-point blocks go to X by D_i, the rank-2 coupling by dA/dX and sum_i c_i D_i^T.
/// What the whole-patch Newton steps (curving/patch_newton.h) assemble: exact, and a
/// fraction of the cost of differencing the gradient (2 n gradients per element).
/// With `nodes` (local node indices, none repeated), the gradient (2 by L) and the
/// Hessian (2 L by 2 L) by those nodes' coordinates only, in that order: the optimiser's
/// patches hold the nodes on their rim, about a quarter of a patch element's Hessian.
double distortion_energy_hessian(const Eigen::Matrix2Xd& X, const ElementTabulation& tab,
                                 const Eigen::Matrix2d& T, const DistortionEnergyOptions& opt,
                                 Eigen::Matrix2Xd& gradient, Eigen::MatrixXd& hessian,
                                 const std::vector<int>* nodes = nullptr);

}  // namespace homesh
