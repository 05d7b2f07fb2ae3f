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

// dX/du, dX/dv (coefficient products: the matrices are small) and det J at every
// point, and A = sum_i w_i det J_i.
struct PointJacobians {
  Eigen::Matrix2Xd Ju, Jv;
  std::vector<double> d;
  double A = 0;
};

// Fills pj; false (E_e = +infinity) if det J <= 0 at a point, or below the barrier
// floor epsilon times the element's mean |J| (A over the reference element's area:
// 2 A on the triangle, area 1/2; A on the square).
bool point_jacobians(const Eigen::Matrix2Xd& X, const ElementTabulation& tab, double epsilon,
                     PointJacobians& pj) {
  const int q = static_cast<int>(tab.rule.weights.size());
  const Eigen::VectorXd& w = tab.rule.weights;
  pj.Ju.noalias() = X.lazyProduct(tab.dNdu);
  pj.Jv.noalias() = X.lazyProduct(tab.dNdv);
  pj.d.resize(q);
  pj.A = 0;
  for (int i = 0; i < q; ++i) {
    pj.d[i] = pj.Ju(0, i) * pj.Jv(1, i) - pj.Jv(0, i) * pj.Ju(1, i);
    if (!(pj.d[i] > 0)) return false;
    pj.A += w(i) * pj.d[i];
  }
  const double mean = tab.quad ? 1.0 : 2.0;
  for (int i = 0; i < q; ++i)
    if (pj.d[i] <= epsilon * mean * pj.A) return false;
  return true;
}

}  // namespace

double distortion_energy(const Eigen::Matrix2Xd& X, const ElementTabulation& tab,
                         const Eigen::Matrix2d& T, const DistortionEnergyOptions& opt,
                         Eigen::Matrix2Xd* gradient, int node) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const int q = static_cast<int>(tab.rule.weights.size());
  const Eigen::VectorXd& w = tab.rule.weights;
  thread_local PointJacobians pj;
  if (!point_jacobians(X, tab, opt.epsilon, pj)) return kInf;
  const std::vector<double>& d = pj.d;
  const double A = pj.A;
  thread_local std::vector<Eigen::Matrix2d> J;
  J.resize(q);
  for (int i = 0; i < q; ++i) {
    J[i].col(0) = pj.Ju.col(i);
    J[i].col(1) = pj.Jv.col(i);
  }
  const double mean = tab.quad ? 1.0 : 2.0;  // the reference element's area is 1 / mean
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

double distortion_energy_hessian(const Eigen::Matrix2Xd& X, const ElementTabulation& tab,
                                 const Eigen::Matrix2d& T, const DistortionEnergyOptions& opt,
                                 Eigen::Matrix2Xd& gradient, Eigen::MatrixXd& hessian,
                                 const std::vector<int>* nodes) {
  // J is indexed by j = 2 col + row (column-major vec): (J00, J10, J01, J11); a 4-vector
  // per point for first derivatives, a 4 by 4 matrix for second.
  using Vec4 = Eigen::Matrix<double, 4, 1>;
  using Mat4 = Eigen::Matrix<double, 4, 4>;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const int q = static_cast<int>(tab.rule.weights.size());
  const Eigen::VectorXd& w = tab.rule.weights;
  thread_local PointJacobians pj;
  if (!point_jacobians(X, tab, opt.epsilon, pj)) return kInf;
  // The basis derivatives of the nodes derived by (all, or `nodes`'s rows).
  thread_local Eigen::MatrixXd Du_rows, Dv_rows;
  if (nodes) {
    const int L = static_cast<int>(nodes->size());
    Du_rows.resize(L, q);
    Dv_rows.resize(L, q);
    for (int k = 0; k < L; ++k) {
      Du_rows.row(k) = tab.dNdu.row((*nodes)[k]);
      Dv_rows.row(k) = tab.dNdv.row((*nodes)[k]);
    }
  }
  const Eigen::MatrixXd& Du = nodes ? Du_rows : tab.dNdu;
  const Eigen::MatrixXd& Dv = nodes ? Dv_rows : tab.dNdv;
  const int n = static_cast<int>(Du.rows());
  const Eigen::Matrix2Xd &Ju = pj.Ju, &Jv = pj.Jv;
  const std::vector<double>& d = pj.d;
  const double A = pj.A;
  const double mean = tab.quad ? 1.0 : 2.0;
  const double detT = T.determinant();
  const Eigen::Matrix2d M = T * T.transpose();
  const double r = opt.r, alpha = opt.alpha, mA = mean * A;
  // d2(det J)/dJ2: d = J00 J11 - J01 J10.
  Mat4 D2 = Mat4::Zero();
  D2(0, 3) = D2(3, 0) = 1;
  D2(1, 2) = D2(2, 1) = -1;
  // d2(|J T|_F^2 / 2) / dJ2 = M (x) I: entry (a + 2 b, c + 2 e) = delta_ac M(b, e).
  Mat4 G2 = Mat4::Zero();
  for (int b = 0; b < 2; ++b)
    for (int e = 0; e < 2; ++e)
      for (int a = 0; a < 2; ++a) G2(a + 2 * b, a + 2 * e) = M(b, e);
  // Per point: f_J, f_JJ, f_JA, f_A, f_AA (f = d theta^r).
  thread_local std::vector<Vec4> fJ, fJA, cof;
  thread_local std::vector<Mat4> fJJ;
  fJ.resize(q);
  fJA.resize(q);
  cof.resize(q);
  fJJ.resize(q);
  double N = 0, NA = 0, NAA = 0;
  for (int i = 0; i < q; ++i) {
    Eigen::Matrix2d J;
    J.col(0) = Ju.col(i);
    J.col(1) = Jv.col(i);
    const Eigen::Matrix2d cofactor_J = cofactor(J);
    const Vec4 C = Eigen::Map<const Vec4>(cofactor_J.data());  // vec of cof(J)
    cof[i] = C;
    const Eigen::Matrix2d JM = J * M;
    const Vec4 gJ = Eigen::Map<const Vec4>(JM.data()) / detT;  // d(|JT|^2 / (2 detT))/dJ
    const double g = (J * T).squaredNorm() / (2 * detT);       // |JT|^2 / (2 detT)
    const double di = d[i];
    const double s = g / di - 1;
    const double v = di / mA;
    const double z = 0.5 * (v + 1 / v) - 1, z1 = 0.5 * (1 - 1 / (v * v)), z2 = 1 / (v * v * v);
    const double theta = std::max(0.0, s + alpha * z);
    const double t_r1 = r == 2 ? theta : std::pow(theta, r - 1), t_r = t_r1 * theta;
    const double t_r2 = r == 2 ? 1.0 : std::pow(theta, r - 2);
    // theta's derivatives by J (through s and v) and by A (through v: dv/dA = -v / A).
    const Vec4 sJ = gJ / di - (s + 1) / di * C;
    const Mat4 sJJ = G2 / (detT * di) - (gJ * C.transpose() + C * gJ.transpose()) / (di * di) +
                     2 * (s + 1) / (di * di) * C * C.transpose() - (s + 1) / di * D2;
    const Vec4 tJ = sJ + alpha * z1 / mA * C;
    const Mat4 tJJ = sJJ + alpha * (z2 / (mA * mA) * C * C.transpose() + z1 / mA * D2);
    const double tA = -alpha * z1 * v / A;
    const Vec4 tJA = -alpha * (z2 * v + z1) / (mean * A * A) * C;
    const double tAA = alpha * (z2 * v * v / (A * A) + 2 * z1 * v / (A * A));
    // f = d theta^r.
    fJ[i] = t_r * C + r * di * t_r1 * tJ;
    fJJ[i] = r * t_r1 * (C * tJ.transpose() + tJ * C.transpose()) +
             r * (r - 1) * di * t_r2 * tJ * tJ.transpose() + r * di * t_r1 * tJJ + t_r * D2;
    fJA[i] = r * t_r1 * tA * C + r * (r - 1) * di * t_r2 * tA * tJ + r * di * t_r1 * tJA;
    const double fA = r * di * t_r1 * tA;
    const double fAA = r * (r - 1) * di * t_r2 * tA * tA + r * di * t_r1 * tAA;
    N += w(i) * di * t_r;
    NA += w(i) * fA;
    NAA += w(i) * fAA;
  }
  const double E = N / A;
  const double PhiA = NA / A - N / (A * A);
  const double PhiAA = NAA / A - 2 * NA / (A * A) + 2 * N / (A * A * A);
  // dE/dJ_i (vec), and the per-point Hessian blocks and c_i, a_i mapped to X.
  thread_local Eigen::MatrixXd H4;  // 16 by q: the per-point blocks, column i = vec(H_i)
  thread_local Eigen::Matrix2Xd Gu, Gv, Au, Av, Cu, Cv;
  H4.resize(16, q);
  Gu.resize(2, q);
  Gv.resize(2, q);
  Au.resize(2, q);
  Av.resize(2, q);
  Cu.resize(2, q);
  Cv.resize(2, q);
  for (int i = 0; i < q; ++i) {
    const Vec4 a = w(i) * cof[i];
    const Vec4 G = w(i) * fJ[i] / A + PhiA * a;
    const Vec4 c = w(i) * (fJA[i] / A - fJ[i] / (A * A));
    Gu.col(i) = G.head<2>();
    Gv.col(i) = G.tail<2>();
    Au.col(i) = a.head<2>();
    Av.col(i) = a.tail<2>();
    Cu.col(i) = c.head<2>();
    Cv.col(i) = c.tail<2>();
    const Mat4 Hi = w(i) * (fJJ[i] / A + PhiA * D2);
    H4.col(i) = Eigen::Map<const Eigen::Matrix<double, 16, 1>>(Hi.data());
  }
  gradient.noalias() = Gu.lazyProduct(Du.transpose());
  gradient.noalias() += Gv.lazyProduct(Dv.transpose());
  thread_local Eigen::Matrix2Xd dA, dC;
  dA.noalias() = Au.lazyProduct(Du.transpose());
  dA.noalias() += Av.lazyProduct(Dv.transpose());
  dC.noalias() = Cu.lazyProduct(Du.transpose());
  dC.noalias() += Cv.lazyProduct(Dv.transpose());
  // Block (c1, c2) of the per-point part, n by n:
  //   sum_{a, b in {u, v}} D_a diag(H_i(c1 + 2a, c2 + 2b)) D_b^T = [Y_u Y_v] [D_u D_v]^T,
  //   Y_b = sum_a D_a diag(H(c1 + 2 a, c2 + 2 b)).
  thread_local Eigen::MatrixXd W, Y, B;
  W.resize(n, 2 * q);
  W.leftCols(q) = Du;
  W.rightCols(q) = Dv;
  Y.resize(n, 2 * q);
  hessian.resize(2 * n, 2 * n);
  B.resize(n, n);
  for (int c1 = 0; c1 < 2; ++c1)
    for (int c2 = c1; c2 < 2; ++c2) {
      for (int b = 0; b < 2; ++b) {
        const auto hu = H4.row(c1 + 4 * (c2 + 2 * b));      // a = u: row c1, col c2 + 2b
        const auto hv = H4.row(c1 + 2 + 4 * (c2 + 2 * b));  // a = v
        Y.middleCols(b * q, q) = Du * hu.asDiagonal() + Dv * hv.asDiagonal();
      }
      if (c1 == c2) {
        // A diagonal block is symmetric: its lower triangle (k >= l) only.
        B.triangularView<Eigen::Lower>() = Y * W.transpose();
        for (int l = 0; l < n; ++l)
          for (int k = l; k < n; ++k) {
            hessian(2 * k + c1, 2 * l + c1) = B(k, l);
            hessian(2 * l + c1, 2 * k + c1) = B(k, l);
          }
        continue;
      }
      B.noalias() = Y * W.transpose();
      for (int k = 0; k < n; ++k)
        for (int l = 0; l < n; ++l) {
          hessian(2 * k + c1, 2 * l + c2) = B(k, l);
          hessian(2 * l + c2, 2 * k + c1) = B(k, l);
        }
    }
  // The rank-2 coupling through A.
  const Eigen::Map<const Eigen::VectorXd> va(dA.data(), 2 * n), vc(dC.data(), 2 * n);
  hessian.noalias() += va * vc.transpose();
  hessian.noalias() += vc * va.transpose();
  hessian.noalias() += PhiAA * va * va.transpose();
  return E;
}

}  // namespace homesh
