// The thesis' measures with d = 3 on tetrahedra (issue 24).
#include "quality/volume_measures.h"

#include <Eigen/Geometry>
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "quality/measure_registry.h"
#include "quality/volume_quality.h"

using namespace homesh;

namespace {

// A random rotation (seeded).
Eigen::Matrix3d rotation(std::mt19937& rng) {
  std::normal_distribution<double> g;
  return Eigen::Quaterniond(g(rng), g(rng), g(rng), g(rng)).normalized().toRotationMatrix();
}

bool scale_invariant(const Measure& m) { return m.invariance.scale; }

}  // namespace

TEST_CASE("volume measures: every 3D quality is 1 at the ideal and 0 when inverted",
          "[quality][volume_measures]") {
  int with_form = 0;
  for (const Measure& m : measures()) {
    INFO(m.name);
    if (!m.quality3) {
      CHECK(m.name == "Q1");  // the one measure of the whole element
      continue;
    }
    ++with_form;
    CHECK(m.quality3(Eigen::Matrix3d::Identity()) == Approx(1.0).epsilon(1e-14));
    Eigen::Matrix3d mirror = Eigen::Matrix3d::Identity();
    mirror(2, 2) = -1;
    CHECK(m.quality3(mirror) == 0.0);
  }
  CHECK(with_form == 15);  // Q2 .. Q17 but Q15
}

TEST_CASE("volume measures: in [0, 1], rotation invariant, the shape measures scale invariant",
          "[quality][volume_measures]") {
  std::mt19937 rng(24);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 200; ++trial) {
    Eigen::Matrix3d W = Eigen::Matrix3d::Identity();
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) W(i, j) += 0.6 * u(rng);
    if (W.determinant() <= 0) W.col(0) *= -1;
    const Eigen::Matrix3d R = rotation(rng);
    const double s = std::exp(2 * u(rng));
    for (const Measure& m : measures()) {
      if (!m.quality3) continue;
      INFO(m.name << " trial " << trial);
      const double q = m.quality3(W);
      CHECK(q >= 0.0);
      CHECK(q <= 1.0 + 1e-12);
      CHECK(m.quality3(R * W) == Approx(q).epsilon(1e-9));
      if (m.name == "Q6" || m.name == "Q7") continue;  // scale invariant in 2D only
      if (scale_invariant(m)) CHECK(m.quality3(s * W) == Approx(q).epsilon(1e-9));
    }
  }
}

TEST_CASE("volume measures: closed forms on a stretch diag(a, 1, 1)",
          "[quality][volume_measures]") {
  for (double a : {0.3, 0.8, 1.7, 4.0}) {
    INFO("a = " << a);
    const Eigen::Matrix3d W = Eigen::Vector3d(a, 1, 1).asDiagonal();
    const double f2 = a * a + 2;
    CHECK(measure("Q10").quality3(W) == Approx(3 * std::cbrt(a * a) / f2).epsilon(1e-14));
    CHECK(measure("Q12").quality3(W) == Approx(a / std::pow(f2 / 3, 1.5)).epsilon(1e-14));
    CHECK(measure("Q11").quality3(W) ==
          Approx(3 / std::sqrt(f2 * (1 / (a * a) + 2))).epsilon(1e-14));
    CHECK(measure("Q17").quality3(W) == Approx(std::min(a, 1 / a)).epsilon(1e-14));
    CHECK(measure("Q4").quality3(W) == Approx(std::min(a * a, 1 / (a * a))).epsilon(1e-14));
    CHECK(measure("Q2").quality3(W) == Approx(std::min(f2 / 3, 3 / f2)).epsilon(1e-14));
  }
}

TEST_CASE("volume_quality: the regular tetrahedron scores 1, a flattened one less",
          "[quality][volume_measures]") {
  VolumeMesh m;
  m.order = 1;
  m.x.resize(3, 5);
  m.x << 0, 1, 0.5, 0.5, 0.5,                                            //
      0, 0, std::sqrt(3.0) / 2, std::sqrt(3.0) / 6, std::sqrt(3.0) / 6,  //
      0, 0, 0, std::sqrt(2.0 / 3.0), 0.1;
  m.tet.resize(4, 2);
  m.tet << 0, 0, 1, 1, 2, 2, 3, 4;
  m.tet_entity = {1, 1};
  std::vector<const Measure*> qs;
  for (const Measure& q : measures()) qs.push_back(&q);
  const std::vector<MeshMeasure> r = volume_quality(m, qs, 2, Reference::ideal, 1);
  REQUIRE(r.size() == qs.size());
  for (std::size_t j = 0; j < qs.size(); ++j) {
    INFO(qs[j]->name);
    CHECK(r[j].element_min(0) == Approx(1.0).epsilon(1e-12));
    CHECK(r[j].node_values.rows() == 4);
    CHECK(r[j].node_values.col(0).minCoeff() == Approx(1.0).epsilon(1e-12));
    if (qs[j]->name != "Q1") CHECK(r[j].element_min(1) < 0.9);  // straight: Q1 stays 1
  }
}
