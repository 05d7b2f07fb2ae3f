// The formulations on quadrilaterals: per-element values indexed after the
// triangles, per-point values on the quadrilateral's rule, the unit square as
// its ideal element (W = J).
#include <catch2/catch.hpp>
#include <cmath>

#include "../fem/fem_test_support.h"
#include "curving/analogy_formulation.h"
#include "fem/element_tabulation.h"

using namespace homesh;

namespace {

int quad_points(int p, const FormulationParams& params) {
  return int(tabulate_quad_element(
                 p, quad_stiffness_quadrature_degree(p, params.assembly.quadrature_margin))
                 .rule.points.cols());
}

}  // namespace

TEST_CASE("area and stiff_q17 on a mixed mesh: E per 2D element, quadrilaterals after triangles",
          "[curving][quad]") {
  // 2 by 2 cells of order 2: quadrilaterals in column 0 (area 1/4), triangles
  // in column 1 (area 1/8). A quadrilateral's A_e is half its area: E = 8 on
  // all (a grid of equal cells equally stiff whether cut into triangles or not).
  const Mesh m = fem_test::mixed_square(2, 2, 1);
  REQUIRE(m.num_triangles() == 4);
  REQUIRE(m.num_quads() == 2);
  const FormulationParams params;
  const ElasticityCoefficients area = analogy_formulation("area").coefficients(m, m, params);
  const ElasticityCoefficients stiff = analogy_formulation("stiff_q17").coefficients(m, m, params);
  for (int e = 0; e < m.num_elements_2d(); ++e) {
    const QuadraturePoint q{e, 0, Eigen::Vector2d::Zero()};
    CHECK(area.young(q) == Approx(8.0).epsilon(1e-12));
    CHECK(stiff.young(q) == Approx(1.0).epsilon(1e-12));
  }
  // A quadrilateral with its interior node moved: its Q17 ratio < 1 stiffens it alone.
  Mesh curved = m;
  curved.x(0, curved.quad(8, 1)) += 0.1;  // the interior node of quadrilateral 1
  const ElasticityCoefficients c = analogy_formulation("stiff_q17").coefficients(curved, m, params);
  CHECK(c.young({5, 0, Eigen::Vector2d::Zero()}) > 1.01);
  CHECK(c.young({4, 0, Eigen::Vector2d::Zero()}) == Approx(1.0).epsilon(1e-12));
  // Stretched by 2 along x: every area doubles, E = 4 on all.
  Mesh stretched = m;
  stretched.x.row(0) *= 2.0;
  const ElasticityCoefficients a2 = analogy_formulation("area").coefficients(stretched, m, params);
  for (int e = 0; e < m.num_elements_2d(); ++e)
    CHECK(a2.young({e, 0, Eigen::Vector2d::Zero()}) == Approx(4.0).epsilon(1e-12));
}

TEST_CASE("metric_ideal, metric_ref and stiff_shear on quadrilaterals: W = J, at every point",
          "[curving][quad]") {
  // Stretching x by 2 turns J = h I into h diag(2, 1) on every quadrilateral:
  // the scaled metric goes from I to diag(2, 1/2), so sigma_t = -heat
  // (diag(2, 1/2) - I) with either map (the unit square is the ideal element),
  // and F = diag(2, 1) has q_F = 2 det F / |F|_F^2 = 4/5.
  const Mesh m = fem_test::mixed_square(2, 3, 1);
  Mesh stretched = m;
  stretched.x.row(0) *= 2.0;
  FormulationParams params;
  params.heat = 1.5;
  params.power = 3;
  const int nq = quad_points(3, params);
  const Eigen::Matrix2d expected =
      -params.heat *
      (Eigen::Vector2d(2.0, 0.5).asDiagonal().toDenseMatrix() - Eigen::Matrix2d::Identity());
  for (const char* name : {"metric_ideal", "metric_ref"}) {
    INFO(name);
    const ElasticityCoefficients c = analogy_formulation(name).coefficients(stretched, m, params);
    for (int e : {4, 5})
      for (int k : {0, nq / 2, nq - 1}) {
        const Eigen::Matrix2d S = c.anisotropic_stress({e, k, Eigen::Vector2d::Zero()});
        CHECK((S - expected).cwiseAbs().maxCoeff() < 1e-12);
      }
  }
  const ElasticityCoefficients c =
      analogy_formulation("stiff_shear").coefficients(stretched, m, params);
  const Lame l0 = lame_plane_strain(1.0, params.poisson);
  for (int k : {0, nq - 1}) {
    const QuadraturePoint q{5, k, Eigen::Vector2d::Zero()};
    const Lame l = lame_plane_strain(c.young(q), c.poisson(q));
    CHECK(l.lambda == Approx(l0.lambda).epsilon(1e-12));
    CHECK(l.mu == Approx(l0.mu * std::pow(0.8, -3.0)).epsilon(1e-12));
  }
}
