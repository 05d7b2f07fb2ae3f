#pragma once
// The elemental load vector of the elastic analogy with additional terms: body
// force and thermal stresses moved to the right-hand side of Eq 4.13.
#include <Eigen/Core>

#include "fem/element_geometry.h"

namespace homesh {

/// fe (2n, dofs [u_1 .. u_n, v_1 .. v_n] as Ke of element_stiffness): with the
/// stress sigma = C eps(u) + sigma_t and div sigma + f = 0 (Eqs 4.1-4.2), Green's
/// lemma on Eqs 4.11-4.12 with traction-free natural boundaries gives
///   int eps(N_i e_c) : C eps(u) = int N_i f_c - int eps(N_i e_c) : sigma_t,
/// i.e. fe_(c,i) = sum_q w_q [N_iq f_cq - (dNi/dx sigma_t,cx + dNi/dy sigma_t,cy)].
///   N        n by #points basis values (ElementTabulation::N);
///   f        2 by #points body force at the points;
///   sigma_t  3 by #points thermal stress (xx, yy, xy) at the points: the
///            isotropic beta (T - T0) on xx and yy (Eq 4.5) plus the anisotropic S.
Eigen::VectorXd element_load(const ElementGeometry& g, const Eigen::MatrixXd& N,
                             const Eigen::Matrix2Xd& f, const Eigen::Matrix3Xd& sigma_t);

/// The same into fe (resized), without allocating once it has size 2n.
void element_load(const ElementGeometry& g, const Eigen::MatrixXd& N, const Eigen::Matrix2Xd& f,
                  const Eigen::Matrix3Xd& sigma_t, Eigen::VectorXd& fe);

}  // namespace homesh
