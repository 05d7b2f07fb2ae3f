// The optimiser's element energy: zero at its targets, its barrier, and its analytic
// gradient against central differences.
#include "curving/distortion_energy.h"

#include <Eigen/LU>
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <vector>

#include "element/quad_reference_nodes.h"
#include "element/reference_nodes.h"
#include "quality/ideal_jacobian.h"

using namespace homesh;

namespace {

// The order-p element through the corners a, b, c, straight-sided.
Eigen::Matrix2Xd straight(int p, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                          const Eigen::Vector2d& c) {
  const Eigen::Matrix2Xd uv = reference_nodes(p);
  Eigen::Matrix2Xd X(2, uv.cols());
  for (int k = 0; k < uv.cols(); ++k) X.col(k) = a + uv(0, k) * (b - a) + uv(1, k) * (c - a);
  return X;
}

const Eigen::Matrix2d kIdeal = ideal_jacobian(Eigen::Matrix2d::Identity());

}  // namespace

TEST_CASE("distortion energy: 0 at the target, +infinity past det J = 0", "[curving]") {
  const ElementTabulation tab = tabulate_element(3, 6);
  const DistortionEnergyOptions opt;
  // Any equilateral element, any size, is the ideal: E = 0.
  const Eigen::Matrix2Xd eq =
      straight(3, {2, 1}, {2 + 1e-3, 1}, {2 + 0.5e-3, 1 + 0.5e-3 * std::sqrt(3.0)});
  CHECK(distortion_energy(eq, tab, kIdeal, opt) == Approx(0).margin(1e-12));
  // A thin straight element is 0 against its own straight shape, large against the ideal.
  const Eigen::Matrix2Xd thin = straight(3, {0, 0}, {1, 0}, {0.4, 1e-3});
  Eigen::Matrix2d J_lin;
  J_lin << 1, 0.4, 0, 1e-3;
  CHECK(distortion_energy(thin, tab, J_lin.inverse(), opt) == Approx(0).margin(1e-9));
  CHECK(distortion_energy(thin, tab, kIdeal, opt) > 1e4);
  // Pushing an edge node towards the opposite corner: the energy grows, then is +infinity
  // once det J <= 0 somewhere.
  Eigen::Matrix2Xd X = straight(3, {0, 0}, {1, 0}, {0.5, 0.8});
  double last = distortion_energy(X, tab, kIdeal, opt);
  int finite = 0;
  for (double t = 0.005; t < 1; t += 0.005) {
    X.col(3) = Eigen::Vector2d(1.0 / 3, t);
    const double E = distortion_energy(X, tab, kIdeal, opt);
    if (std::isinf(E)) break;
    CHECK(E > last);
    last = E;
    ++finite;
  }
  CHECK(finite >= 5);
  CHECK(finite < 150);
  CHECK(last > 100);
  // The floor epsilon refuses before det J reaches 0.
  X.col(3) = Eigen::Vector2d(1.0 / 3, 0.005 * finite);  // the last finite position
  DistortionEnergyOptions floor = opt;
  floor.epsilon = 0.1;
  CHECK(std::isfinite(distortion_energy(X, tab, kIdeal, opt)));
  CHECK(std::isinf(distortion_energy(X, tab, kIdeal, floor)));
}

TEST_CASE("distortion energy: the gradient matches central differences", "[curving]") {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int p : {2, 3, 4})
    for (double alpha : {0.0, 1.0})
      for (double r : {2.0, 3.0}) {
        CAPTURE(p, alpha, r);
        const ElementTabulation tab = tabulate_element(p, 2 * p);
        DistortionEnergyOptions opt;
        opt.alpha = alpha;
        opt.r = r;
        Eigen::Matrix2Xd X = straight(p, {0, 0}, {1, 0.1}, {0.3, 0.7});
        for (int k = 3; k < X.cols(); ++k) X.col(k) += 0.03 * Eigen::Vector2d(u(rng), u(rng));
        Eigen::Matrix2d T;
        T << 1.3, 0.2, -0.1, 0.9;
        Eigen::Matrix2Xd g;
        const double E = distortion_energy(X, tab, T, opt, &g);
        REQUIRE(std::isfinite(E));
        const double h = 1e-6;
        for (int k = 0; k < X.cols(); ++k)
          for (int c = 0; c < 2; ++c) {
            Eigen::Matrix2Xd Xp = X, Xm = X;
            Xp(c, k) += h;
            Xm(c, k) -= h;
            const double fd =
                (distortion_energy(Xp, tab, T, opt) - distortion_energy(Xm, tab, T, opt)) / (2 * h);
            CHECK(g(c, k) == Approx(fd).epsilon(1e-5).margin(1e-6 * std::abs(E) + 1e-8));
          }
      }
}

TEST_CASE("distortion energy: the analytic Hessian matches differences of the gradient",
          "[curving]") {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  for (bool quad : {false, true})
    for (int p : {1, 2, 3, 5})
      for (double alpha : {0.0, 1.0, 100.0})
        for (double r : {2.0, 3.0}) {
          CAPTURE(quad, p, alpha, r);
          // The optimiser's tabulation: Gauss points and the lattice of det J's coefficients.
          const ElementTabulation tab =
              quad ? tabulate_quad_element_and_lattice(p, 2 * p, 0.2)
                   : tabulate_element_and_lattice(p, 2 * p, p > 1 ? 0.2 : 0.0);
          DistortionEnergyOptions opt;
          opt.alpha = alpha;
          opt.r = r;
          // A sheared element (a thin one on the quadrilateral) with its nodes perturbed.
          const Eigen::Matrix2Xd uv = quad ? quad_reference_nodes(p) : reference_nodes(p);
          Eigen::Matrix2d F;
          F << 1, 0.3, quad ? 0.0 : 0.1, quad ? 0.05 : 0.7;
          Eigen::Matrix2Xd X = F * uv;
          for (int k = 0; k < X.cols(); ++k)
            X.col(k) += (quad ? 0.0004 : 0.01) * Eigen::Vector2d(u(rng), u(rng));
          Eigen::Matrix2d T;
          T << 1.3, 0.2, -0.1, 0.9;
          Eigen::Matrix2Xd g, g0;
          Eigen::MatrixXd H;
          const double E = distortion_energy_hessian(X, tab, T, opt, g, H);
          REQUIRE(std::isfinite(E));
          CHECK(E == Approx(distortion_energy(X, tab, T, opt, &g0)).epsilon(1e-12));
          CHECK((g - g0).norm() <= 1e-10 * g0.norm() + 1e-14);
          const int n = static_cast<int>(X.cols());
          REQUIRE(H.rows() == 2 * n);
          CHECK((H - H.transpose()).norm() <= 1e-12 * H.norm());
          // Central differences of the analytic gradient, column by column.
          const double h = 1e-6 * 0.05;
          Eigen::MatrixXd fd(2 * n, 2 * n);
          for (int k = 0; k < n; ++k)
            for (int c = 0; c < 2; ++c) {
              Eigen::Matrix2Xd Xp = X, Xm = X, gp, gm;
              Xp(c, k) += h;
              Xm(c, k) -= h;
              distortion_energy(Xp, tab, T, opt, &gp);
              distortion_energy(Xm, tab, T, opt, &gm);
              const Eigen::Matrix2Xd dg = (gp - gm) / (2 * h);
              fd.col(2 * k + c) = Eigen::Map<const Eigen::VectorXd>(dg.data(), 2 * n);
            }
          CHECK((H - fd).norm() <= 1e-5 * fd.norm());
          // By a subset of the nodes, in its order: the matching rows and columns.
          std::vector<int> some;
          for (int k = n - 1; k >= 0; k -= 2) some.push_back(k);
          Eigen::Matrix2Xd gs;
          Eigen::MatrixXd Hs;
          CHECK(distortion_energy_hessian(X, tab, T, opt, gs, Hs, &some) == E);
          const int L = static_cast<int>(some.size());
          REQUIRE(Hs.rows() == 2 * L);
          REQUIRE(gs.cols() == L);
          double worst = 0;
          for (int a = 0; a < L; ++a) {
            worst = std::max(worst, (gs.col(a) - g.col(some[a])).norm());
            for (int b = 0; b < L; ++b)
              worst = std::max(
                  worst,
                  (Hs.block<2, 2>(2 * a, 2 * b) - H.block<2, 2>(2 * some[a], 2 * some[b])).norm());
          }
          CHECK(worst <= 1e-12 * (H.norm() + g.norm()));
        }
}
