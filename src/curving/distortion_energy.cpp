#include "curving/distortion_energy.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace homesh {
namespace {

// d det J / dJ: the cofactor matrix.
Eigen::Matrix2d cofactor(const Eigen::Matrix2d& J) {
  Eigen::Matrix2d C;
  C << J(1, 1), -J(1, 0), -J(0, 1), J(0, 0);
  return C;
}

}  // namespace

double distortion_energy(const Eigen::Matrix2Xd& X, const ElementTabulation& tab,
                         const Eigen::Matrix2d& T, const DistortionEnergyOptions& opt,
                         Eigen::Matrix2Xd* gradient, int node) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const int q = static_cast<int>(tab.rule.weights.size());
  const Eigen::VectorXd& w = tab.rule.weights;
  thread_local std::vector<Eigen::Matrix2d> J;
  thread_local std::vector<double> d;
  // dX/du, dX/dv at every point (coefficient products: the matrices are small).
  thread_local Eigen::Matrix2Xd Ju, Jv;
  J.resize(q);
  d.resize(q);
  Ju.noalias() = X.lazyProduct(tab.dNdu);
  Jv.noalias() = X.lazyProduct(tab.dNdv);
  double A = 0;
  for (int i = 0; i < q; ++i) {
    J[i].col(0) = Ju.col(i);
    J[i].col(1) = Jv.col(i);
    d[i] = J[i].determinant();
    if (!(d[i] > 0)) return kInf;
    A += w(i) * d[i];
  }
  // The element's mean |J| is A over the reference element's area: 2 A on the
  // triangle (area 1/2), A on the square.
  const double mean = tab.quad ? 1.0 : 2.0;
  for (int i = 0; i < q; ++i)
    if (d[i] <= opt.epsilon * mean * A) return kInf;
  const double detT = T.determinant();
  const Eigen::Matrix2d M = T * T.transpose();
  const double r = opt.r, alpha = opt.alpha;
  // Pointwise terms: Theta = s + alpha z (see the header).
  double N = 0, dN_dA = 0;
  // Theta^(r-1) at each point (pow is most of the cost: r = 2 is a product).
  const auto power_r1 = [r](double t) { return r == 2 ? t : std::pow(t, r - 1); };
  thread_local std::vector<double> theta, theta_r1, s, zprime;
  theta.resize(q);
  theta_r1.resize(q);
  s.resize(q);
  zprime.resize(q);
  for (int i = 0; i < q; ++i) {
    const double w2 = (J[i] * T).squaredNorm();
    s[i] = w2 / (2 * d[i] * detT) - 1;
    const double v = d[i] / (mean * A);
    const double z = 0.5 * (v + 1 / v) - 1;
    zprime[i] = 0.5 * (1 - 1 / (v * v));
    theta[i] = std::max(0.0, s[i] + alpha * z);
    theta_r1[i] = power_r1(theta[i]);
    N += w(i) * d[i] * theta_r1[i] * theta[i];
    // d/dA of Theta_i through v_i = d_i / (mean A): dv/dA = -v / A.
    dN_dA += w(i) * d[i] * r * theta_r1[i] * alpha * zprime[i] * (-v / A);
  }
  const double E = N / A;
  if (!gradient) return E;
  // E = N / A: dE/dJ_i = (1/A) dN/dJ_i|_A + (dN/dA / A - N / A^2) dA/dJ_i, dA/dJ_i = w_i cof J_i;
  // dE/dX = sum_i dE/dJ_i D_i^T with J_i = X D_i, D_i = [dN/du dN/dv] at point i.
  const double coupling = dN_dA / A - N / (A * A);
  // dE/dJ_i's columns at every point, then dE/dX = Gu dNdu^T + Gv dNdv^T (or one column).
  thread_local Eigen::Matrix2Xd Gu, Gv;
  Gu.resize(2, q);
  Gv.resize(2, q);
  for (int i = 0; i < q; ++i) {
    const Eigen::Matrix2d C = cofactor(J[i]);
    const Eigen::Matrix2d ds = J[i] * M / (d[i] * detT) - (s[i] + 1) / d[i] * C;
    const Eigen::Matrix2d dtheta = ds + alpha * zprime[i] / (mean * A) * C;
    const double tr = theta_r1[i] * theta[i], tr1 = r * theta_r1[i];
    const Eigen::Matrix2d G = w(i) * ((tr * C + d[i] * tr1 * dtheta) / A + coupling * C);
    Gu.col(i) = G.col(0);
    Gv.col(i) = G.col(1);
  }
  if (node >= 0) {
    gradient->setZero(2, X.cols());
    gradient->col(node).noalias() =
        Gu * tab.dNdu.row(node).transpose() + Gv * tab.dNdv.row(node).transpose();
  } else {
    gradient->noalias() = Gu.lazyProduct(tab.dNdu.transpose());
    gradient->noalias() += Gv.lazyProduct(tab.dNdv.transpose());
  }
  return E;
}

}  // namespace homesh
