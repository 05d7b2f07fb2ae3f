#include "curving/analogy_formulation.h"

#include <catch2/catch.hpp>
#include <cmath>

#include "core/raise_order.h"
#include "curving/element_distortion.h"
#include "fem/element_tabulation.h"

using namespace homesh;

namespace {

// One straight-sided quadratic triangle with corners (0, 0), (1, 0), (0.3, 0.8).
Mesh triangle() {
  Mesh m;
  m.x.resize(2, 3);
  m.x << 0, 1, 0.3, 0, 0, 0.8;
  m.node_class.assign(3, {});
  m.tri.resize(3, 1);
  m.tri << 0, 1, 2;
  m.tri_entity = {1};
  return raise_order(m, 2);
}

// (lambda, mu) of the coefficients at every assembly point of triangle 0,
// against the expected ones.
void check_lame(const ElasticityCoefficients& c, const FormulationParams& p, double lambda,
                double mu) {
  const int nq =
      int(tabulate_element(2, stiffness_quadrature_degree(2, p.assembly.quadrature_margin))
              .rule.points.cols());
  for (int k = 0; k < nq; ++k) {
    CAPTURE(k);
    const QuadraturePoint q{0, k, Eigen::Vector2d::Zero()};
    const Lame l = lame_plane_strain(c.young(q), c.poisson(q));
    REQUIRE(l.lambda == Approx(lambda).epsilon(1e-12));
    REQUIRE(l.mu == Approx(mu).epsilon(1e-12));
  }
}

}  // namespace

TEST_CASE("stiff_shear: mu grows as (R_e q_F)^-power, lambda kept", "[curving]") {
  const AnalogyFormulation& f = analogy_formulation("stiff_shear");
  FormulationParams p;
  p.poisson = 0.3;
  p.power = 3;
  const Lame lame0 = lame_plane_strain(1.0, p.poisson);
  const Mesh initial = triangle();

  SECTION("a rotation with scaling of a straight-sided element: E = 1 and nu as given") {
    Mesh m = initial;
    Eigen::Matrix2d A;
    A << 1.2, -1.6, 1.6, 1.2;  // 2 x rotation by 53.13 degrees
    m.x = A * initial.x;
    check_lame(f.coefficients(m, initial, p), p, lame0.lambda, lame0.mu);
  }
  SECTION("a uniform shear F = [1 g; 0 1]: q_F = 2 det F / |F|^2 = 2 / (2 + g^2)") {
    Mesh m = initial;
    const double g = 0.7;
    Eigen::Matrix2d F;
    F << 1, g, 0, 1;
    m.x = F * initial.x;
    check_lame(f.coefficients(m, initial, p), p, lame0.lambda,
               lame0.mu * std::pow(2 / (2 + g * g), -p.power));
    p.power = 1;
    check_lame(f.coefficients(m, initial, p), p, lame0.lambda, lame0.mu * (2 + g * g) / 2);
  }
  SECTION("an element curved from the start, not deformed: q_F = 1, R_e = min Q17 / max Q17") {
    Mesh m = initial;
    m.x.col(m.tri(3, 0)) += Eigen::Vector2d(0.05, 0.08);  // the edge node between corners 0, 1
    const double ratio = element_distortion(m).q17_ratio(0);
    REQUIRE(ratio < 0.9);
    check_lame(f.coefficients(m, m, p), p, lame0.lambda, lame0.mu * std::pow(ratio, -p.power));
  }
}
