// Thesis Table 3.2 on our gallery by our criterion
// (optim/distortion_representation.h), against the thesis's table.
#include "optim/distortion_representation.h"

#include <catch2/catch.hpp>
#include <cmath>

using namespace homesh;

namespace {

const std::vector<RepresentationCell>& cells() {
  static const std::vector<RepresentationCell> c = distortion_representation(
      read_gallery(std::string(HOMESH_SOURCE_DIR) + "/geo/gallery_t1_t12.csv"));
  return c;
}

const ThesisTable& thesis() {
  static const ThesisTable t = read_thesis_table(std::string(HOMESH_REFERENCE_DIR) +
                                                 "/table_3_2_distortion_representation.csv");
  return t;
}

const RepresentationCell& cell(const std::string& m, const std::string& e) {
  for (const RepresentationCell& c : cells()) {
    if (c.measure == m && c.element == e) return c;
  }
  throw std::logic_error("no cell " + m + " " + e);
}

}  // namespace

TEST_CASE("Hencky strain: 0 for rotations, log of the stretches otherwise", "[study]") {
  const double a = 0.7;
  Eigen::Matrix2d R;
  R << std::cos(a), -std::sin(a), std::sin(a), std::cos(a);
  CHECK(hencky_distortion(R) < 1e-15);
  CHECK(hencky_distortion(2.0 * R) == Approx(std::sqrt(2.0) * std::log(2.0)));
  CHECK(hencky_distortion(Eigen::Vector2d(3.0, 1.0 / 3.0).asDiagonal()) ==
        Approx(std::sqrt(2.0) * std::log(3.0)));
  CHECK(std::isinf(hencky_distortion(Eigen::Vector2d(1.0, -1.0).asDiagonal())));
}

TEST_CASE("Table 3.2: at least 185 of 192 cells agree with the thesis", "[study]") {
  REQUIRE(cells().size() == 16 * 12);
  const TableAgreement full = compare_with_thesis(cells(), thesis());
  CHECK(full.compared == 192);
  CHECK(full.agree >= 185);
  // Each test of the criterion adds agreement: detection alone, then the
  // distribution (Q1's constant field), then the inversion (Q2, Q3, Q5).
  const TableAgreement detection =
      compare_with_thesis(cells(), thesis(), &RepresentationCell::detects);
  const TableAgreement distribution =
      compare_with_thesis(cells(), thesis(), &RepresentationCell::detects_and_distributes);
  CHECK(detection.agree >= 171);
  CHECK(distribution.agree >= detection.agree + 10);
  CHECK(full.agree > distribution.agree);
}

TEST_CASE("Table 3.2: the columns and rows the thesis is sure of", "[study]") {
  for (const Measure& m : measures()) {
    INFO(m.name);
    // T1: every measure recognises the ideal element.
    CHECK(cell(m.name, "T1").represents);
    CHECK(cell(m.name, "T1").f < 1e-12);
    // T2 (constant W, ideal area): seen by the shape measures only, as in the thesis.
    CHECK(cell(m.name, "T2").represents == (thesis().at(m.name, "T2") == "1"));
  }
  // Q1 is constant over each element: it represents no distortion.
  for (int n = 2; n <= 12; ++n) CHECK_FALSE(cell("Q1", "T" + std::to_string(n)).represents);
  CHECK_FALSE(cell("Q1", "T5").distributes);
  // The shape measures represent every element of the gallery.
  for (const char* m : {"Q6", "Q7", "Q8", "Q11", "Q12", "Q14", "Q16"}) {
    for (int n = 1; n <= 12; ++n) CHECK(cell(m, "T" + std::to_string(n)).represents);
  }
  // Q2, Q3, Q5 (Q / Qmax) invert the symmetric vertex distortions of T4, T6.
  for (const char* m : {"Q2", "Q3", "Q5"}) {
    for (const char* e : {"T4", "T6"}) {
      INFO(m << " " << e);
      CHECK(cell(m, e).detected);
      CHECK(cell(m, e).inverted);
      CHECK(cell(m, e).correlation < -0.9);
    }
  }
  // Q4 and Q17 represent everything but T2.
  for (const char* m : {"Q4", "Q17"}) {
    for (int n = 1; n <= 12; ++n) CHECK(cell(m, "T" + std::to_string(n)).represents == (n != 2));
  }
}
